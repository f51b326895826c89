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
 * By default the radiance there is a final gather (the "local pass" of
 * hierarchical radiosity renderers, e.g. Lischinski, Tampieri and
 * Greenberg 1993; Smits, Arvo and Greenberg 1994): the links that the
 * leaf and its ancestors gather from are evaluated again from the point
 * itself, with the exact point-to-polygon factor, the source's solved
 * radiosity (its children's where the point is near it) and, for
 * emitters and partly hidden sources, the point's own visibility.  On
 * the Cornell box this halves the error of reading the elements'
 * smoothed corner values (lookup 1, quadtree.c).  The result is a
 * radiance, B / pi.
 */
#include "radiosity/radiosity.h"

#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "core/budget.h"
#include "core/team.h"
#include "radiosity/formfactor.h"
#include "trace/obj_mesh.h"

ZR_API void zr_radiosity_params_init(zr_radiosity_params *p,
                                     const zr_scene *scene) {
  memset(p, 0, sizeof *p);
  p->size = sizeof *p;
  p->bf_eps = 1e-4;
  p->area_eps = 1e-4;
  p->visibility_rays = 4;
  p->max_iterations = 1000;
  p->residual = 1e-6;
  p->refine_rounds = 6;
  p->uniform = 0;
  p->shooting = 0;
  p->brightness = 1.0;
  p->max_mesh_faces = 0;
  p->cluster_surfaces = 64;
  /* A flat emitter shines from both sides and a closed one from its
     outside, each side by the share of its light that gets away from
     it (mesh.c): povray shows emission on both sides, and a lamp hung
     0.01 below the ceiling (the Cornell box's) sends its back's light
     into a gap it does not leave (zrcube(1) explains the choice).  The
     command line takes this default too. */
  p->one_sided_emission = 2;
  p->bounces = 0;
  if (scene == NULL)
    return;
  /* The scene's radiosity block (lib/sdl/build_radiosity.c): zRcube's
     items are 0 when not written, and the parser checked their range. */
  const zr_radiosity_settings *r = &scene->settings.radiosity;
  p->brightness = r->brightness;
  if (r->bf_eps > 0.0)
    p->bf_eps = r->bf_eps;
  if (r->area_eps > 0.0)
    p->area_eps = r->area_eps;
  if (r->residual > 0.0)
    p->residual = r->residual;
  if (r->visibility_rays > 0)
    p->visibility_rays = r->visibility_rays;
  if (r->max_iterations > 0)
    p->max_iterations = r->max_iterations;
  /* POV-Ray's radiosity stops at recursion_limit bounces (default 2;
     manual, "recursion_limit"), and so does the solve of a scene that
     comes with a radiosity block: measured in a closed room lit by an
     emitting lamp (tests/gi_bounce.pov, bench/gi_bounce.sh), povray's
     picture follows the limit bounce by bounce, and the converged
     solution was 1.8 times povray's at the default 2. */
  if (r->on)
    p->bounces = r->recursion_limit > 0 ? r->recursion_limit : 2;
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
  else if ((int)p->criterion < 0 || (int)p->criterion > 1)
    what = "criterion must be 0 (BF) or 1 (error estimate)";
  else if ((int)p->lookup < 0 || (int)p->lookup > 1)
    what = "lookup must be 0 (final gather) or 1 (smoothed elements)";
  else if (!(p->brightness >= 0.0) || !isfinite(p->brightness))
    what = "brightness must be a finite number >= 0";
  else if (p->threads < 0)
    what = "threads must be >= 0";
  else if (p->bounces < 0)
    what = "bounces must be >= 0 (0: every bounce)";
  else if (p->one_sided_emission < 0 || p->one_sided_emission > 2)
    what = "one_sided_emission must be 0 (both sides), 1 (front) or 2 "
           "(open sides)";
  if (what == NULL)
    return ZR_OK;
  return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL, "radiosity: %s",
                  what);
}

/* The message for a solve stopped by the memory budget. */
static zr_status over_budget(zr_context *ctx) {
  return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ELIMIT, NULL,
                  "radiosity: the solution's elements and links do not "
                  "fit in the memory budget of %llu bytes (raise it with "
                  "--memory-limit, or coarsen the solution with a larger "
                  "--bf-eps or --area-eps)",
                  (unsigned long long)zr_context_memory_limit(ctx));
}

/* The tracer's view of a solution (lib/trace/shade.h). */
_Static_assert(offsetof(struct zr_radiosity, source) == 0,
               "the tracer reads a solution as its first member");
static bool source_radiance(const zr_radiance_source *self,
                            const zr_object *object, zr_vec3 p, zr_vec3 d,
                            zr_rgb *out) {
  return zr__radiosity_radiance((const zr_radiosity *)(const void *)self,
                                object, p, d, out);
}

zr_status zr__rad_create(zr_context *ctx, const zr_scene *scene,
                         const zr_radiosity_params *params,
                         zr_radiosity **out) {
  *out = NULL;
  /* The caller's parameters over the defaults (zrcube.h: a struct's
     size says which members it has). */
  zr_radiosity_params taken;
  zr_radiosity_params_init(&taken, scene);
  if (params &&
      zr__params_take(&taken, sizeof taken, params, sizeof taken) != ZR_OK)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL,
                    "radiosity: the parameters were not made by "
                    "zr_radiosity_params_init() (their size is %zu)",
                    params->size);
  params = &taken;
  zr_status st = check_params(ctx, params);
  if (st != ZR_OK)
    return st;
  zr_radiosity *rad = calloc(1, sizeof *rad);
  if (rad == NULL)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL,
                    "radiosity: out of memory");
  rad->scene = scene;
  rad->source.radiance = source_radiance;
  rad->source.scene = scene;
  rad->params = *params;
  rad->budget = ctx ? zr__budget_ref(ctx->budget) : NULL;
  rad->fingerprint = zr__rad_fingerprint(scene);
  /* Different orders, so a self link's two rules never share a point. */
  zr__gauss_rule_init(&rad->rule_recv, 4);
  zr__gauss_rule_init(&rad->rule_src, 5);
  st = zr__rad_mesh_build(rad, ctx);
  if (st != ZR_OK) {
    bool budget = rad->over_budget;
    zr_radiosity_free(rad);
    return budget ? over_budget(ctx) : st;
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
    /* A mesh's faces are planar; its clusters split as links ask. */
    if (rad->surfs[s].geom.planar ||
        rad->surfs[s].geom.kind == ZR__SURFACE_MESH)
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

/* With a team, every member's status after a step that may fail on one
   member alone (out of memory): all then go on, or all stop, and none
   waits in an exchange the others have left.  Alone: st. */
static zr_status agreed(const zr_radiosity *rad, zr_status st) {
  return zr__team_size(rad->params.team) > 1
             ? zr__team_agree(rad->params.team, st)
             : st;
}

zr_status zr__rad_progress(zr_radiosity *rad) {
  return zr__progress(rad->progress_ctx, ZR_PHASE_RADIOSITY,
                      rad->progress_done, rad->progress_total);
}

/* Link, then alternate solving and refining. */
static zr_status solve_rounds(zr_radiosity *rad, zr_context *ctx) {
  rad->progress_ctx = ctx;
  rad->progress_done = 0;
  rad->progress_total =
      rad->params.uniform > 0 ? 1 : (uint64_t)rad->params.refine_rounds + 1;
  zr_status st = zr__rad_progress(rad);
  if (st == ZR_OK)
    st = initial_split(rad);
  /* Cells a CSG trim crosses go down to A_eps (trim.c). */
  if (st == ZR_OK && rad->params.uniform == 0)
    st = zr__rad_trim_split(rad);
  /* Light sources first, so links start from lit sources (direct.c). */
  if (st == ZR_OK)
    st = zr__rad_direct_refine(rad);
  /* Volume clusters of surfaces over the cells made so far (volume.c). */
  if (st == ZR_OK)
    st = zr__rad_vol_build(rad);
  st = agreed(rad, st);
  if (st == ZR_OK)
    st = agreed(rad, zr__rad_link_all(rad));
  int round = 0;
  while (st == ZR_OK) {
    zr__rad_direct_update(rad);
    st = zr__rad_finish_links(rad);
    if (st != ZR_OK)
      break;
    zr__rad_compact_links(rad);
    st = agreed(rad, zr__rad_solve(rad, ctx));
    if (st != ZR_OK || rad->params.uniform > 0 ||
        round >= rad->params.refine_rounds)
      break;
    rad->progress_done = (uint64_t)round + 1;
    st = zr__rad_progress(rad);
    if (st != ZR_OK)
      break;
    size_t changed = 0;
    st = agreed(rad, zr__rad_refine_links(rad, &changed));
    if (changed == 0)
      break;
    round++;
  }
  rad->progress_ctx = NULL;
  rad->stats.refine_rounds = round;
  if (st == ZR_ECANCELLED)
    return zr__diag(ctx, ZR_DIAG_ERROR, st, NULL,
                    "radiosity: the solve was cancelled");
  if (st != ZR_OK && rad->over_budget)
    return over_budget(ctx);
  if (st == ZR_ENOMEM)
    return zr__diag(ctx, ZR_DIAG_ERROR, st, NULL,
                    "radiosity: out of memory refining links");
  if (st == ZR_EMPI)
    return zr__diag(ctx, ZR_DIAG_ERROR, st, NULL,
                    "radiosity: the processes solving together could not "
                    "exchange their parts of the solution");
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
  const zr_team *team = params ? params->team : NULL;
  if (zr__team_size(team) > 1) {
    zr_status all = zr__team_agree(team, st);
    if (all != ZR_OK && st == ZR_OK) {
      zr_radiosity_free(rad);
      return zr__diag(ctx, ZR_DIAG_ERROR, all, NULL,
                      "radiosity: another process solving with this one "
                      "failed: %s", zr_status_str(all));
    }
  }
  if (st != ZR_OK)
    return st;
  zr__rad_direct_power(rad);
  /* The solver's transfer crosses no media; povray's radiosity rays
     cross them under "media on" (zr_gi_choose then picks the cache, so
     only an explicit choice of this solver gets here). */
  if (zr__rad_media_counts(scene))
    zr__diag(ctx, ZR_DIAG_WARNING, ZR_OK, NULL,
             "radiosity: the hierarchical solver carries no light "
             "through media, which the radiosity block's media on asks "
             "for (--gi=cache does)");
  if (!(rad->power_ref > 0.0))
    zr__diag(ctx, ZR_DIAG_WARNING, ZR_OK, NULL,
             scene->n_lights > 0
                 ? "radiosity: no surface emits light (finish { emission "
                   "}) and no light source reaches a surface, so the "
                   "solution is black"
                 : "radiosity: no surface emits light (finish { emission "
                   "}), so the solution is black");
  st = solve_rounds(rad, ctx);
  zr__rad_team_buffers_free(rad); /* the exchanges are over */
  if (st != ZR_OK) {
    zr_radiosity_free(rad);
    return st;
  }
  zr__rad_energy(rad);
  zr__rad_smooth(rad);
  zr__rad_count(rad);
  rad->stats.links = rad->n_links + zr__rad_vol_live(rad);
  rad->stats.visibility_rays += rad->vol_rays;
  if (agreed(rad, rad->params.lookup == 0 ? zr__rad_index_links(rad)
                                           : ZR_OK) != ZR_OK) {
    zr_radiosity_free(rad);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL,
                    "radiosity: out of memory indexing links");
  }
  *out = rad;
  return ZR_OK;
}

/* A source node's boundary polygon and its plane (plane.verts is p),
   for the final gather. */
typedef struct zr__rad_poly {
  zr__ff_polygon plane;
  zr_vec3 p[];
} zr__rad_poly;

/* A source node's visibility grid for k rays a side: the k x k points
   and outward normals of point_visibility, p[2i] and p[2i + 1]. */
typedef struct zr__rad_vgrid {
  int k;
  zr_vec3 p[];
} zr__rad_vgrid;

void zr__rad_free_poly_cache(zr_radiosity *rad) {
  for (size_t i = 0; i < rad->n_poly_cache; i++) {
    if (rad->poly_cache != NULL)
      free(atomic_load_explicit(&rad->poly_cache[i], memory_order_relaxed));
    if (rad->vis_cache != NULL)
      free(atomic_load_explicit(&rad->vis_cache[i], memory_order_relaxed));
  }
  free((void *)rad->poly_cache);
  free((void *)rad->vis_cache);
  rad->poly_cache = NULL;
  rad->vis_cache = NULL;
  rad->n_poly_cache = 0;
}

zr_status zr__rad_index_links(zr_radiosity *rad) {
  free(rad->recv_start);
  free(rad->recv_links);
  zr__rad_free_poly_cache(rad);
  rad->recv_start = calloc(rad->n_nodes + 2, sizeof *rad->recv_start);
  rad->recv_links = malloc((rad->n_links + 1) * sizeof *rad->recv_links);
  /* calloc's zero bytes are null pointers on every platform we build
     for; atomic pointers of that value are simply "not made yet". */
  rad->poly_cache = calloc(rad->n_nodes + 1, sizeof *rad->poly_cache);
  rad->vis_cache = calloc(rad->n_nodes + 1, sizeof *rad->vis_cache);
  rad->n_poly_cache = rad->n_nodes;
  if (rad->recv_start == NULL || rad->recv_links == NULL ||
      rad->poly_cache == NULL || rad->vis_cache == NULL) {
    zr__rad_free_poly_cache(rad);
    free(rad->recv_start);
    free(rad->recv_links);
    rad->recv_start = rad->recv_links = NULL;
    return ZR_ENOMEM;
  }
  /* A counting sort by receiver; links keep their order within one
     receiver, so the sums of a gather are the same on every run. */
  uint32_t *start = rad->recv_start;
  for (size_t i = 0; i < rad->n_links; i++)
    start[rad->links[i].recv + 2]++;
  for (size_t n = 2; n < rad->n_nodes + 2; n++)
    start[n] += start[n - 1];
  for (size_t i = 0; i < rad->n_links; i++)
    rad->recv_links[start[rad->links[i].recv + 1]++] = (uint32_t)i;
  return ZR_OK;
}

ZR_API void zr_radiosity_free(zr_radiosity *rad) {
  if (rad == NULL)
    return;
  zr__rad_team_buffers_free(rad);
  zr__rad_free_arrays(rad);
  zr__budget_release(rad->budget, rad->charged);
  zr__budget_unref(rad->budget);
  free(rad);
}

void zr__rad_team_buffers_free(zr_radiosity *rad) {
  zr__team_room_free(&rad->team_room);
  zr__team_room_free(&rad->team_send);
  zr__pack_free(&rad->team_pack);
}

bool zr__rad_charge(zr_radiosity *rad, size_t bytes) {
  if (!zr__budget_charge(rad->budget, bytes)) {
    rad->over_budget = true;
    return false;
  }
  if (rad->budget)
    rad->charged += bytes;
  return true;
}


ZR_API void zr_radiosity_get_stats(const zr_radiosity *rad,
                                   zr_radiosity_stats *stats) {
  *stats = rad->stats;
}

/* The face of mesh surface g that a ray with direction dir hits at
   point, from the mesh's own BVH: a short ray across the point. */
static bool mesh_hit_face(const zr__surface *g, zr_vec3 point, zr_vec3 dir,
                          size_t *face) {
  const zr_transform *xf = g->mesh_xf;
  zr_vec3 p = xf ? zr__xform_point(xf->inv, point) : point;
  zr_vec3 d = xf ? zr__xform_dir(xf->inv, dir) : dir;
  double dl = zr_v3_len(d);
  double size = zr_v3_len(zr_v3_sub(g->mesh->hi, g->mesh->lo));
  if (!(dl > 0.0) || !(size > 0.0))
    return false;
  double t0 = 1e-6 * size / dl;
  zr_mesh_crossing c[2];
  int n = zr__mesh_crossings(g->mesh, zr_v3_madd(p, d, -t0), d, 0.0,
                             2.0 * t0, c);
  if (n == 0)
    return false;
  int best = n == 2 && fabs(c[1].t - t0) < fabs(c[0].t - t0);
  *face = c[best].face;
  return true;
}

/* The surface of the entry nearest to point, with its (u,v) and normal. */
static size_t nearest_surface(const zr_radiosity *rad,
                              const zr__rad_object_entry *e, zr_vec3 point,
                              zr_vec3 dir, double *u, double *v,
                              zr_vec3 *normal) {
  const zr__surface *first = &rad->surfs[e->first].geom;
  size_t face;
  if (e->count == 1 && first->kind == ZR__SURFACE_MESH &&
      mesh_hit_face(first, point, dir, &face)) {
    zr__surface_mesh_locate_face(first, face, point, u, v);
    zr__surface_point pt;
    zr__surface_eval(first, *u, *v, &pt);
    *normal = pt.n;
    return e->first;
  }
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

int32_t zr__rad_hit_leaf(const zr_radiosity *rad, const zr_object *object,
                         zr_vec3 point, zr_vec3 dir, int *side) {
  const zr__rad_object_entry *e = zr__rad_object_find(rad, object);
  if (e == NULL || e->count == 0)
    return -1;
  double u = 0.0, v = 0.0;
  zr_vec3 n = zr_v3(0, 0, 0);
  size_t s = nearest_surface(rad, e, point, dir, &u, &v, &n);
  *side = zr_v3_dot(dir, n) > 0.0;
  return zr__rad_leaf_at(rad, (int32_t)s, u, v);
}

/*
 * The final gather: the incident radiosity H (irradiance / pi) at point,
 * normal n (the side's), over every link that the leaf and its
 * ancestors gather from on that side.  Each link's source is taken at
 * its mean radiosity, as the solution has it, but its form factor is the
 * exact one from this point (Lambert's contour formula over the source
 * cell's boundary), not the receiver's mean: the picture then follows
 * the light's variation inside an element and across the edges of
 * surfaces, where the elements' constant values show seams.  A link
 * that is partly occluded (a shadow's edge runs through it) gets its
 * visibility from this point too (point_visibility), so shadows are as
 * sharp as the sources are small; a fully visible link keeps 1.  A self
 * link (inside a curved surface) keeps its mean factor.
 */
/*
 * The visible fraction of source node q's side sside from point (normal
 * n, the receiving side's): k x k rays to the centres of a k x k grid
 * of the source's cell, as the link's own estimate but from this point
 * alone.  Points facing away on either end do not count, as in
 * refine.c.  The grid is the same for every point, so a penumbra varies
 * smoothly (in k^2 steps) instead of showing noise, which would also
 * make adaptive antialiasing take more samples.
 */
/* Source node qi's visibility grid (see zr__rad_vgrid) for k rays a
   side: from the cache (made on first use, as source_polygon's) or,
   when it cannot be kept, into buf (2 k^2 points). */
static const zr_vec3 *visibility_grid(const zr_radiosity *rad, int32_t qi,
                                      int k, zr_vec3 *buf) {
  bool cache = (size_t)qi < rad->n_poly_cache;
  if (cache) {
    zr__rad_vgrid *c =
        atomic_load_explicit(&rad->vis_cache[qi], memory_order_acquire);
    if (c != NULL && c->k == k)
      return c->p;
    cache = c == NULL;
  }
  const zr__rad_node *q = &rad->nodes[qi];
  double cell[4];
  zr__rad_node_cell(q, cell);
  for (int i = 0; i < k * k; i++) {
    zr__surface_point pt;
    zr__surface_eval(&rad->surfs[q->surf].geom,
                     cell[0] + (i % k + 0.5) / k * (cell[1] - cell[0]),
                     cell[2] + (i / k + 0.5) / k * (cell[3] - cell[2]), &pt);
    buf[2 * i] = pt.p;
    buf[2 * i + 1] = pt.n;
  }
  if (!cache)
    return buf;
  size_t np = 2 * (size_t)k * (size_t)k;
  zr__rad_vgrid *made = malloc(sizeof *made + np * sizeof made->p[0]);
  if (made == NULL)
    return buf;
  made->k = k;
  memcpy(made->p, buf, np * sizeof *buf);
  zr__rad_vgrid *expected = NULL;
  if (!atomic_compare_exchange_strong_explicit(
          &rad->vis_cache[qi], &expected, made, memory_order_acq_rel,
          memory_order_acquire))
    free(made);
  return buf;
}

/*
 * The visible fraction of source node q's side sside from point (normal
 * n, the receiving side's): k x k rays to the centres of a k x k grid
 * of the source's cell, as the link's own estimate but from this point
 * alone.  Points facing away on either end do not count, as in
 * refine.c.  The grid is the same for every point, so a penumbra varies
 * smoothly (in k^2 steps) instead of showing noise, which would also
 * make adaptive antialiasing take more samples.
 */
static double point_visibility(const zr_radiosity *rad, int32_t qi,
                               int sside, zr_vec3 point, zr_vec3 n) {
  int k = rad->params.visibility_rays, open = 0, cast = 0;
  double eps = 1e-7 * sqrt(rad->total_area);
  zr_vec3 buf[2 * 16 * 16];
  /* 1 to 16 rays a side (zr_radiosity_params); a saved solution read
     back with more is evaluated point by point, without the grid. */
  bool small = k >= 1 && k <= 16;
  const zr_vec3 *grid = small ? visibility_grid(rad, qi, k, buf) : NULL;
  zr_vec3 from = zr_v3_madd(point, n, eps);
  /* The rays of one point to one cell are mostly blocked, if at all, by
     the same surface: each asks first where the last was blocked. */
  zr_bvh_hint hint = {0};
  for (int i = 0; i < k * k; i++) {
    zr_vec3 gp, gn;
    if (small) {
      gp = grid[2 * i];
      gn = grid[2 * i + 1];
    } else {
      const zr__rad_node *q = &rad->nodes[qi];
      double cell[4];
      zr__surface_point pt;
      zr__rad_node_cell(q, cell);
      zr__surface_eval(&rad->surfs[q->surf].geom,
                       cell[0] + (i % k + 0.5) / k * (cell[1] - cell[0]),
                       cell[2] + (i / k + 0.5) / k * (cell[3] - cell[2]),
                       &pt);
      gp = pt.p;
      gn = pt.n;
    }
    zr_vec3 qn = sside ? zr_v3_neg(gn) : gn;
    zr_vec3 to = zr_v3_madd(gp, qn, eps);
    zr_vec3 d = zr_v3_sub(to, from);
    if (!(zr_v3_dot(d, n) > 0.0 && zr_v3_dot(d, qn) < 0.0))
      continue;
    cast++;
    if (!zr__rad_occluded_hint(rad, from, to, &hint))
      open++;
  }
  return cast > 0 ? (double)open / cast : 0.0;
}

/* Source node qi's boundary polygon and its plane: from the cache
   (made on first use; a thread that loses the race to publish frees its
   copy, which is the same, and takes the winner's) or, when it cannot
   be kept, a planar cell's corners or a curved cell's chords into buf
   and the plane into *tmp. */
static const zr__ff_polygon *source_polygon(const zr_radiosity *rad,
                                            int32_t qi, zr_vec3 *buf,
                                            zr__ff_polygon *tmp) {
  const zr__rad_node *q = &rad->nodes[qi];
  const zr__surface *g = &rad->surfs[q->surf].geom;
  double sc[4];
  bool cache = (size_t)qi < rad->n_poly_cache;
  if (cache) {
    zr__rad_poly *c = atomic_load_explicit(&rad->poly_cache[qi],
                                           memory_order_acquire);
    if (c != NULL)
      return &c->plane;
  }
  zr__rad_node_cell(q, sc);
  size_t nv = zr__surface_patch_polygon(g, sc[0], sc[1], sc[2], sc[3], 16,
                                        buf, 4 * ZR__FF_MAX_SEGS);
  zr__ff_polygon_init(tmp, buf, nv);
  if (!cache)
    return tmp;
  zr__rad_poly *made = malloc(sizeof *made + nv * sizeof made->p[0]);
  if (made == NULL)
    return tmp;
  memcpy(made->p, buf, nv * sizeof *buf);
  made->plane = *tmp;
  made->plane.verts = made->p;
  zr__rad_poly *expected = NULL;
  if (atomic_compare_exchange_strong_explicit(
          &rad->poly_cache[qi], &expected, made, memory_order_acq_rel,
          memory_order_acquire))
    return &made->plane;
  free(made);
  return &expected->plane; /* another thread's copy, the same values */
}

/*
 * The gather's terms wait in a queue, in the order they add to h, so
 * the exact factors of up to four sources are found at once
 * (zr__ff_point_polygons: lanes hide the latency of each contour sum)
 * and h is still summed term by term in that order: the same bits as
 * one source at a time.
 */
enum { GATHER_QUEUE = 32 };

typedef struct gather_term {
  const double *b;            /* the source's radiosity, the side's */
  const zr__ff_polygon *poly; /* NULL: f is the link's mean factor */
  double f, vis;
  int32_t qi;
  int sside;
  bool per_point;
} gather_term;

typedef struct gather {
  const zr_radiosity *rad;
  zr_vec3 point, n;
  double *h;
  int n_terms;
  gather_term terms[GATHER_QUEUE];
} gather;

/* The queue's factors found and its terms added to h in order. */
static void gather_flush(gather *g) {
  zr_vec3 ps[ZR__FF_LANES], ns[ZR__FF_LANES];
  const zr__ff_polygon *polys[ZR__FF_LANES];
  double ff[ZR__FF_LANES];
  gather_term *lane_of[ZR__FF_LANES];
  int lanes = 0;
  for (int i = 0; i < g->n_terms; i++) {
    gather_term *t = &g->terms[i];
    if (t->poly == NULL)
      continue;
    ps[lanes] = g->point;
    ns[lanes] = g->n;
    polys[lanes] = t->poly;
    lane_of[lanes++] = t;
    if (lanes == ZR__FF_LANES) {
      zr__ff_point_polygons((size_t)lanes, ps, ns, polys, 0.0, ff);
      for (int l = 0; l < lanes; l++)
        lane_of[l]->f = ff[l];
      lanes = 0;
    }
  }
  if (lanes > 0) {
    zr__ff_point_polygons((size_t)lanes, ps, ns, polys, 0.0, ff);
    for (int l = 0; l < lanes; l++)
      lane_of[l]->f = ff[l];
  }
  for (int i = 0; i < g->n_terms; i++) {
    const gather_term *t = &g->terms[i];
    double f = t->f;
    if (t->poly != NULL) {
      /* Only the part of the source that CSG keeps shines (trim.c). */
      f = g->rad->nodes[t->qi].kept * f;
      if (!(f > 0.0))
        continue;
      f *= t->per_point || t->vis < 1.0
               ? point_visibility(g->rad, t->qi, t->sside, g->point, g->n)
               : t->vis;
    }
    for (int c = 0; c < 3; c++)
      g->h[c] += f * t->b[c];
  }
  g->n_terms = 0;
}

static gather_term *gather_push(gather *g) {
  if (g->n_terms == GATHER_QUEUE)
    gather_flush(g);
  return &g->terms[g->n_terms++];
}

/* Adds source node q's (side sside) light at the point: the exact
   factor from the point times the node's mean radiosity, or, when the
   point is closer to q than twice q's size and q has children, the sum
   over the children, whose values say how the light varies inside q (a
   wall's radiosity falls towards the corner where it meets the wall
   holding the point).  vis: the link's visible fraction; below 1, or
   with per_point set, the point's own visibility replaces it. */
static void gather_source(gather *g, int32_t qi, int sside, double vis,
                          bool per_point) {
  const zr_radiosity *rad = g->rad;
  const zr__rad_node *q = &rad->nodes[qi];
  if (q->child >= 0) {
    zr_vec3 d = zr_v3_sub(q->centre, g->point);
    if (zr_v3_dot(d, d) < 4.0 * q->area) {
      for (int k = 0; k < 4; k++)
        gather_source(g, q->child + k, sside, vis, per_point);
      return;
    }
  }
  zr_vec3 buf[4 * ZR__FF_MAX_SEGS];
  zr__ff_polygon tmp;
  const zr__ff_polygon *poly = source_polygon(rad, qi, buf, &tmp);
  gather_term *t = gather_push(g);
  t->b = q->b[sside];
  t->poly = poly;
  t->vis = vis;
  t->qi = qi;
  t->sside = sside;
  t->per_point = per_point;
  if (poly == &tmp) {
    /* Not kept past this call (no memory for the cache): now. */
    t->f = zr__ff_point_polygon_pre(g->point, g->n, poly);
    t->poly = NULL;
    t->f = q->kept * t->f;
    if (!(t->f > 0.0)) {
      g->n_terms--;
      return;
    }
    t->f *= per_point || vis < 1.0
                ? point_visibility(rad, qi, sside, g->point, g->n)
                : vis;
  }
}

static void final_gather(const zr_radiosity *rad, int32_t leaf, int side,
                         zr_vec3 point, zr_vec3 n, double h[3]) {
  h[0] = h[1] = h[2] = 0.0;
  gather g;
  g.rad = rad;
  g.point = point;
  g.n = n;
  g.h = h;
  g.n_terms = 0;
  for (int32_t a = leaf; a >= 0; a = rad->nodes[a].parent)
    for (uint32_t k = rad->recv_start[a]; k < rad->recv_start[a + 1]; k++) {
      const zr__rad_link *l = &rad->links[rad->recv_links[k]];
      if (l->rside != side)
        continue;
      const zr__rad_node *q = &rad->nodes[l->src];
      /* A cluster of a mesh's faces keeps its mean factor too: its
         links are the faint ones, and its exact factor is a sum over
         every face (cluster.c). */
      if (l->src == l->recv || zr__rad_cluster(rad, q, NULL, NULL)) {
        gather_term *t = gather_push(&g);
        t->b = q->b[l->sside];
        t->poly = NULL;
        t->f = l->ff;
        continue;
      }
      /* Light straight from an emitter is where shadows are sharpest:
         every point tests its own visibility. */
      bool emitter = zr__rad_max3(rad->surfs[q->surf].emission[l->sside]) >
                     0.0;
      gather_source(&g, l->src, l->sside, l->vis, emitter);
    }
  gather_flush(&g);
  /* Cluster links keep their mean irradiance over the element. */
  if (rad->clustered)
    zr__rad_vol_incident(rad, leaf, side, h);
}

bool zr__radiosity_radiance(const zr_radiosity *rad, const zr_object *object,
                            zr_vec3 point, zr_vec3 dir, zr_rgb *out) {
  *out = zr_rgb3(0.0, 0.0, 0.0);
  const zr__rad_object_entry *e = zr__rad_object_find(rad, object);
  if (e == NULL || e->count == 0)
    return false;
  double u = 0.0, v = 0.0;
  zr_vec3 n = zr_v3(0, 0, 0);
  size_t s = nearest_surface(rad, e, point, dir, &u, &v, &n);
  int side = zr_v3_dot(dir, n) > 0.0; /* arriving from behind: back */
  int32_t leaf = zr__rad_leaf_at(rad, (int32_t)s, u, v);
  double b[3];
  if (rad->recv_start != NULL) {
    const zr__rad_surface *surf = &rad->surfs[s];
    double h[3];
    final_gather(rad, leaf, side, point, side ? zr_v3_neg(n) : n, h);
    for (int c = 0; c < 3; c++)
      b[c] = surf->shown[side][c] +
             rad->params.brightness * surf->rho[c] * h[c];
  } else {
    zr__rad_interpolate(rad, leaf, side, u, v, b);
    /* brightness scales the reflected part only, as in POV-Ray: the
       surface's own emission is constant over it. */
    const double *e = rad->surfs[s].emission[side];
    const double *shown = rad->surfs[s].shown[side];
    for (int c = 0; c < 3; c++)
      b[c] = shown[c] + rad->params.brightness * (b[c] - e[c]);
  }
  *out = zr_rgb3(fmax(0.0, b[0]) / M_PI, fmax(0.0, b[1]) / M_PI,
                 fmax(0.0, b[2]) / M_PI);
  return true;
}
