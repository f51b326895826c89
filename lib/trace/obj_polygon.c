/*
 * obj_polygon.c - the polygon (POV-Ray 3.7 reference, "Polygon"): any
 * number of closed sub-polygons in one plane, a point being on the
 * surface when a line from it crosses an odd number of their edges
 * (Jordan's curve theorem, as the manual puts it), so overlaps of an
 * even number of sub-polygons are holes.
 *
 * The parser (lib/sdl/build_shape.c) fits the plane and stores every
 * edge already projected onto it, in the plane's own (u, v) axes.  A ray
 * meets the plane at one t; the hit point's (u, v) is then tested with
 * the crossing-number rule along the +u direction, counting an edge when
 * its end points lie on opposite sides of the line v = const (one end
 * strictly below, the other at or above), which counts a vertex on that
 * line exactly once.  Like a triangle the polygon is flat and has no
 * inside.
 */
#include "trace/obj_shapes.h"

#include <math.h>

#include "trace/shape.h"

/* Whether (u, v) is inside by the even-odd rule. */
static bool polygon_covers(const zr_object *o, double u, double v) {
  const double *e = o->u.polygon.edges;
  bool in = false;
  for (size_t i = 0; i < o->u.polygon.n_edges; i++, e += 4) {
    double u0 = e[0], v0 = e[1], u1 = e[2], v1 = e[3];
    if ((v0 > v) == (v1 > v))
      continue;
    /* Where the edge crosses the line through the point. */
    double uc = u0 + (v - v0) * (u1 - u0) / (v1 - v0);
    if (uc > u)
      in = !in;
  }
  return in;
}

bool zr__polygon_covers(const zr_object *o, zr_vec3 p) {
  return polygon_covers(o, zr_v3_dot(p, o->u.polygon.u_axis),
                        zr_v3_dot(p, o->u.polygon.v_axis));
}

int zr__polygon_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                          double tmin, double tmax, double t[4],
                          zr_vec3 normal[4]) {
  zr_vec3 n = o->u.polygon.normal;
  double dn = zr_v3_dot(n, dir);
  if (dn == 0.0)
    return 0;
  double th = (o->u.polygon.distance - zr_v3_dot(n, org)) / dn;
  if (!(th > tmin && th < tmax))
    return 0;
  zr_vec3 p = zr_v3_madd(org, dir, th);
  if (!polygon_covers(o, zr_v3_dot(p, o->u.polygon.u_axis),
                      zr_v3_dot(p, o->u.polygon.v_axis)))
    return 0;
  t[0] = th;
  normal[0] = n;
  return 1;
}

/* The box of the points; none without edges. */
static bool polygon_box(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  *lo = o->u.polygon.lo;
  *hi = o->u.polygon.hi;
  return o->u.polygon.n_edges > 0;
}

/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_polygon = {
    .name = "a polygon",
    .search = zr__polygon_crossings,
    .bounds = polygon_box,
};
