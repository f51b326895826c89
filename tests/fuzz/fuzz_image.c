/*
 * fuzz_image.c - a libFuzzer target for the image decoders.
 *
 * Each input goes through the three ways a scene's file reaches a
 * decoder: zr__image_decode() (image_map, pigment maps: PNG, JPEG, GIF,
 * TGA, PPM/PGM/PBM, PFM, HDR, EXR, BMP, TIFF, chosen by content),
 * zr__image_decode_heights() twice, as a height field file (PNG, GIF,
 * TGA, PGM/PPM, JPEG, BMP, TIFF) and as a POT file (a double-width GIF),
 * and the height field the scene keeps (codes, block hierarchy) with a
 * few rays and inside tests through it.  The
 * context's memory budget is 4 MiB, so a header declaring a huge
 * picture is refused before its pixels are allocated rather than
 * growing to libFuzzer's RSS limit (it was 64 MiB: GIF files of 50
 * bytes declaring 16 million pixels, each decoded four ways and every
 * sample read, took 4-6 s of CPU a unit under the sanitizers and over
 * a minute of wall clock on the loaded machine; they are in
 * regress-image as gif-16m-pixels-*.gif).  Every pixel of a decoded image is
 * read, so a short or misplaced buffer shows up under AddressSanitizer;
 * diagnostics go to a callback that reads the whole message.
 * Built with --enable-fuzz and clang (tests/fuzz/local.mk); seeds, one
 * tiny valid file per format, are in tests/fuzz/image-seeds (made by
 * tests/fuzz/make-image-seeds.sh); tests/fuzz/replay_image (replay.c)
 * calls the same entry point on tests/fuzz/regress-image in every
 * `make check`.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <math.h>

#include "core/arena.h"
#include "image/image.h"
#include "scene/shapes.h"
#include "trace/obj_isosurface.h"
#include "zrcube.h"

static void on_diag(const zr_diag *d, void *user) {
  size_t *sum = user;
  if (d->text)
    *sum += strlen(d->text);
  if (d->message)
    *sum += strlen(d->message);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Keeps the reads of the pixels from being optimised away. */
static volatile float sink;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  zr_context *ctx = NULL;
  if (zr_context_new(&ctx) != ZR_OK)
    return 0;
  size_t sum = 0;
  zr_context_set_memory_limit(ctx, 4ULL << 20);
  zr_context_set_diag(ctx, on_diag, &sum);
  const char *bytes = (const char *)data;

  zr_image *image = NULL;
  if (zr__image_decode(ctx, "fuzz.img", bytes, size, &image) == ZR_OK &&
      image) {
    size_t n = (size_t)image->width * (size_t)image->height;
    float acc = 0.0f;
    /* Every sample as the samplers read it (image.h). */
    for (size_t i = 0; i < 3 * n; i++)
      acc += zr__image_linear(image, i);
    if (image->indices)
      for (size_t i = 0; i < n; i++)
        acc += (float)image->indices[i];
    if (image->layout != ZR_LAYOUT_FLOAT)
      for (size_t i = 0; i < 3 * n; i++)
        acc += (float)zr__image_stored(image, i);
    sink = acc;
  }
  zr_image_free(image);

  for (int pot = 0; pot <= 1; pot++) {
    float *heights = NULL;
    int w = 0, h = 0;
    if (zr__image_decode_heights(ctx, pot ? "fuzz.pot" : "fuzz.hf",
                                 pot != 0, bytes, size, &heights, &w,
                                 &h) == ZR_OK &&
        heights) {
      float acc = 0.0f;
      for (size_t i = 0; i < (size_t)w * (size_t)h; i++)
        acc += heights[i];
      sink = acc;
    }
    free(heights);
  }

  /* The height field as the scene keeps it: codes in an arena, the
     block hierarchy over them, and rays through it (down, grazing,
     diagonal, from outside and from under the water). */
  zr_arena arena;
  zr__arena_init(&arena);
  zr_height_codes codes;
  const struct zr_hf_grid *grid = NULL;
  if (zr__image_decode_height_codes(ctx, "fuzz.hf", false, bytes, size,
                                    &arena, &codes) == ZR_OK &&
      codes.width >= 2 && codes.height >= 2 &&
      zr__height_field_grid(&arena, codes.codes, codes.bits, codes.width,
                            codes.height, &grid) == ZR_OK) {
    zr_object o;
    memset(&o, 0, sizeof o);
    o.kind = ZR_OBJ_HEIGHT_FIELD;
    o.u.height_field.grid = grid;
    o.u.height_field.w = codes.width;
    o.u.height_field.h = codes.height;
    o.u.height_field.smooth = size % 2 == 1;
    o.u.height_field.water_level = size % 3 == 0 ? 0.25 : 0.0;
    static const double rays[][6] = {
        {0.5, 2, 0.5, 0, -1, 0},       {0.1, 2, 0.9, 0.01, -1, -0.02},
        {-1, 0.5, 0.5, 1, 0, 0},       {-1, 0.3, -1, 1, 0.01, 1},
        {2, 0.1, 0.3, -1, -0.001, 0.2}, {0.5, -1, 0.5, 0, 1, 0},
        {0.25, 0.2, 0.75, 0.3, 0.1, -0.4}};
    double acc = 0.0;
    for (size_t k = 0; k < sizeof rays / sizeof rays[0]; k++) {
      double t[4];
      zr_vec3 n[4];
      int found = zr__height_field_crossings(
          &o, zr_v3(rays[k][0], rays[k][1], rays[k][2]),
          zr_v3(rays[k][3], rays[k][4], rays[k][5]), 0.0, INFINITY, t, n);
      for (int i = 0; i < found; i++)
        acc += t[i] + n[i].y;
      acc += zr__height_field_inside(&o, zr_v3(rays[k][0], 0.1,
                                               rays[k][2]));
    }
    sink = (float)acc;
  }
  zr__arena_free(&arena);
  zr_context_free(ctx);
  return 0;
}
