/*
 * workers.c - a parallel loop for the radiosity solve (see workers.h):
 * the library's one loop of threads, lib/core/parallel.c, which the
 * render and the irradiance cache's pretrace use too.
 */
#include "radiosity/workers.h"

#include "core/parallel.h"

void zr__rad_parallel(int threads, size_t n, size_t grain,
                      zr__rad_work_fn fn, void *user) {
  if (threads > ZR__RAD_MAX_THREADS)
    threads = ZR__RAD_MAX_THREADS;
  (void)zr__parallel_for(threads, n, grain, fn, user, NULL);
}
