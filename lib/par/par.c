/*
 * par.c - MPI for zrcube: joining the world, sharing the scene files,
 * rendering interleaved rows and gathering the picture.
 *
 * This is the only file of the project that includes <mpi.h>, after
 * Tachyon's parallel.c; the library never sees a communicator.  The
 * design follows ARCHITECTURE.md ("Parallelism"):
 *   - rank 0 reads the scene files, every rank parses the same bytes
 *     (zr__par_share_bundle);
 *   - rank r renders rows r, r + n, ... with a pool of threads (pool.c);
 *   - antialiasing needs each pixel's neighbours, so the centres of pass 1
 *     are assembled on every rank (MPI_Allgatherv) before pass 2;
 *   - rank 0 gathers the rows (MPI_Gatherv) and the statistics.
 * Rows travel as an MPI datatype of one row, so counts stay small
 * integers for any image MPI can hold.  Each collective is preceded by an
 * agreement on the status of the work before it, so a rank that fails
 * (out of memory) makes every rank return that failure instead of leaving
 * the others blocked in a collective.
 *
 * Without an MPI launcher in the environment the world has one rank and
 * MPI is not initialised: a plain `zrcube scene.pov` starts no daemon.
 */
#define _GNU_SOURCE /* sched_getaffinity, CPU_COUNT */
#include "par/par.h"

#include "config.h"
#ifdef ZR_HAVE_MPI
#include <mpi.h>
#else
#include "par/nompi.h" /* configure --without-mpi: one process */
#endif
#include <sched.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "par/rows.h"

struct zr_par {
  int uses_mpi;
  int threads_allowed; /* the MPI library allows threads beside MPI */
  int rank;
  int size;
  int local_size;
  MPI_Comm comm;
};

/* Environment variables that MPI launchers set in the processes they start
   (OpenMPI's mpirun, PMIx, MPICH's hydra and Slurm's PMI). */
static const char *const launcher_vars[] = {
    "OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE",
};

static int launched_by_mpi(void) {
  for (size_t i = 0; i < sizeof launcher_vars / sizeof *launcher_vars; i++)
    if (getenv(launcher_vars[i]))
      return 1;
  return 0;
}

static zr_status mpi_status(int rc) {
  return rc == MPI_SUCCESS ? ZR_OK : ZR_EMPI;
}

zr_status zr__par_init(int *argc, char ***argv, zr_par **out) {
  zr_par *par = calloc(1, sizeof *par);
  if (!par)
    return ZR_ENOMEM;
  par->size = 1;
  par->local_size = 1;
  par->comm = MPI_COMM_NULL;
  par->threads_allowed = 1;
  if (launched_by_mpi()) {
    int provided;
    /* Only the main thread calls MPI; workers only render. */
    if (MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided) !=
        MPI_SUCCESS) {
      free(par);
      return ZR_EMPI;
    }
    par->uses_mpi = 1;
    /* With MPI_THREAD_SINGLE even threads that never call MPI are not
       allowed, so such an MPI gets one thread per rank. */
    par->threads_allowed = provided >= MPI_THREAD_FUNNELED;
    MPI_Comm node = MPI_COMM_NULL;
    /* A private communicator, returning errors instead of aborting. */
    int rc = MPI_Comm_dup(MPI_COMM_WORLD, &par->comm);
    if (rc == MPI_SUCCESS)
      rc = MPI_Comm_set_errhandler(par->comm, MPI_ERRORS_RETURN);
    if (rc == MPI_SUCCESS)
      rc = MPI_Comm_rank(par->comm, &par->rank);
    if (rc == MPI_SUCCESS)
      rc = MPI_Comm_size(par->comm, &par->size);
    if (rc == MPI_SUCCESS)
      rc = MPI_Comm_split_type(par->comm, MPI_COMM_TYPE_SHARED, par->rank,
                               MPI_INFO_NULL, &node);
    if (rc == MPI_SUCCESS)
      rc = MPI_Comm_size(node, &par->local_size);
    if (node != MPI_COMM_NULL)
      MPI_Comm_free(&node);
    if (rc != MPI_SUCCESS) {
      zr__par_finalize(par);
      return ZR_EMPI;
    }
  }
  *out = par;
  return ZR_OK;
}

void zr__par_finalize(zr_par *par) {
  if (!par)
    return;
  if (par->uses_mpi) {
    if (par->comm != MPI_COMM_NULL)
      MPI_Comm_free(&par->comm);
    MPI_Finalize();
  }
  free(par);
}

int zr__par_rank(const zr_par *par) { return par->rank; }
int zr__par_size(const zr_par *par) { return par->size; }
int zr__par_uses_mpi(const zr_par *par) { return par->uses_mpi; }
int zr__par_local_size(const zr_par *par) { return par->local_size; }

int zr__par_threads(const zr_par *par, int wanted) {
  if (!par->threads_allowed)
    return 1;
  return wanted > 0 ? wanted : zr__par_default_threads(par);
}

int zr__par_cpus_allowed(void) {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) >= 1)
    return CPU_COUNT(&set);
  long online = sysconf(_SC_NPROCESSORS_ONLN);
  return online < 1 ? 1 : (int)online;
}

int zr__par_default_threads(const zr_par *par) {
  long online = sysconf(_SC_NPROCESSORS_ONLN);
  if (online < 1)
    online = 1;
  long share = online / (par->local_size > 0 ? par->local_size : 1);
  int allowed = zr__par_cpus_allowed();
  if (allowed < share)
    share = allowed;
  return share < 1 ? 1 : (int)share;
}

void zr__par_mpi_version(char *buf, size_t size) {
  char version[MPI_MAX_LIBRARY_VERSION_STRING];
  int len = 0;
  if (size == 0)
    return;
  if (MPI_Get_library_version(version, &len) != MPI_SUCCESS)
    len = 0;
  /* Open MPI's text runs on with build details after its first line. */
  int first_line = 0;
  while (first_line < len && version[first_line] != '\n' &&
         version[first_line] != ',')
    first_line++;
  snprintf(buf, size, "%.*s", first_line, version);
}

double zr__par_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* MPI counts are ints: large blobs go in pieces of at most 1 GiB. */
#define BCAST_CHUNK ((size_t)1 << 30)

static zr_status bcast_bytes(zr_par *par, char *bytes, size_t size) {
  for (size_t off = 0; off < size; off += BCAST_CHUNK) {
    size_t n = size - off < BCAST_CHUNK ? size - off : BCAST_CHUNK;
    int rc = MPI_Bcast(bytes + off, (int)n, MPI_BYTE, 0, par->comm);
    if (rc != MPI_SUCCESS)
      return ZR_EMPI;
  }
  return ZR_OK;
}

zr_status zr__par_share_bundle(zr_par *par, zr_bundle *bundle,
                               zr_status *root_status) {
  if (!par->uses_mpi || par->size == 1)
    return ZR_OK;
  char *blob = NULL;
  size_t blob_size = 0;
  int64_t header[2] = {0, 0}; /* rank 0's parse status, blob size */
  if (par->rank == 0) {
    zr_status s = *root_status;
    if (s == ZR_OK)
      s = zr__bundle_serialise(bundle, &blob, &blob_size);
    header[0] = s;
    header[1] = s == ZR_OK ? (int64_t)blob_size : 0;
  }
  zr_status s = mpi_status(MPI_Bcast(header, 2, MPI_INT64_T, 0, par->comm));
  if (s != ZR_OK) {
    free(blob);
    return s;
  }
  if (par->rank != 0) {
    blob_size = (size_t)header[1];
    blob = malloc(blob_size ? blob_size : 1);
  }
  /* All ranks agree that the blob fits before it is sent, so none is
     left waiting in a broadcast that another rank has given up on. */
  s = zr__par_agree(par, par->rank == 0 || blob ? ZR_OK : ZR_ENOMEM);
  if (s == ZR_OK && blob_size > 0)
    s = bcast_bytes(par, blob, blob_size);
  /* Rank 0 learns it too: its parse may have worked and the bundle not. */
  *root_status = (zr_status)header[0];
  if (s == ZR_OK && par->rank != 0) {
    if (header[0] == ZR_OK)
      s = zr__bundle_deserialise(bundle, blob, blob_size);
  }
  free(blob);
  return s;
}

zr_status zr__par_share_string(zr_par *par, char **text) {
  if (!par->uses_mpi || par->size == 1)
    return ZR_OK;
  /* The length, or -1 for NULL, then the bytes with their NUL. */
  int64_t length = par->rank == 0 && *text ? (int64_t)strlen(*text) : -1;
  if (MPI_Bcast(&length, 1, MPI_INT64_T, 0, par->comm) != MPI_SUCCESS)
    return ZR_EMPI;
  char *copy = NULL;
  if (par->rank != 0 && length >= 0)
    copy = malloc((size_t)length + 1);
  zr_status s = zr__par_agree(
      par, par->rank == 0 || length < 0 || copy ? ZR_OK : ZR_ENOMEM);
  if (s == ZR_OK && length >= 0)
    s = bcast_bytes(par, par->rank == 0 ? *text : copy, (size_t)length + 1);
  if (s != ZR_OK || par->rank == 0) {
    free(copy);
    return s;
  }
  free(*text);
  *text = copy;
  return ZR_OK;
}

zr_status zr__par_agree(zr_par *par, zr_status local) {
  if (!par->uses_mpi || par->size == 1)
    return local;
  /* Failures are negative: the minimum is a failure if any rank failed. */
  int mine = (int)local, worst;
  if (MPI_Allreduce(&mine, &worst, 1, MPI_INT, MPI_MIN, par->comm) !=
      MPI_SUCCESS)
    return ZR_EMPI;
  return (zr_status)worst;
}

/* The layout of an MPI_Gatherv of every rank's rows, rank after rank. */
typedef struct row_layout {
  int *counts; /* rows of each rank */
  int *displs; /* first row of each rank in the rank-major buffer */
} row_layout;

static zr_status layout_new(const zr_par *par, int height, row_layout *l) {
  l->counts = malloc((size_t)par->size * sizeof *l->counts);
  l->displs = malloc((size_t)par->size * sizeof *l->displs);
  if (!l->counts || !l->displs)
    return ZR_ENOMEM;
  int first = 0;
  for (int r = 0; r < par->size; r++) {
    l->counts[r] = zr__rows_count(height, r, par->size);
    l->displs[r] = first;
    first += l->counts[r];
  }
  return ZR_OK;
}

static void layout_free(row_layout *l) {
  free(l->counts);
  free(l->displs);
}

/*
 * Collects every rank's rows (mine, in order) into image, top to bottom:
 * on every rank (everyone) or on rank 0 only.  rank_major is scratch room
 * for height rows, used where the MPI call lands rows rank after rank.
 */
static zr_status collect_rows(zr_par *par, const float *mine, float *image,
                              float *rank_major, int width, int height,
                              int everyone) {
  size_t row_floats = (size_t)width * 3;
  if (!par->uses_mpi || par->size == 1) {
    zr__rows_uninterleave(mine, image, height, 1, row_floats);
    return ZR_OK;
  }
  row_layout layout = {NULL, NULL};
  MPI_Datatype row = MPI_DATATYPE_NULL;
  zr_status s = layout_new(par, height, &layout);
  s = zr__par_agree(par, s);
  if (s == ZR_OK)
    s = mpi_status(MPI_Type_contiguous((int)row_floats, MPI_FLOAT, &row));
  if (s == ZR_OK)
    s = mpi_status(MPI_Type_commit(&row));
  if (s == ZR_OK) {
    /* MPI's send buffers are const only from MPI 3 on. */
    float *send = (float *)mine;
    int count = layout.counts[par->rank];
    s = mpi_status(everyone ? MPI_Allgatherv(send, count, row, rank_major,
                                             layout.counts, layout.displs,
                                             row, par->comm)
                            : MPI_Gatherv(send, count, row, rank_major,
                                          layout.counts, layout.displs, row,
                                          0, par->comm));
  }
  if (s == ZR_OK && (everyone || par->rank == 0))
    zr__rows_uninterleave(rank_major, image, height, par->size, row_floats);
  if (row != MPI_DATATYPE_NULL)
    MPI_Type_free(&row);
  layout_free(&layout);
  return s;
}

/* Sums the statistics of all ranks into *stats on rank 0. */
static zr_status reduce_stats(zr_par *par, zr_render_stats *stats,
                              double *seconds) {
  if (!par->uses_mpi || par->size == 1)
    return ZR_OK;
  uint64_t mine[6] = {stats->camera_rays,    stats->supersample_rays,
                      stats->reflected_rays, stats->refracted_rays,
                      stats->shadow_rays,    stats->supersampled_pixels};
  uint64_t sum[6] = {0};
  double slowest = 0;
  int rc = MPI_Reduce(mine, sum, 6, MPI_UINT64_T, MPI_SUM, 0, par->comm);
  if (rc == MPI_SUCCESS)
    rc = MPI_Reduce(seconds, &slowest, 1, MPI_DOUBLE, MPI_MAX, 0, par->comm);
  if (rc != MPI_SUCCESS)
    return ZR_EMPI;
  if (par->rank == 0) {
    stats->camera_rays = sum[0];
    stats->supersample_rays = sum[1];
    stats->reflected_rays = sum[2];
    stats->refracted_rays = sum[3];
    stats->shadow_rays = sum[4];
    stats->supersampled_pixels = sum[5];
    *seconds = slowest;
  }
  return ZR_OK;
}

/* A malloc of n floats that also succeeds (one float) for n == 0. */
static float *float_alloc(size_t n) {
  if (n > SIZE_MAX / sizeof(float))
    return NULL;
  return malloc((n ? n : 1) * sizeof(float));
}

static zr_status render_pass(zr_par *par, zr_par_render *job,
                             const float *centres, float *rows_rgb,
                             size_t progress_base, size_t progress_total) {
  zr_pool_job pool = {
      .scene = job->scene,
      .params = job->params,
      .rank = par->rank,
      .nranks = par->size,
      .centres = centres,
      .rows_rgb = rows_rgb,
      .threads = job->threads,
      .stats = &job->stats,
      .progress = job->progress,
      .progress_user = job->progress_user,
      .progress_base = progress_base,
      .progress_total = progress_total,
  };
  return zr__par_agree(par, zr__pool_render(&pool));
}

zr_status zr__par_render(zr_par *par, zr_par_render *job) {
  double start = zr__par_now();
  memset(&job->stats, 0, sizeof job->stats);
  job->render_seconds = 0;
  int width = job->params->width, height = job->params->height;
  zr_status s = ZR_OK;
  if (width < 1 || height < 1)
    s = ZR_EINVAL;
  /* Pixels are named y * width + x in 32 bits by zr_render_pixels. */
  else if ((uint64_t)width * (uint64_t)height > UINT32_MAX)
    s = ZR_ELIMIT;
  else if (par->rank == 0 &&
           (!job->image || zr_image_width(job->image) != width ||
            zr_image_height(job->image) != height))
    s = ZR_EINVAL;
  size_t row_floats = (size_t)(width > 0 ? width : 0) * 3;
  int mine = s == ZR_OK ? zr__rows_count(height, par->rank, par->size) : 0;
  int passes = job->params->antialias ? 2 : 1;
  size_t total = (size_t)mine * (size_t)passes;
  float *centre_rows = NULL, *final_rows = NULL, *centres = NULL;
  float *rank_major = NULL;
  int gather_here = par->rank == 0 || passes == 2;
  int mpi_scratch = par->uses_mpi && par->size > 1 && gather_here;
  if (s == ZR_OK) {
    centre_rows = float_alloc((size_t)mine * row_floats);
    final_rows = passes == 2 ? float_alloc((size_t)mine * row_floats)
                             : centre_rows;
    if (passes == 2)
      centres = float_alloc((size_t)height * row_floats);
    if (mpi_scratch)
      rank_major = float_alloc((size_t)height * row_floats);
    if (!centre_rows || !final_rows || (passes == 2 && !centres) ||
        (mpi_scratch && !rank_major))
      s = ZR_ENOMEM;
  }
  s = zr__par_agree(par, s);
  if (s == ZR_OK)
    s = render_pass(par, job, NULL, centre_rows, 0, total);
  if (s == ZR_OK && passes == 2) {
    s = collect_rows(par, centre_rows, centres, rank_major, width, height, 1);
    s = zr__par_agree(par, s);
    if (s == ZR_OK)
      s = render_pass(par, job, centres, final_rows, (size_t)mine, total);
  }
  if (s == ZR_OK) {
    float *image = par->rank == 0 ? zr_image_pixels(job->image) : NULL;
    s = zr__par_agree(par, collect_rows(par, final_rows, image, rank_major,
                                        width, height, 0));
  }
  job->render_seconds = zr__par_now() - start;
  if (s == ZR_OK)
    s = zr__par_agree(par, reduce_stats(par, &job->stats,
                                        &job->render_seconds));
  if (final_rows != centre_rows)
    free(final_rows);
  free(centre_rows);
  free(centres);
  free(rank_major);
  return s;
}
