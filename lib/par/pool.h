/*
 * pool.h - POSIX threads rendering one rank's rows.
 *
 * Threads pull rows from a shared counter, so a slow row (a glass sphere)
 * does not hold up a thread while another idles; each row is rendered by
 * one zr_render_pixels() call, whose result depends only on the pixel, so
 * the image does not depend on which thread took which row.
 */
#ifndef ZR_PAR_POOL_H
#define ZR_PAR_POOL_H

#include <stdatomic.h>
#include <stddef.h>

#include "zrcube.h"

/*
 * Called after each finished row with the rows done so far (offset by
 * progress_base) out of progress_total.  Calls are serialised by the pool
 * and come from worker threads.
 */
typedef void (*zr__rows_progress_fn)(size_t done, size_t total, void *user);

/*
 * Called, serialised like the progress, when the job's rows 0 .. rows - 1
 * (in the rank's order) are all finished and rows has grown: rows may
 * end in any order among threads, so this is the finished prefix.
 */
typedef void (*zr__rows_final_fn)(int rows, void *user);

typedef struct zr_pool_job {
  const zr_scene *scene;
  const zr_render_params *params;
  int rank;              /* this rank takes rows rank, rank + nranks, ... */
  int nranks;
  const float *centres;  /* NULL for pass 1, else the whole centre image */
  float *rows_rgb;       /* out: the rank's rows, in order, width * 3 each
                            (4 with params->alpha) */
  size_t row_stride;     /* floats from one of them to the next (0: one
                            row's floats, packed); the image's rows
                            times nranks renders into the image itself */
  int threads;           /* at least 1 */
  zr_render_stats *stats; /* added to; may be NULL */
  zr__rows_progress_fn progress; /* may be NULL */
  void *progress_user;
  size_t progress_base;
  size_t progress_total;
  /* A band of the image: rows first_row .. end_row - 1 (the rank takes
     first_row + rank, + nranks, ...) and columns first_col .. end_col -
     1; rows_rgb then holds (end_col - first_col) * 3 floats a row.
     end_row == 0: every row and column. */
  int first_row, end_row;
  int first_col, end_col;
  zr__rows_final_fn rows_final; /* may be NULL; NULL with claim */
  void *rows_final_user;
  /* Rows shared with other ranks (zr__rows_claim): when claim is given
     the threads take the band's rows first_row .. end_row - 1 (end_row
     must be given) from it instead of the rank's interleaved set (rank
     and nranks are then unused), row y goes to rows_rgb + (y -
     first_row) * row_stride, and owner[y] is set to owner_rank. */
  atomic_int *claim;
  int *owner;
  int owner_rank;
} zr_pool_job;

/*
 * Renders the job's rows with job->threads threads, the calling one
 * included.  Returns the first failure of any row (the other threads stop
 * at their next row).  When the system refuses to start a thread, the
 * threads already running take its rows: fewer threads, same image.
 */
zr_status zr__pool_render(const zr_pool_job *job);

#endif /* ZR_PAR_POOL_H */
