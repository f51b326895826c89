/*
 * mpi_api.c - zrcube_mpi.h: the MPI driver of lib/par (par.c, pool.c,
 * rows.c) on a caller's communicator, as the public libzrcube_mpi.
 * zrcube(1) drives the same code on MPI_COMM_WORLD.
 */
#include "zrcube_mpi.h"

#include <stdlib.h>

#include "par/par.h"

struct zr_mpi {
  zr_par *par;
  zr_team team;
};

ZR_MPI_API zr_status zr_mpi_new(MPI_Comm comm, zr_mpi **out) {
  if (out == NULL)
    return ZR_EINVAL;
  *out = NULL;
  zr_mpi *m = calloc(1, sizeof *m);
  zr_par *par = NULL;
  /* Collective: every rank calls zr__par_from_comm, even one whose
     calloc failed, and the ranks then agree. */
  zr_status s = zr__par_from_comm(&comm, &par);
  if (s != ZR_OK) {
    free(m);
    return s;
  }
  s = zr__par_agree(par, m ? ZR_OK : ZR_ENOMEM);
  if (s == ZR_OK) {
    m->par = par;
    s = zr__par_team(par, &m->team);
  }
  if (s != ZR_OK) {
    zr__par_finalize(par);
    free(m);
    return s;
  }
  *out = m;
  return ZR_OK;
}

ZR_MPI_API void zr_mpi_free(zr_mpi *mpi) {
  if (mpi == NULL)
    return;
  zr__par_finalize(mpi->par);
  free(mpi);
}

ZR_MPI_API int zr_mpi_rank(const zr_mpi *mpi) {
  return zr__par_rank(mpi->par);
}

ZR_MPI_API int zr_mpi_size(const zr_mpi *mpi) {
  return zr__par_size(mpi->par);
}

ZR_MPI_API const zr_team *zr_mpi_team(const zr_mpi *mpi) {
  return &mpi->team;
}

ZR_MPI_API zr_status zr_mpi_render_image(zr_mpi *mpi, const zr_scene *scene,
                                         const zr_render_params *params,
                                         int threads, zr_image *image) {
  if (mpi == NULL)
    return ZR_EINVAL;
  zr_par_render job = {0};
  job.scene = scene;
  job.params = params;
  job.threads = zr__par_threads(mpi->par, threads);
  job.image = zr__par_rank(mpi->par) == 0 ? image : NULL;
  /* Every rank checks the arguments it can see and the ranks agree,
     before any collective of the render. */
  zr_status s = scene && params ? ZR_OK : ZR_EINVAL;
  s = zr__par_agree(mpi->par, s);
  if (s != ZR_OK)
    return s;
  return zr__par_render(mpi->par, &job);
}
