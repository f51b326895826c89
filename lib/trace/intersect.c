/*
 * intersect.c - ray intersection and inside tests for POV-Ray's finite
 * primitives and the plane (POV-Ray 3.7 reference, "Finite Solid
 * Primitives", "Finite Patch Primitives" and "Infinite Solid
 * Primitives": sphere, box, cylinder, cone, disc, triangle, plane).
 *
 * A transformed object is intersected in its own coordinates: the ray is
 * mapped by the inverse matrix and its direction is NOT normalised, so
 * the parameter t found there is the same t along the world ray and needs
 * no conversion.  The object-space normal goes back to world space by the
 * inverse transpose (zr__xform_normal with the inverse).
 *
 * Quadrics (sphere, cylinder and cone sides) are solved with the
 * cancellation-free form of the quadratic formula, so a root next to the
 * ray origin (a secondary ray leaving the surface) is computed to full
 * relative precision and lands on the right side of the caller's offset.
 * Each shape collects its candidate crossings and keeps those inside the
 * interval, sorted; all shapes are convex or flat, so there are at most
 * two.
 */
#include "trace/intersect.h"

#include <math.h>

#include "trace/obj_isosurface.h"
#include "trace/obj_mesh.h"
#include "trace/obj_poly.h"
#include "trace/obj_quadric.h"
#include "trace/obj_shapes.h"
#include "trace/obj_sweep.h"
#include "trace/obj_text.h"

/* Crossings gathered for one shape before clipping to the interval. */
typedef struct crossing_list {
  int n;
  double t[4];
  zr_vec3 normal[4]; /* object space, any length */
  int32_t texture[4]; /* a mesh's texture list index, -1 for none */
  double u[4], v[4];  /* a mesh's surface coordinates (else unset) */
} crossing_list;

static void add_crossing(crossing_list *l, double t, zr_vec3 n) {
  if (l->n < 4 && isfinite(t)) {
    l->t[l->n] = t;
    l->normal[l->n] = n;
    l->texture[l->n] = -1;
    l->n++;
  }
}

/* Meshes and text hold many surfaces, so they search the interval
   themselves (lib/trace/obj_mesh.c, obj_text.c) and give the nearest
   two crossings in it. */
static void compound_crossings(const zr_object *o, zr_vec3 org,
                               zr_vec3 dir, double tmin, double tmax,
                               crossing_list *l) {
  zr_mesh_crossing c[2];
  int n = o->kind == ZR_OBJ_MESH
              ? zr__mesh_crossings(o->u.mesh.data, org, dir, tmin, tmax, c)
              : zr__text_crossings(o->u.text.data, org, dir, tmin, tmax, c);
  for (int i = 0; i < n; i++) {
    add_crossing(l, c[i].t, c[i].normal);
    l->texture[l->n - 1] = c[i].texture;
    if (o->kind == ZR_OBJ_MESH) {
      l->u[l->n - 1] = c[i].u;
      l->v[l->n - 1] = c[i].v;
    }
  }
}

/* Shapes whose crossings are searched for (lib/trace/obj_shapes.h) take
   the interval, so that a ray leaving such a shape does not spend its
   room on crossings behind it. */
static bool is_searched(zr_object_kind kind) {
  return kind == ZR_OBJ_SPHERE_SWEEP || kind == ZR_OBJ_JULIA ||
         kind == ZR_OBJ_TORUS || kind == ZR_OBJ_POLYGON ||
         kind == ZR_OBJ_SUPERELLIPSOID || kind == ZR_OBJ_PRISM ||
         kind == ZR_OBJ_LATHE || kind == ZR_OBJ_BLOB || kind == ZR_OBJ_SOR ||
         kind == ZR_OBJ_ISOSURFACE || kind == ZR_OBJ_HEIGHT_FIELD ||
         kind == ZR_OBJ_OVUS || kind == ZR_OBJ_PARAMETRIC;
}

static void searched_crossings(const zr_object *o, zr_vec3 org,
                               zr_vec3 dir, double tmin, double tmax,
                               crossing_list *l) {
  double t[ZR_SHAPE_MAX_CROSSINGS];
  zr_vec3 n[ZR_SHAPE_MAX_CROSSINGS];
  int k = 0;
  if (o->kind == ZR_OBJ_TORUS)
    k = zr__torus_crossings(o, org, dir, tmin, tmax, t, n);
  else if (o->kind == ZR_OBJ_SPHERE_SWEEP)
    k = zr__sweep_crossings(o, org, dir, tmin, tmax, t, n);
  else if (o->kind == ZR_OBJ_JULIA)
    k = zr__julia_crossings(o, org, dir, tmin, tmax, t, n);
  else if (o->kind == ZR_OBJ_POLYGON)
    k = zr__polygon_crossings(o, org, dir, tmin, tmax, t, n);
  else if (o->kind == ZR_OBJ_PRISM)
    k = zr__prism_crossings(o, org, dir, tmin, tmax, t, n);
  else if (o->kind == ZR_OBJ_LATHE)
    k = zr__lathe_crossings(o, org, dir, tmin, tmax, t, n);
  else if (o->kind == ZR_OBJ_BLOB)
    k = zr__blob_crossings(o, org, dir, tmin, tmax, t, n);
  else if (o->kind == ZR_OBJ_SOR)
    k = zr__sor_crossings(o, org, dir, tmin, tmax, t, n);
  else if (o->kind == ZR_OBJ_ISOSURFACE)
    k = zr__isosurface_crossings(o, org, dir, tmin, tmax, t, n);
  else if (o->kind == ZR_OBJ_HEIGHT_FIELD)
    k = zr__height_field_crossings(o, org, dir, tmin, tmax, t, n);
  else if (o->kind == ZR_OBJ_OVUS)
    k = zr__ovus_crossings(o, org, dir, tmin, tmax, t, n);
  else if (o->kind == ZR_OBJ_PARAMETRIC)
    k = zr__parametric_crossings(o, org, dir, tmin, tmax, t, n);
  else
    k = zr__superellipsoid_crossings(o, org, dir, tmin, tmax, t, n);
  for (int i = 0; i < k; i++)
    add_crossing(l, t[i], n[i]);
}

/*
 * Real roots of a t^2 + b t + c = 0 into r[0] <= r[1]; returns their
 * number (0 or 2; a double root counts as a graze and is dropped).
 */
static int solve_quadratic(double a, double b, double c, double r[2]) {
  if (a == 0.0) {
    if (b == 0.0)
      return 0;
    r[0] = r[1] = -c / b;
    return 1;
  }
  double disc = b * b - 4.0 * a * c;
  if (!(disc > 0.0))
    return 0;
  double q = -0.5 * (b + copysign(sqrt(disc), b));
  double r0 = q / a, r1 = q != 0.0 ? c / q : r0;
  r[0] = fmin(r0, r1);
  r[1] = fmax(r0, r1);
  return 2;
}

static void sphere_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                             crossing_list *l) {
  zr_vec3 oc = zr_v3_sub(org, o->u.sphere.centre);
  double r = o->u.sphere.radius;
  double a = zr_v3_dot(dir, dir);
  double b = 2.0 * zr_v3_dot(dir, oc);
  double c = zr_v3_dot(oc, oc) - r * r;
  double t[2];
  if (solve_quadratic(a, b, c, t) != 2)
    return;
  for (int i = 0; i < 2; i++)
    add_crossing(l, t[i], zr_v3_sub(zr_v3_madd(org, dir, t[i]),
                                    o->u.sphere.centre));
}

/* Slab test: the entry and exit faces of an axis-aligned box. */
static void box_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                          crossing_list *l) {
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
  add_crossing(l, tnear, zr_v3(n0[0], n0[1], n0[2]));
  add_crossing(l, tfar, zr_v3(n1[0], n1[1], n1[2]));
}

static void plane_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                            crossing_list *l) {
  zr_vec3 n = o->u.plane.normal;
  double dn = zr_v3_dot(n, dir);
  if (dn == 0.0)
    return;
  add_crossing(l, (o->u.plane.distance - zr_v3_dot(n, org)) / dn, n);
}

/* Moller and Trumbore's test ("Fast, minimum storage ray/triangle
   intersection", 1997), with edges taken from the first vertex. */
static void triangle_crossings(const zr_object *o, zr_vec3 org,
                               zr_vec3 dir, crossing_list *l) {
  const zr_vec3 *p = o->u.triangle.p;
  zr_vec3 e1 = zr_v3_sub(p[1], p[0]), e2 = zr_v3_sub(p[2], p[0]);
  zr_vec3 pv = zr_v3_cross(dir, e2);
  double det = zr_v3_dot(e1, pv);
  if (det == 0.0 || !isfinite(det))
    return;
  double inv = 1.0 / det;
  zr_vec3 tv = zr_v3_sub(org, p[0]);
  double u = zr_v3_dot(tv, pv) * inv;
  if (u < 0.0 || u > 1.0)
    return;
  zr_vec3 qv = zr_v3_cross(tv, e1);
  double v = zr_v3_dot(dir, qv) * inv;
  if (v < 0.0 || u + v > 1.0)
    return;
  add_crossing(l, zr_v3_dot(e2, qv) * inv, zr_v3_cross(e1, e2));
}

/*
 * The frame of a shape with an axis from base to cap: the unit axis w,
 * the height h, and the ray split into its part along w (o_par, d_par)
 * and across it (o_perp, d_perp), measured from base.
 */
typedef struct axis_frame {
  zr_vec3 w;
  double h;
  double o_par, d_par;
  zr_vec3 o_perp, d_perp;
} axis_frame;

static bool make_frame(zr_vec3 base, zr_vec3 cap, zr_vec3 org, zr_vec3 dir,
                       axis_frame *f) {
  zr_vec3 a = zr_v3_sub(cap, base);
  f->h = zr_v3_len(a);
  if (!(f->h > 0.0))
    return false;
  f->w = zr_v3_scale(a, 1.0 / f->h);
  zr_vec3 ob = zr_v3_sub(org, base);
  f->o_par = zr_v3_dot(ob, f->w);
  f->d_par = zr_v3_dot(dir, f->w);
  f->o_perp = zr_v3_madd(ob, f->w, -f->o_par);
  f->d_perp = zr_v3_madd(dir, f->w, -f->d_par);
  return true;
}

/* An end cap: the disc of radius r across the axis at height s. */
static void cap_crossing(const axis_frame *f, double s, double r,
                         double outward, crossing_list *l) {
  if (f->d_par == 0.0 || !(r > 0.0))
    return;
  double t = (s - f->o_par) / f->d_par;
  zr_vec3 q = zr_v3_madd(f->o_perp, f->d_perp, t);
  if (zr_v3_dot(q, q) <= r * r)
    add_crossing(l, t, zr_v3_scale(f->w, outward));
}

/*
 * Cylinders and cones in one: the radius grows linearly from r0 at the
 * base to r1 at the cap, r(s) = r0 + k s.  The side is where
 * |perp|^2 = r(s)^2 with 0 <= s <= h; its gradient perp - r(s) k w is
 * the outward normal.
 */
static void round_crossings(zr_vec3 base, zr_vec3 cap, double r0, double r1,
                            bool open, zr_vec3 org, zr_vec3 dir,
                            crossing_list *l) {
  axis_frame f;
  if (!make_frame(base, cap, org, dir, &f))
    return;
  r0 = fabs(r0);
  r1 = fabs(r1);
  double k = (r1 - r0) / f.h;
  double rq = r0 + k * f.o_par; /* the radius at the origin's height */
  double a = zr_v3_dot(f.d_perp, f.d_perp) - k * k * f.d_par * f.d_par;
  double b = 2.0 * (zr_v3_dot(f.o_perp, f.d_perp) - k * f.d_par * rq);
  double c = zr_v3_dot(f.o_perp, f.o_perp) - rq * rq;
  double t[2];
  int n = solve_quadratic(a, b, c, t);
  for (int i = 0; i < n; i++) {
    double s = f.o_par + t[i] * f.d_par;
    if (s < 0.0 || s > f.h)
      continue;
    double rs = r0 + k * s;
    if (rs < 0.0)
      continue; /* the mirror nappe of a cone beyond its apex */
    zr_vec3 perp = zr_v3_madd(f.o_perp, f.d_perp, t[i]);
    add_crossing(l, t[i], zr_v3_madd(perp, f.w, -rs * k));
  }
  if (!open) {
    cap_crossing(&f, 0.0, r0, -1.0, l);
    cap_crossing(&f, f.h, r1, 1.0, l);
  }
}

static void disc_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                           crossing_list *l) {
  zr_vec3 n = o->u.disc.normal;
  double dn = zr_v3_dot(n, dir);
  if (dn == 0.0)
    return;
  double t = zr_v3_dot(n, zr_v3_sub(o->u.disc.centre, org)) / dn;
  zr_vec3 q = zr_v3_sub(zr_v3_madd(org, dir, t), o->u.disc.centre);
  double d2 = zr_v3_dot(q, q);
  double r = o->u.disc.radius, hole = o->u.disc.hole_radius;
  if (d2 <= r * r && d2 >= hole * hole)
    add_crossing(l, t, n);
}

static void shape_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                            crossing_list *l) {
  switch (o->kind) {
  case ZR_OBJ_SPHERE:
    sphere_crossings(o, org, dir, l);
    break;
  case ZR_OBJ_BOX:
    box_crossings(o, org, dir, l);
    break;
  case ZR_OBJ_PLANE:
    plane_crossings(o, org, dir, l);
    break;
  case ZR_OBJ_TRIANGLE:
    triangle_crossings(o, org, dir, l);
    break;
  case ZR_OBJ_CYLINDER:
    round_crossings(o->u.cylinder.base, o->u.cylinder.cap,
                    o->u.cylinder.radius, o->u.cylinder.radius,
                    o->u.cylinder.open, org, dir, l);
    break;
  case ZR_OBJ_CONE:
    round_crossings(o->u.cone.base, o->u.cone.cap, o->u.cone.base_radius,
                    o->u.cone.cap_radius, o->u.cone.open, org, dir, l);
    break;
  case ZR_OBJ_DISC:
    disc_crossings(o, org, dir, l);
    break;
  case ZR_OBJ_UNION:
  case ZR_OBJ_MESH:
  case ZR_OBJ_TEXT:
    break; /* flattened before tracing; compound_crossings() */
  case ZR_OBJ_QUADRIC: {
    double t[2];
    zr_vec3 n[2];
    int k = zr__quadric_crossings(o->u.quadric.coef, org, dir, t, n);
    for (int i = 0; i < k; i++)
      add_crossing(l, t[i], n[i]);
    break;
  }
  case ZR_OBJ_INTERSECTION:
  case ZR_OBJ_MERGE:
    break; /* lib/trace/csg.c, called before the transform */
  case ZR_OBJ_POLY:
    break; /* poly_crossings() */
  case ZR_OBJ_SPHERE_SWEEP:
  case ZR_OBJ_JULIA:
  case ZR_OBJ_TORUS:
  case ZR_OBJ_POLYGON:
  case ZR_OBJ_SUPERELLIPSOID:
  case ZR_OBJ_PRISM:
  case ZR_OBJ_LATHE:
  case ZR_OBJ_BLOB:
  case ZR_OBJ_SOR:
  case ZR_OBJ_ISOSURFACE:
  case ZR_OBJ_HEIGHT_FIELD:
  case ZR_OBJ_OVUS:
  case ZR_OBJ_PARAMETRIC:
    break; /* searched_crossings() */
  }
}

/* poly, cubic, quartic: the root finder needs the interval. */
static void poly_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                           double tmin, double tmax, crossing_list *l) {
  double t[4];
  zr_vec3 n[4];
  int k = zr__poly_crossings(o, org, dir, tmin, tmax, t, n);
  for (int i = 0; i < k; i++)
    add_crossing(l, t[i], n[i]);
}

/* clipped_by: drops the crossings outside the clipping object, which is
   tested in world space (the ray's t is the same in both spaces). */
static void clip_crossings(const zr_object *clip, const zr_ray *ray,
                           crossing_list *l) {
  int kept = 0;
  for (int i = 0; i < l->n; i++) {
    if (!zr__inside(clip, zr_v3_madd(ray->origin, ray->dir, l->t[i])))
      continue;
    l->t[kept] = l->t[i];
    l->normal[kept] = l->normal[i];
    l->texture[kept] = l->texture[i];
    l->u[kept] = l->u[i];
    l->v[kept] = l->v[i];
    kept++;
  }
  l->n = kept;
}

/* The crossings in (tmin, tmax), sorted, with world normals only when
   asked for: traversal needs t alone, and normals cost a matrix product
   and a square root each. */
static int crossings(const zr_object *object, const zr_ray *ray,
                     double tmin, double tmax, bool want_normals,
                     zr_hit hits[ZR_MAX_CROSSINGS]) {
  if (zr__is_csg(object->kind)) /* children carry their transforms */
    return zr__csg_crossings(object, ray, tmin, tmax, want_normals, hits);
  zr_vec3 org = ray->origin, dir = ray->dir;
  if (object->transform) {
    org = zr__xform_point(object->transform->inv, org);
    dir = zr__xform_dir(object->transform->inv, dir);
  }
  crossing_list l;
  l.n = 0;
  if (object->kind == ZR_OBJ_MESH || object->kind == ZR_OBJ_TEXT)
    compound_crossings(object, org, dir, tmin, tmax, &l);
  else if (is_searched(object->kind))
    searched_crossings(object, org, dir, tmin, tmax, &l);
  else if (object->kind == ZR_OBJ_POLY)
    poly_crossings(object, org, dir, tmin, tmax, &l);
  else
    shape_crossings(object, org, dir, &l);
  if (object->clip)
    clip_crossings(object->clip, ray, &l);
  int n = 0;
  for (int i = 0; i < l.n; i++) {
    double t = l.t[i];
    if (!(t > tmin && t < tmax))
      continue;
    /* Insertion keeps the list sorted; a third crossing (only possible
       through rounding at a cap edge) replaces the farthest if nearer. */
    int j = n < ZR_MAX_CROSSINGS ? n++ : ZR_MAX_CROSSINGS;
    if (j == ZR_MAX_CROSSINGS) {
      if (t >= hits[j - 1].t)
        continue;
      j--;
    }
    while (j > 0 && hits[j - 1].t > t) {
      hits[j] = hits[j - 1];
      j--;
    }
    zr_vec3 nrm = zr_v3(0, 0, 0);
    if (want_normals) {
      nrm = l.normal[i];
      if (object->transform)
        nrm = zr__xform_normal(object->transform->inv, nrm);
      nrm = zr_v3_norm(nrm);
      if (object->inverse)
        nrm = zr_v3_neg(nrm);
    }
    hits[j].t = t;
    hits[j].normal = nrm;
    hits[j].object = object->kind == ZR_OBJ_MESH
                         ? zr__mesh_hit_object(object, l.texture[i])
                         : object;
    hits[j].u = hits[j].v = 0.0;
    if (object->kind == ZR_OBJ_MESH) {
      hits[j].u = l.u[i];
      hits[j].v = l.v[i];
    }
  }
  return n;
}

int zr__intersect(const zr_object *object, const zr_ray *ray, double tmin,
                  double tmax, zr_hit hits[ZR_MAX_CROSSINGS]) {
  return crossings(object, ray, tmin, tmax, true, hits);
}

int zr__intersect_t(const zr_object *object, const zr_ray *ray, double tmin,
                    double tmax, zr_hit hits[ZR_MAX_CROSSINGS]) {
  return crossings(object, ray, tmin, tmax, false, hits);
}

/* Inside tests in object space. */
static bool round_inside(zr_vec3 base, zr_vec3 cap, double r0, double r1,
                         zr_vec3 p) {
  axis_frame f;
  if (!make_frame(base, cap, p, zr_v3(0, 0, 0), &f))
    return false;
  if (f.o_par < 0.0 || f.o_par > f.h)
    return false;
  double r = fabs(r0) + (fabs(r1) - fabs(r0)) * f.o_par / f.h;
  return zr_v3_dot(f.o_perp, f.o_perp) < r * r;
}

static bool shape_inside(const zr_object *o, zr_vec3 p) {
  switch (o->kind) {
  case ZR_OBJ_SPHERE: {
    zr_vec3 d = zr_v3_sub(p, o->u.sphere.centre);
    return zr_v3_dot(d, d) < o->u.sphere.radius * o->u.sphere.radius;
  }
  case ZR_OBJ_BOX: {
    zr_vec3 lo = zr_v3_min(o->u.box.corner1, o->u.box.corner2);
    zr_vec3 hi = zr_v3_max(o->u.box.corner1, o->u.box.corner2);
    return p.x > lo.x && p.x < hi.x && p.y > lo.y && p.y < hi.y &&
           p.z > lo.z && p.z < hi.z;
  }
  case ZR_OBJ_PLANE:
    return zr_v3_dot(p, o->u.plane.normal) < o->u.plane.distance;
  case ZR_OBJ_DISC:
    return zr_v3_dot(zr_v3_sub(p, o->u.disc.centre), o->u.disc.normal) < 0.0;
  case ZR_OBJ_CYLINDER:
    return round_inside(o->u.cylinder.base, o->u.cylinder.cap,
                        o->u.cylinder.radius, o->u.cylinder.radius, p);
  case ZR_OBJ_CONE:
    return round_inside(o->u.cone.base, o->u.cone.cap, o->u.cone.base_radius,
                        o->u.cone.cap_radius, p);
  case ZR_OBJ_MESH:
    return zr__mesh_inside(o->u.mesh.data, p);
  case ZR_OBJ_TEXT:
    return zr__text_inside(o->u.text.data, p);
  case ZR_OBJ_QUADRIC:
    return zr__quadric_inside(o->u.quadric.coef, p);
  case ZR_OBJ_POLY:
    return zr__poly_inside(o, p);
  case ZR_OBJ_TORUS:
    return zr__torus_inside(o, p);
  case ZR_OBJ_SUPERELLIPSOID:
    return zr__superellipsoid_inside(o, p);
  case ZR_OBJ_PRISM:
    return zr__prism_inside(o, p);
  case ZR_OBJ_LATHE:
    return zr__lathe_inside(o, p);
  case ZR_OBJ_BLOB:
    return zr__blob_inside(o, p);
  case ZR_OBJ_SOR:
    return zr__sor_inside(o, p);
  case ZR_OBJ_SPHERE_SWEEP:
    return zr__sweep_inside(o, p);
  case ZR_OBJ_JULIA:
    return zr__julia_inside(o, p);
  case ZR_OBJ_ISOSURFACE:
    return zr__isosurface_inside(o, p);
  case ZR_OBJ_HEIGHT_FIELD:
    return zr__height_field_inside(o, p);
  case ZR_OBJ_OVUS:
    return zr__ovus_inside(o, p);
  case ZR_OBJ_TRIANGLE:
  case ZR_OBJ_POLYGON:
  case ZR_OBJ_PARAMETRIC:
  case ZR_OBJ_UNION:
  case ZR_OBJ_INTERSECTION:
  case ZR_OBJ_MERGE:
    break; /* CSG: zr__csg_inside() */
  }
  return false;
}

bool zr__inside(const zr_object *object, zr_vec3 p) {
  if (object->kind == ZR_OBJ_TRIANGLE || object->kind == ZR_OBJ_POLYGON ||
      object->kind == ZR_OBJ_PARAMETRIC ||
      (object->kind == ZR_OBJ_MESH && !zr__has_inside(object)))
    return false; /* no inside, inverse or not */
  if (zr__is_csg(object->kind))
    return zr__csg_inside(object, p);
  zr_vec3 local = p;
  if (object->transform)
    local = zr__xform_point(object->transform->inv, p);
  bool in = shape_inside(object, local) != object->inverse;
  /* A clipped object is inside where it and its clip both are. */
  return in && (!object->clip || zr__inside(object->clip, p));
}

/* ---- surface coordinates ("UV Mapping", "Supported Objects") ---- */

#define UV_PI 3.14159265358979323846

/* POV-Ray 3.7's sphere mapping: u the angle about y from +x towards +z
   over a full turn, v from the south pole (0) to the north (1). */
static void sphere_uv(zr_vec3 d, double *u, double *v) {
  double len = zr_v3_len(d);
  if (!(len > 0.0)) {
    *u = *v = 0.0;
    return;
  }
  d = zr_v3_scale(d, 1.0 / len);
  *v = 0.5 + asin(fmax(-1.0, fmin(1.0, d.y))) / UV_PI;
  double r = sqrt(d.x * d.x + d.z * d.z);
  double theta = 0.0;
  if (r > 1e-10) {
    theta = acos(fmax(-1.0, fmin(1.0, d.x / r)));
    if (d.z < 0.0)
      theta = 2.0 * UV_PI - theta;
  }
  *u = theta / (2.0 * UV_PI);
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

bool zr__hit_uv(const zr_hit *hit, zr_vec3 p, double *u, double *v) {
  const zr_object *o = hit->object;
  if (o->kind == ZR_OBJ_MESH) {
    *u = hit->u;
    *v = hit->v;
    return true;
  }
  if (o->transform)
    p = zr__xform_point(o->transform->inv, p);
  if (o->kind == ZR_OBJ_SPHERE) {
    sphere_uv(zr_v3_sub(p, o->u.sphere.centre), u, v);
    return true;
  }
  if (o->kind == ZR_OBJ_BOX) {
    box_uv(o, p, u, v);
    return true;
  }
  if (o->kind == ZR_OBJ_TORUS) {
    /* u about the y axis from -x, v about the tube from its inner
       equator (POV-Ray 3.7's torus; povray renders of uv_mapping
       gradient x and gradient y on a torus agree). */
    *u = 1.0 - (atan2(p.z, p.x) + UV_PI) / (2.0 * UV_PI);
    double x = sqrt(p.x * p.x + p.z * p.z) - o->u.torus.major;
    *v = (atan2(p.y, x) + UV_PI) / (2.0 * UV_PI);
    return true;
  }
  *u = *v = 0.0;
  return false;
}
