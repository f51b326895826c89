/*
 * ttf.c - a small TrueType reader for the text object.
 *
 * Follows Apple's TrueType Reference Manual and the OpenType
 * specification's chapters on the tables it reads: the table directory
 * (and a collection's first font, as POV-Ray's "Text" section says),
 * head (units per em, loca format), maxp (glyph count), hhea and hmtx
 * (advance widths), cmap format 4 (the Windows Unicode or symbol map),
 * loca and glyf (simple glyphs: on- and off-curve points of quadratic
 * B-splines; composite glyphs: components placed by offsets and an
 * optional 2x2 scale), and kern format 0 (horizontal pairs).  Hinting
 * instructions are skipped: the outlines are used at their design size.
 *
 * Fonts come from scene files, so every read is bounds-checked against
 * the file's size and a broken file gives a message, never a crash or a
 * read outside it.
 */
#include "scene/ttf.h"

#include <stdlib.h>
#include <string.h>

enum { COMPOSITE_DEPTH_MAX = 8, CONTOUR_POINTS_MAX = 65535 };

static unsigned u16(const uint8_t *p) { return (unsigned)p[0] << 8 | p[1]; }
static int s16(const uint8_t *p) { return (int16_t)u16(p); }
static uint32_t u32(const uint8_t *p) {
  return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 |
         p[3];
}

/* Whether [off, off + len) lies inside a table of size size. */
static bool fits(size_t size, size_t off, size_t len) {
  return off <= size && len <= size - off;
}

static bool find_table(const zr_ttf *f, size_t dir, const char *tag,
                       size_t *off, size_t *len) {
  unsigned n = u16(f->data + dir + 4);
  for (unsigned i = 0; i < n; i++) {
    const uint8_t *rec = f->data + dir + 12 + 16 * (size_t)i;
    if (memcmp(rec, tag, 4) == 0) {
      *off = u32(rec + 8);
      *len = u32(rec + 12);
      return fits(f->size, *off, *len);
    }
  }
  return false;
}

/* Picks the cmap subtable: Windows Unicode BMP, else Windows symbol,
   else Unicode platform, all in format 4. */
static const char *open_cmap(zr_ttf *f, size_t off, size_t len) {
  if (len < 4)
    return "its cmap table is truncated";
  unsigned n = u16(f->data + off + 2);
  if (!fits(len, 4, 8 * (size_t)n))
    return "its cmap table is truncated";
  int best = -1;
  for (unsigned i = 0; i < n; i++) {
    const uint8_t *rec = f->data + off + 4 + 8 * (size_t)i;
    unsigned platform = u16(rec), encoding = u16(rec + 2);
    size_t sub = u32(rec + 4);
    if (!fits(len, sub, 4) || u16(f->data + off + sub) != 4)
      continue;
    int rank = platform == 3 && encoding == 1   ? 3
               : platform == 3 && encoding == 0 ? 2
               : platform == 0                  ? 1
                                                : -1;
    if (rank > best) {
      size_t sublen = u16(f->data + off + sub + 2);
      if (!fits(len, sub, sublen) || sublen < 16)
        return "its cmap format 4 subtable is truncated";
      best = rank;
      f->cmap4 = off + sub;
      f->cmap4_len = sublen;
      f->symbol = rank == 2;
    }
  }
  if (best < 0)
    return "it has no cmap format 4 character map";
  size_t seg2 = u16(f->data + f->cmap4 + 6);
  if (seg2 % 2 || !fits(f->cmap4_len, 16, 4 * seg2))
    return "its cmap format 4 subtable is truncated";
  return NULL;
}

static void open_kern(zr_ttf *f, size_t off, size_t len) {
  if (len < 4 || u16(f->data + off) != 0)
    return;
  unsigned n = u16(f->data + off + 2);
  size_t at = off + 4;
  for (unsigned i = 0; i < n && fits(off + len, at, 14); i++) {
    size_t sublen = u16(f->data + at + 2);
    unsigned coverage = u16(f->data + at + 4);
    /* Format 0, horizontal, not minimum or cross-stream values. */
    if ((coverage >> 8) == 0 && (coverage & 0x7) == 1) {
      size_t pairs = u16(f->data + at + 6);
      if (fits(f->size, at + 14, 6 * pairs)) {
        f->kern = at + 14;
        f->kern_len = pairs;
      }
      return;
    }
    if (sublen < 6)
      return;
    at += sublen;
  }
}

const char *zr__ttf_open(zr_ttf *f, const uint8_t *data, size_t size) {
  memset(f, 0, sizeof *f);
  f->data = data;
  f->size = size;
  if (size < 12)
    return "it is too short to be a TrueType font";
  size_t dir = 0;
  if (memcmp(data, "ttcf", 4) == 0) {
    if (size < 16)
      return "its collection header is truncated";
    dir = u32(data + 12);
    if (!fits(size, dir, 12))
      return "its collection header points outside the file";
  }
  uint32_t version = u32(data + dir);
  if (version != 0x00010000 && memcmp(data + dir, "true", 4) != 0)
    return "it is not a TrueType font";
  if (!fits(size, dir + 12, 16 * (size_t)u16(data + dir + 4)))
    return "its table directory is truncated";
  size_t off, len;
  if (!find_table(f, dir, "head", &off, &len) || len < 54)
    return "its head table is missing or truncated";
  f->units_per_em = u16(data + off + 18);
  f->loca_long = s16(data + off + 50) != 0;
  if (f->units_per_em == 0)
    return "its head table gives zero units per em";
  if (!find_table(f, dir, "maxp", &off, &len) || len < 6)
    return "its maxp table is missing or truncated";
  f->n_glyphs = u16(data + off + 4);
  if (!find_table(f, dir, "hhea", &off, &len) || len < 36)
    return "its hhea table is missing or truncated";
  f->n_hmetrics = u16(data + off + 34);
  if (!find_table(f, dir, "hmtx", &f->hmtx, &f->hmtx_len) ||
      f->n_hmetrics == 0 || f->hmtx_len < 4 * (size_t)f->n_hmetrics)
    return "its hmtx table is missing or truncated";
  if (!find_table(f, dir, "loca", &f->loca, &f->loca_len) ||
      f->loca_len < ((size_t)f->n_glyphs + 1) * (f->loca_long ? 4 : 2))
    return "its loca table is missing or truncated";
  if (!find_table(f, dir, "glyf", &f->glyf, &f->glyf_len))
    return "its glyf table is missing or truncated";
  if (!find_table(f, dir, "cmap", &off, &len))
    return "it has no cmap table";
  const char *err = open_cmap(f, off, len);
  if (err)
    return err;
  if (find_table(f, dir, "kern", &off, &len))
    open_kern(f, off, len);
  return NULL;
}

static unsigned cmap_lookup(const zr_ttf *f, uint32_t c) {
  if (c > 0xFFFF)
    return 0;
  const uint8_t *t = f->data + f->cmap4;
  size_t seg2 = u16(t + 6);
  const uint8_t *ends = t + 14, *starts = t + 16 + seg2;
  const uint8_t *deltas = starts + seg2, *ranges = deltas + seg2;
  for (size_t i = 0; i < seg2; i += 2) {
    unsigned end = u16(ends + i);
    if (end < c)
      continue;
    unsigned start = u16(starts + i);
    if (start > c)
      return 0;
    unsigned delta = u16(deltas + i), range = u16(ranges + i);
    if (range == 0)
      return (c + delta) & 0xFFFF;
    /* idRangeOffset counts from its own place in the subtable. */
    size_t at = (size_t)(ranges + i - t) + range + 2 * (size_t)(c - start);
    if (!fits(f->cmap4_len, at, 2))
      return 0;
    unsigned g = u16(t + at);
    return g ? (g + delta) & 0xFFFF : 0;
  }
  return 0;
}

unsigned zr__ttf_glyph(const zr_ttf *f, uint32_t code) {
  unsigned g = cmap_lookup(f, code);
  /* Symbol fonts put their characters at 0xF000 plus the code. */
  if (g == 0 && f->symbol && code < 0x100)
    g = cmap_lookup(f, 0xF000 | code);
  return g < f->n_glyphs ? g : 0;
}

int zr__ttf_advance(const zr_ttf *f, unsigned glyph) {
  unsigned i = glyph < f->n_hmetrics ? glyph : f->n_hmetrics - 1;
  return (int)u16(f->data + f->hmtx + 4 * (size_t)i);
}

int zr__ttf_kerning(const zr_ttf *f, unsigned left, unsigned right) {
  if (!f->kern)
    return 0;
  /* The specification asks for pairs sorted by (left, right), but
     fonts in the wild (POV-Ray's cyrvetic.ttf) break that, so every
     pair is looked at; a string lays out only a few glyphs. */
  uint32_t key = (uint32_t)left << 16 | right;
  for (size_t i = 0; i < f->kern_len; i++) {
    const uint8_t *pair = f->data + f->kern + 6 * i;
    if (u32(pair) == key)
      return s16(pair + 4);
  }
  return 0;
}

/* The glyph's data range; false when loca points outside glyf. */
static bool glyph_range(const zr_ttf *f, unsigned g, size_t *off,
                        size_t *len) {
  size_t a, b;
  if (f->loca_long) {
    a = u32(f->data + f->loca + 4 * (size_t)g);
    b = u32(f->data + f->loca + 4 * (size_t)g + 4);
  } else {
    a = 2 * (size_t)u16(f->data + f->loca + 2 * (size_t)g);
    b = 2 * (size_t)u16(f->data + f->loca + 2 * (size_t)g + 2);
  }
  if (b < a || !fits(f->glyf_len, a, b - a))
    return false;
  *off = f->glyf + a;
  *len = b - a;
  return true;
}

/* A 2x3 affine map from glyph to output units. */
typedef struct affine {
  double a, b, c, d, dx, dy;
} affine;

static void apply(const affine *m, double x, double y, double out[2]) {
  out[0] = m->a * x + m->c * y + m->dx;
  out[1] = m->b * x + m->d * y + m->dy;
}

typedef struct walker {
  zr_ttf_segment_fn segment;
  void *user;
  bool stopped;
} walker;

/* Emits one contour of points (x, y, on-curve) as lines and curves:
   two off-curve points in a row imply an on-curve one between them. */
static void emit_contour(walker *w, const double (*pt)[2], const bool *on,
                         size_t n) {
  if (n < 2)
    return;
  /* Start on an on-curve point, or at the midpoint of two off ones. */
  size_t first = 0;
  while (first < n && !on[first])
    first++;
  double start[2];
  size_t skip; /* points walked after the start */
  if (first < n) {
    start[0] = pt[first][0];
    start[1] = pt[first][1];
    skip = 1;
  } else {
    first = 0;
    start[0] = 0.5 * (pt[0][0] + pt[n - 1][0]);
    start[1] = 0.5 * (pt[0][1] + pt[n - 1][1]);
    skip = 0;
  }
  double cur[2] = {start[0], start[1]}, ctrl[2] = {0, 0};
  bool have_ctrl = false;
  size_t count = skip ? n - 1 : n;
  for (size_t k = 0; k < count && !w->stopped; k++) {
    size_t i = skip ? (first + 1 + k) % n : k;
    const double *q = pt[i];
    bool q_on = on[i];
    if (q_on) {
      bool ok = have_ctrl ? w->segment(w->user, cur, ctrl, q, false)
                          : (q[0] == cur[0] && q[1] == cur[1]) ||
                                w->segment(w->user, cur, cur, q, true);
      w->stopped = !ok;
      cur[0] = q[0];
      cur[1] = q[1];
      have_ctrl = false;
    } else {
      if (have_ctrl) {
        double mid[2] = {0.5 * (ctrl[0] + q[0]), 0.5 * (ctrl[1] + q[1])};
        w->stopped = !w->segment(w->user, cur, ctrl, mid, false);
        cur[0] = mid[0];
        cur[1] = mid[1];
      }
      ctrl[0] = q[0];
      ctrl[1] = q[1];
      have_ctrl = true;
    }
  }
  /* Close the contour at its start. */
  if (w->stopped)
    return;
  bool ok = have_ctrl ? w->segment(w->user, cur, ctrl, start, false)
                      : (start[0] == cur[0] && start[1] == cur[1]) ||
                            w->segment(w->user, cur, cur, start, true);
  w->stopped = !ok;
}

static const char *simple_glyph(walker *w, const zr_ttf *f, size_t off,
                                size_t len, int contours, const affine *m) {
  const uint8_t *g = f->data + off;
  size_t at = 10;
  if (!fits(len, at, 2 * (size_t)contours + 2))
    return "a glyph's contour list is truncated";
  unsigned n_points = contours ? u16(g + at + 2 * (contours - 1)) + 1 : 0;
  at += 2 * (size_t)contours;
  size_t instr = u16(g + at);
  at += 2 + instr;
  if (!fits(len, at, 0))
    return "a glyph's instructions are truncated";
  uint8_t *flags = malloc(n_points ? n_points : 1);
  double(*pt)[2] = malloc((n_points ? n_points : 1) * sizeof *pt);
  bool *on = malloc(n_points ? n_points : 1);
  const char *err = NULL;
  if (!flags || !pt || !on) {
    err = "out of memory";
    goto done;
  }
  for (unsigned i = 0; i < n_points;) {
    if (!fits(len, at, 1)) {
      err = "a glyph's flags are truncated";
      goto done;
    }
    uint8_t fl = g[at++];
    unsigned repeat = 0;
    if (fl & 8) {
      if (!fits(len, at, 1)) {
        err = "a glyph's flags are truncated";
        goto done;
      }
      repeat = g[at++];
    }
    for (unsigned r = 0; r <= repeat && i < n_points; r++)
      flags[i++] = fl;
  }
  for (int axis = 0; axis < 2; axis++) {
    uint8_t short_bit = axis ? 4 : 2, same_bit = axis ? 32 : 16;
    int v = 0;
    for (unsigned i = 0; i < n_points; i++) {
      if (flags[i] & short_bit) {
        if (!fits(len, at, 1)) {
          err = "a glyph's coordinates are truncated";
          goto done;
        }
        v += flags[i] & same_bit ? g[at] : -(int)g[at];
        at++;
      } else if (!(flags[i] & same_bit)) {
        if (!fits(len, at, 2)) {
          err = "a glyph's coordinates are truncated";
          goto done;
        }
        v += s16(g + at);
        at += 2;
      }
      pt[i][axis] = v;
    }
  }
  for (unsigned i = 0; i < n_points; i++) {
    double q[2];
    apply(m, pt[i][0], pt[i][1], q);
    pt[i][0] = q[0];
    pt[i][1] = q[1];
    on[i] = flags[i] & 1;
  }
  size_t begin = 0;
  for (int c = 0; c < contours && !w->stopped; c++) {
    size_t end = (size_t)u16(g + 10 + 2 * c) + 1;
    if (end < begin || end > n_points) {
      err = "a glyph's contour ends are out of order";
      goto done;
    }
    emit_contour(w, (const double(*)[2])(pt + begin), on + begin,
                 end - begin);
    begin = end;
  }
  if (w->stopped)
    err = "out of memory";
done:
  free(flags);
  free(pt);
  free(on);
  return err;
}

static const char *glyph_outline(walker *w, const zr_ttf *f, unsigned glyph,
                                 const affine *m, int depth);

static const char *composite_glyph(walker *w, const zr_ttf *f, size_t off,
                                   size_t len, const affine *m, int depth) {
  const uint8_t *g = f->data + off;
  size_t at = 10;
  unsigned flags;
  do {
    if (!fits(len, at, 4))
      return "a composite glyph is truncated";
    flags = u16(g + at);
    unsigned part = u16(g + at + 2);
    at += 4;
    size_t arg_size = flags & 1 ? 4 : 2;
    if (!fits(len, at, arg_size))
      return "a composite glyph is truncated";
    double dx, dy;
    if (flags & 1) {
      dx = s16(g + at);
      dy = s16(g + at + 2);
    } else {
      dx = (int8_t)g[at];
      dy = (int8_t)g[at + 1];
    }
    at += arg_size;
    if (!(flags & 2))
      return "a composite glyph places a part by matching points, which "
             "is not supported";
    affine part_m = {1, 0, 0, 1, dx, dy};
    size_t scale_size = flags & 8 ? 2 : flags & 0x40 ? 4 : flags & 0x80 ? 8
                                                                        : 0;
    if (!fits(len, at, scale_size))
      return "a composite glyph is truncated";
    if (flags & 8) {
      part_m.a = part_m.d = s16(g + at) / 16384.0;
    } else if (flags & 0x40) {
      part_m.a = s16(g + at) / 16384.0;
      part_m.d = s16(g + at + 2) / 16384.0;
    } else if (flags & 0x80) {
      part_m.a = s16(g + at) / 16384.0;
      part_m.b = s16(g + at + 2) / 16384.0;
      part_m.c = s16(g + at + 4) / 16384.0;
      part_m.d = s16(g + at + 6) / 16384.0;
    }
    at += scale_size;
    /* The part's map followed by the whole glyph's. */
    affine both = {
        m->a * part_m.a + m->c * part_m.b, m->b * part_m.a + m->d * part_m.b,
        m->a * part_m.c + m->c * part_m.d, m->b * part_m.c + m->d * part_m.d,
        m->a * dx + m->c * dy + m->dx,     m->b * dx + m->d * dy + m->dy};
    if (part >= f->n_glyphs)
      return "a composite glyph refers to a glyph the font lacks";
    const char *err = glyph_outline(w, f, part, &both, depth + 1);
    if (err)
      return err;
  } while (flags & 0x20);
  return NULL;
}

static const char *glyph_outline(walker *w, const zr_ttf *f, unsigned glyph,
                                 const affine *m, int depth) {
  if (depth > COMPOSITE_DEPTH_MAX)
    return "a composite glyph nests too deeply (does it contain itself?)";
  size_t off, len;
  if (glyph >= f->n_glyphs || !glyph_range(f, glyph, &off, &len))
    return "a glyph's loca entry points outside the glyf table";
  if (len == 0)
    return NULL; /* a blank glyph such as the space */
  if (len < 10)
    return "a glyph's header is truncated";
  int contours = s16(f->data + off);
  if (contours >= 0)
    return simple_glyph(w, f, off, len, contours, m);
  return composite_glyph(w, f, off, len, m, depth);
}

const char *zr__ttf_outline(const zr_ttf *f, unsigned glyph,
                            zr_ttf_segment_fn segment, void *user) {
  walker w = {segment, user, false};
  affine identity = {1, 0, 0, 1, 0, 0};
  return glyph_outline(&w, f, glyph, &identity, 0);
}
