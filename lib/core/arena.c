/*
 * arena.c - region allocation in chained blocks, and big blocks in
 * mappings of their own.
 */
#define _GNU_SOURCE /* mremap */
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
  /* The bytes of the block's own mapping (zr__map_alloc), this header
     included; 0 for a block of malloc's. */
  size_t mapped;
  alignas(max_align_t) unsigned char data[];
};

enum { BLOCK_SIZE = 64 * 1024 };

void zr__arena_init(zr_arena *a) { memset(a, 0, sizeof *a); }

void zr__arena_free(zr_arena *a) {
  zr_arena_block *b = a->head;
  while (b) {
    zr_arena_block *next = b->next;
    if (b->mapped)
      zr__map_free(b, b->mapped);
    else
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

/*
 * A new block of cap bytes of room, charged to the arena's budget.  From
 * ZR__MAP_FROM bytes on (header included) it is a mapping of its own
 * (zr__map_alloc: huge pages, and its memory goes back to the system
 * when the arena is freed); below, malloc's.
 */
static zr_arena_block *new_block(zr_arena *a, size_t cap) {
  size_t bytes = sizeof(zr_arena_block) + cap;
  if (!zr__budget_charge(a->budget, bytes)) {
    a->over_budget = 1;
    return NULL;
  }
  bool mapped = bytes >= ZR__MAP_FROM;
  zr_arena_block *b = mapped ? zr__map_alloc(bytes) : malloc(bytes);
  if (!b) {
    zr__budget_release(a->budget, bytes);
    return NULL;
  }
  if (a->budget)
    a->charged += bytes;
  b->mapped = mapped ? zr__map_room(bytes) : 0;
  if (!mapped)
    zr__mem_huge_pages(b->data, cap);
  b->size = cap;
  b->used = 0;
  return b;
}

void *zr__arena_alloc_raw(zr_arena *a, size_t size) {
  if (size > SIZE_MAX / 2)
    return NULL;
  size = rounded(size);
  zr_arena_block *b = a->head;
  if (!b || b->size - b->used < size) {
    size_t cap = size > BLOCK_SIZE / 4 ? size : BLOCK_SIZE;
    /* An arena that has grown big takes its next blocks of small
       allocations a huge page at a time (a mapping of one huge page): a
       scene of 7,381 spheres' textures took about 250 page faults of
       4 KiB. */
    bool huge = cap == BLOCK_SIZE && a->used >= ZR__HUGE_FROM;
    if (huge)
      cap = ZR__HUGE_PAGE - sizeof *b;
    b = new_block(a, cap);
    if (!b)
      return NULL;
    if (a->populate && !huge)
      zr__mem_populate(b->data, cap);
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

size_t zr__map_room(size_t size) {
  return size < ZR__MAP_FROM ? size : huge_rounded(size);
}

#if defined(MAP_ANONYMOUS) && defined(MREMAP_FIXED)
/*
 * room bytes (whole huge pages) of fresh address space that starts on a
 * huge page: a reservation one huge page longer, its ends cut off.
 * Nothing is touched, so nothing is resident yet.  prot is the access
 * the pages get: none for a place mremap is to move a block to.
 */
static void *map_aligned(size_t room, int prot) {
  if (room > SIZE_MAX - ZR__HUGE_PAGE)
    return NULL;
  size_t span = room + ZR__HUGE_PAGE;
  int flags = MAP_PRIVATE | MAP_ANONYMOUS | (prot ? 0 : MAP_NORESERVE);
  unsigned char *p = mmap(NULL, span, prot, flags, -1, 0);
  if (p == MAP_FAILED)
    return NULL;
  const uintptr_t mask = (uintptr_t)(ZR__HUGE_PAGE - 1);
  unsigned char *q = (unsigned char *)(((uintptr_t)p + mask) & ~mask);
  if (q > p)
    (void)munmap(p, (size_t)(q - p));
  if (p + span > q + room)
    (void)munmap(q + room, (size_t)(p + span - (q + room)));
  return q;
}

void *zr__map_alloc(size_t size) {
  if (size < ZR__MAP_FROM)
    return malloc(size ? size : 1);
  size_t room = huge_rounded(size);
  void *p = room ? map_aligned(room, PROT_READ | PROT_WRITE) : NULL;
  zr__mem_advise_huge(p, room);
  return p;
}

void zr__map_free(void *p, size_t size) {
  if (size < ZR__MAP_FROM)
    free(p);
  else if (p)
    (void)munmap(p, huge_rounded(size));
}

void *zr__map_zeroed(size_t size) {
  if (size < ZR__MAP_FROM)
    return calloc(size ? size : 1, 1);
  return zr__map_alloc(size);
}

void *zr__map_grow(void *p, size_t old_size, size_t new_size) {
  if (!p)
    return zr__map_alloc(new_size);
  if (new_size < ZR__MAP_FROM) {
    if (old_size < ZR__MAP_FROM)
      return realloc(p, new_size ? new_size : 1);
    void *q = malloc(new_size ? new_size : 1);
    if (q) {
      memcpy(q, p, new_size);
      zr__map_free(p, old_size);
    }
    return q;
  }
  size_t room = huge_rounded(new_size);
  if (!room)
    return NULL;
  if (old_size < ZR__MAP_FROM) {
    /* From malloc's to a mapping: the one copy. */
    void *q = zr__map_alloc(new_size);
    if (q) {
      memcpy(q, p, old_size);
      free(p);
    }
    return q;
  }
  size_t old_room = huge_rounded(old_size);
  if (room <= old_room)
    return p; /* a shrink keeps its room: the pages past it are untouched */
  /* The pages already there move with their page tables (no copy, no
     fault), to a place on a huge page so that the room added gets huge
     pages too; in place when the address space after the block is free. */
  void *q = mremap(p, old_room, room, 0);
  if (q == MAP_FAILED) {
    void *to = map_aligned(room, PROT_NONE);
    if (!to)
      return NULL;
    q = mremap(p, old_room, room, MREMAP_MAYMOVE | MREMAP_FIXED, to);
    if (q == MAP_FAILED) {
      (void)munmap(to, room);
      return NULL;
    }
  }
  zr__mem_advise_huge(q, room);
  return q;
}
#else
/* Without anonymous mappings or mremap: zr__huge_alloc's blocks. */
void *zr__map_alloc(size_t size) { return zr__huge_alloc(size); }

void *zr__map_zeroed(size_t size) {
  void *p = zr__huge_alloc(size);
  if (p)
    memset(p, 0, size ? size : 1);
  return p;
}

void zr__map_free(void *p, size_t size) {
  (void)size;
  free(p);
}

void *zr__map_grow(void *p, size_t old_size, size_t new_size) {
  return zr__huge_grow(p, old_size, new_size);
}
#endif

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
  /* A block of its own: moved whole by the kernel when it is a mapping
     (zr__map_grow: no copy, and its pages stay where they were), moved
     once into a mapping when it grows past ZR__MAP_FROM, resized by
     realloc below that. */
  size_t bytes = sizeof *b + size;
  zr_arena_block *grown = b->mapped || bytes >= ZR__MAP_FROM
                              ? zr__map_grow(b, b->mapped ? b->mapped
                                                          : sizeof *b + old,
                                             bytes)
                              : realloc(b, bytes);
  if (!grown) {
    zr__budget_release(a->budget, size - old);
    return NULL;
  }
  if (a->budget)
    a->charged += size - old;
  /* A mapping keeps the room it had when that was enough. */
  if (bytes >= ZR__MAP_FROM && grown->mapped < zr__map_room(bytes))
    grown->mapped = zr__map_room(bytes);
  if (!grown->mapped)
    zr__mem_huge_pages(grown->data, size);
  /* An arena of a big scene file fills what it grows (zr_arena's
     populate): the room added is faulted in at once. */
  if (!grown->mapped && a->populate)
    zr__mem_populate(grown->data + old, size - old);
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
