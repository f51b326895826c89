/*
 * parallel.h - the library's own threads: a parallel loop over an index
 * range, used by the render (zr_render_image), the radiosity solve and
 * the irradiance cache's pretrace.
 *
 * lib/par's pool belongs to the command line (it may speak MPI), not to
 * libzrcube, so the library runs its own few POSIX threads here.
 * Workers take chunks of the range from a shared counter, so which
 * thread does which index varies from run to run; callers keep results
 * identical anyway by writing each index's result into a slot of its
 * own and combining the slots afterwards in index order.  No state
 * outlives a call.
 */
#ifndef ZR_CORE_PARALLEL_H
#define ZR_CORE_PARALLEL_H

#include <stdatomic.h>
#include <stddef.h>

/* The most threads a loop uses, whatever it is asked. */
#define ZR__MAX_THREADS 256

/* Handles indices [begin, end); worker is 0 .. threads - 1. */
typedef void (*zr__parallel_fn)(void *user, size_t begin, size_t end,
                                int worker);

/*
 * Calls fn over [0, n) in chunks of grain indices on up to threads
 * threads, the caller's among them (worker 0), and returns when all are
 * done.  When stop is not NULL and becomes non-zero, no thread starts
 * another chunk (fn may set it to stop the loop).  A thread that cannot
 * be started leaves its share to the others, so the call never fails;
 * threads <= 1 runs everything on the caller.  Returns the number of
 * threads that ran (1 .. threads).
 */
int zr__parallel_for(int threads, size_t n, size_t grain,
                     zr__parallel_fn fn, void *user, atomic_int *stop);

#endif /* ZR_CORE_PARALLEL_H */
