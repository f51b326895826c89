/*
 * workers.c - a parallel loop for the radiosity solve (see workers.h).
 *
 * Threads are started for each loop and joined at its end: a solve
 * runs a few dozen loops, each of milliseconds or more, so starting
 * threads costs nothing measurable and no pool has to be kept alive
 * between calls or shut down.  Chunks come from one atomic counter
 * (the dynamic schedule of OpenMP), which balances cells of very
 * different cost: a link between two near curved cells costs a
 * hundred times one between far planar ones.
 */
#include "radiosity/workers.h"

#include <pthread.h>
#include <stdatomic.h>

typedef struct loop {
  atomic_size_t next;
  size_t n, grain;
  zr__rad_work_fn fn;
  void *user;
} loop;

typedef struct worker_arg {
  loop *job;
  int worker;
} worker_arg;

static void run_chunks(loop *job, int worker) {
  for (;;) {
    size_t begin = atomic_fetch_add(&job->next, job->grain);
    if (begin >= job->n)
      return;
    size_t end = job->n - begin < job->grain ? job->n : begin + job->grain;
    job->fn(job->user, begin, end, worker);
  }
}

static void *worker_main(void *p) {
  worker_arg *a = p;
  run_chunks(a->job, a->worker);
  return NULL;
}

void zr__rad_parallel(int threads, size_t n, size_t grain,
                      zr__rad_work_fn fn, void *user) {
  if (n == 0)
    return;
  if (grain == 0)
    grain = 1;
  size_t chunks = (n + grain - 1) / grain;
  if (threads > ZR__RAD_MAX_THREADS)
    threads = ZR__RAD_MAX_THREADS;
  if ((size_t)threads > chunks)
    threads = (int)chunks;
  if (threads <= 1) {
    fn(user, 0, n, 0);
    return;
  }
  loop job;
  atomic_init(&job.next, 0);
  job.n = n;
  job.grain = grain;
  job.fn = fn;
  job.user = user;
  pthread_t tid[ZR__RAD_MAX_THREADS];
  worker_arg args[ZR__RAD_MAX_THREADS];
  int started = 0;
  for (int w = 1; w < threads; w++) {
    args[started].job = &job;
    args[started].worker = started + 1;
    if (pthread_create(&tid[started], NULL, worker_main, &args[started]) !=
        0)
      break;
    started++;
  }
  run_chunks(&job, 0);
  for (int w = 0; w < started; w++)
    pthread_join(tid[w], NULL);
}
