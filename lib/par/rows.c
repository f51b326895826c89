/*
 * rows.c - interleaved row sets (the scheme of Tachyon's parallel
 * renderer): rank r renders rows r, r + n, ...  The arithmetic lives here,
 * away from MPI, so a unit test can check it for every small case.
 */
#include "par/rows.h"

#include <string.h>

int zr__rows_count(int height, int rank, int nranks) {
  if (nranks <= 0 || rank < 0 || rank >= height)
    return 0;
  return (height - rank + nranks - 1) / nranks;
}

void zr__rows_uninterleave(const float *rank_major, float *image, int height,
                           int nranks, size_t row_floats) {
  const float *src = rank_major;
  for (int rank = 0; rank < nranks; rank++) {
    int count = zr__rows_count(height, rank, nranks);
    for (int i = 0; i < count; i++) {
      int y = zr__rows_row(i, rank, nranks);
      memcpy(image + (size_t)y * row_floats, src,
             row_floats * sizeof *src);
      src += row_floats;
    }
  }
}

int zr__rows_claim(atomic_int *next, int y0, int y1) {
  int seen = atomic_load(next);
  for (;;) {
    int row = seen < y0 ? y0 : seen;
    if (row >= y1)
      return -1;
    /* On failure seen is reloaded with the counter's current value. */
    if (atomic_compare_exchange_weak(next, &seen, row + 1))
      return row;
  }
}
