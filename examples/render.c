/* render.c - the smallest program using libzrcube: parse a scene, render
 * it on this thread, write a PNG.
 *   cc render.c $(pkg-config --cflags --libs libzrcube) -o render
 *   ./render scene.pov out.png
 */
#include <stdio.h>
#include <stdlib.h>
#include <zrcube.h>

static void print_diag(const zr_diag *d, void *user) {
  (void)user;
  fputs(d->text, stderr);
}

int main(int argc, char **argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: %s scene.pov out.png\n", argv[0]);
    return 2;
  }
  zr_context *ctx = NULL;
  zr_scene *scene = NULL;
  zr_image *image = NULL;
  zr_status s = zr_context_new(&ctx);
  if (s == ZR_OK) {
    zr_context_set_diag(ctx, print_diag, NULL);
    s = zr_scene_parse_file(ctx, argv[1], &scene);
  }
  zr_render_params params;
  zr_render_params_init(&params);
  params.width = 160;
  params.height = 120;
  if (s == ZR_OK)
    s = zr_image_new(params.width, params.height, &image);
  if (s == ZR_OK)
    s = zr_render_image(scene, &params, zr_image_pixels(image), NULL);
  if (s == ZR_OK)
    s = zr_image_write(ctx, image, argv[2], ZR_FORMAT_AUTO,
                       zr_scene_assumed_gamma(scene));
  if (s != ZR_OK)
    fprintf(stderr, "render: %s\n", zr_status_str(s));
  zr_image_free(image);
  zr_scene_free(scene);
  zr_context_free(ctx);
  return s == ZR_OK ? 0 : 1;
}
