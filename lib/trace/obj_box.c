/*
 * obj_box.c - the box (POV-Ray 3.7 reference, "Box"): ray crossings by
 * the slab test, inside, box and POV-Ray's box map (u, v).
 */
#include "trace/shape.h"

#include <math.h>

/* Slab test: the entry and exit faces of an axis-aligned box. */
static void box_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                          double tmin, double tmax, zr_crossings *l) {
  (void)tmin;
  (void)tmax;
  zr_vec3 lo = zr_v3_min(o->u.box.corner1, o->u.box.corner2);
  zr_vec3 hi = zr_v3_max(o->u.box.corner1, o->u.box.corner2);
  double tnear = -INFINITY, tfar = INFINITY;
  int near_axis = -1, far_axis = -1;
  double near_sign = 0.0, far_sign = 0.0;
  for (int axis = 0; axis < 3; axis++) {
    double oa = zr_v3_get(org, axis), da = zr_v3_get(dir, axis);
    double la = zr_v3_get(lo, axis), ha = zr_v3_get(hi, axis);
    if (da == 0.0) {
      /* Parallel to this pair of faces: in the slab or a miss. */
      if (oa < la || oa > ha)
        return;
      continue;
    }
    double t0 = (la - oa) / da, t1 = (ha - oa) / da;
    double s0 = -1.0, s1 = 1.0;
    if (t0 > t1) {
      double tt = t0;
      t0 = t1;
      t1 = tt;
      s0 = 1.0;
      s1 = -1.0;
    }
    if (t0 > tnear) {
      tnear = t0;
      near_axis = axis;
      near_sign = s0;
    }
    if (t1 < tfar) {
      tfar = t1;
      far_axis = axis;
      far_sign = s1;
    }
  }
  /* A box flat along one axis is still hit, on its face: POV-Ray 3.7
     shows box { <0,0,0>, <1,1,0> } (tests/scenes/flat_box.pov). */
  if (!(tnear <= tfar) || near_axis < 0 || far_axis < 0)
    return;
  double n0[3] = {0, 0, 0}, n1[3] = {0, 0, 0};
  n0[near_axis] = near_sign;
  n1[far_axis] = far_sign;
  zr__crossings_add(l, tnear, zr_v3(n0[0], n0[1], n0[2]));
  zr__crossings_add(l, tfar, zr_v3(n1[0], n1[1], n1[2]));
}

/* The faces count as inside: POV-Ray 3.7 keeps the shared face of two
   boxes in an intersection and drops it from a difference (measured:
   tests/legacy/csg_shared_face.pov). */
static bool box_inside(const zr_object *o, zr_vec3 p) {
  zr_vec3 lo = zr_v3_min(o->u.box.corner1, o->u.box.corner2);
  zr_vec3 hi = zr_v3_max(o->u.box.corner1, o->u.box.corner2);
  return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y &&
         p.z >= lo.z && p.z <= hi.z;
}

static bool box_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  *lo = zr_v3_min(o->u.box.corner1, o->u.box.corner2);
  *hi = zr_v3_max(o->u.box.corner1, o->u.box.corner2);
  return true;
}

/* POV-Ray 3.7's box map ("UV Mapping", the UV Boxmap figure): the faces
   unfolded as a cross over u in [0, 1], v in [0, 1] (min x, max z, max
   x, min z in the middle row; min y below and max y above max z).  The
   face is the one the object-space point p lies nearest. */
static void box_uv(const zr_object *o, zr_vec3 p, double *u, double *v) {
  zr_vec3 a = o->u.box.corner1, b = o->u.box.corner2;
  zr_vec3 lo = zr_v3(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z));
  zr_vec3 hi = zr_v3(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z));
  double d[6] = {fabs(p.x - lo.x), fabs(p.x - hi.x), fabs(p.y - lo.y),
                 fabs(p.y - hi.y), fabs(p.z - lo.z), fabs(p.z - hi.z)};
  int face = 0;
  for (int k = 1; k < 6; k++)
    if (d[k] < d[face])
      face = k;
  double x = (p.x - lo.x) / (hi.x - lo.x);
  double y = (p.y - lo.y) / (hi.y - lo.y);
  double z = (p.z - lo.z) / (hi.z - lo.z);
  switch (face) {
  case 0: /* min x */
    *u = z / 4.0;
    *v = 1.0 / 3.0 + y / 3.0;
    break;
  case 1: /* max x */
    *u = 3.0 / 4.0 - z / 4.0;
    *v = 1.0 / 3.0 + y / 3.0;
    break;
  case 2: /* min y */
    *u = 1.0 / 4.0 + x / 4.0;
    *v = z / 3.0;
    break;
  case 3: /* max y */
    *u = 1.0 / 4.0 + x / 4.0;
    *v = 1.0 - z / 3.0;
    break;
  case 4: /* min z */
    *u = 1.0 - x / 4.0;
    *v = 1.0 / 3.0 + y / 3.0;
    break;
  default: /* max z */
    *u = 1.0 / 4.0 + x / 4.0;
    *v = 1.0 / 3.0 + y / 3.0;
    break;
  }
}

const zr_shape_ops zr__shape_box = {
    .name = "a box",
    .crossings = box_crossings,
    .interval_free = true,
    .inside = box_inside,
    .bounds = box_bounds,
    .uv = box_uv,
};
