/*
 * imgcmp.c - compares a render with a reference image.
 *
 *   imgcmp IMAGE REFERENCE [--ssim-min 0.98] [--delta-max D]
 *   imgcmp IMAGE REFERENCE --rmse [--rmse-max 0.05]
 *
 * Both files are read with zr_image_read (PNG, JPEG, PPM, PFM) and must
 * have the same size.  Each is first reduced by a 2x2 box filter, which
 * averages away the single-pixel differences two correct ray tracers show
 * on silhouettes (a ray grazing an edge lands on either side), so that
 * the score measures the picture, not the sampling.
 *
 * SSIM follows Wang, Bovik, Sheikh and Simoncelli, "Image quality
 * assessment: from error visibility to structural similarity" (IEEE TIP
 * 13(4), 2004): an 11x11 circular-symmetric Gaussian window with sigma
 * 1.5, K1 = 0.01, K2 = 0.03, dynamic range L = 1, evaluated at every
 * position where the window fits inside the image (as the authors'
 * reference code does) and averaged.  It is computed on each of R, G and
 * B in the encoded sRGB space [0, 1] (what a viewer sees) and the three
 * means are averaged; a per-channel score catches colour errors that a
 * luminance-only score would miss, such as red and green swapped.
 *
 * SSIM is built to judge structure, and forgives a change of brightness
 * or colour over a smooth area: the luminance term of a 0.45 against a
 * 0.55 mean is still 0.98.  Removing the ambient term of a whole scene
 * or turning a mirror's reflection from 0.9 down to 0.7 still scores
 * above 0.98.  So the SSIM line also gives "delta", the worst mean
 * absolute difference of any 8x8 block (half overlapping) of the
 * filtered sRGB images, on any channel: a wrong colour over an area
 * shows in full there, while silhouette pixels, a few per block, are
 * diluted.  --delta-max sets a limit for it (none by default).  For
 * scale: POV-Ray's own renders of our scenes with and without
 * antialiasing differ by delta 0.005 to 0.038 (SSIM 0.978 to 0.998);
 * the ambient and reflection changes above give 0.11 and 0.066.
 *
 * --rmse is for linear results (radiosity, Monte Carlo; usually PFM):
 * both images are clipped to [0, 1] in linear light, box filtered, and
 * the root mean square difference over all samples is divided by the
 * reference's mean, so the figure is a relative error.
 *
 * Besides what zr_image_read reads, imgcmp reads Radiance RGBE files
 * (.hdr, "#?RADIANCE"), which is how POV-Ray 3.7 writes linear HDR
 * output (+FH; 3.7 has no PFM writer).  The format is Greg Ward's, as
 * described in "Real Pixels" (Graphics Gems II, 1991) and in Radiance's
 * documentation of its picture files: a text header ending in an empty
 * line, a resolution line, then scanlines of 4-byte pixels (a mantissa
 * per channel and a shared exponent), either flat, in the old run-length
 * encoding or in the adaptive run-length encoding per component.  Only
 * the standard orientation "-Y H +X W" (rows top to bottom) is accepted.
 * A mantissa m with exponent e decodes to (m + 0.5) * 2^(e - 136), the
 * centre of the interval the writer truncated into (POV-Ray truncates:
 * 0.7 is stored as 89/128, not 90/128), as Radiance itself decodes.
 *
 *   imgcmp --info IMAGE
 *
 * prints the size, the mean of all samples (linear), the mean of the
 * samples clipped to [0, 1] (the --rmse denominator, before the box
 * filter) and the largest sample, to look at a reference or a result.
 *
 * Prints "ssim=0.9xxx delta=0.0xxx" or "rmse=0.0xxx"; exits 0 when the
 * thresholds are met, 1 when one is not, 2 on a usage or file error.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "zrcube.h"

#define WINDOW_RADIUS 5 /* 11x11 */
#define WINDOW_SIGMA 1.5

/* One channel of an image as doubles. */
typedef struct plane {
  int w, h;
  double *v;
} plane;

static void print_diag(const zr_diag *d, void *user) {
  (void)user;
  fputs(d->text, stderr);
}

static void usage(void) {
  fputs("usage: imgcmp IMAGE REFERENCE [--ssim-min MIN] [--delta-max D]\n"
        "       imgcmp IMAGE REFERENCE --rmse [--rmse-max MAX]\n"
        "       imgcmp --info IMAGE\n"
        "  SSIM of the sRGB-encoded images after a 2x2 box filter\n"
        "  (default minimum 0.98) and the worst 8x8 block's mean\n"
        "  absolute difference (no maximum by default), or with --rmse\n"
        "  the relative RMSE of the linear images clipped to [0,1]\n"
        "  (no maximum by default).  --info prints an image's size,\n"
        "  mean, clipped mean and maximum.  Radiance .hdr files are\n"
        "  read too.\n",
        stderr);
}

/* Exit status 2 after the usage text, for a bad command line. */
static int usage_error(void) {
  usage();
  return 2;
}

static double srgb(double linear) {
  if (linear <= 0.0031308)
    return 12.92 * linear;
  return 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
}

static double clip01(double v) { return !(v > 0.0) ? 0.0 : v > 1.0 ? 1.0 : v; }

/*
 * Channel c of img, clipped to [0, 1], optionally sRGB-encoded, averaged
 * over 2x2 blocks (an odd last row or column is dropped).
 */
static int box_plane(const zr_image *img, int c, int encode, plane *out) {
  int w = zr_image_width(img) / 2, h = zr_image_height(img) / 2;
  int stride = zr_image_width(img) * 3;
  const float *px = zr_image_pixels_const(img);
  out->w = w;
  out->h = h;
  out->v = malloc((size_t)w * (size_t)h * sizeof *out->v);
  if (!out->v)
    return -1;
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      double sum = 0.0;
      for (int dy = 0; dy < 2; dy++)
        for (int dx = 0; dx < 2; dx++) {
          double v = clip01(px[(size_t)(2 * y + dy) * (size_t)stride +
                               (size_t)(2 * x + dx) * 3 + (size_t)c]);
          sum += encode ? srgb(v) : v;
        }
      out->v[(size_t)y * (size_t)w + (size_t)x] = sum / 4.0;
    }
  return 0;
}

/* Mean SSIM of two planes of the same size (Wang et al. 2004, eq. 13). */
static double ssim_plane(const plane *a, const plane *b) {
  const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  int r = WINDOW_RADIUS;
  /* Small images get the largest window that fits. */
  while (r > 0 && (2 * r + 1 > a->w || 2 * r + 1 > a->h))
    r--;
  double weight[2 * WINDOW_RADIUS + 1][2 * WINDOW_RADIUS + 1];
  double total = 0.0;
  for (int j = -r; j <= r; j++)
    for (int i = -r; i <= r; i++)
      total += weight[j + r][i + r] =
          exp(-(i * i + j * j) / (2.0 * WINDOW_SIGMA * WINDOW_SIGMA));
  double sum = 0.0;
  long count = 0;
  for (int y = r; y < a->h - r; y++)
    for (int x = r; x < a->w - r; x++) {
      double ma = 0, mb = 0, saa = 0, sbb = 0, sab = 0;
      for (int j = -r; j <= r; j++)
        for (int i = -r; i <= r; i++) {
          double wgt = weight[j + r][i + r] / total;
          size_t k = (size_t)(y + j) * (size_t)a->w + (size_t)(x + i);
          double va = a->v[k], vb = b->v[k];
          ma += wgt * va;
          mb += wgt * vb;
          saa += wgt * va * va;
          sbb += wgt * vb * vb;
          sab += wgt * va * vb;
        }
      double var_a = saa - ma * ma, var_b = sbb - mb * mb;
      double cov = sab - ma * mb;
      sum += (2 * ma * mb + c1) * (2 * cov + c2) /
             ((ma * ma + mb * mb + c1) * (var_a + var_b + c2));
      count++;
    }
  return count ? sum / (double)count : 1.0;
}

/*
 * The worst colour error of any BLOCK x BLOCK block of two planes: the
 * mean absolute difference inside each block, maximised over blocks.
 */
#define BLOCK 8
static double block_delta_plane(const plane *a, const plane *b) {
  double worst = 0.0;
  for (int by = 0; by + BLOCK <= a->h; by += BLOCK / 2)
    for (int bx = 0; bx + BLOCK <= a->w; bx += BLOCK / 2) {
      double sum = 0.0;
      for (int y = by; y < by + BLOCK; y++)
        for (int x = bx; x < bx + BLOCK; x++) {
          size_t k = (size_t)y * (size_t)a->w + (size_t)x;
          sum += fabs(a->v[k] - b->v[k]);
        }
      sum /= BLOCK * BLOCK;
      if (sum > worst)
        worst = sum;
    }
  return worst;
}

static double compare_delta(const zr_image *a, const zr_image *b) {
  double worst = 0.0;
  for (int c = 0; c < 3; c++) {
    plane pa, pb;
    if (box_plane(a, c, 1, &pa) || box_plane(b, c, 1, &pb)) {
      fputs("imgcmp: out of memory\n", stderr);
      exit(2);
    }
    double d = block_delta_plane(&pa, &pb);
    if (d > worst)
      worst = d;
    free(pa.v);
    free(pb.v);
  }
  return worst;
}

static double compare_ssim(const zr_image *a, const zr_image *b) {
  double sum = 0.0;
  for (int c = 0; c < 3; c++) {
    plane pa, pb;
    if (box_plane(a, c, 1, &pa) || box_plane(b, c, 1, &pb)) {
      fputs("imgcmp: out of memory\n", stderr);
      exit(2);
    }
    sum += ssim_plane(&pa, &pb);
    free(pa.v);
    free(pb.v);
  }
  return sum / 3.0;
}

static double compare_rmse(const zr_image *a, const zr_image *ref) {
  double sq = 0.0, ref_sum = 0.0;
  size_t n = 0;
  for (int c = 0; c < 3; c++) {
    plane pa, pr;
    if (box_plane(a, c, 0, &pa) || box_plane(ref, c, 0, &pr)) {
      fputs("imgcmp: out of memory\n", stderr);
      exit(2);
    }
    for (size_t k = 0; k < (size_t)pa.w * (size_t)pa.h; k++) {
      double d = pa.v[k] - pr.v[k];
      sq += d * d;
      ref_sum += pr.v[k];
      n++;
    }
    free(pa.v);
    free(pr.v);
  }
  double mean = ref_sum / (double)n;
  double rmse = sqrt(sq / (double)n);
  return mean > 0.0 ? rmse / mean : (rmse > 0.0 ? INFINITY : 0.0);
}

/* ---- Radiance RGBE files ---- */

/* The bytes of a whole file, or NULL after a message on stderr. */
static unsigned char *slurp(const char *path, size_t *size) {
  FILE *f = fopen(path, "rb");
  if (!f) {
    fprintf(stderr, "imgcmp: %s: cannot open\n", path);
    return NULL;
  }
  size_t cap = 1 << 16, n = 0;
  unsigned char *bytes = malloc(cap);
  while (bytes) {
    n += fread(bytes + n, 1, cap - n, f);
    if (n < cap)
      break;
    unsigned char *bigger = realloc(bytes, cap * 2);
    if (!bigger) {
      free(bytes);
      bytes = NULL;
      break;
    }
    bytes = bigger;
    cap *= 2;
  }
  int failed = ferror(f);
  fclose(f);
  if (!bytes || failed) {
    fprintf(stderr, "imgcmp: %s: cannot read\n", path);
    free(bytes);
    return NULL;
  }
  *size = n;
  return bytes;
}

/* Whether the file starts with Radiance's magic "#?". */
static int is_rgbe(const char *path) {
  FILE *f = fopen(path, "rb");
  if (!f)
    return 0;
  char magic[2];
  int yes = fread(magic, 1, 2, f) == 2 && magic[0] == '#' && magic[1] == '?';
  fclose(f);
  return yes;
}

/* A cursor over the file's bytes. */
typedef struct reader {
  const unsigned char *p, *end;
} reader;

static int next_byte(reader *r) { return r->p < r->end ? *r->p++ : -1; }

/*
 * Reads the next header line into line (NUL-terminated, without its
 * newline, truncated to size - 1); -1 at the end of the file.
 */
static int header_line(reader *r, char *line, size_t size) {
  size_t n = 0;
  int c;
  while ((c = next_byte(r)) >= 0 && c != '\n')
    if (n + 1 < size)
      line[n++] = (char)c;
  line[n] = '\0';
  return c < 0 && n == 0 ? -1 : 0;
}

/*
 * One scanline of width pixels into rgbe (4 bytes a pixel).  Scanlines of
 * 8 to 32767 pixels may use the adaptive encoding, which announces itself
 * with the bytes 2, 2 and the width; anything else is flat pixels where
 * the pixel 1, 1, 1, n repeats the previous pixel n times (n shifted by 8
 * more bits for each repeat code that follows directly: the old
 * encoding).  Returns 0, or -1 on malformed data.
 */
static int read_scanline(reader *r, unsigned char *rgbe, int width) {
  if (r->end - r->p < 4)
    return -1;
  const unsigned char *q = r->p;
  if (width >= 8 && width <= 0x7fff && q[0] == 2 && q[1] == 2 &&
      !(q[2] & 0x80)) {
    if ((q[2] << 8 | q[3]) != width)
      return -1;
    r->p += 4;
    for (int c = 0; c < 4; c++)
      for (int x = 0; x < width;) {
        int code = next_byte(r);
        if (code <= 0)
          return -1;
        if (code > 128) {
          int run = code - 128, value = next_byte(r);
          if (value < 0 || x + run > width)
            return -1;
          while (run--)
            rgbe[4 * x++ + c] = (unsigned char)value;
        } else {
          if (x + code > width || r->end - r->p < code)
            return -1;
          while (code--)
            rgbe[4 * x++ + c] = *r->p++;
        }
      }
    return 0;
  }
  int shift = 0;
  for (int x = 0; x < width;) {
    if (r->end - r->p < 4)
      return -1;
    const unsigned char *px = r->p;
    r->p += 4;
    if (px[0] == 1 && px[1] == 1 && px[2] == 1) {
      /* Widths fit in 15 bits: a third repeat code in a row is bad. */
      long run = shift <= 16 ? (long)px[3] << shift : -1;
      if (x == 0 || run < 0 || run > width - x)
        return -1;
      for (; run > 0; run--, x++)
        memcpy(rgbe + 4 * x, rgbe + 4 * (x - 1), 4);
      shift += 8;
    } else {
      memcpy(rgbe + 4 * x++, px, 4);
      shift = 0;
    }
  }
  return 0;
}

/*
 * Parses the header of a Radiance picture up to its resolution line.
 * Returns NULL, or a message saying what is wrong.
 */
static const char *rgbe_header(reader *r, int *width, int *height,
                               double *exposure) {
  char line[256];
  if (header_line(r, line, sizeof line) || line[0] != '#' || line[1] != '?')
    return "not a Radiance picture";
  *exposure = 1.0;
  for (;;) {
    if (header_line(r, line, sizeof line))
      return "truncated header";
    if (!line[0])
      break;
    if (!strncmp(line, "FORMAT=", 7) && strcmp(line + 7, "32-bit_rle_rgbe"))
      return "only FORMAT=32-bit_rle_rgbe is supported";
    if (!strncmp(line, "EXPOSURE=", 9)) {
      /* Each EXPOSURE line multiplies the values stored after it. */
      char *end;
      double e = strtod(line + 9, &end);
      if (end == line + 9 || !(e > 0.0) || !isfinite(e))
        return "bad EXPOSURE";
      *exposure *= e;
    }
  }
  char tail;
  if (header_line(r, line, sizeof line) ||
      sscanf(line, "-Y %d +X %d %c", height, width, &tail) != 2)
    return "only the resolution line \"-Y H +X W\" is supported";
  if (*width < 1 || *height < 1 || *width > 1 << 15 || *height > 1 << 15)
    return "bad image size";
  return NULL;
}

/* Reads a Radiance RGBE picture into linear floats. */
static int read_rgbe(const char *path, zr_image **out) {
  size_t size = 0;
  unsigned char *bytes = slurp(path, &size);
  if (!bytes)
    return -1;
  reader r = {bytes, bytes + size};
  int width = 0, height = 0;
  double exposure = 1.0;
  const char *error = rgbe_header(&r, &width, &height, &exposure);
  unsigned char *row = NULL;
  *out = NULL;
  if (!error && (!(row = malloc((size_t)width * 4)) ||
                 zr_image_new(width, height, out) != ZR_OK))
    error = "out of memory";
  for (int y = 0; !error && y < height; y++) {
    if (read_scanline(&r, row, width)) {
      error = "malformed or truncated pixel data";
      break;
    }
    float *dst = zr_image_pixels(*out) + (size_t)y * (size_t)width * 3;
    for (int x = 0; x < width; x++) {
      const unsigned char *px = row + 4 * x;
      double scale = px[3] ? ldexp(1.0, px[3] - 136) / exposure : 0.0;
      for (int c = 0; c < 3; c++)
        dst[3 * x + c] = px[3] ? (float)((px[c] + 0.5) * scale) : 0.0f;
    }
  }
  free(row);
  free(bytes);
  if (error) {
    fprintf(stderr, "imgcmp: %s: %s\n", path, error);
    zr_image_free(*out);
    *out = NULL;
    return -1;
  }
  return 0;
}

/* Any image imgcmp reads: Radiance pictures here, the rest by the library. */
static int read_image(zr_context *ctx, const char *path, zr_image **out) {
  if (is_rgbe(path))
    return read_rgbe(path, out);
  return zr_image_read(ctx, path, out) == ZR_OK ? 0 : -1;
}

/* Prints the figures of --info. */
static void print_info(const zr_image *img) {
  size_t n = (size_t)zr_image_width(img) * (size_t)zr_image_height(img) * 3;
  const float *v = zr_image_pixels_const(img);
  double sum = 0.0, clipped = 0.0, max = -INFINITY;
  for (size_t k = 0; k < n; k++) {
    sum += v[k];
    clipped += clip01(v[k]);
    if (v[k] > max)
      max = v[k];
  }
  printf("width=%d height=%d mean=%.6f clipped_mean=%.6f max=%.6f\n",
         zr_image_width(img), zr_image_height(img), sum / (double)n,
         clipped / (double)n, max);
}

static int parse_number(const char *text, double *out) {
  char *end;
  *out = strtod(text, &end);
  return *text && !*end && isfinite(*out);
}

int main(int argc, char **argv) {
  const char *files[2] = {NULL, NULL};
  int n_files = 0, rmse_mode = 0, info_mode = 0;
  double ssim_min = 0.98, rmse_max = INFINITY, delta_max = INFINITY;
  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "--rmse")) {
      rmse_mode = 1;
    } else if (!strcmp(argv[i], "--info")) {
      info_mode = 1;
    } else if (!strcmp(argv[i], "--ssim-min") && i + 1 < argc) {
      if (!parse_number(argv[++i], &ssim_min))
        return usage_error();
    } else if (!strcmp(argv[i], "--delta-max") && i + 1 < argc) {
      if (!parse_number(argv[++i], &delta_max))
        return usage_error();
    } else if (!strcmp(argv[i], "--rmse-max") && i + 1 < argc) {
      rmse_mode = 1;
      if (!parse_number(argv[++i], &rmse_max))
        return usage_error();
    } else if (!strcmp(argv[i], "-h") || !strcmp(argv[i], "--help")) {
      usage();
      return 0;
    } else if (argv[i][0] == '-' && argv[i][1]) {
      fprintf(stderr, "imgcmp: unknown option '%s'\n", argv[i]);
      return usage_error();
    } else if (n_files < 2) {
      files[n_files++] = argv[i];
    } else {
      return usage_error();
    }
  }
  if (info_mode ? n_files != 1 || rmse_mode : n_files != 2)
    return usage_error();

  zr_context *ctx;
  if (zr_context_new(&ctx) != ZR_OK)
    return 2;
  zr_context_set_diag(ctx, print_diag, NULL);
  zr_image *img[2] = {NULL, NULL};
  int rc = 2;
  if (info_mode) {
    if (read_image(ctx, files[0], &img[0]) == 0) {
      print_info(img[0]);
      rc = 0;
    }
    goto done;
  }
  if (read_image(ctx, files[0], &img[0]) ||
      read_image(ctx, files[1], &img[1]))
    goto done;
  if (zr_image_width(img[0]) != zr_image_width(img[1]) ||
      zr_image_height(img[0]) != zr_image_height(img[1])) {
    fprintf(stderr, "imgcmp: sizes differ: %s is %dx%d, %s is %dx%d\n",
            files[0], zr_image_width(img[0]), zr_image_height(img[0]),
            files[1], zr_image_width(img[1]), zr_image_height(img[1]));
    goto done;
  }
  if (zr_image_width(img[0]) < 2 || zr_image_height(img[0]) < 2) {
    fprintf(stderr, "imgcmp: images must be at least 2x2\n");
    goto done;
  }
  if (rmse_mode) {
    double e = compare_rmse(img[0], img[1]);
    printf("rmse=%.4f\n", e);
    rc = e <= rmse_max ? 0 : 1;
  } else {
    double s = compare_ssim(img[0], img[1]);
    double d = compare_delta(img[0], img[1]);
    printf("ssim=%.4f delta=%.4f\n", s, d);
    rc = s >= ssim_min && d <= delta_max ? 0 : 1;
  }
done:
  zr_image_free(img[0]);
  zr_image_free(img[1]);
  zr_context_free(ctx);
  return rc;
}
