/*
 * preview.c - a scene as coloured triangles and lines, for a previewer
 * that draws it with OpenGL instead of tracing it (zrcube-gtk; the
 * public contract is zr_scene_preview in include/zrcube.h).
 *
 * The triangles come from the exact parametric surfaces the
 * hierarchical radiosity solver meshes (surface.c, through
 * zr__rad_primitive_surfaces in mesh.c): one set of surfaces for both,
 * so the previewer shows the geometry radiosity sees, and a primitive
 * that gains a surface there gains it here.  Each surface is sampled on
 * a grid of cells in its (u, v) square, two triangles a cell, with the
 * surface's own normals at the corners; a triangle keeps its three
 * corners as they are and a mesh its faces.  The parts of a CSG
 * intersection, difference or merge lose the cells whose centre the
 * solid does not keep, the inside test radiosity trims them with
 * (trim.c).  A triangle's colour is its object's pigment evaluated at
 * the triangle's centre, so a checker or gradient shows at the grid's
 * resolution.  What has no surface yet is drawn as the edges of its
 * world bounding box, which at least shows where and how large it is.
 */
#include "radiosity/radiosity.h"

#include <stdlib.h>
#include <string.h>

#include "core/context.h"
#include "scene/texture.h"
#include "trace/intersect.h"
#include "trace/obj_mesh.h"

/* Default and largest cells a side on a curved surface.  24 draws a
   sphere of 1152 triangles whose outline is within 1 - cos(pi / 24),
   under 1%, of the radius; 256 keeps one surface under 2^17
   triangles. */
#define DEFAULT_DETAIL 24
#define MAX_DETAIL 256

struct zr_preview {
  float *tri_xyz, *tri_normal, *tri_rgb;
  size_t n_tris, cap_tris;
  float *line_xyz, *line_rgb;
  size_t n_lines, cap_lines;
  zr_preview_camera camera;
  zr_preview_info info;
};

static bool grow(float **p, size_t *cap, size_t need, size_t unit) {
  if (need <= *cap)
    return true;
  size_t n = *cap ? *cap : 1024;
  while (n < need)
    n *= 2;
  float *q = realloc(*p, n * unit * sizeof(float));
  if (q == NULL)
    return false;
  *p = q;
  *cap = n;
  return true;
}

static bool reserve_tris(zr_preview *pv, size_t more) {
  size_t need = pv->n_tris + more, cap = pv->cap_tris;
  size_t c1 = cap, c2 = cap;
  if (!grow(&pv->tri_xyz, &cap, need, 9) ||
      !grow(&pv->tri_normal, &c1, need, 9) ||
      !grow(&pv->tri_rgb, &c2, need, 3))
    return false;
  pv->cap_tris = cap;
  return true;
}

static void put3(float *dst, zr_vec3 v) {
  dst[0] = (float)v.x;
  dst[1] = (float)v.y;
  dst[2] = (float)v.z;
}

/* The object's pigment at p (normal n), as linear rgb. */
static zr_rgb object_colour(const zr_object *o, zr_vec3 p, zr_vec3 n) {
  const zr_texture *tex = o->texture;
  if (tex == NULL || tex->pigment == NULL)
    return zr_rgb3(1.0, 1.0, 1.0);
  zr_rgb c = zr_colour_rgb(zr__pigment_eval_n(tex->pigment, p, n));
  if (!(isfinite(c.r) && isfinite(c.g) && isfinite(c.b)))
    return zr_rgb3(1.0, 0.0, 1.0);
  return c;
}

/* Adds the triangle a, b, c (normals na, nb, nc); room is reserved. */
static void add_tri(zr_preview *pv, const zr_object *o, const zr_vec3 p[3],
                    const zr_vec3 n[3]) {
  size_t t = pv->n_tris++;
  zr_vec3 centre = zr_v3_scale(zr_v3_add(zr_v3_add(p[0], p[1]), p[2]),
                               1.0 / 3.0);
  zr_vec3 nc = zr_v3_add(zr_v3_add(n[0], n[1]), n[2]);
  double len = zr_v3_len(nc);
  nc = len > 0.0 ? zr_v3_scale(nc, 1.0 / len) : nc;
  for (int k = 0; k < 3; k++) {
    put3(&pv->tri_xyz[9 * t + 3 * k], p[k]);
    put3(&pv->tri_normal[9 * t + 3 * k], n[k]);
  }
  zr_rgb c = object_colour(o, centre, nc);
  pv->tri_rgb[3 * t] = (float)c.r;
  pv->tri_rgb[3 * t + 1] = (float)c.g;
  pv->tri_rgb[3 * t + 2] = (float)c.b;
}

/* The flat normal of a triangle, (p1 - p0) x (p2 - p0) made unit (0
   for a triangle without area). */
static zr_vec3 flat_normal(const zr_vec3 p[3]) {
  zr_vec3 n = zr_v3_cross(zr_v3_sub(p[1], p[0]), zr_v3_sub(p[2], p[0]));
  double len = zr_v3_len(n);
  return len > 0.0 ? zr_v3_scale(n, 1.0 / len) : n;
}

/* A grid of cells x cells over surface s (trim: the CSG solid that
   keeps a cell by its centre, NULL for all). */
static bool add_grid(zr_preview *pv, const zr_object *o,
                     const zr__surface *s, const zr_object *trim,
                     int cells) {
  if (!reserve_tris(pv, 2 * (size_t)cells * (size_t)cells))
    return false;
  zr__rad_surface rs;
  memset(&rs, 0, sizeof rs);
  rs.geom = *s;
  rs.object = o;
  rs.trim = trim;
  for (int j = 0; j < cells; j++)
    for (int i = 0; i < cells; i++) {
      double u0 = (double)i / cells, u1 = (double)(i + 1) / cells;
      double v0 = (double)j / cells, v1 = (double)(j + 1) / cells;
      if (trim != NULL) {
        zr__surface_point mid;
        zr__surface_eval(s, 0.5 * (u0 + u1), 0.5 * (v0 + v1), &mid);
        if (!zr__rad_trim_keeps(&rs, mid.p))
          continue;
      }
      zr__surface_point q[4];
      zr__surface_eval(s, u0, v0, &q[0]);
      zr__surface_eval(s, u1, v0, &q[1]);
      zr__surface_eval(s, u1, v1, &q[2]);
      zr__surface_eval(s, u0, v1, &q[3]);
      /* Two triangles, each dropped when a pole collapses it. */
      static const int split[2][3] = {{0, 1, 2}, {0, 2, 3}};
      for (int h = 0; h < 2; h++) {
        zr_vec3 p[3], n[3];
        for (int k = 0; k < 3; k++) {
          p[k] = q[split[h][k]].p;
          n[k] = q[split[h][k]].n;
        }
        zr_vec3 f = flat_normal(p);
        if (zr_v3_len(f) == 0.0)
          continue;
        add_tri(pv, o, p, n);
      }
    }
  return true;
}

static bool add_triangle_surface(zr_preview *pv, const zr_object *o,
                                 const zr__surface *s,
                                 const zr_object *trim) {
  zr_vec3 p[3] = {s->p[0], s->p[1], s->p[2]};
  zr_vec3 f = flat_normal(p);
  if (zr_v3_len(f) == 0.0)
    return true;
  if (trim != NULL) {
    zr__rad_surface rs;
    memset(&rs, 0, sizeof rs);
    rs.geom = *s;
    rs.object = o;
    rs.trim = trim;
    zr_vec3 c = zr_v3_scale(zr_v3_add(zr_v3_add(p[0], p[1]), p[2]),
                            1.0 / 3.0);
    if (!zr__rad_trim_keeps(&rs, c))
      return true;
  }
  if (!reserve_tris(pv, 1))
    return false;
  /* The normal the surface reports (outwards), on every corner. */
  zr__surface_point pt;
  zr__surface_eval(s, 1.0 / 3.0, 0.5, &pt);
  zr_vec3 n[3] = {pt.n, pt.n, pt.n};
  add_tri(pv, o, p, n);
  return true;
}

static bool add_mesh_surface(zr_preview *pv, const zr_object *o,
                             const zr__surface *s) {
  if (!reserve_tris(pv, s->n_faces))
    return false;
  /* A face with a texture from the mesh's texture_list is coloured by
     it: the copy of the object that carries it (obj_mesh.h), chosen by
     the face's first corner as a flat triangle can show one. */
  const struct zr_mesh *mesh = s->mesh;
  for (size_t f = 0; f < s->n_faces; f++) {
    zr__mesh_face face;
    if (!zr__surface_mesh_tri(s, f, &face))
      continue;
    zr_vec3 n[3] = {face.n, face.n, face.n};
    const zr_object *textured = o;
    if (o->kind == ZR_OBJ_MESH && mesh->face_textures != NULL)
      textured = zr__mesh_hit_object(o, mesh->face_textures[f][0]);
    add_tri(pv, textured, face.p, n);
  }
  return true;
}

/* The 12 edges of o's world bounding box [lo, hi]. */
static bool add_box_lines(zr_preview *pv, const zr_object *o, zr_vec3 lo,
                          zr_vec3 hi) {
  size_t cap = pv->cap_lines, c1 = cap;
  if (!grow(&pv->line_xyz, &cap, pv->n_lines + 12, 6) ||
      !grow(&pv->line_rgb, &c1, pv->n_lines + 12, 3))
    return false;
  pv->cap_lines = cap;
  zr_vec3 centre = zr_v3_scale(zr_v3_add(lo, hi), 0.5);
  zr_rgb c = object_colour(o, centre, zr_v3(0.0, 0.0, 0.0));
  zr_vec3 corner[8];
  for (int k = 0; k < 8; k++)
    corner[k] = zr_v3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y,
                      k & 4 ? hi.z : lo.z);
  /* Corners k and k | bit, for each corner without that bit. */
  for (int k = 0; k < 8; k++)
    for (int bit = 1; bit < 8; bit <<= 1) {
      if (k & bit)
        continue;
      size_t l = pv->n_lines++;
      put3(&pv->line_xyz[6 * l], corner[k]);
      put3(&pv->line_xyz[6 * l + 3], corner[k | bit]);
      pv->line_rgb[3 * l] = (float)c.r;
      pv->line_rgb[3 * l + 1] = (float)c.g;
      pv->line_rgb[3 * l + 2] = (float)c.b;
    }
  return true;
}

/* Cells a side for surface s: curved ones detail, flat faces fewer (a
   quarter, at least 1: enough for a pattern to show), an infinite
   plane's patch more (twice, so a checker floor reads as one). */
static int surface_cells(const zr_object *o, const zr__surface *s,
                         int detail) {
  if (o->kind == ZR_OBJ_PLANE)
    return 2 * detail;
  if (s->kind == ZR__SURFACE_PARALLELOGRAM) {
    int n = detail / 4;
    return n > 0 ? n : 1;
  }
  return detail;
}

/* Adds primitive o (not a CSG node), trimmed by the solid trim (NULL:
   whole). */
static bool add_primitive(zr_preview *pv, const zr_object *o,
                          const zr_vec3 *lo, const zr_vec3 *hi,
                          const zr_object *trim, int detail) {
  size_t faces;
  bool modelled = zr__rad_models(o, &faces) && o->kind != ZR_OBJ_HEIGHT_FIELD;
  zr__surface geo[6];
  int n = -1;
  if (modelled) {
    const struct zr_mesh *mesh =
        o->kind == ZR_OBJ_MESH ? o->u.mesh.data : NULL;
    n = zr__rad_primitive_surfaces(o, mesh, lo, hi, geo);
  }
  /* A polygon's rectangle is cut to the polygon by trim.c's test, as
     for radiosity, and so is a clipped_by object to its clip (the test
     checks both when the object is its own trim); in a CSG solid, trim
     cuts what the solid does not keep, the part's own polygon and clip
     included. */
  const zr_object *cut =
      trim                                               ? trim
      : o->kind == ZR_OBJ_POLYGON || o->clip != NULL ? o
                                                         : NULL;
  if (n > 0) {
    for (int i = 0; i < n; i++) {
      bool ok;
      if (geo[i].kind == ZR__SURFACE_MESH)
        ok = add_mesh_surface(pv, o, &geo[i]);
      else if (geo[i].kind == ZR__SURFACE_TRIANGLE)
        ok = add_triangle_surface(pv, o, &geo[i], cut);
      else
        ok = add_grid(pv, o, &geo[i], cut, surface_cells(o, &geo[i], detail));
      if (!ok)
        return false;
    }
    pv->info.objects_as_triangles++;
    return true;
  }
  zr_vec3 a, b;
  if (o->kind != ZR_OBJ_PLANE && zr__object_bounds(o, &a, &b) &&
      a.x <= b.x && a.y <= b.y && a.z <= b.z && isfinite(a.x) &&
      isfinite(a.y) && isfinite(a.z) && isfinite(b.x) && isfinite(b.y) &&
      isfinite(b.z)) {
    pv->info.objects_as_boxes++;
    return add_box_lines(pv, o, a, b);
  }
  pv->info.objects_left_out++;
  return true;
}

static bool add_parts(zr_preview *pv, const zr_object *node,
                      const zr_object *solid, const zr_vec3 *lo,
                      const zr_vec3 *hi, int detail) {
  if (!zr__is_csg(node->kind))
    return add_primitive(pv, node, lo, hi, solid, detail);
  for (size_t i = 0; i < node->u.csg.n_children; i++)
    if (!add_parts(pv, node->u.csg.children[i], solid, lo, hi, detail))
      return false;
  return true;
}

static void get3(double dst[3], zr_vec3 v) {
  dst[0] = v.x;
  dst[1] = v.y;
  dst[2] = v.z;
}

zr_status zr_scene_preview(zr_context *ctx, const zr_scene *scene,
                           int detail, zr_preview **out) {
  if (out != NULL)
    *out = NULL;
  if (scene == NULL || out == NULL || detail < 0 || detail > MAX_DETAIL)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL,
                    "zr_scene_preview: detail %d is outside 0 .. %d, or "
                    "the scene or result is NULL",
                    detail, MAX_DETAIL);
  if (detail == 0)
    detail = DEFAULT_DETAIL;
  zr_preview *pv = calloc(1, sizeof *pv);
  if (pv == NULL)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL,
                    "zr_scene_preview: out of memory");
  const zr_camera *cam = &scene->camera;
  get3(pv->camera.location, cam->location);
  get3(pv->camera.direction, cam->direction);
  get3(pv->camera.up, cam->up);
  get3(pv->camera.right, cam->right);
  get3(pv->camera.sky, cam->sky);
  pv->camera.perspective = cam->kind == ZR_CAMERA_PERSPECTIVE;
  pv->camera.given = cam->given;
  zr_vec3 blo, bhi;
  (void)zr__rad_finite_bounds(scene, &blo, &bhi); /* empty: +inf, -inf */
  get3(pv->info.lo, blo);
  get3(pv->info.hi, bhi);
  zr_vec3 lo, hi;
  bool bounded = zr__rad_plane_bounds(scene, &lo, &hi);
  const zr_vec3 *l = bounded ? &lo : NULL, *h = bounded ? &hi : NULL;
  for (size_t i = 0; i < scene->n_primitives; i++) {
    const zr_object *o = scene->primitives[i];
    bool ok = zr__is_csg(o->kind) ? add_parts(pv, o, o, l, h, detail)
                                  : add_primitive(pv, o, l, h, NULL, detail);
    if (!ok) {
      size_t tris = pv->n_tris;
      zr_preview_free(pv);
      return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL,
                      "zr_scene_preview: out of memory after %zu triangles",
                      tris);
    }
  }
  pv->info.triangles = pv->n_tris;
  pv->info.lines = pv->n_lines;
  *out = pv;
  return ZR_OK;
}

void zr_preview_free(zr_preview *preview) {
  if (preview == NULL)
    return;
  free(preview->tri_xyz);
  free(preview->tri_normal);
  free(preview->tri_rgb);
  free(preview->line_xyz);
  free(preview->line_rgb);
  free(preview);
}

void zr_preview_get_info(const zr_preview *preview, zr_preview_info *info) {
  *info = preview->info;
}

void zr_preview_get_camera(const zr_preview *preview,
                           zr_preview_camera *camera) {
  *camera = preview->camera;
}

size_t zr_preview_triangles(const zr_preview *preview, const float **xyz,
                            const float **normal, const float **rgb) {
  if (xyz != NULL)
    *xyz = preview->tri_xyz;
  if (normal != NULL)
    *normal = preview->tri_normal;
  if (rgb != NULL)
    *rgb = preview->tri_rgb;
  return preview->n_tris;
}

size_t zr_preview_lines(const zr_preview *preview, const float **xyz,
                        const float **rgb) {
  if (xyz != NULL)
    *xyz = preview->line_xyz;
  if (rgb != NULL)
    *rgb = preview->line_rgb;
  return preview->n_lines;
}
