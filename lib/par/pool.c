/*
 * pool.c - a pool of POSIX threads pulling rows from an atomic counter.
 *
 * This is the inner level of the two-level scheme of Tachyon (John Stone's
 * parallel ray tracer): MPI ranks take interleaved rows, the threads of a
 * rank share those rows dynamically.  The counter, the finished-row count
 * and each worker's statistics sit on separate cache lines, because
 * threads writing neighbouring words of one line make the line bounce
 * between cores (false sharing) even though no datum is shared.
 *
 * The calling thread is a worker too, so a pool of one thread starts no
 * thread at all and a serial run is the same code path.
 */
#include "par/pool.h"

#include <pthread.h>
#include <stdalign.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "par/rows.h"

#define CACHE_LINE 64

typedef struct shared_state {
  alignas(CACHE_LINE) atomic_int next_row; /* index into the rank's rows */
  alignas(CACHE_LINE) atomic_int failure;  /* first zr_status != ZR_OK */
  alignas(CACHE_LINE) pthread_mutex_t progress_lock;
  size_t rows_done; /* guarded by progress_lock */
  unsigned char *finished; /* rows_final: a flag a row, under the lock */
  int prefix;              /* rows 0 .. prefix - 1 finished, the same */
  const zr_pool_job *job;
  int row_count;
} shared_state;

typedef struct worker {
  alignas(CACHE_LINE) zr_render_stats stats;
  shared_state *shared;
  pthread_t thread;
  int started;
} worker;

static void report_row(shared_state *sh, int index) {
  const zr_pool_job *job = sh->job;
  if (!job->progress && !sh->finished)
    return;
  pthread_mutex_lock(&sh->progress_lock);
  sh->rows_done++;
  if (job->progress)
    job->progress(job->progress_base + sh->rows_done, job->progress_total,
                  job->progress_user);
  if (sh->finished) {
    int before = sh->prefix;
    sh->finished[index] = 1;
    while (sh->prefix < sh->row_count && sh->finished[sh->prefix])
      sh->prefix++;
    if (sh->prefix > before)
      job->rows_final(sh->prefix, job->rows_final_user);
  }
  pthread_mutex_unlock(&sh->progress_lock);
}

static void work(worker *w) {
  shared_state *sh = w->shared;
  const zr_pool_job *job = sh->job;
  int width = job->params->width;
  int first_row = job->end_row ? job->first_row : 0;
  int first_col = job->end_row ? job->first_col : 0;
  int cols = job->end_row ? job->end_col - first_col : width;
  size_t row_floats = (size_t)cols * (job->params->alpha ? 4 : 3);
  size_t stride = job->row_stride ? job->row_stride : row_floats;
  uint32_t *pixels = malloc((size_t)(cols > 0 ? cols : 1) * sizeof *pixels);
  if (!pixels) {
    int ok = ZR_OK;
    atomic_compare_exchange_strong(&sh->failure, &ok, ZR_ENOMEM);
    return;
  }
  for (;;) {
    if (atomic_load(&sh->failure) != ZR_OK)
      break;
    int index;
    uint32_t y;
    if (job->claim) {
      int row = zr__rows_claim(job->claim, first_row, job->end_row);
      if (row < 0)
        break;
      job->owner[row] = job->owner_rank;
      index = row - first_row;
      y = (uint32_t)row;
    } else {
      index = atomic_fetch_add(&sh->next_row, 1);
      if (index >= sh->row_count)
        break;
      y = (uint32_t)(first_row + zr__rows_row(index, job->rank, job->nranks));
    }
    for (int x = 0; x < cols; x++)
      pixels[x] = y * (uint32_t)width + (uint32_t)(first_col + x);
    zr_status s = zr_render_pixels(job->scene, job->params, pixels,
                                   (size_t)cols, job->centres,
                                   job->rows_rgb + (size_t)index * stride,
                                   &w->stats);
    if (s != ZR_OK) {
      int ok = ZR_OK;
      atomic_compare_exchange_strong(&sh->failure, &ok, (int)s);
      break;
    }
    report_row(sh, index);
  }
  free(pixels);
}

static void *thread_main(void *arg) {
  work(arg);
  return NULL;
}

zr_status zr__pool_render(const zr_pool_job *job) {
  int threads = job->threads < 1 ? 1 : job->threads;
  shared_state sh;
  memset(&sh, 0, sizeof sh);
  atomic_init(&sh.next_row, 0);
  atomic_init(&sh.failure, ZR_OK);
  if (pthread_mutex_init(&sh.progress_lock, NULL) != 0)
    return ZR_ETHREAD;
  sh.job = job;
  if (job->claim && (!job->end_row || !job->owner || job->rows_final))
    return ZR_EINVAL;
  /* With claims, the band's rows are an upper bound of the rank's. */
  sh.row_count = job->claim ? job->end_row - job->first_row
                            : zr__rows_count(job->end_row
                                                 ? job->end_row -
                                                       job->first_row
                                                 : job->params->height,
                                             job->rank, job->nranks);
  /* No more threads than rows: an idle thread only costs its start-up. */
  if (threads > sh.row_count)
    threads = sh.row_count > 0 ? sh.row_count : 1;
  /* Rows end out of order among threads; the flags find the prefix. */
  if (job->rows_final && sh.row_count > 0)
    sh.finished = calloc((size_t)sh.row_count, 1);
  worker *workers =
      aligned_alloc(CACHE_LINE, (size_t)threads * sizeof *workers);
  if (!workers || (job->rows_final && sh.row_count > 0 && !sh.finished)) {
    free(workers);
    free(sh.finished);
    pthread_mutex_destroy(&sh.progress_lock);
    return ZR_ENOMEM;
  }
  memset(workers, 0, (size_t)threads * sizeof *workers);
  for (int i = 0; i < threads; i++)
    workers[i].shared = &sh;
  for (int i = 1; i < threads; i++)
    workers[i].started =
        pthread_create(&workers[i].thread, NULL, thread_main, &workers[i]) ==
        0;
  work(&workers[0]);
  for (int i = 1; i < threads; i++)
    if (workers[i].started)
      pthread_join(workers[i].thread, NULL);
  if (job->stats)
    for (int i = 0; i < threads; i++)
      zr_render_stats_add(job->stats, &workers[i].stats);
  zr_status status = (zr_status)atomic_load(&sh.failure);
  free(workers);
  free(sh.finished);
  pthread_mutex_destroy(&sh.progress_lock);
  return status;
}
