/*
 * mesh.c - the exact surfaces of a finished scene's primitives, the input
 * of hierarchical radiosity.
 *
 * Hanrahan, Salzman and Aupperle start from a handful of large input
 * surfaces and let refinement decide where to split them; here those are
 * the exact parametric surfaces of surface.c, one per face of every
 * primitive that has area: a triangle, the six faces of a box, a disc or
 * annulus, a sphere, the side of a cylinder or cone and, unless the
 * object is open, its end caps as discs.  An infinite plane becomes the
 * part of it inside the scene's bounds: the box around every finite
 * object, stretched to reach every axis-aligned plane (so six planes
 * forming a room bound themselves), then widened by a margin of 10% of
 * its diagonal on every side so that light reaching past the objects
 * still lands on the floor.  A tilted plane is its exact section of
 * those bounds, a convex polygon of three to six corners as a fan of
 * triangles.  A mesh (mesh, mesh2, smooth_triangle, and a height_field
 * without water_level) is one surface whose quadtree groups its faces
 * into clusters (surface.c, cluster.c), so a large mesh is no multitude
 * of surfaces linked in pairs.  Objects of the other kinds (text,
 * polygon, prism, lathe, sor, blob, isosurface ...) have no radiosity
 * surface yet: they are counted and named in one warning per kind.
 *
 * The surface's light follows POV-Ray's finish (reference manual,
 * "Finish"): emission is a radiance that POV-Ray multiplies by the
 * pigment, so the emitted radiosity is pi * emission * pigment; diffuse
 * is the fraction of light reflected diffusely, times the pigment, so
 * the reflectance is rho = diffuse * pigment.  Emission leaves both
 * sides of a flat object, as POV-Ray's emitting triangle lights both
 * ways, and the outside of a closed one, each side by the share of its
 * light that gets away from it (side_openness; params.one_sided_emission
 * 2, the default): a lamp hung a hair below a ceiling would otherwise
 * pour its back's light into that gap, and the ceiling cells above the
 * lamp, larger than the gap, would leak the trapped light into the
 * room.  With one_sided_emission 1 only the front side (the outward
 * normal, for a triangle (p1 - p0) x (p2 - p0)) emits, with 0 both at
 * full.  The parts of a CSG
 * intersection, difference or merge are surfaces like any primitive's,
 * trimmed to what the solid keeps (trim.c); a union inside one keeps
 * all of its children.  A reflectance above 1
 * would create energy; it is clamped to 1 with a warning.  Objects with
 * no area (a degenerate triangle, a flat box) get a warning and take no
 * part, as POV-Ray itself renders nothing for them.
 */
#include "radiosity/radiosity.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "trace/intersect.h"
#include "trace/obj_isosurface.h"
#include "trace/obj_mesh.h"

/* Where an object was written, for messages. */
static zr_diag_place object_place(const zr_object *obj) {
  zr_diag_place where;
  memset(&where, 0, sizeof where);
  where.file = obj->where.file;
  where.line = obj->where.line;
  where.column = obj->where.column;
  return where;
}

/* POV-Ray's keyword for each kind, in zr_object_kind's order. */
const char *zr__rad_kind_name(zr_object_kind kind) {
  static const char *const names[] = {
      "sphere",       "box",         "plane",    "triangle",
      "cylinder",     "cone",        "disc",     "union",
      "mesh",         "text",        "intersection", "merge",
      "quadric",      "torus",       "polygon",  "superellipsoid",
      "prism",        "lathe",       "blob",     "poly",
      "sor",          "sphere_sweep", "julia_fractal", "isosurface",
      "height_field", "ovus",        "parametric"};
  return (size_t)kind < sizeof names / sizeof names[0] ? names[kind]
                                                       : "object";
}

/* The faces radiosity would model for an object, 0 for none.  A height
   field's are its triangles unless water_level hides some of them (the
   tracer drops what lies below it; radiosity cannot yet); they are made
   as a mesh only when it is modelled (hf_mesh). */
static size_t object_faces(const zr_object *o) {
  if (o->kind == ZR_OBJ_MESH)
    return o->u.mesh.data->n_faces;
  if (o->kind == ZR_OBJ_HEIGHT_FIELD &&
      !(o->u.height_field.water_level > 0.0))
    return 2 * (size_t)(o->u.height_field.w - 1) *
           (size_t)(o->u.height_field.h - 1);
  return 0;
}

/* Whether radiosity models objects of this kind at all (others are
   counted and named once, in zr__rad_mesh_build). */
static bool modelled(const zr_object *o) {
  switch (o->kind) {
  case ZR_OBJ_SPHERE: case ZR_OBJ_BOX: case ZR_OBJ_PLANE:
  case ZR_OBJ_TRIANGLE: case ZR_OBJ_CYLINDER: case ZR_OBJ_CONE:
  case ZR_OBJ_DISC: case ZR_OBJ_TORUS: case ZR_OBJ_POLYGON:
    return true;
  case ZR_OBJ_MESH:
    return true;
  case ZR_OBJ_HEIGHT_FIELD:
    return object_faces(o) > 0;
  default:
    return false;
  }
}

bool zr__rad_models(const zr_object *o, size_t *faces) {
  *faces = object_faces(o);
  return modelled(o);
}

/* Whether rays between surfaces would cross media that POV-Ray's
   radiosity takes into account: only with the block's "media on" (the
   manual, "Media and Radiosity": the default is off, and a medium's
   emission lights other objects only with it), and then atmospheric
   media or any object's interior media. */
bool zr__rad_media_counts(const zr_scene *scene) {
  const zr_settings *s = &scene->settings;
  if (!s->radiosity.on || s->radiosity.media != 1)
    return false;
  if (s->n_media > 0)
    return true;
  if (scene->default_interior && scene->default_interior->n_media > 0)
    return true;
  for (size_t i = 0; i < scene->n_primitives; i++) {
    const zr_interior *in = scene->primitives[i]->interior;
    if (in && in->n_media > 0)
      return true;
  }
  return false;
}

/* The bounds that clip infinite planes; false when nothing bounds them. */
bool zr__rad_finite_bounds(const zr_scene *scene, zr_vec3 *lo,
                           zr_vec3 *hi) {
  bool any = false;
  zr_vec3 l = zr_v3(INFINITY, INFINITY, INFINITY), h = zr_v3_neg(l);
  for (size_t i = 0; i < scene->n_primitives; i++) {
    zr_vec3 a, b;
    if (zr__object_bounds(scene->primitives[i], &a, &b)) {
      l = zr_v3_min(l, a);
      h = zr_v3_max(h, b);
      any = true;
    }
  }
  *lo = l;
  *hi = h;
  return any;
}

bool zr__rad_plane_bounds(const zr_scene *scene, zr_vec3 *lo, zr_vec3 *hi) {
  zr_vec3 l, h;
  if (!zr__rad_finite_bounds(scene, &l, &h))
    return false;
  /* Axis-aligned planes without a transform stretch the box to reach
     them, so the walls of a room of planes meet. */
  for (size_t i = 0; i < scene->n_primitives; i++) {
    const zr_object *o = scene->primitives[i];
    if (o->kind != ZR_OBJ_PLANE || o->transform != NULL)
      continue;
    zr_vec3 n = o->u.plane.normal;
    for (int axis = 0; axis < 3; axis++) {
      double c = zr_v3_get(n, axis);
      if (fabs(c) != 1.0)
        continue;
      double at = o->u.plane.distance * c;
      if (axis == 0) { l.x = fmin(l.x, at); h.x = fmax(h.x, at); }
      if (axis == 1) { l.y = fmin(l.y, at); h.y = fmax(h.y, at); }
      if (axis == 2) { l.z = fmin(l.z, at); h.z = fmax(h.z, at); }
    }
  }
  double margin = 0.1 * zr_v3_len(zr_v3_sub(h, l));
  zr_vec3 m = zr_v3(margin, margin, margin);
  *lo = zr_v3_sub(l, m);
  *hi = zr_v3_add(h, m);
  return true;
}

/* The surfaces of one primitive into out[] (room for 6); the count, or
   -1 when the object has no area.  The previewer (preview.c) draws the
   same surfaces. */
int zr__rad_primitive_surfaces(const zr_object *o,
                               const struct zr_mesh *mesh, const zr_vec3 *lo,
                               const zr_vec3 *hi, zr__surface out[6]) {
  const zr_transform *xf = o->transform;
  zr_status st = ZR_OK;
  int n = 0;
  switch (o->kind) {
  case ZR_OBJ_TRIANGLE:
    st = zr__surface_triangle(&out[n++], o->u.triangle.p[0],
                              o->u.triangle.p[1], o->u.triangle.p[2], xf,
                              NULL, NULL);
    break;
  case ZR_OBJ_BOX:
    st = zr__surface_box_faces(out, o->u.box.corner1, o->u.box.corner2, xf,
                               NULL, NULL);
    n = 6;
    break;
  case ZR_OBJ_SPHERE:
    st = zr__surface_sphere(&out[n++], o->u.sphere.centre,
                            o->u.sphere.radius, xf, NULL, NULL);
    break;
  case ZR_OBJ_TORUS:
    st = zr__surface_torus(&out[n++], o->u.torus.major, o->u.torus.minor,
                           xf, NULL, NULL);
    break;
  case ZR_OBJ_DISC:
    st = zr__surface_disc(&out[n++], o->u.disc.centre, o->u.disc.normal,
                          o->u.disc.radius, o->u.disc.hole_radius, xf, NULL,
                          NULL);
    break;
  case ZR_OBJ_PLANE:
    if (lo == NULL)
      return -1;
    n = zr__surface_plane_section(out, o->u.plane.normal,
                                  o->u.plane.distance, *lo, *hi, xf, NULL,
                                  NULL);
    return n > 0 ? n : -1;
  case ZR_OBJ_MESH:
  case ZR_OBJ_HEIGHT_FIELD:
    st = zr__surface_mesh(&out[n++], mesh, xf, NULL, NULL);
    break;
  case ZR_OBJ_POLYGON: {
    /* The rectangle of the edges in the plane's (u, v) axes; trim.c
       keeps the polygon of it. */
    const double *e = o->u.polygon.edges;
    if (o->u.polygon.n_edges == 0)
      return -1;
    double u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
    for (size_t k = 0; k < 2 * o->u.polygon.n_edges; k++) {
      u0 = fmin(u0, e[2 * k]);
      u1 = fmax(u1, e[2 * k]);
      v0 = fmin(v0, e[2 * k + 1]);
      v1 = fmax(v1, e[2 * k + 1]);
    }
    zr_vec3 ua = o->u.polygon.u_axis, va = o->u.polygon.v_axis;
    zr_vec3 origin = zr_v3_add(
        zr_v3_scale(o->u.polygon.normal, o->u.polygon.distance),
        zr_v3_add(zr_v3_scale(ua, u0), zr_v3_scale(va, v0)));
    zr_vec3 e1 = zr_v3_scale(ua, u1 - u0), e2 = zr_v3_scale(va, v1 - v0);
    /* The surface's normal e1 x e2 along the polygon's. */
    if (zr_v3_dot(zr_v3_cross(e1, e2), o->u.polygon.normal) < 0.0) {
      zr_vec3 t = e1;
      e1 = e2;
      e2 = t;
    }
    st = zr__surface_parallelogram(&out[n++], origin, e1, e2, xf, NULL,
                                   NULL);
    break;
  }
  case ZR_OBJ_CYLINDER: {
    zr_vec3 b = o->u.cylinder.base, c = o->u.cylinder.cap;
    double r = o->u.cylinder.radius;
    st = zr__surface_cylinder(&out[n++], b, c, r, xf, NULL, NULL);
    if (st == ZR_OK && !o->u.cylinder.open) {
      zr_vec3 ax = zr_v3_sub(c, b);
      st = zr__surface_disc(&out[n++], b, zr_v3_neg(ax), r, 0.0, xf, NULL,
                            NULL);
      if (st == ZR_OK)
        st = zr__surface_disc(&out[n++], c, ax, r, 0.0, xf, NULL, NULL);
    }
    break;
  }
  case ZR_OBJ_CONE: {
    zr_vec3 b = o->u.cone.base, c = o->u.cone.cap;
    double rb = o->u.cone.base_radius, rc = o->u.cone.cap_radius;
    st = zr__surface_cone(&out[n++], b, rb, c, rc, xf, NULL, NULL);
    zr_vec3 ax = zr_v3_sub(c, b);
    if (st == ZR_OK && !o->u.cone.open && rb > 0.0)
      st = zr__surface_disc(&out[n++], b, zr_v3_neg(ax), rb, 0.0, xf, NULL,
                            NULL);
    if (st == ZR_OK && !o->u.cone.open && rc > 0.0)
      st = zr__surface_disc(&out[n++], c, ax, rc, 0.0, xf, NULL, NULL);
    break;
  }
  default:
    return -1;
  }
  return st == ZR_OK ? n : -1;
}

/* Which sides of o's surfaces emit (bit 0 the front, bit 1 the back),
   by params.one_sided_emission: 1 the front alone, 0 both, 2 (the
   default) both sides of a flat object and the outside of a closed
   one (whose inside the camera is not in: lib/gi/choose.c sends such a
   scene to the cache). */
static int emitting_sides(const zr_radiosity *rad, const zr_object *o) {
  switch (rad->params.one_sided_emission) {
  case 0:
    return 3;
  case 1:
    return 1;
  default:
    return zr__has_inside(o) ? 1 : 3;
  }
}

/* Emission and reflectance from the object's texture. */
static void surface_light(zr__rad_surface *s, const zr_object *o,
                          int sides, bool *clamped) {
  const zr_texture *tex = o->texture;
  zr_rgb pig = zr_colour_rgb(tex->pigment->colour);
  const zr_finish *fin = tex->finish;
  double pc[3] = {pig.r, pig.g, pig.b};
  double em[3] = {fin->emission.r, fin->emission.g, fin->emission.b};
  for (int c = 0; c < 3; c++) {
    double e = M_PI * em[c] * pc[c];
    double r = fin->diffuse * pc[c];
    if (!(isfinite(e) && e > 0.0))
      e = 0.0;
    for (int side = 0; side < 2; side++)
      s->emission[side][c] = s->shown[side][c] = sides >> side & 1 ? e : 0.0;
    if (!(r >= 0.0))
      r = 0.0;
    if (r > 1.0) {
      r = 1.0;
      *clamped = true;
    }
    s->rho[c] = r;
  }
  s->open[0] = s->open[1] = 1.0;
}

/* The radical inverse of k in base b (a low-discrepancy sequence). */
static double radical_inverse(unsigned k, unsigned b) {
  double x = 0.0, f = 1.0 / b;
  for (; k > 0; k /= b, f /= b)
    x += f * (k % b);
  return x;
}

/*
 * The openness of one side of an emitting surface: the share of the
 * light it emits that gets away from it.  povray's emitting surfaces
 * shine from both sides, and light sent into a gap narrower than the
 * solver's cells (a lamp's back hung a hair below a ceiling) comes out
 * only at the gap's rim; the solver, whose cells at the lamp's edge are
 * wider than the gap, would instead pour it into the room (the Cornell
 * box with both sides emitting at full: relative RMSE 1.34 against the
 * path-traced truth, 0.041 with the front alone).  So rays leave from an
 * 8 x 8 grid of the side's points (area weighted, CSG-trimmed points
 * left out) in cosine-distributed directions; one that meets a surface
 * at a distance t below res (twice the side of the finest cell,
 * sqrt(area_eps * total area)) counts min(1, t / L), L = sqrt(area) the
 * side's size, any other 1.  A side facing open space, or a room's far
 * wall, has 1; a side facing a parallel surface at a gap g below res
 * about 2 g / L (the mean of min(1, g / (L cos)) over cosine rays): the
 * Cornell lamp's back 0.0017.  Wider gaps the solver resolves itself.
 */
static double side_openness(const zr_radiosity *rad, const zr__rad_surface *s,
                            int side, double res) {
  const int n = 8;
  double L = sqrt(s->area);
  if (!(L > 0.0) || !isfinite(L) || rad->scene->bvh == NULL)
    return 1.0;
  double sum = 0.0, weight = 0.0;
  for (int j = 0; j < n; j++)
    for (int i = 0; i < n; i++) {
      zr__surface_point pt;
      zr__surface_eval(&s->geom, (i + 0.5) / n, (j + 0.5) / n, &pt);
      if (!(pt.da > 0.0) || !zr__rad_trim_keeps(s, pt.p))
        continue;
      zr_vec3 nn = side ? zr_v3_neg(pt.n) : pt.n;
      zr_vec3 a = fabs(nn.x) < 0.6 ? zr_v3(1, 0, 0) : zr_v3(0, 1, 0);
      zr_vec3 t1 = zr_v3_norm(zr_v3_cross(a, nn));
      zr_vec3 t2 = zr_v3_cross(nn, t1);
      /* Directions from another order than the points', so a point's
         place does not choose its direction. */
      unsigned k = (unsigned)((j * n + i) * 29 + 11) % (unsigned)(n * n);
      double r1 = radical_inverse(k, 2), r2 = radical_inverse(k, 3);
      double r = sqrt(r1), phi = 2.0 * M_PI * r2;
      zr_vec3 d = zr_v3_add(
          zr_v3_add(zr_v3_scale(t1, r * cos(phi)), zr_v3_scale(t2, r * sin(phi))),
          zr_v3_scale(nn, sqrt(1.0 - r1)));
      zr_ray ray = {zr_v3_madd(pt.p, nn, 1e-6 * L), d};
      zr_hit hit;
      double f = 1.0;
      if (zr__bvh_nearest(rad->scene->bvh, &ray, 0.0, fmin(L, res), &hit))
        f = hit.t / L;
      sum += pt.da * f;
      weight += pt.da;
    }
  return weight > 0.0 ? sum / weight : 1.0;
}

/* Whether o's finish emits (emission or energy). */
static bool finish_emits(const zr_object *o) {
  const zr_finish *fin = o->texture->finish;
  return fin->emission.r > 0.0 || fin->emission.g > 0.0 ||
         fin->emission.b > 0.0 || fin->energy.r > 0.0 ||
         fin->energy.g > 0.0 || fin->energy.b > 0.0;
}

/* finish { energy P } (lib/sdl/build_radiosity.c): the object emits P
   in all from the sides that emit, shared among them by area times
   openness, on top of its emission.  With every side closed (openness
   0) it is shared by area. */
static void add_energy(zr_radiosity *rad, const zr__rad_object_entry *e,
                       int sides) {
  zr_rgb P = e->object->texture->finish->energy;
  double pw[3] = {P.r, P.g, P.b};
  if (!(zr__rad_max3(pw) > 0.0))
    return;
  double w = 0.0, area = 0.0;
  for (uint32_t i = 0; i < e->count; i++)
    for (int side = 0; side < 2; side++)
      if (sides >> side & 1) {
        w += rad->surfs[e->first + i].area * rad->surfs[e->first + i].open[side];
        area += rad->surfs[e->first + i].area;
      }
  bool by_area = !(w > 0.0);
  if (by_area)
    w = area;
  if (!(w > 0.0))
    return;
  for (uint32_t i = 0; i < e->count; i++) {
    zr__rad_surface *s = &rad->surfs[e->first + i];
    for (int side = 0; side < 2; side++) {
      if (!(sides >> side & 1))
        continue;
      double f = by_area ? 1.0 : s->open[side];
      for (int c = 0; c < 3; c++) {
        s->emission[side][c] += pw[c] * f / w;
        s->shown[side][c] += pw[c] * f / w;
      }
    }
  }
  rad->power_ref += zr__rad_max3(pw);
}

static int entry_cmp(const void *a, const void *b) {
  uintptr_t x = (uintptr_t)((const zr__rad_object_entry *)a)->object;
  uintptr_t y = (uintptr_t)((const zr__rad_object_entry *)b)->object;
  return x < y ? -1 : x > y;
}

/* Adds the surfaces of primitive o, trimmed by the CSG primitive trim
   when it is a part of one (NULL: whole); ZR_ENOMEM on failure. */
/* The objects of each kind that radiosity does not model, and the
   first of them, for one warning per kind. */
typedef struct skip_tally {
  size_t count[ZR_OBJ_PARAMETRIC + 1];
  const zr_object *first[ZR_OBJ_PARAMETRIC + 1];
} skip_tally;

static zr_status add_primitive(zr_radiosity *rad, zr_context *ctx,
                               const zr_object *o, const zr_vec3 *lo,
                               const zr_vec3 *hi, const zr_object *trim,
                               skip_tally *tally) {
  zr__surface geo[6];
  zr_diag_place where = object_place(o);
  size_t n_faces = object_faces(o);
  if (n_faces > 0 && rad->params.max_mesh_faces > 0 &&
      n_faces > (size_t)rad->params.max_mesh_faces) {
    zr__diag(ctx, ZR_DIAG_WARNING, ZR_OK, &where,
             "radiosity: this %s has %zu faces, more than the %d radiosity "
             "takes (zr_radiosity_params.max_mesh_faces); it takes no part "
             "in the radiosity solution",
             zr__rad_kind_name(o->kind), n_faces,
             rad->params.max_mesh_faces);
    return ZR_OK;
  }
  if (!modelled(o)) {
    size_t k = (size_t)o->kind <= ZR_OBJ_PARAMETRIC ? (size_t)o->kind : 0;
    if (tally->count[k]++ == 0)
      tally->first[k] = o;
    return ZR_OK;
  }
  const struct zr_mesh *mesh = NULL;
  if (o->kind == ZR_OBJ_MESH)
    mesh = o->u.mesh.data;
  if (o->kind == ZR_OBJ_HEIGHT_FIELD) {
    rad->hf_meshes.budget = rad->budget;
    rad->hf_meshes.over_budget = 0;
    zr_status st = zr__height_field_mesh(o, &rad->hf_meshes, &mesh);
    if (st != ZR_OK && rad->hf_meshes.over_budget)
      rad->over_budget = true;
    if (st != ZR_OK)
      return zr__diag(ctx, ZR_DIAG_ERROR, st, &where,
                      "radiosity: cannot make the height_field's faces: %s",
                      zr_status_str(st));
  }
  int n = zr__rad_primitive_surfaces(o, mesh, lo, hi, geo);
  if (n < 0) {
    zr__diag(ctx, ZR_DIAG_WARNING, ZR_OK, &where,
             "radiosity: this %s has no area (or no bounds); it takes no "
             "part in the radiosity solution",
             zr__rad_kind_name(o->kind));
    return ZR_OK;
  }
  zr__rad_object_entry *e = &rad->objects[rad->n_objects++];
  e->object = o;
  e->first = (uint32_t)rad->n_surfs;
  e->count = (uint32_t)n;
  if (o->kind == ZR_OBJ_MESH && o->u.mesh.textured != NULL) {
    /* A mesh with a texture list: hits report the copy that carries the
       face's texture; every copy looks up the same surface (whose light
       is the mesh's own texture's). */
    for (size_t k = 0; k < o->u.mesh.data->n_textures; k++) {
      zr__rad_object_entry *c = &rad->objects[rad->n_objects++];
      *c = *e;
      c->object = &o->u.mesh.textured[k];
    }
  }
  bool clamped = false;
  int sides = emitting_sides(rad, o);
  for (int i = 0; i < n; i++) {
    zr__rad_surface *s = &rad->surfs[rad->n_surfs];
    memset(s, 0, sizeof *s);
    s->geom = geo[i];
    s->object = o;
    /* A mesh's faces and clusters are read at every node, link and
       sample: made once here (surface.c). */
    size_t bytes;
    if (zr__surface_mesh_cache(&s->geom, &bytes) != ZR_OK)
      return ZR_ENOMEM;
    if (!zr__rad_charge(rad, bytes)) {
      zr__surface_mesh_cache_free(&s->geom);
      return ZR_ENOMEM;
    }
    /* A polygon trims its own rectangle (trim.c). */
    s->trim = trim ? trim : o->kind == ZR_OBJ_POLYGON ? o : NULL;
    surface_light(s, o, sides, &clamped);
    s->area = zr__surface_area(&s->geom, 0, 1, 0, 1, 2, &rad->rule_src);
    if (s->trim != NULL) {
      /* The part the CSG keeps, from a fine grid of inside tests. */
      const double whole[4] = {0.0, 1.0, 0.0, 1.0};
      s->area *= zr__rad_trim_fraction(rad, s, whole, 64);
    }
    zr_status st = zr__rad_add_root(rad, (int32_t)rad->n_surfs);
    if (st != ZR_OK)
      return st;
    rad->total_area += s->area;
    rad->n_surfs++;
  }
  if (clamped)
    zr__diag(ctx, ZR_DIAG_WARNING, ZR_OK, &where,
             "radiosity: diffuse times pigment exceeds 1 and would create "
             "energy; the reflectance is clamped to 1");
  return ZR_OK;
}

/* The primitives under a CSG primitive's node (1 for a primitive). */
static size_t count_parts(const zr_object *o) {
  if (o->kind == ZR_OBJ_MESH && o->u.mesh.textured != NULL)
    return 1 + o->u.mesh.data->n_textures; /* the copies' entries */
  if (!zr__is_csg(o->kind))
    return 1;
  size_t n = 0;
  for (size_t i = 0; i < o->u.csg.n_children; i++)
    n += count_parts(o->u.csg.children[i]);
  return n;
}

/* Adds every part under node of the CSG primitive solid (an
   intersection, difference or merge), each trimmed by the solid. */
static zr_status add_parts(zr_radiosity *rad, zr_context *ctx,
                           const zr_object *node, const zr_object *solid,
                           const zr_vec3 *lo, const zr_vec3 *hi,
                           skip_tally *tally) {
  if (!zr__is_csg(node->kind))
    return add_primitive(rad, ctx, node, lo, hi, solid, tally);
  for (size_t i = 0; i < node->u.csg.n_children; i++) {
    zr_status st = add_parts(rad, ctx, node->u.csg.children[i], solid, lo,
                             hi, tally);
    if (st != ZR_OK)
      return st;
  }
  return ZR_OK;
}

zr_status zr__rad_mesh_build(zr_radiosity *rad, zr_context *ctx) {
  const zr_scene *scene = rad->scene;
  size_t np = 0;
  for (size_t i = 0; i < scene->n_primitives; i++)
    np += count_parts(scene->primitives[i]);
  rad->surfs = calloc(6 * np + 1, sizeof *rad->surfs);
  rad->objects = calloc(np + 1, sizeof *rad->objects);
  if (rad->surfs == NULL || rad->objects == NULL)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL,
                    "radiosity: out of memory for %zu surfaces", 6 * np);
  zr_vec3 lo, hi;
  bool bounded = zr__rad_plane_bounds(scene, &lo, &hi);
  skip_tally tally;
  memset(&tally, 0, sizeof tally);
  for (size_t i = 0; i < scene->n_primitives; i++) {
    const zr_object *o = scene->primitives[i];
    const zr_vec3 *l = bounded ? &lo : NULL, *h = bounded ? &hi : NULL;
    zr_status st = zr__is_csg(o->kind)
                       ? add_parts(rad, ctx, o, o, l, h, &tally)
                       : add_primitive(rad, ctx, o, l, h, NULL, &tally);
    if (st != ZR_OK && rad->over_budget)
      return ZR_ELIMIT; /* the caller says so */
    if (st != ZR_OK)
      return zr__diag(ctx, ZR_DIAG_ERROR, st, NULL,
                      "radiosity: out of memory building surfaces");
  }
  /* One warning per kind radiosity does not model yet, so a picture
     with such objects dark to radiosity is no silent surprise. */
  for (size_t k = 0; k <= ZR_OBJ_PARAMETRIC; k++) {
    if (tally.count[k] == 0)
      continue;
    zr_diag_place where = object_place(tally.first[k]);
    const char *why = k == ZR_OBJ_HEIGHT_FIELD
                          ? " (a height_field with water_level)"
                          : "";
    zr__diag(ctx, ZR_DIAG_WARNING, ZR_OK, &where,
             "radiosity: %zu %s object%s%s take%s no part (they neither "
             "receive nor give radiosity light; the first is here)",
             tally.count[k], zr__rad_kind_name((zr_object_kind)k),
             tally.count[k] == 1 ? "" : "s", why,
             tally.count[k] == 1 ? "s" : "");
  }
  if (rad->n_surfs == 0)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ESCENE, NULL,
                    "radiosity: the scene has no finite surface to solve "
                    "on (an infinite plane alone has no bounds)");
  /* With every surface made (res needs the total area): each emitting
     side shoots the share of its light that gets away from it
     (side_openness), energy is shared, and the power the thresholds
     scale by is summed, object by object in the order they came. */
  double res = 2.0 * sqrt(rad->params.area_eps * rad->total_area);
  for (size_t k = 0; k < rad->n_objects; k++) {
    const zr__rad_object_entry *e = &rad->objects[k];
    /* A textured mesh's copies share the mesh's surfaces. */
    if (e->count == 0 || rad->surfs[e->first].object != e->object)
      continue;
    int sides = emitting_sides(rad, e->object);
    bool open = rad->params.one_sided_emission == 2 &&
                finish_emits(e->object);
    for (uint32_t i = 0; i < e->count; i++) {
      zr__rad_surface *s = &rad->surfs[e->first + i];
      for (int side = 0; open && side < 2; side++)
        if (sides >> side & 1) {
          s->open[side] = side_openness(rad, s, side, res);
          for (int c = 0; c < 3; c++) {
            s->emission[side][c] *= s->open[side];
            rad->nodes[s->root].b[side][c] = s->emission[side][c];
          }
        }
      double p[3];
      for (int c = 0; c < 3; c++)
        p[c] = s->area * (s->emission[0][c] + s->emission[1][c]);
      rad->power_ref += zr__rad_max3(p);
    }
    add_energy(rad, e, sides);
  }
  qsort(rad->objects, rad->n_objects, sizeof *rad->objects, entry_cmp);
  return ZR_OK;
}

const zr__rad_object_entry *zr__rad_object_find(const zr_radiosity *rad,
                                                const zr_object *object) {
  size_t lo = 0, hi = rad->n_objects;
  uintptr_t key = (uintptr_t)object;
  while (lo < hi) {
    size_t mid = lo + (hi - lo) / 2;
    uintptr_t at = (uintptr_t)rad->objects[mid].object;
    if (at == key)
      return &rad->objects[mid];
    if (at < key)
      lo = mid + 1;
    else
      hi = mid;
  }
  return NULL;
}
