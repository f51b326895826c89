/*
 * obj_quadric.c - POV-Ray's quadric object (reference manual r3_4,
 * "Quadric"): the points where
 *   Q(x,y,z) = A x^2 + B y^2 + C z^2 + D xy + E xz + F yz
 *              + G x + H y + I z + J
 * is zero, inside where it is negative.  shapes.inc builds its infinite
 * cylinders, cones, paraboloids and hyperboloids from it, usually
 * intersected with a box to make them finite.
 *
 * Along a ray p = o + t d, Q is a quadratic in t whose coefficients come
 * from the symmetric matrix form Q(p) = p'Mp + 2 b'p + J:
 *   a = d'Md,  b = 2 (o'Md + b'd),  c = Q(o).
 * It is solved with the cancellation-free form of the quadratic formula
 * (see intersect.c); when a is zero (a ray along a cylinder's axis, or
 * parallel to a paraboloid's) the equation is linear and has one root.
 * The outward normal is the gradient of Q.  A quadric is unbounded.
 */
#include "trace/obj_quadric.h"

#include <math.h>

#include "trace/shape.h"

static double value(const double q[10], zr_vec3 p) {
  return q[0] * p.x * p.x + q[1] * p.y * p.y + q[2] * p.z * p.z +
         q[3] * p.x * p.y + q[4] * p.x * p.z + q[5] * p.y * p.z +
         q[6] * p.x + q[7] * p.y + q[8] * p.z + q[9];
}

static zr_vec3 gradient(const double q[10], zr_vec3 p) {
  return zr_v3(2.0 * q[0] * p.x + q[3] * p.y + q[4] * p.z + q[6],
               2.0 * q[1] * p.y + q[3] * p.x + q[5] * p.z + q[7],
               2.0 * q[2] * p.z + q[4] * p.x + q[5] * p.y + q[8]);
}

int zr__quadric_crossings(const double q[10], zr_vec3 o, zr_vec3 d,
                          double t[2], zr_vec3 n[2]) {
  double a = q[0] * d.x * d.x + q[1] * d.y * d.y + q[2] * d.z * d.z +
             q[3] * d.x * d.y + q[4] * d.x * d.z + q[5] * d.y * d.z;
  /* The linear coefficient is the gradient at o along d. */
  double b = zr_v3_dot(gradient(q, o), d);
  double c = value(q, o);
  int k = 0;
  if (a == 0.0) {
    if (b == 0.0)
      return 0;
    t[k++] = -c / b;
  } else {
    double disc = b * b - 4.0 * a * c;
    if (!(disc > 0.0))
      return 0; /* a miss, or a graze */
    double h = -0.5 * (b + copysign(sqrt(disc), b));
    double r0 = h / a, r1 = h != 0.0 ? c / h : r0;
    t[k++] = fmin(r0, r1);
    t[k++] = fmax(r0, r1);
  }
  for (int i = 0; i < k; i++)
    n[i] = gradient(q, zr_v3_madd(o, d, t[i]));
  return k;
}

bool zr__quadric_inside(const double q[10], zr_vec3 p) {
  return value(q, p) < 0.0;
}

static void quadric_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                              double tmin, double tmax, zr_crossings *l) {
  (void)tmin;
  (void)tmax;
  double t[2];
  zr_vec3 n[2];
  int k = zr__quadric_crossings(o->u.quadric.coef, org, dir, t, n);
  for (int i = 0; i < k; i++)
    zr__crossings_add(l, t[i], n[i]);
}

static bool quadric_inside(const zr_object *o, zr_vec3 p) {
  return zr__quadric_inside(o->u.quadric.coef, p);
}

/* No box: a quadric is infinite unless clipped or intersected. */
/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_quadric = {
    .name = "a quadric",
    .crossings = quadric_crossings,
    .interval_free = true,
    .inside = quadric_inside,
};
