/* render.c - a small program using libzrcube: parse a scene, render it
 * with 4 threads, show progress, stop cleanly on Ctrl-C, write a PNG.
 *   cc render.c $(pkg-config --cflags --libs libzrcube) -o render
 *   ./render scene.pov out.png [stop-at-percent]
 */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <zrcube.h>

static zr_context *ctx; /* for the signal handler */

static void on_interrupt(int sig) {
  (void)sig;
  zr_context_cancel(ctx, 1); /* safe in a signal handler */
}

static void print_diag(const zr_diag *d, void *user) {
  (void)user;
  fputs(d->text, stderr);
}

/* Called from the render's threads, one at a time; non-zero cancels. */
static int print_progress(const zr_progress *p, void *user) {
  int stop_at = *(int *)user;
  if (p->total == 0)
    return 0; /* the parse: tokens, no total */
  int percent = (int)(100 * p->done / p->total);
  fprintf(stderr, "\rphase %d: %3d%%", (int)p->phase, percent);
  if (p->done == p->total)
    fputc('\n', stderr);
  return p->phase == ZR_PHASE_RENDER && percent >= stop_at;
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
  if (argc != 3 && argc != 4) {
    fprintf(stderr, "usage: %s scene.pov out.png [stop-at-percent]\n",
            argv[0]);
    return 2;
  }
  int stop_at = argc == 4 ? atoi(argv[3]) : 101;
  zr_scene *scene = NULL;
  zr_image *image = NULL;
  zr_status s = zr_context_new(&ctx);
  if (s == ZR_OK) {
    zr_context_set_diag(ctx, print_diag, NULL);
    zr_context_set_progress(ctx, print_progress, &stop_at);
    signal(SIGINT, on_interrupt);
    s = zr_scene_parse_file(ctx, argv[1], &scene);
  }
  zr_render_params params;
  zr_render_params_init(&params);
  params.width = 160;
  params.height = 120;
  params.threads = 4;    /* the same bytes as 1 thread */
  params.context = ctx;  /* progress, cancel and diagnostics */
  if (s == ZR_OK)
    s = zr_image_new(params.width, params.height, &image);
  if (s == ZR_OK)
    s = zr_render_image(scene, &params, zr_image_pixels(image), NULL);
  if (s == ZR_OK)
    s = write_picture(ctx, scene, image, argv[2]);
  if (s != ZR_OK)
    fprintf(stderr, "\nrender: %s\n", zr_status_str(s));
  signal(SIGINT, SIG_DFL);
  zr_image_free(image);
  zr_scene_free(scene);
  zr_context_free(ctx);
  return s == ZR_OK ? 0 : 1;
}
