/*
 * hugepage.h - asking the kernel for 2 MiB pages, as one static inline.
 *
 * On this project's virtual machine first touching a 4 KiB page costs
 * about 14 us, so big buffers filled once (a scene file's bytes, its
 * tokens, a mesh's arrays, a render's image-sized buffers) are advised
 * to Linux's transparent huge pages (madvise MADV_HUGEPAGE) before they
 * are first touched; where transparent huge pages are in "madvise" mode
 * (a common default) only memory marked this way gets them.  The advice
 * is never required: where it is unknown or refused the memory stays
 * ordinary.
 *
 * Inline, in a header, because two libraries use it: libzrcube
 * (lib/core's zr__mem_huge_pages, arena.h) and lib/par's libzrpar,
 * which is linked beside libzrcube and cannot reach its hidden
 * symbols.
 */
#ifndef ZR_CORE_HUGEPAGE_H
#define ZR_CORE_HUGEPAGE_H

#include <stddef.h>
#include <stdint.h>
#include <sys/mman.h>

/* A transparent huge page of x86-64 and arm64 Linux (4 KiB base). */
#define ZR__HUGE_PAGE ((size_t)2 << 20)

/*
 * Advises the whole huge pages inside [p, p + size) (those that start
 * and end in it: nothing when it holds none).  A buffer aligned on
 * ZR__HUGE_PAGE with a size rounded up to it is advised whole.
 */
static inline void zr__mem_advise_huge(void *p, size_t size) {
#ifdef MADV_HUGEPAGE
  const uintptr_t mask = (uintptr_t)(ZR__HUGE_PAGE - 1);
  uintptr_t lo = ((uintptr_t)p + mask) & ~mask;
  uintptr_t hi = ((uintptr_t)p + size) & ~mask;
  if (p && hi > lo)
    (void)madvise((void *)lo, hi - lo, MADV_HUGEPAGE); /* advice only */
#else
  (void)p;
  (void)size;
#endif
}

#endif /* ZR_CORE_HUGEPAGE_H */
