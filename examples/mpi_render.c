/*
 * mpi_render.c - libzrcube inside a program that already uses MPI
 * (zrcube_mpi.h): every rank parses the scene, the ranks of the
 * caller's communicator solve its radiosity (or pretrace its irradiance
 * cache) together and render it together, and rank 0 writes the image.
 * The image is the same bytes for any number of ranks.
 *
 *   mpirun -n 4 mpi_render scene.pov out.png
 *
 * Here the program's own MPI work is a split of MPI_COMM_WORLD: the
 * renderer gets a communicator of its own, as it would beside other
 * work.
 */
#include <stdio.h>
#include <stdlib.h>
#include <zrcube_mpi.h>

static void print_diag(const zr_diag *d, void *user) {
  if (*(const int *)user == 0) /* rank 0 speaks for all */
    fputs(d->text, stderr);
}

/* The picture as POV-Ray writes it: the scene's working gamma undone,
   sRGB codes, or none at all for a legacy scene (zr_scene_image_encoding). */
static zr_status write_picture(zr_context *ctx, const zr_scene *scene,
                               const zr_image *image, const char *path) {
  zr_image_encoding e;
  zr_scene_image_encoding(scene, ZR_FORMAT_AUTO, &e);
  return zr_image_save(ctx, image, path, &e);
}

int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  int world_rank;
  MPI_Comm_rank(MPI_COMM_WORLD, &world_rank);
  if (argc != 3) {
    if (world_rank == 0)
      fprintf(stderr, "usage: %s scene.pov out.png\n", argv[0]);
    MPI_Finalize();
    return 2;
  }
  MPI_Comm render_comm;
  MPI_Comm_split(MPI_COMM_WORLD, 0, world_rank, &render_comm);
  zr_mpi *mpi = NULL;
  zr_context *ctx = NULL;
  zr_scene *scene = NULL;
  zr_radiosity *rad = NULL;
  zr_gi_cache *cache = NULL;
  zr_image *image = NULL;
  zr_status s = zr_mpi_new(render_comm, &mpi);
  int rank = s == ZR_OK ? zr_mpi_rank(mpi) : world_rank;
  if (s == ZR_OK)
    s = zr_context_new(&ctx);
  if (s == ZR_OK) {
    zr_context_set_diag(ctx, print_diag, &rank);
    s = zr_scene_parse_file(ctx, argv[1], &scene);
  }
  zr_render_params params;
  zr_render_params_init(&params);
  params.width = 160;
  params.height = 120;
  params.antialias = 0;
  /* Global illumination by the model the scene asks for, shared by
     the ranks through their team. */
  zr_gi_method gi =
      s == ZR_OK ? zr_gi_choose(scene, ZR_GI_AUTO, NULL, 0) : ZR_GI_OFF;
  if (s == ZR_OK && gi == ZR_GI_HIERARCHICAL) {
    zr_radiosity_params rp;
    zr_radiosity_params_init(&rp, scene);
    rp.threads = 1;
    rp.team = zr_mpi_team(mpi);
    s = zr_radiosity_solve(ctx, scene, &rp, &rad);
    params.radiosity = rad;
  } else if (s == ZR_OK && gi == ZR_GI_CACHE) {
    zr_gi_params gp;
    zr_gi_params_init(&gp, scene);
    gp.threads = 1;
    gp.team = zr_mpi_team(mpi);
    s = zr_gi_cache_new(ctx, scene, &gp, &cache);
    if (s == ZR_OK)
      s = zr_gi_cache_pretrace(cache, &params);
    params.gi_cache = cache;
  }
  if (s == ZR_OK && rank == 0)
    s = zr_image_new(params.width, params.height, &image);
  /* Collective: the ranks agree on failures before rendering. */
  if (s == ZR_OK)
    s = zr_mpi_render_image(mpi, scene, &params, 1, image);
  if (s == ZR_OK && rank == 0)
    s = write_picture(ctx, scene, image, argv[2]);
  if (s != ZR_OK)
    fprintf(stderr, "mpi_render: rank %d: %s\n", rank, zr_status_str(s));
  zr_image_free(image);
  zr_gi_cache_free(cache);
  zr_radiosity_free(rad);
  zr_scene_free(scene);
  zr_context_free(ctx);
  zr_mpi_free(mpi);
  MPI_Comm_free(&render_comm);
  MPI_Finalize();
  return s == ZR_OK ? 0 : 1;
}
