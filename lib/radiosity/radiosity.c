/*
 * radiosity.c - the public radiosity API: parameters, the solve driver,
 * statistics, and the lookup a ray hit makes into the solution.
 *
 * The driver follows Hanrahan, Salzman and Aupperle (SIGGRAPH 1991):
 * build the exact surfaces (mesh.c), link every pair of surfaces that
 * see each other and refine those links with the oracle (refine.c),
 * then alternate solving (solve.c) with re-refining the links whose
 * brightness-weighted factor B F A the new solution shows too large,
 * until nothing changes or the rounds run out.  Curved surfaces start
 * split in 4 x 4 cells (quarter turns of the NURBS circle and quarters
 * of the profile), since a single cell's centre says little about where
 * a whole sphere faces.  Uniform mode, for comparisons, splits every
 * surface into 2^n x 2^n cells and links every pair of leaves, with no
 * refinement.  Thresholds are relative: BF_eps to the scene's emitted
 * power and A_eps to its total surface area, so the mesh of a scene does
 * not change when it is scaled or brightened.
 *
 * Lookup.  A hit gives the object and the world point; the object's
 * surfaces (a box has six) each invert the point to (u,v)
 * (zr__surface_locate) and the one whose S(u,v) lies closest holds it.
 * The leaf there interpolates its smoothed corner values bilinearly
 * (quadtree.c), from the side the ray arrives on.  The result is a
 * radiance, B / pi.
 */
#include "radiosity/radiosity.h"

#include <stdlib.h>
#include <string.h>

ZR_API void zr_radiosity_params_init(zr_radiosity_params *p,
                                     const zr_scene *scene) {
  (void)scene; /* no radiosity block in the scene model yet */
  memset(p, 0, sizeof *p);
  p->bf_eps = 1e-4;
  p->area_eps = 1e-4;
  p->visibility_rays = 4;
  p->max_iterations = 1000;
  p->residual = 1e-6;
  p->refine_rounds = 6;
  p->uniform = 0;
  p->shooting = 0;
}

static zr_status check_params(zr_context *ctx, const zr_radiosity_params *p) {
  const char *what = NULL;
  if (!(p->bf_eps >= 0.0) || !isfinite(p->bf_eps))
    what = "bf_eps must be a finite number >= 0";
  else if (!(p->area_eps > 0.0 && p->area_eps < 1.0))
    what = "area_eps must lie between 0 and 1";
  else if (p->visibility_rays < 1 || p->visibility_rays > 16)
    what = "visibility_rays must be 1 to 16";
  else if (p->max_iterations < 1)
    what = "max_iterations must be at least 1";
  else if (!(p->residual > 0.0) || !isfinite(p->residual))
    what = "residual must be a finite number > 0";
  else if (p->refine_rounds < 0)
    what = "refine_rounds must be >= 0";
  else if (p->uniform < 0 || p->uniform > 10)
    what = "uniform must be 0 to 10";
  else if (p->criterion < 0 || p->criterion > 1)
    what = "criterion must be 0 (BF) or 1 (error estimate)";
  if (what == NULL)
    return ZR_OK;
  return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL, "radiosity: %s",
                  what);
}

zr_status zr__rad_create(zr_context *ctx, const zr_scene *scene,
                         const zr_radiosity_params *params,
                         zr_radiosity **out) {
  *out = NULL;
  zr_radiosity_params defaults;
  if (params == NULL) {
    zr_radiosity_params_init(&defaults, scene);
    params = &defaults;
  }
  zr_status st = check_params(ctx, params);
  if (st != ZR_OK)
    return st;
  zr_radiosity *rad = calloc(1, sizeof *rad);
  if (rad == NULL)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL,
                    "radiosity: out of memory");
  rad->scene = scene;
  rad->params = *params;
  rad->fingerprint = zr__rad_fingerprint(scene);
  /* Different orders, so a self link's two rules never share a point. */
  zr__gauss_rule_init(&rad->rule_recv, 4);
  zr__gauss_rule_init(&rad->rule_src, 5);
  st = zr__rad_mesh_build(rad, ctx);
  if (st != ZR_OK) {
    zr_radiosity_free(rad);
    return st;
  }
  rad->area_eps_abs = params->area_eps * rad->total_area;
  *out = rad;
  return ZR_OK;
}

void zr__rad_count(zr_radiosity *rad) {
  zr_radiosity_stats *s = &rad->stats;
  s->surfaces = rad->n_surfs;
  s->nodes = rad->n_nodes;
  s->vertices = rad->n_verts;
  s->elements = 0;
  for (size_t n = 0; n < rad->n_nodes; n++)
    s->elements += rad->nodes[n].child < 0;
}

/* Curved surfaces start in 4 x 4 cells; uniform mode splits all. */
static zr_status initial_split(zr_radiosity *rad) {
  if (rad->params.uniform > 0)
    return zr__rad_uniform(rad, rad->params.uniform);
  for (size_t s = 0; s < rad->n_surfs; s++) {
    if (rad->surfs[s].geom.planar)
      continue;
    int32_t root = rad->surfs[s].root;
    if (!zr__rad_subdivide(rad, root))
      return ZR_ENOMEM;
    for (int k = 0; k < 4; k++)
      if (!zr__rad_subdivide(rad, rad->nodes[root].child + k))
        return ZR_ENOMEM;
  }
  return ZR_OK;
}

/* Link, then alternate solving and refining. */
static zr_status solve_rounds(zr_radiosity *rad, zr_context *ctx) {
  zr_status st = initial_split(rad);
  if (st == ZR_OK)
    st = zr__rad_link_all(rad);
  int round = 0;
  while (st == ZR_OK) {
    zr__rad_finish_links(rad);
    zr__rad_compact_links(rad);
    st = zr__rad_solve(rad, ctx);
    if (st != ZR_OK || rad->params.uniform > 0 ||
        round >= rad->params.refine_rounds)
      break;
    size_t changed = 0;
    st = zr__rad_refine_links(rad, &changed);
    if (changed == 0)
      break;
    round++;
  }
  rad->stats.refine_rounds = round;
  if (st == ZR_ENOMEM)
    return zr__diag(ctx, ZR_DIAG_ERROR, st, NULL,
                    "radiosity: out of memory refining links");
  return st;
}

ZR_API zr_status zr_radiosity_solve(zr_context *ctx, const zr_scene *scene,
                                    const zr_radiosity_params *params,
                                    zr_radiosity **out) {
  *out = NULL;
  if (scene == NULL)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL,
                    "radiosity: no scene");
  zr_radiosity *rad;
  zr_status st = zr__rad_create(ctx, scene, params, &rad);
  if (st != ZR_OK)
    return st;
  if (!(rad->power_ref > 0.0))
    zr__diag(ctx, ZR_DIAG_WARNING, ZR_OK, NULL,
             "radiosity: no surface emits light (finish { emission }), "
             "so the solution is black");
  st = solve_rounds(rad, ctx);
  if (st != ZR_OK) {
    zr_radiosity_free(rad);
    return st;
  }
  zr__rad_energy(rad);
  zr__rad_smooth(rad);
  zr__rad_count(rad);
  rad->stats.links = rad->n_links;
  *out = rad;
  return ZR_OK;
}

ZR_API void zr_radiosity_free(zr_radiosity *rad) {
  if (rad == NULL)
    return;
  zr__rad_free_arrays(rad);
  free(rad);
}

ZR_API void zr_radiosity_get_stats(const zr_radiosity *rad,
                                   zr_radiosity_stats *stats) {
  *stats = rad->stats;
}

/* The surface of the entry nearest to point, with its (u,v) and normal. */
static size_t nearest_surface(const zr_radiosity *rad,
                              const zr__rad_object_entry *e, zr_vec3 point,
                              double *u, double *v, zr_vec3 *normal) {
  double best = INFINITY;
  size_t found = e->first;
  for (uint32_t k = 0; k < e->count; k++) {
    const zr__surface *g = &rad->surfs[e->first + k].geom;
    double a, b;
    zr__surface_locate(g, point, &a, &b);
    zr__surface_point pt;
    zr__surface_eval(g, a, b, &pt);
    zr_vec3 d = zr_v3_sub(pt.p, point);
    double dist = zr_v3_dot(d, d);
    if (dist < best) {
      best = dist;
      found = e->first + k;
      *u = a;
      *v = b;
      *normal = pt.n;
    }
  }
  return found;
}

bool zr__radiosity_radiance(const zr_radiosity *rad, const zr_object *object,
                            zr_vec3 point, zr_vec3 dir, zr_rgb *out) {
  *out = zr_rgb3(0.0, 0.0, 0.0);
  const zr__rad_object_entry *e = zr__rad_object_find(rad, object);
  if (e == NULL || e->count == 0)
    return false;
  double u = 0.0, v = 0.0;
  zr_vec3 n = zr_v3(0, 0, 0);
  size_t s = nearest_surface(rad, e, point, &u, &v, &n);
  int side = zr_v3_dot(dir, n) > 0.0; /* arriving from behind: back */
  int32_t leaf = zr__rad_leaf_at(rad, (int32_t)s, u, v);
  double b[3];
  zr__rad_interpolate(rad, leaf, side, u, v, b);
  *out = zr_rgb3(fmax(0.0, b[0]) / M_PI, fmax(0.0, b[1]) / M_PI,
                 fmax(0.0, b[2]) / M_PI);
  return true;
}
