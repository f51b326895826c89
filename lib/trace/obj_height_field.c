/*
 * obj_height_field.c - the height field (POV-Ray 3.7 reference, "Height
 * Field"): a grid of heights in [0, 1] over the unit square of the x-z
 * plane, each square of four neighbouring samples cut into two
 * triangles.  The triangles are an ordinary mesh (lib/trace/obj_mesh.c,
 * with its own BVH), built by lib/sdl/build_hf.c; smooth gives them
 * normals interpolated from the grid's slopes.
 *
 * What this file adds is the height field's own rules: water_level hides
 * the surface below it (crossings there are skipped), and the solid is
 * what lies under the surface, above y = 0, within the unit square, so
 * height fields take part in CSG.
 */
#include "trace/obj_isosurface.h"

#include <math.h>

#include "trace/shape.h"

#include "trace/obj_mesh.h"

int zr__height_field_crossings(const zr_object *o, zr_vec3 org,
                               zr_vec3 dir, double tmin, double tmax,
                               double t[4], zr_vec3 normal[4]) {
  const double water = o->u.height_field.water_level;
  int found = 0;
  if (o->u.height_field.data->n_faces == 0)
    return 0;
  /* Each round gives the mesh's next two crossings; those under the
     water are dropped and the search goes on beyond them. */
  for (int round = 0; round < 1000 && found < 2; round++) {
    zr_mesh_crossing c[2];
    int k = zr__mesh_crossings(o->u.height_field.data, org, dir, tmin, tmax,
                               c);
    for (int i = 0; i < k && found < 2; i++) {
      if (water > 0.0 && org.y + c[i].t * dir.y < water)
        continue;
      /* A ray through an edge or corner meets the triangles that share
         it at one t: one crossing. */
      if (found > 0 &&
          fabs(c[i].t - t[found - 1]) <= 1e-12 * fmax(1.0, fabs(c[i].t)))
        continue;
      t[found] = c[i].t;
      normal[found] = c[i].normal;
      found++;
    }
    if (k < 2 || !(c[1].t > tmin))
      break;
    tmin = c[1].t;
  }
  return found;
}

double zr__height_field_height(const zr_object *o, double x, double z) {
  int w = o->u.height_field.w, h = o->u.height_field.h;
  const float *hs = o->u.height_field.heights;
  double fx = fmin(fmax(x, 0.0), 1.0) * (w - 1);
  double fz = fmin(fmax(z, 0.0), 1.0) * (h - 1);
  int i = (int)fx, j = (int)fz;
  if (i > w - 2)
    i = w - 2;
  if (j > h - 2)
    j = h - 2;
  double u = fx - i, v = fz - j;
  double h00 = hs[(size_t)j * w + i], h10 = hs[(size_t)j * w + i + 1];
  double h01 = hs[(size_t)(j + 1) * w + i];
  double h11 = hs[(size_t)(j + 1) * w + i + 1];
  /* The square's diagonal runs from (i + 1, j) to (i, j + 1), as
     lib/sdl/build_hf.c cuts it. */
  if (u + v <= 1.0)
    return h00 + u * (h10 - h00) + v * (h01 - h00);
  return h11 + (1.0 - u) * (h01 - h11) + (1.0 - v) * (h10 - h11);
}

bool zr__height_field_inside(const zr_object *o, zr_vec3 p) {
  if (!(p.x >= 0.0 && p.x <= 1.0 && p.z >= 0.0 && p.z <= 1.0 && p.y >= 0.0))
    return false;
  return p.y < zr__height_field_height(o, p.x, p.z);
}

bool zr__height_field_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  const struct zr_mesh *m = o->u.height_field.data;
  if (m->n_faces == 0)
    return false;
  *lo = m->lo;
  *hi = m->hi;
  lo->y = fmax(lo->y, o->u.height_field.water_level);
  hi->y = fmax(hi->y, lo->y);
  return true;
}

/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_height_field = {
    .name = "a height_field",
    .search = zr__height_field_crossings,
    .inside = zr__height_field_inside,
    .bounds = zr__height_field_bounds,
};
