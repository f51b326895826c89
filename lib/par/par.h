/*
 * par.h - the MPI world of one zrcube run, and rendering across it.
 *
 * This is the only header through which MPI reaches the program, and it
 * does not include <mpi.h>: callers see ranks and statuses only.  When the
 * program was not started by an MPI launcher it runs as a world of one
 * rank without initialising MPI at all, through the same calls.
 */
#ifndef ZR_PAR_PAR_H
#define ZR_PAR_PAR_H

#include "par/bundle.h"
#include "par/pool.h"
#include "zrcube.h"

typedef struct zr_par zr_par;

/*
 * Joins the MPI world when an MPI launcher (mpirun, srun, mpiexec.hydra)
 * started this process, else makes a world of one.  Errors of MPI calls
 * are returned as ZR_EMPI rather than aborting the job.
 */
zr_status zr__par_init(int *argc, char ***argv, zr_par **out);
/* Leaves MPI (if joined) and frees par; NULL is a no-op. */
void zr__par_finalize(zr_par *par);

int zr__par_rank(const zr_par *par);
int zr__par_size(const zr_par *par);
/* 1 when MPI is in use. */
int zr__par_uses_mpi(const zr_par *par);
/* Ranks of this job on this host. */
int zr__par_local_size(const zr_par *par);
/*
 * Threads a rank should use when the user does not say: the host's
 * processors shared among its ranks, but no more than the processors
 * this process may run on (mpirun binds a rank to one core by default).
 */
int zr__par_default_threads(const zr_par *par);

/* The MPI library's name and version, for --version (callable before
   zr__par_init). */
void zr__par_mpi_version(char *buf, size_t size);

/* The processors this process may run on (its CPU affinity). */
int zr__par_cpus_allowed(void);

/*
 * The threads a rank will use: wanted (or the default when wanted is 0),
 * but 1 when the MPI library does not allow threads beside it.
 */
int zr__par_threads(const zr_par *par, int wanted);

/* Seconds on a monotonic clock. */
double zr__par_now(void);

/*
 * Rank 0 passes the files it parsed and the parse status; every other
 * rank receives them into bundle (which it passed empty) and *root_status.
 */
zr_status zr__par_share_bundle(zr_par *par, zr_bundle *bundle,
                               zr_status *root_status);

/*
 * Rank 0's string (which may be NULL) replaces *text on every other rank
 * (a malloc'ed copy; the old one is freed).  Collective.
 */
zr_status zr__par_share_string(zr_par *par, char **text);

/*
 * Every rank passes its status; every rank gets the same answer: ZR_OK
 * when all succeeded, else the lowest failure code among the ranks, so
 * all ranks take the same branch.
 */
zr_status zr__par_agree(zr_par *par, zr_status local);

typedef struct zr_par_render {
  const zr_scene *scene;
  const zr_render_params *params;
  int threads;
  zr__rows_progress_fn progress; /* may be NULL; give it on rank 0 only */
  void *progress_user;
  zr_image *image;         /* rank 0: receives the picture; others NULL */
  zr_render_stats stats;   /* out: summed over all ranks, on rank 0 */
  double render_seconds;   /* out: the slowest rank's, on rank 0 */
} zr_par_render;

/*
 * Renders the image over all ranks and their threads: pass 1 on the
 * rank's interleaved rows, then (with antialiasing) the complete centre
 * image on every rank and pass 2 on the same rows, then the rows gathered
 * into job->image on rank 0.  Collective: every rank must call it, and
 * every rank gets the same status.
 */
zr_status zr__par_render(zr_par *par, zr_par_render *job);

#endif /* ZR_PAR_PAR_H */
