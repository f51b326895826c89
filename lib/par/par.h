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
/*
 * A world of the ranks of a caller's communicator (comm points to an
 * MPI_Comm; this header stays free of <mpi.h>), for a program that runs
 * MPI itself (zrcube_mpi.h): the communicator is duplicated, and
 * zr__par_finalize frees the duplicate but leaves MPI running.
 * Collective over comm.  ZR_EINVAL when MPI is not initialised.
 */
zr_status zr__par_from_comm(void *comm, zr_par **out);
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

/*
 * With ZRCUBE_TIMELINE in the environment, a line "zrcube: timeline:
 * rank R wall W cpu C thread T WHAT" on stderr (W: seconds since the
 * epoch, C and T: CPU seconds of the process and of this thread), for
 * bench/timeline.sh; nothing without it.  Callable before zr__par_init.
 */
void zr__par_mark(const char *what);
/* Seconds on a monotonic clock. */
double zr__par_now(void);
/* CPU seconds of this process, all its threads. */
double zr__par_cpu(void);

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

/*
 * What a render has done so far, band by band, for a state file that
 * lets an interrupted render continue (zrcube +C).  The image's rows are
 * cut in bands of band_rows rows; pass 1 (one ray through each pixel
 * centre) runs over every band, then, with antialiasing, pass 2.
 * done[p][b] is 1 when pass p + 1 of band b is complete: its pixels are
 * in centres (pass 1 with antialiasing, width * height * channels
 * floats) or in image (the final pixels, as many floats).
 */
typedef struct zr_par_progress {
  int channels;   /* floats a pixel: 3, or 4 with alpha (+UA) */
  int passes;     /* 1, or 2 with antialiasing */
  int bands;
  int band_rows;
  unsigned char *done[2]; /* bands flags each */
  float *centres;         /* NULL with one pass */
  float *image;
} zr_par_progress;

/* Rank 0, after each band: the render's state so far. */
typedef void (*zr_par_band_fn)(const zr_par_progress *progress, void *user);

typedef struct zr_par_render {
  const zr_scene *scene;
  const zr_render_params *params;
  int threads;
  zr__rows_progress_fn progress; /* may be NULL; give it on rank 0 only */
  void *progress_user;
  zr_image *image;         /* rank 0: receives the picture; others NULL */
  /* Rank 0: nonzero when image's pixels are all 0 already (a fresh
     zr_image_new: a mapping the kernel gives zeroed), so the render
     need not zero them first; its rows then touch the pages as they
     arrive, during a render the ranks share, instead of rank 0 alone
     before it while the others wait. */
  int image_zero;
  zr_render_stats stats;   /* out: summed over all ranks, on rank 0 */
  double render_seconds;   /* out: the slowest rank's, on rank 0 */
  /* A partial render (+SR +ER +SC +EC): rows row0 .. row1 - 1 and
     columns col0 .. col1 - 1 are rendered, the other pixels are black.
     All 0: the whole image.  With antialiasing, pass 1 also covers a
     margin of one pixel, so the window's pixels are those of a whole
     render. */
  int row0, row1, col0, col1;
  zr_par_band_fn band_done; /* rank 0; may be NULL */
  void *band_user;
  /* Rank 0: the state of an interrupted render to continue from (NULL:
     start afresh), with the same passes, bands and band_rows as this
     render has (zr__par_render_layout). */
  const zr_par_progress *resume;
  /* Rank 0: about how long the runs of bands between two calls of
     band_done should take (0: one band at a time). */
  double band_seconds;
  double gather_seconds;   /* out: this rank's wait in the last gather */
  /* Rank 0 (NULL elsewhere, and without one): the image's write,
     running on its own thread (writer.h), told each time more rows of
     job->image are final; with several ranks, the others then render
     the last bands of the last pass without rank 0, as many as they
     take about as long as the encoder takes for the rows before them,
     at write_row_seconds a row (an estimate: bin/zrcube.c's is
     measured by bench/write_rows.sh), in one chunk; on one host rank 0
     takes rows of it too once the encoder has nothing to do, so an
     estimate too high costs little. */
  struct zr_par_writer *writer;
  double write_row_seconds;
  int tail_bands;          /* out: the bands rendered without rank 0 */
  int tail_root_rows;      /* out: rows of them rank 0 rendered after all,
                              its encoder done (zr__par_render) */
} zr_par_render;

/* The passes, bands and band rows job will use (for a state file). */
void zr__par_render_layout(const zr_par *par, const zr_par_render *job,
                           int *passes, int *bands, int *band_rows);

/*
 * A world of one rank seen from this rank, for work a rank does alone
 * (whole frames of an animation): collectives on it return at once.
 */
zr_status zr__par_solo(const zr_par *par, zr_par **out);

/* What this rank sent, for bench/scale.sh's model: the scene files it
   broadcast (rank 0), the rows of pixels it gathered to rank 0 (and, with
   antialiasing, to every rank), and its parts of the radiosity solution
   or irradiance cache (a team's exchanges, with their wall time). */
typedef struct zr_par_traffic {
  uint64_t bcast_bytes_sent;
  uint64_t pixel_bytes_sent;
  uint64_t team_bytes_sent;
  uint64_t team_calls;
  double team_seconds;
  double team_cpu_seconds; /* the process's CPU time in those exchanges */
} zr_par_traffic;

void zr__par_get_traffic(const zr_par *par, zr_par_traffic *out);

/*
 * A team (zrcube.h) of all the ranks, for the radiosity solve and the
 * irradiance cache: its allgather is MPI_Allgatherv on the private
 * communicator.  Without MPI it is a team of one.  team refers to par,
 * which must outlive it.  Collective; fails (on every rank) only when a
 * rank has no room for its count arrays.
 */
zr_status zr__par_team(zr_par *par, zr_team *team);

/*
 * Renders the image over all ranks and their threads: pass 1 on the
 * rank's interleaved rows, then (with antialiasing) the complete centre
 * image on every rank and pass 2 on the same rows, then the rows gathered
 * into job->image on rank 0.  Collective: every rank must call it, and
 * every rank gets the same status.
 */
zr_status zr__par_render(zr_par *par, zr_par_render *job);

#endif /* ZR_PAR_PAR_H */
