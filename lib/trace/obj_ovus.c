/*
 * obj_ovus.c - the ovus (POV-Ray 3.7 reference, "Ovus"): an egg made of
 * the lower part of a bottom sphere (radius a, at the origin), the upper
 * part of a top sphere (radius b, centred on the bottom sphere's top,
 * <0, a, 0>), and between them a lemon, a spindle torus's inner sheet,
 * tangent to both.  lib/sdl/build_iso.c finds the lemon's circle.
 *
 * The lemon is the circle of radius R about (r, y) = (-c, h) in the
 * half-plane of the y axis, turned about it: with y' = y - h its torus
 * (x^2 + y'^2 + z^2 + c^2 - R^2)^2 = 4 c^2 (x^2 + z^2) is a quartic along
 * a ray (built around the start of the ray's stretch in the bounding
 * box, so its coefficients keep the size of the shape), solved by
 * lib/trace/roots.c.  Of its roots only those of the inner sheet,
 * (r + c)^2 + y'^2 = R^2, between the two tangent heights y0 and y1
 * belong to the ovus; the spheres give theirs below y0 and above y1.
 */
#include "trace/obj_isosurface.h"

#include <math.h>

#include "trace/shape.h"

#include "trace/obj_shapes.h"
#include "trace/roots.h"

void zr__ovus_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  double a = o->u.ovus.bottom, b = o->u.ovus.top;
  double r = fmax(a, b);
  if (o->u.ovus.lemon_r > 0.0)
    r = fmax(r, o->u.ovus.lemon_r - o->u.ovus.lemon_c);
  double ylo = o->u.ovus.lemon_r > 0.0 ? -a : a - b;
  *lo = zr_v3(-r, ylo, -r);
  *hi = zr_v3(r, a + b, r);
}

/* Which piece of the surface holds height y: -1 bottom sphere, 0 lemon,
   1 top sphere. */
static int piece(const zr_object *o, double y) {
  if (!(o->u.ovus.lemon_r > 0.0) || y > o->u.ovus.y1)
    return 1;
  return y < o->u.ovus.y0 ? -1 : 0;
}

bool zr__ovus_inside(const zr_object *o, zr_vec3 p) {
  double a = o->u.ovus.bottom, b = o->u.ovus.top;
  switch (piece(o, p.y)) {
  case -1:
    return zr_v3_dot(p, p) < a * a;
  case 1: {
    zr_vec3 d = zr_v3(p.x, p.y - a, p.z);
    return zr_v3_dot(d, d) < b * b;
  }
  default: {
    double yh = p.y - o->u.ovus.lemon_h, rr = o->u.ovus.lemon_r;
    double w = rr * rr - yh * yh;
    return w > 0.0 &&
           sqrt(p.x * p.x + p.z * p.z) < sqrt(w) - o->u.ovus.lemon_c;
  }
  }
}

/* A small sorted list of crossings. */
typedef struct hits {
  int n;
  double t[8];
  zr_vec3 normal[8];
} hits;

static void add(hits *h, double t, zr_vec3 n) {
  if (h->n == 8)
    return;
  int j = h->n++;
  while (j > 0 && h->t[j - 1] > t) {
    h->t[j] = h->t[j - 1];
    h->normal[j] = h->normal[j - 1];
    j--;
  }
  h->t[j] = t;
  h->normal[j] = n;
}

/* The sphere's crossings that lie on the ovus piece `which`. */
static void sphere_part(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                        double cy, double r, int which, hits *h) {
  zr_vec3 oc = zr_v3(org.x, org.y - cy, org.z);
  double qa = zr_v3_dot(dir, dir), qb = 2.0 * zr_v3_dot(dir, oc);
  double qc = zr_v3_dot(oc, oc) - r * r;
  double disc = qb * qb - 4.0 * qa * qc;
  if (!(disc > 0.0))
    return;
  double q = -0.5 * (qb + copysign(sqrt(disc), qb));
  double t[2] = {q / qa, q != 0.0 ? qc / q : q / qa};
  for (int i = 0; i < 2; i++) {
    zr_vec3 p = zr_v3_madd(org, dir, t[i]);
    if (piece(o, p.y) == which)
      add(h, t[i], zr_v3(p.x, p.y - cy, p.z));
  }
}

static void lemon_part(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                       hits *h) {
  zr_vec3 lo, hi;
  zr__ovus_bounds(o, &lo, &hi);
  double s0, s1;
  if (!zr__ray_box_span(lo, hi, org, dir, &s0, &s1))
    return;
  double R = o->u.ovus.lemon_r, c = o->u.ovus.lemon_c;
  double hh = o->u.ovus.lemon_h;
  /* The ray from the start of its stretch in the box, y shifted to the
     lemon's centre. */
  zr_vec3 s = zr_v3_madd(org, dir, s0);
  zr_vec3 p0 = zr_v3(s.x, s.y - hh, s.z);
  double A = zr_v3_dot(dir, dir), B = 2.0 * zr_v3_dot(p0, dir);
  double C = zr_v3_dot(p0, p0) + c * c - R * R;
  double a2 = dir.x * dir.x + dir.z * dir.z;
  double a1 = 2.0 * (p0.x * dir.x + p0.z * dir.z);
  double a0 = p0.x * p0.x + p0.z * p0.z;
  double k = 4.0 * c * c;
  double poly[5] = {C * C - k * a0, 2.0 * B * C - k * a1,
                    B * B + 2.0 * A * C - k * a2, 2.0 * A * B, A * A};
  double u[4];
  int n = zr__poly_roots(poly, 4, 0.0, s1 - s0, u);
  for (int i = 0; i < n; i++) {
    double t = s0 + u[i];
    zr_vec3 p = zr_v3_madd(org, dir, t);
    if (piece(o, p.y) != 0)
      continue;
    double r = sqrt(p.x * p.x + p.z * p.z), yh = p.y - hh;
    double inner = (r + c) * (r + c) + yh * yh - R * R;
    double outer = (r - c) * (r - c) + yh * yh - R * R;
    if (fabs(inner) > fabs(outer) || !(r > 0.0))
      continue; /* the apple, the torus's outer sheet */
    double nr = (r + c) / r;
    add(h, t, zr_v3(p.x * nr, yh, p.z * nr));
  }
}

int zr__ovus_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                       double tmin, double tmax, double t[4],
                       zr_vec3 normal[4]) {
  hits h = {0, {0}, {{0, 0, 0}}};
  double a = o->u.ovus.bottom, b = o->u.ovus.top;
  sphere_part(o, org, dir, a, b, 1, &h);
  if (o->u.ovus.lemon_r > 0.0) {
    sphere_part(o, org, dir, 0.0, a, -1, &h);
    lemon_part(o, org, dir, &h);
  }
  int found = 0;
  for (int i = 0; i < h.n && found < 4; i++)
    if (h.t[i] > tmin && h.t[i] < tmax) {
      t[found] = h.t[i];
      normal[found] = h.normal[i];
      found++;
    }
  return found;
}

static bool ovus_box(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  zr__ovus_bounds(o, lo, hi);
  return true;
}

/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_ovus = {
    .name = "an ovus",
    .search = zr__ovus_crossings,
    .inside = zr__ovus_inside,
    .bounds = ovus_box,
};
