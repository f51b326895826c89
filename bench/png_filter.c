/*
 * png_filter.c - what libpng's row filters and zlib's strategies cost
 * and save on rendered pictures (issue 13; bench/png_filter.sh runs it).
 *
 *   png_filter REPEAT LEVELS FILE.png...
 *
 * Each FILE is read (8-bit RGB, any alpha dropped) and written to memory
 * again at every zlib level of LEVELS (a comma list, e.g. 1,2,6,9) with
 * each single filter, libpng's adaptive choice among all five ("all")
 * and each strategy (default, filtered, rle); the best CPU time of
 * REPEAT writes and the size are printed, with both as ratios to the
 * adaptive filter's default strategy at the same level.
 */
#define _POSIX_C_SOURCE 200809L
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <zlib.h>

typedef struct sink {
  unsigned char *bytes;
  size_t size, cap;
} sink;

static void sink_write(png_structp png, png_bytep data, png_size_t n) {
  sink *s = png_get_io_ptr(png);
  if (s->size + n > s->cap) {
    s->cap = 2 * (s->size + n);
    s->bytes = realloc(s->bytes, s->cap);
    if (!s->bytes)
      png_error(png, "out of memory");
  }
  memcpy(s->bytes + s->size, data, n);
  s->size += n;
}

static void sink_flush(png_structp png) { (void)png; }

static double cpu_seconds(void) {
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* One write; returns its CPU seconds and sets *size. */
static double write_once(png_bytepp rows, int w, int h, int level,
                         int filter, int strategy, size_t *size) {
  sink s = {NULL, 0, 0};
  double t0 = cpu_seconds();
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    fprintf(stderr, "png_filter: libpng failed\n");
    exit(1);
  }
  png_set_write_fn(png, &s, sink_write, sink_flush);
  png_set_compression_level(png, level);
  png_set_compression_strategy(png, strategy);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, filter);
  png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < h; y++)
    png_write_row(png, rows[y]);
  png_write_end(png, NULL);
  png_destroy_write_struct(&png, &info);
  double t = cpu_seconds() - t0;
  *size = s.size;
  free(s.bytes);
  return t;
}

int main(int argc, char **argv) {
  if (argc < 4) {
    fprintf(stderr, "usage: png_filter REPEAT LEVELS FILE.png...\n");
    return 2;
  }
  int repeat = atoi(argv[1]);
  static const struct {
    const char *name;
    int mask;
  } filters[] = {{"all", PNG_ALL_FILTERS}, {"none", PNG_FILTER_NONE},
                 {"sub", PNG_FILTER_SUB},  {"up", PNG_FILTER_UP},
                 {"avg", PNG_FILTER_AVG},  {"paeth", PNG_FILTER_PAETH}};
  static const struct {
    const char *name;
    int strategy;
  } strategies[] = {{"default", Z_DEFAULT_STRATEGY},
                    {"filtered", Z_FILTERED},
                    {"rle", Z_RLE}};
  printf("%-12s %5s %-6s %-8s %9s %9s %7s %7s\n", "file", "level", "filter",
         "strategy", "write_ms", "bytes", "t/all", "B/all");
  for (int f = 3; f < argc; f++) {
    FILE *in = fopen(argv[f], "rb");
    if (!in) {
      perror(argv[f]);
      return 1;
    }
    png_structp rd =
        png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop ri = png_create_info_struct(rd);
    if (setjmp(png_jmpbuf(rd))) {
      fprintf(stderr, "png_filter: cannot read %s\n", argv[f]);
      return 1;
    }
    png_init_io(rd, in);
    png_read_png(rd, ri,
                 PNG_TRANSFORM_STRIP_16 | PNG_TRANSFORM_STRIP_ALPHA |
                     PNG_TRANSFORM_EXPAND,
                 NULL);
    int w = (int)png_get_image_width(rd, ri);
    int h = (int)png_get_image_height(rd, ri);
    png_bytepp rows = png_get_rows(rd, ri);
    const char *name = strrchr(argv[f], '/');
    name = name ? name + 1 : argv[f];
    char levels[64];
    snprintf(levels, sizeof levels, "%s", argv[2]);
    for (char *l = strtok(levels, ","); l; l = strtok(NULL, ",")) {
      int level = atoi(l);
      double t_all = 0;
      size_t b_all = 0;
      for (size_t i = 0; i < sizeof filters / sizeof *filters; i++)
        for (size_t j = 0; j < sizeof strategies / sizeof *strategies; j++) {
          double best = 1e30;
          size_t size = 0;
          for (int k = 0; k < repeat; k++) {
            double t = write_once(rows, w, h, level, filters[i].mask,
                                  strategies[j].strategy, &size);
            best = t < best ? t : best;
          }
          if (i == 0 && j == 0) {
            t_all = best;
            b_all = size;
          }
          printf("%-12.12s %5d %-6s %-8s %9.3f %9zu %7.2f %7.2f\n", name,
                 level, filters[i].name, strategies[j].name, 1e3 * best,
                 size, best / t_all, (double)size / (double)b_all);
        }
    }
    png_destroy_read_struct(&rd, &ri, NULL);
    fclose(in);
  }
  return 0;
}
