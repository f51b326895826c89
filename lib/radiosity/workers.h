/*
 * workers.h - the threads of one rank for the radiosity solve: a
 * parallel loop over an index range.
 *
 * The threads are the library's own loop (lib/core/parallel.c, shared
 * with the render and the pretrace; lib/par's pool belongs to the
 * command line, not to libzrcube).  Workers take chunks of
 * the range from a shared counter, so which thread does which index
 * varies from run to run; callers keep the results identical anyway by
 * writing each index's result into a slot of its own and combining the
 * slots afterwards in index order (or by summing integers, whose sum
 * has no order).  No state outlives a call.
 */
#ifndef ZR_RADIOSITY_WORKERS_H
#define ZR_RADIOSITY_WORKERS_H

#include <stddef.h>

/* The most threads a solve uses, whatever it is asked. */
#define ZR__RAD_MAX_THREADS 256

/* Handles indices [begin, end); worker is 0 .. threads - 1. */
typedef void (*zr__rad_work_fn)(void *user, size_t begin, size_t end,
                                int worker);

/*
 * Calls fn over [0, n) in chunks of grain indices on up to threads
 * threads, the caller's among them, and returns when all are done.  A
 * thread that cannot be started leaves its share to the others, so the
 * call never fails; threads <= 1 runs everything on the caller.
 */
void zr__rad_parallel(int threads, size_t n, size_t grain,
                      zr__rad_work_fn fn, void *user);

#endif /* ZR_RADIOSITY_WORKERS_H */
