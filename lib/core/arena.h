/*
 * arena.h - a region allocator.  A scene's objects, textures and
 * transforms live in one arena and are freed together, so the shared
 * pointers that #declare creates (one texture used by many objects) need
 * no reference counts.
 */
#ifndef ZR_CORE_ARENA_H
#define ZR_CORE_ARENA_H

#include <stdbool.h>
#include <stddef.h>

typedef struct zr_arena_block zr_arena_block;

struct zr_budget;

typedef struct zr_arena {
  zr_arena_block *head;
  size_t used; /* bytes handed out, for statistics */
  /* Blocks are charged to this budget (NULL: none) and given back when
     the arena is freed; over_budget tells why an allocation failed. */
  struct zr_budget *budget;
  size_t charged;
  int over_budget;
  /* Every new block is filled in at once (zr__mem_populate): for an
     arena its owner knows will use many blocks (a big scene file's,
     lib/sdl/directive.c), whose blocks are then used to the end. */
  bool populate;
} zr_arena;

void zr__arena_init(zr_arena *a);
/* Frees every block; the arena keeps its budget and can be used again. */
void zr__arena_free(zr_arena *a);
/* Zeroed memory aligned for any type; NULL when out of memory. */
void *zr__arena_alloc(zr_arena *a, size_t size);
/* The same, not zeroed: for callers that write every byte before they
   read it (copies, arrays filled row by row).  Zeroing costs a pass
   over the memory and touches pages that may never be used. */
void *zr__arena_alloc_raw(zr_arena *a, size_t size);
/*
 * Room for new_size bytes where p (old_size bytes from this arena, or
 * NULL) was, keeping its bytes; the bytes after old_size are not zeroed.
 * A large allocation has a block of its own, which is resized (realloc:
 * the C library moves a big block by remapping its pages, so the old
 * room is neither copied nor left behind); anything else is copied to a
 * new allocation.  NULL when out of memory, p then unchanged.  An array
 * that grows by doubling costs its final size, not twice it (issue 13:
 * a mesh of 130,050 triangles left 12 MB of old vertex arrays behind).
 */
void *zr__arena_grow(zr_arena *a, void *p, size_t old_size,
                     size_t new_size);
char *zr__arena_strdup(zr_arena *a, const char *s);
/* Takes back p, of size bytes, when it is the arena's last allocation
   (true then); anything else stays where it is (false). */
bool zr__arena_give_back(zr_arena *a, void *p, size_t size);
void *zr__arena_memdup(zr_arena *a, const void *p, size_t size);

/*
 * Asks the kernel to back the 2 MB-aligned pages inside [p, p + size)
 * with huge pages (madvise MADV_HUGEPAGE; nothing where that does not
 * exist), before they are first touched: core/hugepage.h's advice, for
 * buffers of two huge pages or more.  For big buffers filled once
 * (a scene file's bytes, its token array, a mesh's arrays): a first
 * touch of a 4 KB page costs a page fault, which took 22% of the parse
 * of a 130,050-triangle mesh on this project's VM (issue 13).  Where
 * transparent huge pages are "madvise" (a common default), only memory
 * marked this way gets them.
 */
void zr__mem_huge_pages(void *p, size_t size);

/*
 * Big buffers about to be filled, in huge pages from the start.  On this
 * project's virtual machine first touching a 4 KiB page of fresh memory
 * costs about 14 us (core/hugepage.h), and a buffer of malloc's lies
 * at a 4 KiB boundary, so advice reaches only the whole huge pages that
 * happen to fall inside it: none in most buffers under 4 MiB.  From
 * ZR__HUGE_FROM bytes on, zr__huge_alloc gives a block aligned on
 * 2 MiB, its size rounded up to them, advised (one fault per 2 MiB
 * where the kernel obliges; a buffer of 256 KiB costs 64 faults, about
 * 0.9 ms, otherwise, a huge page's fault and zeroing about 0.2 ms);
 * below, plain malloc.  The price is up to 2 MiB of rounding per buffer,
 * so the line is drawn at 1 MiB (at most twice a buffer's size): from
 * 256 KiB on, the peers flake's peak memory was 14.1 MiB (12.1 MiB
 * above an empty scene's, 696 bytes a sphere, 2.8x Tachyon's: issue 13
 * wants <= 1.5x), from 512 KiB 488 bytes a sphere; from 1 MiB it is
 * 331 bytes (1.35x) and 1,338 page faults at 512^2 (main 2,144, from
 * 256 KiB 553).  Freed (and shrunk) with free and realloc.  p of
 * zr__huge_grow must come from malloc or realloc (below ZR__HUGE_FROM)
 * or from these two.
 *
 * zr__huge_grow is realloc for an array that grows (by doubling): p
 * holds old_size bytes (the size last asked of these two, or of malloc
 * or realloc), to become new_size.  Below ZR__HUGE_FROM it is realloc;
 * from there on the array moves, once, to a block of zr__huge_alloc's
 * and then stays in it while its rounding has room.  NULL when out of
 * memory, p then unchanged.
 */
enum { ZR__HUGE_FROM = 1024 * 1024 };

/*
 * Has the kernel back the whole 4 KiB pages inside [p, p + size) now, in
 * one call (madvise MADV_POPULATE_WRITE, Linux 5.14; nothing where it
 * does not exist), for memory that is about to be written all through:
 * the same pages, so the same resident size, for about half the time.
 * Measured here (a Firecracker VM): a first touch of a fresh page costs
 * ~15 us, a page populated ~7 us (bench/results/parse-2026-12-03-s13.md).
 * Never for room that may stay unused: populated pages count as used.
 */
void zr__mem_populate(void *p, size_t size);
void *zr__huge_alloc(size_t size);
void *zr__huge_grow(void *p, size_t old_size, size_t new_size);

/*
 * Big blocks in mappings of their own (mmap), for buffers whose owner
 * knows their size when it frees them: an arena's big blocks, a mesh's
 * and a hierarchy's build arrays.  From ZR__MAP_FROM bytes on a block
 * is a fresh mapping aligned on a huge page, its size rounded up to
 * whole huge pages (zr__map_room) and advised to huge pages, so each
 * 2 MiB costs one page fault where the kernel obliges (not 512 of
 * 14 us: bench/results/arena-2026-12-03-s15.md); below, malloc's.
 *
 * Against zr__huge_alloc (posix_memalign, freed with free): a freed
 * block is unmapped, so its memory goes back to the system at once.
 * glibc keeps freed memory in its heap once its mmap threshold has
 * risen (it does when a big block is freed), and the next big blocks
 * then come out of pages touched before, in 4 KiB pages, which is
 * where the terrain's arena in huge pages (session 14) lost its 14 MB.
 * And a growing block moves by mremap: its pages, huge or not, are
 * handed over with their page tables, never copied (a realloc in
 * glibc's heap copies, and the copy touches as many fresh pages again).
 *
 * zr__map_free and zr__map_grow take the size last asked of these
 * three (or of malloc and realloc, below ZR__MAP_FROM), which says
 * where the block came from.  zr__map_grow keeps the bytes up to the
 * lesser size; NULL when out of memory, p then unchanged.  Without
 * anonymous mappings and mremap they are zr__huge_alloc's.
 */
enum { ZR__MAP_FROM = ZR__HUGE_FROM };
size_t zr__map_room(size_t size);
void *zr__map_alloc(size_t size);
void *zr__map_grow(void *p, size_t old_size, size_t new_size);
void zr__map_free(void *p, size_t size);
/* zr__map_alloc's block with every byte 0, freed with zr__map_free: a
   fresh mapping is zero as the kernel gives it, so its pages are first
   touched when they are first written (a render's image: by the rows
   as they come, not all at once before the render); below ZR__MAP_FROM
   calloc's, and without mappings zeroed here. */
void *zr__map_zeroed(size_t size);

#endif /* ZR_CORE_ARENA_H */
