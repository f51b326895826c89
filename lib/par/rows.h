/*
 * rows.h - which image rows a rank renders, and putting them back in order.
 *
 * Rows are dealt out like cards: rank r of n takes rows r, r + n, r + 2n,
 * ...  Neighbouring rows cost about the same to trace, so the ranks get
 * nearly equal work without any communication while rendering.
 */
#ifndef ZR_PAR_ROWS_H
#define ZR_PAR_ROWS_H

#include <stdatomic.h>
#include <stddef.h>

/* How many of height rows rank takes out of nranks. */
int zr__rows_count(int height, int rank, int nranks);

/* The image row of the rank's index-th row. */
static inline int zr__rows_row(int index, int rank, int nranks) {
  return rank + index * nranks;
}

/*
 * rank_major holds every rank's rows one rank after the other (rank 0's
 * rows in order, then rank 1's, ...), as MPI_Gatherv lays them out;
 * writes them to image in top-to-bottom order.  row_floats is the length
 * of a row (width * 3).
 */
void zr__rows_uninterleave(const float *rank_major, float *image, int height,
                           int nranks, size_t row_floats);

/*
 * Rows handed out as they are asked for, for ranks that share memory
 * (one host): next holds the next row of the pass not yet taken, and
 * every rank's threads take rows of the band y0 .. y1 - 1 from it, so a
 * rank that runs slower for a while simply takes fewer.  The bands of
 * a pass come in increasing order, so the counter only grows: a band
 * starting past it moves it up to its first row.  Returns the row
 * taken, or -1 when the band has none left.  next may be shared
 * between processes (lock-free atomics work on shared memory).
 */
int zr__rows_claim(atomic_int *next, int y0, int y1);

#endif /* ZR_PAR_ROWS_H */
