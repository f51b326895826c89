/*
 * zrcube_mpi.h - libzrcube for a program that already uses MPI.
 *
 * zrcube.h knows nothing of MPI; this header (and libzrcube_mpi, which
 * links MPI) hands the library a communicator of the caller's, as
 * Tachyon's rt_set_mpi_comm does: the ranks of that communicator then
 * solve one radiosity solution or irradiance cache together (each its
 * share, exchanged) and render one image together (interleaved rows,
 * gathered on rank 0), with the same bytes as one process alone.  The
 * communicator is duplicated, so the library's messages never meet the
 * caller's; MPI must be initialised before zr_mpi_new and finalised by
 * the caller after zr_mpi_free.  Every call is collective: every rank of
 * the communicator makes it, with the same arguments (the scene parsed
 * from the same files on each rank).  See zrcube_mpi(3) and
 * examples/mpi_render.c.
 */
#ifndef ZRCUBE_MPI_H
#define ZRCUBE_MPI_H

#include <mpi.h>

#include "zrcube.h"

#ifdef __cplusplus
extern "C" {
#endif

#if defined(ZR_BUILDING_MPI_LIBRARY) && defined(__GNUC__)
#define ZR_MPI_API __attribute__((visibility("default")))
#else
#define ZR_MPI_API
#endif

typedef struct zr_mpi zr_mpi;

/* The ranks of comm as one renderer.  ZR_EINVAL when MPI is not
   initialised or comm is MPI_COMM_NULL; ZR_EMPI when MPI fails. */
ZR_MPI_API zr_status zr_mpi_new(MPI_Comm comm, zr_mpi **out);
/* Frees the duplicate communicator (collective); NULL is a no-op. */
ZR_MPI_API void zr_mpi_free(zr_mpi *mpi);

ZR_MPI_API int zr_mpi_rank(const zr_mpi *mpi);
ZR_MPI_API int zr_mpi_size(const zr_mpi *mpi);

/* The team of the communicator's ranks, for zr_radiosity_params.team,
   zr_gi_params.team and zr_context_set_team; valid until zr_mpi_free. */
ZR_MPI_API const zr_team *zr_mpi_team(const zr_mpi *mpi);

/*
 * Renders params' image over the ranks, threads threads each (0: the
 * host's processors shared among its ranks): rank r traces rows r,
 * r + n, ..., and rank 0 receives the picture into image (width x
 * height of params; the other ranks pass NULL).  Every rank returns the
 * same status.
 */
ZR_MPI_API zr_status zr_mpi_render_image(zr_mpi *mpi, const zr_scene *scene,
                                         const zr_render_params *params,
                                         int threads, zr_image *image);

#ifdef __cplusplus
}
#endif

#endif /* ZRCUBE_MPI_H */
