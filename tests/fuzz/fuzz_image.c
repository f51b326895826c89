/*
 * fuzz_image.c - a libFuzzer target for the image decoders.
 *
 * Each input goes through the three ways a scene's file reaches a
 * decoder: zr__image_decode() (image_map, pigment maps: PNG, JPEG, GIF,
 * TGA, PPM/PGM/PBM, PFM, chosen by content), and
 * zr__image_decode_heights() twice, as a height field file (PNG, GIF,
 * TGA, PGM/PPM, JPEG) and as a POT file (a double-width GIF).  The
 * context's memory budget is 64 MiB, so a header declaring a huge
 * picture is refused before its pixels are allocated rather than
 * growing to libFuzzer's RSS limit.  Every pixel of a decoded image is
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

#include "image/image.h"
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
  zr_context_set_memory_limit(ctx, 64ULL << 20);
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
  zr_context_free(ctx);
  return 0;
}
