/*
 * mkhfpng.c - writes a large 8-bit grey PNG for the height field case of
 * tests/test_faults.sh (issue 10): mkhfpng FILE SIDE makes a SIDE x SIDE
 * picture of ridges along z, a sine of x, which zlib packs to about
 * 150 KB at SIDE = 11000, so the test needs no such file in the tree.
 */
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: mkhfpng FILE SIDE\n");
    return 2;
  }
  long side = strtol(argv[2], NULL, 10);
  if (side < 2 || side > 65535) {
    fprintf(stderr, "mkhfpng: SIDE must be 2 to 65535\n");
    return 2;
  }
  FILE *f = fopen(argv[1], "wb");
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
  png_infop info = png ? png_create_info_struct(png) : NULL;
  png_bytep row = malloc((size_t)side);
  if (!f || !info || !row) {
    fprintf(stderr, "mkhfpng: cannot write %s\n", argv[1]);
    return 1;
  }
  if (setjmp(png_jmpbuf(png))) {
    fprintf(stderr, "mkhfpng: cannot write %s\n", argv[1]);
    return 1;
  }
  png_init_io(png, f);
  png_set_IHDR(png, info, (png_uint_32)side, (png_uint_32)side, 8,
               PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, 9);
  png_write_info(png, info);
  for (long x = 0; x < side; x++)
    row[x] = (png_byte)lround(127.5 + 127.5 * sin((double)x / 700.0));
  for (long y = 0; y < side; y++)
    png_write_row(png, row);
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  free(row);
  return fclose(f) == 0 ? 0 : 1;
}
