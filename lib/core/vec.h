/*
 * vec.h - three-component vectors and colours, as static inline functions.
 *
 * Everything geometric in zRcube is double precision: POV-Ray scenes mix
 * scales from 1e-3 to 1e5 and the tracer's epsilons assume doubles.
 * Coordinates follow POV-Ray: left-handed, y up, the camera looking along
 * +z by default.
 */
#ifndef ZR_CORE_VEC_H
#define ZR_CORE_VEC_H

#include <math.h>

typedef struct zr_vec3 {
  double x, y, z;
} zr_vec3;

/* A POV-Ray colour: red, green, blue, filter, transmit. */
typedef struct zr_colour {
  double r, g, b, f, t;
} zr_colour;

/* An RGB triple for light and radiance, where filter/transmit mean nothing. */
typedef struct zr_rgb {
  double r, g, b;
} zr_rgb;

/*
 * fmin and fmax without the call: glibc's are functions in libm (gcc
 * inlines them only under -ffinite-math-only), and the prism, CSG and
 * box code calls them for every piece of every object a ray passes
 * (7% of the corpus' aug10-2.pov in calls alone).  The same answers:
 * the smaller (larger) of two numbers, the other when one is a NaN,
 * and for equal ones (+0 and -0) the second, as glibc's minsd/maxsd
 * give it (tests/test_core.c compares them with libm's on every pair of
 * a set of special values).
 */
static inline double zr_min(double a, double b) {
  return a < b ? a : b != b ? a : b;
}
static inline double zr_max(double a, double b) {
  return a > b ? a : b != b ? a : b;
}

static inline zr_vec3 zr_v3(double x, double y, double z) {
  zr_vec3 v = {x, y, z};
  return v;
}
static inline zr_vec3 zr_v3_add(zr_vec3 a, zr_vec3 b) {
  return zr_v3(a.x + b.x, a.y + b.y, a.z + b.z);
}
static inline zr_vec3 zr_v3_sub(zr_vec3 a, zr_vec3 b) {
  return zr_v3(a.x - b.x, a.y - b.y, a.z - b.z);
}
static inline zr_vec3 zr_v3_mul(zr_vec3 a, zr_vec3 b) {
  return zr_v3(a.x * b.x, a.y * b.y, a.z * b.z);
}
static inline zr_vec3 zr_v3_scale(zr_vec3 a, double s) {
  return zr_v3(a.x * s, a.y * s, a.z * s);
}
/* a + b * s, the ray-point form. */
static inline zr_vec3 zr_v3_madd(zr_vec3 a, zr_vec3 b, double s) {
  return zr_v3(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s);
}
static inline zr_vec3 zr_v3_neg(zr_vec3 a) { return zr_v3(-a.x, -a.y, -a.z); }
static inline double zr_v3_dot(zr_vec3 a, zr_vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
static inline zr_vec3 zr_v3_cross(zr_vec3 a, zr_vec3 b) {
  return zr_v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
               a.x * b.y - a.y * b.x);
}
static inline double zr_v3_len(zr_vec3 a) { return sqrt(zr_v3_dot(a, a)); }
/* Two unit vectors making an orthonormal frame with unit n (the branch-
   free construction of Duff et al., "Building an Orthonormal Basis,
   Revisited", JCGT 2017). */
static inline void zr_v3_frame(zr_vec3 n, zr_vec3 *t1, zr_vec3 *t2) {
  double sign = copysign(1.0, n.z);
  double a = -1.0 / (sign + n.z);
  double b = n.x * n.y * a;
  *t1 = (zr_vec3){1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
  *t2 = (zr_vec3){b, sign + n.y * n.y * a, -n.y};
}
/* The unit vector along a; a zero vector stays zero rather than NaN. */
static inline zr_vec3 zr_v3_norm(zr_vec3 a) {
  double l = zr_v3_len(a);
  return l > 0.0 ? zr_v3_scale(a, 1.0 / l) : a;
}
static inline double zr_v3_min_comp(zr_vec3 a) {
  return zr_min(a.x, zr_min(a.y, a.z));
}
static inline double zr_v3_max_comp(zr_vec3 a) {
  return zr_max(a.x, zr_max(a.y, a.z));
}
static inline zr_vec3 zr_v3_min(zr_vec3 a, zr_vec3 b) {
  return zr_v3(zr_min(a.x, b.x), zr_min(a.y, b.y), zr_min(a.z, b.z));
}
static inline zr_vec3 zr_v3_max(zr_vec3 a, zr_vec3 b) {
  return zr_v3(zr_max(a.x, b.x), zr_max(a.y, b.y), zr_max(a.z, b.z));
}
static inline double zr_v3_get(zr_vec3 a, int axis) {
  return axis == 0 ? a.x : axis == 1 ? a.y : a.z;
}

static inline zr_rgb zr_rgb3(double r, double g, double b) {
  zr_rgb c = {r, g, b};
  return c;
}
static inline zr_rgb zr_rgb_add(zr_rgb a, zr_rgb b) {
  return zr_rgb3(a.r + b.r, a.g + b.g, a.b + b.b);
}
static inline zr_rgb zr_rgb_mul(zr_rgb a, zr_rgb b) {
  return zr_rgb3(a.r * b.r, a.g * b.g, a.b * b.b);
}
static inline zr_rgb zr_rgb_scale(zr_rgb a, double s) {
  return zr_rgb3(a.r * s, a.g * s, a.b * s);
}
static inline zr_rgb zr_rgb_madd(zr_rgb a, zr_rgb b, double s) {
  return zr_rgb3(a.r + b.r * s, a.g + b.g * s, a.b + b.b * s);
}
static inline zr_rgb zr_colour_rgb(zr_colour c) {
  return zr_rgb3(c.r, c.g, c.b);
}
static inline zr_colour zr_colour5(double r, double g, double b, double f,
                                   double t) {
  zr_colour c = {r, g, b, f, t};
  return c;
}

#endif /* ZR_CORE_VEC_H */
