/*
 * page_touch.c - what a first touch of fresh memory costs here, the
 * figure behind core/arena.h's zr__mem_populate and huge-page advice.
 *
 *   cc -O2 -o page_touch bench/page_touch.c && ./page_touch [PAGES]
 *
 * Maps PAGES (default 128) fresh 4 KiB pages 50 times and writes a byte
 * to each, three ways: touched one by one (a page fault each), filled
 * in first by madvise(MADV_POPULATE_WRITE) (one call), and as advised
 * transparent huge pages (MADV_HUGEPAGE on 2 MiB-aligned memory).
 * Prints CPU microseconds (user + system) per 4 KiB page for each.
 * Figures are printed, never asserted.
 */
#define _GNU_SOURCE
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <sys/resource.h>

static double cpu_seconds(void) {
  struct rusage u;
  getrusage(RUSAGE_SELF, &u);
  return (double)(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * (double)(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

int main(int argc, char **argv) {
  size_t pages = argc > 1 ? strtoul(argv[1], NULL, 10) : 128;
  const size_t huge = (size_t)2 << 20;
  size_t size = pages * 4096;
  static const char *const names[3] = {"touched", "populated", "huge"};
  for (int mode = 0; mode < 3; mode++) {
    enum { ROUNDS = 50 };
    double start = cpu_seconds();
    for (int r = 0; r < ROUNDS; r++) {
      size_t room = mode == 2 ? size + huge : size;
      char *m = mmap(NULL, room, PROT_READ | PROT_WRITE,
                     MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if (m == MAP_FAILED)
        return 1;
      char *p = m;
      if (mode == 1) {
#ifdef MADV_POPULATE_WRITE
        madvise(p, size, MADV_POPULATE_WRITE);
#endif
      } else if (mode == 2) {
        p = (char *)(((uintptr_t)m + huge - 1) & ~(uintptr_t)(huge - 1));
        madvise(p, size, MADV_HUGEPAGE);
      }
      for (size_t i = 0; i < size; i += 4096)
        p[i] = 1;
      munmap(m, room);
    }
    printf("%-9s %6.2f us a 4 KiB page (%zu pages, %d rounds)\n",
           names[mode], (cpu_seconds() - start) / ROUNDS / (double)pages * 1e6,
           pages, ROUNDS);
  }
  return 0;
}
