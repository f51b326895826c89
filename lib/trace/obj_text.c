/*
 * obj_text.c - rays against POV-Ray's text object (reference manual,
 * "Text"): glyph outlines in the x-y plane extruded from z = 0 to
 * z = thickness, traced exactly rather than cut into triangles.
 *
 * A ray meets an extruded glyph in two kinds of places.  On a cap (the
 * planes z = 0 and z = thickness) the crossing counts when its (x, y)
 * lies inside the outline, by the non-zero winding rule TrueType fills
 * with: the signed number of times the outline crosses a half-line from
 * the point towards +x.  On a side wall the ray's projection onto the
 * x-y plane meets a piece of the outline: a line, solved as two lines
 * meet, or a quadratic Bezier curve B(s), where the condition
 * cross(d, B(s) - o) = 0 is a quadratic in s; the crossing counts when
 * 0 <= s <= 1 and its z lies between the caps.  The wall's normal is the
 * curve's tangent turned a quarter to the right: TrueType draws outer
 * contours clockwise, so that points out of the glyph.
 *
 * Each glyph keeps a 2-D box, and a ray only looks at the glyphs whose
 * boxes (extruded) it passes through.
 */
#include "trace/obj_text.h"

#include <math.h>

#include "trace/shape.h"

/* Real roots of a s^2 + b s + c in r[], cancellation-free; a == 0 is
   the linear case.  Returns how many (0..2). */
static int roots(double a, double b, double c, double r[2]) {
  if (fabs(a) < 1e-12 * (fabs(b) + fabs(c))) {
    if (b == 0.0)
      return 0;
    r[0] = -c / b;
    return 1;
  }
  double disc = b * b - 4.0 * a * c;
  if (disc < 0.0)
    return 0;
  double q = -0.5 * (b + copysign(sqrt(disc), b));
  r[0] = q / a;
  if (q == 0.0)
    return 1;
  r[1] = c / q;
  return 2;
}

/* The curve, its derivative and its coefficients A s^2 + B s + C. */
static void coefficients(const zr_text_segment *sg, double A[2], double B[2],
                         double C[2]) {
  for (int i = 0; i < 2; i++) {
    if (sg->line) {
      A[i] = 0.0;
      B[i] = sg->p2[i] - sg->p0[i];
    } else {
      A[i] = sg->p0[i] - 2.0 * sg->p1[i] + sg->p2[i];
      B[i] = 2.0 * (sg->p1[i] - sg->p0[i]);
    }
    C[i] = sg->p0[i];
  }
}

/* The winding number of the glyph's outline around (x, y). */
static int winding(const struct zr_text *tx, const zr_text_glyph *g,
                   double x, double y) {
  int w = 0;
  for (size_t i = g->first; i < g->first + g->n; i++) {
    const zr_text_segment *sg = &tx->segments[i];
    double ylo = fmin(sg->p0[1], sg->p2[1]), yhi = fmax(sg->p0[1], sg->p2[1]);
    if (!sg->line) {
      ylo = fmin(ylo, sg->p1[1]);
      yhi = fmax(yhi, sg->p1[1]);
    }
    if (y < ylo || y > yhi)
      continue;
    double A[2], B[2], C[2], r[2];
    coefficients(sg, A, B, C);
    int n = roots(A[1], B[1], C[1] - y, r);
    for (int k = 0; k < n; k++) {
      double s = r[k];
      /* Half open, so a point where two pieces meet counts once. */
      if (!(s >= 0.0 && s < 1.0))
        continue;
      double dy = 2.0 * A[1] * s + B[1];
      if (dy == 0.0)
        continue;
      if ((A[0] * s + B[0]) * s + C[0] > x)
        w += dy > 0.0 ? 1 : -1;
    }
  }
  return w;
}

/* The interval of t in which the ray is inside the box lo..hi. */
static bool box_span(const double lo[3], const double hi[3], zr_vec3 o,
                     zr_vec3 d, double *t0, double *t1) {
  double org[3] = {o.x, o.y, o.z}, dir[3] = {d.x, d.y, d.z};
  for (int a = 0; a < 3; a++) {
    if (dir[a] == 0.0) {
      if (org[a] < lo[a] || org[a] > hi[a])
        return false;
      continue;
    }
    double ta = (lo[a] - org[a]) / dir[a], tb = (hi[a] - org[a]) / dir[a];
    if (ta > tb) {
      double t = ta;
      ta = tb;
      tb = t;
    }
    *t0 = fmax(*t0, ta);
    *t1 = fmin(*t1, tb);
  }
  return *t0 <= *t1;
}

typedef struct nearest2 {
  int n;
  zr_mesh_crossing c[2];
  double limit;
} nearest2;

static void keep(nearest2 *k, double t, zr_vec3 normal) {
  if (!(t < k->limit))
    return;
  zr_mesh_crossing c = {t, normal, -1, 0.0, 0.0, 0};
  if (k->n < 2) {
    k->c[k->n++] = c;
  } else {
    k->c[1] = c;
  }
  if (k->n == 2 && k->c[1].t < k->c[0].t) {
    zr_mesh_crossing s = k->c[0];
    k->c[0] = k->c[1];
    k->c[1] = s;
  }
  if (k->n == 2)
    k->limit = k->c[1].t;
}

static void glyph_crossings(const struct zr_text *tx, const zr_text_glyph *g,
                            zr_vec3 o, zr_vec3 d, double tmin,
                            nearest2 *k) {
  double th = tx->thickness;
  double lo[3] = {g->lo[0], g->lo[1], 0.0}, hi[3] = {g->hi[0], g->hi[1], th};
  double t0 = tmin, t1 = k->limit;
  if (!box_span(lo, hi, o, d, &t0, &t1))
    return;
  /* The caps. */
  if (d.z != 0.0) {
    for (int cap = 0; cap < 2; cap++) {
      double z = cap ? th : 0.0;
      double t = (z - o.z) / d.z;
      if (!(t > tmin && t < k->limit))
        continue;
      double x = o.x + t * d.x, y = o.y + t * d.y;
      if (x < g->lo[0] || x > g->hi[0] || y < g->lo[1] || y > g->hi[1])
        continue;
      if (winding(tx, g, x, y) != 0)
        keep(k, t, zr_v3(0, 0, cap ? 1.0 : -1.0));
    }
  }
  /* The walls. */
  double dd = d.x * d.x + d.y * d.y;
  if (!(dd > 0.0))
    return;
  for (size_t i = g->first; i < g->first + g->n; i++) {
    const zr_text_segment *sg = &tx->segments[i];
    double A[2], B[2], C[2], r[2];
    coefficients(sg, A, B, C);
    /* cross(d, P(s) - o) = 0. */
    double a = d.x * A[1] - d.y * A[0];
    double b = d.x * B[1] - d.y * B[0];
    double c = d.x * (C[1] - o.y) - d.y * (C[0] - o.x);
    int n = roots(a, b, c, r);
    for (int j = 0; j < n; j++) {
      double s = r[j];
      if (!(s >= 0.0 && s <= 1.0))
        continue;
      double px = (A[0] * s + B[0]) * s + C[0];
      double py = (A[1] * s + B[1]) * s + C[1];
      double t = ((px - o.x) * d.x + (py - o.y) * d.y) / dd;
      if (!(t > tmin && t < k->limit))
        continue;
      double z = o.z + t * d.z;
      if (z < 0.0 || z > th)
        continue;
      double tx_ = 2.0 * A[0] * s + B[0], ty = 2.0 * A[1] * s + B[1];
      if (tx_ == 0.0 && ty == 0.0)
        continue;
      keep(k, t, zr_v3(-ty, tx_, 0.0));
    }
  }
}

int zr__text_crossings(const struct zr_text *tx, zr_vec3 org, zr_vec3 dir,
                       double tmin, double tmax, zr_mesh_crossing out[2]) {
  if (tx->n_glyphs == 0)
    return 0;
  double lo[3] = {tx->lo.x, tx->lo.y, tx->lo.z};
  double hi[3] = {tx->hi.x, tx->hi.y, tx->hi.z};
  double t0 = tmin, t1 = tmax;
  if (!box_span(lo, hi, org, dir, &t0, &t1))
    return 0;
  nearest2 k;
  k.n = 0;
  k.limit = tmax;
  for (size_t i = 0; i < tx->n_glyphs; i++)
    glyph_crossings(tx, &tx->glyphs[i], org, dir, tmin, &k);
  for (int i = 0; i < k.n; i++)
    out[i] = k.c[i];
  return k.n;
}

bool zr__text_inside(const struct zr_text *tx, zr_vec3 p) {
  if (!(p.z > 0.0 && p.z < tx->thickness))
    return false;
  for (size_t i = 0; i < tx->n_glyphs; i++) {
    const zr_text_glyph *g = &tx->glyphs[i];
    if (p.x < g->lo[0] || p.x > g->hi[0] || p.y < g->lo[1] ||
        p.y > g->hi[1])
      continue;
    if (winding(tx, g, p.x, p.y) != 0)
      return true;
  }
  return false;
}

/* Text holds many surfaces, so it searches the interval itself and
   gives the nearest two crossings in it. */
static void text_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                           double tmin, double tmax, zr_crossings *l) {
  zr_mesh_crossing c[2];
  int n = zr__text_crossings(o->u.text.data, org, dir, tmin, tmax, c);
  for (int i = 0; i < n; i++) {
    zr__crossings_add(l, c[i].t, c[i].normal);
    l->texture[l->n - 1] = c[i].texture;
  }
}

static bool text_inside(const zr_object *o, zr_vec3 p) {
  return zr__text_inside(o->u.text.data, p);
}

/* The box of every glyph; none without glyphs. */
static bool text_box(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  *lo = o->u.text.data->lo;
  *hi = o->u.text.data->hi;
  return o->u.text.data->n_glyphs > 0;
}

/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_text = {
    .name = "a text",
    .crossings = text_crossings,
    .inside = text_inside,
    .bounds = text_box,
};
