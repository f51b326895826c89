/*
 * parallel.c - a parallel loop (see parallel.h).
 *
 * Threads are started for each loop and joined at its end: a solve runs
 * a few dozen loops and a render two, each of milliseconds or more, so
 * starting threads costs nothing measurable and no pool has to be kept
 * alive between calls or shut down (a library with a pool of its own
 * would have to say who owns it and when it dies).  Chunks come from
 * one atomic counter (the dynamic schedule of OpenMP), which balances
 * chunks of very different cost: a row through a glass sphere against
 * a row of sky, a link between near curved cells against far planar
 * ones.
 */
#include "core/parallel.h"

#include <pthread.h>

typedef struct loop {
  atomic_size_t next;
  size_t n, grain;
  zr__parallel_fn fn;
  void *user;
  atomic_int *stop;
} loop;

typedef struct worker_arg {
  loop *job;
  int worker;
} worker_arg;

static void run_chunks(loop *job, int worker) {
  for (;;) {
    if (job->stop && atomic_load_explicit(job->stop, memory_order_relaxed))
      return;
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

int zr__parallel_for(int threads, size_t n, size_t grain,
                     zr__parallel_fn fn, void *user, atomic_int *stop) {
  if (n == 0)
    return 1;
  if (grain == 0)
    grain = 1;
  size_t chunks = (n + grain - 1) / grain;
  if (threads > ZR__MAX_THREADS)
    threads = ZR__MAX_THREADS;
  if ((size_t)threads > chunks)
    threads = (int)chunks;
  loop job;
  atomic_init(&job.next, 0);
  job.n = n;
  job.grain = grain;
  job.fn = fn;
  job.user = user;
  job.stop = stop;
  if (threads <= 1 && !stop) {
    fn(user, 0, n, 0); /* one call, as the loop's single-thread form */
    return 1;
  }
  if (threads <= 1) {
    run_chunks(&job, 0);
    return 1;
  }
  pthread_t tid[ZR__MAX_THREADS];
  worker_arg args[ZR__MAX_THREADS];
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
  return started + 1;
}
