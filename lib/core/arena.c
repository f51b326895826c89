/*
 * arena.c - region allocation in chained blocks.
 */
#include "core/arena.h"

#include "core/budget.h"
#include "core/hugepage.h"

#include <stdalign.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

struct zr_arena_block {
  zr_arena_block *next;
  size_t size;
  size_t used;
  alignas(max_align_t) unsigned char data[];
};

enum { BLOCK_SIZE = 64 * 1024 };

void zr__arena_init(zr_arena *a) { memset(a, 0, sizeof *a); }

void zr__arena_free(zr_arena *a) {
  zr_arena_block *b = a->head;
  while (b) {
    zr_arena_block *next = b->next;
    free(b);
    b = next;
  }
  zr__budget_release(a->budget, a->charged);
  struct zr_budget *budget = a->budget;
  bool populate = a->populate;
  zr__arena_init(a);
  a->budget = budget;
  a->populate = populate;
}

/* size rounded up to the arena's alignment (at least one unit). */
static size_t rounded(size_t size) {
  const size_t align = alignof(max_align_t);
  size = (size + align - 1) & ~(align - 1);
  return size ? size : align;
}

void *zr__arena_alloc_raw(zr_arena *a, size_t size) {
  if (size > SIZE_MAX / 2)
    return NULL;
  size = rounded(size);
  zr_arena_block *b = a->head;
  if (!b || b->size - b->used < size) {
    size_t cap = size > BLOCK_SIZE / 4 ? size : BLOCK_SIZE;
    /* An arena that has grown big takes its next blocks of small
       allocations a huge page at a time (zr__huge_alloc): a scene of
       7,381 spheres' textures took about 250 page faults of 4 KiB. */
    bool huge = cap == BLOCK_SIZE && a->used >= ZR__HUGE_FROM;
    if (huge)
      cap = ZR__HUGE_PAGE - sizeof *b;
    if (!zr__budget_charge(a->budget, sizeof *b + cap)) {
      a->over_budget = 1;
      return NULL;
    }
    b = huge ? zr__huge_alloc(sizeof *b + cap) : malloc(sizeof *b + cap);
    if (!b) {
      zr__budget_release(a->budget, sizeof *b + cap);
      return NULL;
    }
    if (a->budget)
      a->charged += sizeof *b + cap;
    zr__mem_huge_pages(b->data, cap);
    if (a->populate && !huge)
      zr__mem_populate(b->data, cap);
    b->size = cap;
    b->used = 0;
    /* A large one-off block goes behind the head so the head keeps its
       free space for the small allocations that follow. */
    if (cap != BLOCK_SIZE && !huge && a->head) {
      b->next = a->head->next;
      a->head->next = b;
    } else {
      b->next = a->head;
      a->head = b;
    }
  }
  void *p = b->data + b->used;
  b->used += size;
  a->used += size;
  return p;
}

void zr__mem_populate(void *p, size_t size) {
#ifdef MADV_POPULATE_WRITE
  const uintptr_t mask = 4095;
  uintptr_t lo = ((uintptr_t)p + mask) & ~mask;
  uintptr_t hi = ((uintptr_t)p + size) & ~mask;
  if (p && hi > lo)
    (void)madvise((void *)lo, hi - lo, MADV_POPULATE_WRITE); /* a hint */
#else
  (void)p;
  (void)size;
#endif
}

void zr__mem_huge_pages(void *p, size_t size) {
  /* Below two huge pages the rounding would leave little or nothing. */
  if (size >= 2 * ZR__HUGE_PAGE)
    zr__mem_advise_huge(p, size);
}

/* size rounded up to whole huge pages; 0 when that overflows. */
static size_t huge_rounded(size_t size) {
  if (size > SIZE_MAX - ZR__HUGE_PAGE)
    return 0;
  return (size + ZR__HUGE_PAGE - 1) & ~(ZR__HUGE_PAGE - 1);
}

void *zr__huge_alloc(size_t size) {
  if (size < ZR__HUGE_FROM)
    return malloc(size ? size : 1);
  size_t room = huge_rounded(size);
  void *p = NULL;
  if (!room || posix_memalign(&p, ZR__HUGE_PAGE, room) != 0)
    return NULL;
  zr__mem_advise_huge(p, room);
  return p;
}

void *zr__huge_grow(void *p, size_t old_size, size_t new_size) {
  if (new_size < ZR__HUGE_FROM || !p)
    return p || new_size < ZR__HUGE_FROM ? realloc(p, new_size ? new_size : 1)
                                         : zr__huge_alloc(new_size);
  /* A block of zr__huge_alloc's: still room in its rounding. */
  if (old_size >= ZR__HUGE_FROM && new_size <= huge_rounded(old_size) &&
      ((uintptr_t)p & (ZR__HUGE_PAGE - 1)) == 0)
    return p;
  void *q = zr__huge_alloc(new_size);
  if (!q)
    return NULL;
  memcpy(q, p, old_size < new_size ? old_size : new_size);
  free(p);
  return q;
}

void *zr__arena_alloc(zr_arena *a, size_t size) {
  void *p = zr__arena_alloc_raw(a, size);
  if (p)
    memset(p, 0, rounded(size));
  return p;
}

void *zr__arena_grow(zr_arena *a, void *p, size_t old_size,
                     size_t new_size) {
  if (!p)
    return zr__arena_alloc_raw(a, new_size);
  if (new_size <= old_size)
    return p;
  if (new_size > SIZE_MAX / 2)
    return NULL;
  size_t old = rounded(old_size), size = rounded(new_size);
  /* Only an allocation above a quarter block has a block of its own; a
     large block goes in behind the head, so a growing array is found
     near the front. */
  zr_arena_block **link = &a->head;
  if (old > BLOCK_SIZE / 4)
    while (*link && (*link)->data != (unsigned char *)p)
      link = &(*link)->next;
  zr_arena_block *b = old > BLOCK_SIZE / 4 ? *link : NULL;
  if (!b || b->size != old || b->used != old) {
    void *q = zr__arena_alloc_raw(a, new_size);
    if (q)
      memcpy(q, p, old_size);
    return q;
  }
  if (!zr__budget_charge(a->budget, size - old)) {
    a->over_budget = 1;
    return NULL;
  }
  zr_arena_block *grown = realloc(b, sizeof *b + size);
  if (!grown) {
    zr__budget_release(a->budget, size - old);
    return NULL;
  }
  if (a->budget)
    a->charged += size - old;
  zr__mem_huge_pages(grown->data, size);
  *link = grown;
  grown->size = grown->used = size;
  a->used += size - old;
  return grown->data;
}

void *zr__arena_memdup(zr_arena *a, const void *p, size_t size) {
  void *q = zr__arena_alloc_raw(a, size);
  if (q && size)
    memcpy(q, p, size);
  return q;
}

bool zr__arena_give_back(zr_arena *a, void *p, size_t size) {
  const size_t align = alignof(max_align_t);
  size = (size + align - 1) & ~(align - 1);
  if (size == 0)
    size = align;
  zr_arena_block *b = a->head;
  if (!b || b->used < size || (unsigned char *)p != b->data + b->used - size)
    return false;
  b->used -= size;
  a->used -= size;
  return true;
}

char *zr__arena_strdup(zr_arena *a, const char *s) {
  return zr__arena_memdup(a, s, strlen(s) + 1);
}
