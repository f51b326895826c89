/*
 * direct.c - POV-Ray light sources (point, spot, cylinder, parallel and
 * area lights) shooting their direct light into the radiosity mesh, so
 * that it is carried onward as indirect light.
 *
 * A light source is not a surface: it has no quadtree and no links.  Its
 * light enters the radiosity equation of each leaf as a second source
 * term beside the emission,
 *
 *     B = E + rho (H_d + sum over links F B_q),
 *
 * where H_d is the irradiance the lights deliver straight to the leaf:
 * the mean over the leaf's cell of  pi * colour * cone * fading *
 * (N.L)^brilliance * visibility,  that is the light POV-Ray's diffuse
 * term puts on the surface (reference manual, "Light Source" and
 * "Finish": diffuse * C * (N.L)^brilliance * light is the radiance it
 * reflects, so rho H_d / pi is that radiance).  The cone, fading and
 * visibility come from lib/trace/lights.c, the functions the tracer's
 * own shading calls, so the mesh sees the very shadows and spot falloff
 * of the per-pixel direct light: shadow rays through the tracer's BVH,
 * transparent blockers, and area lights sampled on their grid with the
 * deterministic jitter (a hash of the point).  The mean is taken over a
 * k x k grid of cell-centred points (k the visibility rays), weighted
 * by the area element.  Each side of a surface gets the light on its own
 * side, as POV-Ray lights the side facing the viewer.
 *
 * Refinement.  Like an emitter, a light refines where its light varies:
 * before any link is made, a leaf is split while the reflected direct
 * power its cell would misplace, max over channels of rho (H_max -
 * H_min) A with H_max and H_min the extreme samples of the cell, exceeds
 * BF_eps times the scene's reference power, down to A_eps.  This puts
 * small elements along shadow edges and spot falloff rings and leaves
 * evenly lit regions coarse; links made afterwards see sources that
 * already hold their reflected direct light, so Hanrahan's BF criterion
 * refines them as it would for an emitter of that radiosity.  The
 * reference power gains the lights' power onto the surfaces, estimated
 * on an 8 x 8 grid of every surface, so BF_eps keeps its meaning
 * (relative, unchanged by scale or brightness).
 *
 * The picture does not count the first bounce twice: the tracer adds
 * the direct light of every light source per pixel, with sharp shadows,
 * and the solution's lookup (radiosity.c) gathers only over links, from
 * sources whose radiosity holds the reflected direct light: what reaches
 * the eye from the solution is light after at least one diffuse bounce.
 * The smoothed lookup (lookup 1) leaves rho H_d out of the corner values
 * for the same reason (quadtree.c).
 */
#include "radiosity/radiosity.h"

#include <stdlib.h>
#include <string.h>

#include "trace/intersect.h"
#include "trace/lights.h"
#include "trace/shade.h"

/* The irradiance of every light that lights object (light groups) at
   point p (unit normal n) on the front (side 0, along n) and back
   sides. */
static void direct_point(const zr_tracer *tr, const zr_object *object,
                         zr_vec3 p, zr_vec3 n, double brilliance,
                         double h[2][3]) {
  const zr_scene *scene = tr->scene;
  memset(h, 0, 2 * sizeof h[0]);
  double off = zr__surface_offset(p);
  for (size_t i = 0; i < scene->n_lights; i++) {
    const zr_light *light = &scene->lights[i];
    zr_vec3 l;
    zr_rgb lc;
    if (!zr__light_lights(scene, light, object))
      continue; /* another light_group's light */
    if (!zr__light_arrive(light, p, &l, &lc))
      continue; /* outside a spotlight's or cylinder's cone */
    for (int side = 0; side < 2; side++) {
      zr_vec3 ns = side ? zr_v3_neg(n) : n;
      double c = zr_v3_dot(ns, l);
      if (!(c > 0.0))
        continue; /* the light is on the other side */
      zr_rgb v = zr__light_visibility(tr, light, p, zr_v3_madd(p, ns, off));
      double k = M_PI * (brilliance == 1.0 ? c : pow(c, brilliance));
      double add[3] = {k * lc.r * v.r, k * lc.g * v.g, k * lc.b * v.b};
      for (int ch = 0; ch < 3; ch++)
        if (isfinite(add[ch]) && add[ch] > 0.0)
          h[side][ch] += add[ch];
    }
  }
}

/* The direct light of a parameter cell: the area-weighted mean over a
   k x k grid of its cell-centred points, and the extreme samples, of
   those and, with edges set, of a (k + 1) x (k + 1) grid through the
   cell's corners too: a shadow edge that runs near the cell's boundary,
   between the centred points and the neighbour's, is seen by both
   cells. */
typedef struct cell_light {
  double mean[2][3], lo[2][3], hi[2][3];
} cell_light;

static void cell_direct(const zr_radiosity *rad, const zr_tracer *tr,
                        int32_t surf, const double cell[4], int k,
                        bool edges, cell_light *out) {
  const zr__rad_surface *s = &rad->surfs[surf];
  double brilliance = s->object->texture->finish->brilliance;
  double sum[2][3] = {{0}}, plain[2][3] = {{0}}, wsum = 0.0;
  int kept = 0;
  for (int side = 0; side < 2; side++)
    for (int c = 0; c < 3; c++) {
      out->lo[side][c] = INFINITY;
      out->hi[side][c] = 0.0;
    }
  for (int i = 0; i < k * k; i++) {
    zr__surface_point pt;
    zr__surface_eval(&s->geom,
                     cell[0] + (i % k + 0.5) / k * (cell[1] - cell[0]),
                     cell[2] + (i / k + 0.5) / k * (cell[3] - cell[2]), &pt);
    /* Points that CSG removes (trim.c) receive nothing: the cell's
       kept part is what the mean is over. */
    if (s->trim != NULL && !zr__rad_trim_keeps(s, pt.p))
      continue;
    double h[2][3];
    direct_point(tr, s->object, pt.p, pt.n, brilliance, h);
    double w = isfinite(pt.da) && pt.da > 0.0 ? pt.da : 0.0;
    wsum += w;
    kept++;
    for (int side = 0; side < 2; side++)
      for (int c = 0; c < 3; c++) {
        sum[side][c] += w * h[side][c];
        plain[side][c] += h[side][c];
        out->lo[side][c] = fmin(out->lo[side][c], h[side][c]);
        out->hi[side][c] = fmax(out->hi[side][c], h[side][c]);
      }
  }
  for (int i = 0; edges && i < (k + 1) * (k + 1); i++) {
    zr__surface_point pt;
    zr__surface_eval(&s->geom,
                     cell[0] + (double)(i % (k + 1)) / k * (cell[1] - cell[0]),
                     cell[2] + (double)(i / (k + 1)) / k * (cell[3] - cell[2]),
                     &pt);
    if (s->trim != NULL && !zr__rad_trim_keeps(s, pt.p))
      continue;
    double h[2][3];
    direct_point(tr, s->object, pt.p, pt.n, brilliance, h);
    for (int side = 0; side < 2; side++)
      for (int c = 0; c < 3; c++) {
        out->lo[side][c] = fmin(out->lo[side][c], h[side][c]);
        out->hi[side][c] = fmax(out->hi[side][c], h[side][c]);
      }
  }
  /* A cell whose area element vanishes at every sample (it cannot on a
     surface with area) falls back to the plain mean; one that CSG
     removes at every sample gets nothing. */
  for (int side = 0; side < 2; side++)
    for (int c = 0; c < 3; c++) {
      out->mean[side][c] = wsum > 0.0  ? sum[side][c] / wsum
                           : kept > 0 ? plain[side][c] / kept
                                      : 0.0;
      if (out->lo[side][c] > out->hi[side][c])
        out->lo[side][c] = out->hi[side][c]; /* no sample kept */
    }
}

static void tracer_init(const zr_radiosity *rad, zr_tracer *tr,
                        zr_render_stats *stats) {
  memset(stats, 0, sizeof *stats);
  memset(tr, 0, sizeof *tr);
  tr->scene = rad->scene;
  tr->stats = stats;
}

/* Sample points a side of a leaf's cell; at least 2 x 2. */
static int grid_size(const zr_radiosity *rad) {
  return rad->params.visibility_rays > 1 ? rad->params.visibility_rays : 2;
}

/* Sets hd of node n; cl gets the cell's samples. */
static void set_direct(zr_radiosity *rad, const zr_tracer *tr, int32_t n,
                       bool edges, cell_light *cl) {
  double cell[4];
  zr__rad_node_cell(&rad->nodes[n], cell);
  cell_direct(rad, tr, rad->nodes[n].surf, cell, grid_size(rad), edges, cl);
  memcpy(rad->nodes[n].hd, cl->mean, sizeof cl->mean);
  rad->nodes[n].has_direct = 1;
}

void zr__rad_direct_power(zr_radiosity *rad) {
  rad->light_power = 0.0;
  if (rad->scene->n_lights == 0)
    return;
  zr_tracer tr;
  zr_render_stats stats;
  tracer_init(rad, &tr, &stats);
  double p[3] = {0, 0, 0};
  static const double whole[4] = {0.0, 1.0, 0.0, 1.0};
  for (size_t s = 0; s < rad->n_surfs; s++) {
    cell_light cl;
    cell_direct(rad, &tr, (int32_t)s, whole, 8, false, &cl);
    for (int c = 0; c < 3; c++)
      p[c] += rad->surfs[s].area * (cl.mean[0][c] + cl.mean[1][c]);
  }
  rad->light_power = zr__rad_max3(p);
  rad->power_ref += rad->light_power;
}

/* The largest reflected direct power the cell of leaf n misplaces by
   holding the mean. */
static double direct_error(const zr_radiosity *rad, int32_t n,
                           const cell_light *cl) {
  const zr__rad_node *node = &rad->nodes[n];
  const double *rho = rad->surfs[node->surf].rho;
  double e = 0.0;
  for (int side = 0; side < 2; side++)
    for (int c = 0; c < 3; c++)
      e = fmax(e, rho[c] * (cl->hi[side][c] - cl->lo[side][c]));
  return e * node->area;
}

static bool can_split(const zr_radiosity *rad, int32_t n) {
  const zr__rad_node *node = &rad->nodes[n];
  return rad->params.uniform == 0 && node->area > rad->area_eps_abs &&
         node->depth < ZR__RAD_DEPTH;
}

/* Sets hd below node n, splitting leaves whose error exceeds thr. */
static zr_status refine_node(zr_radiosity *rad, const zr_tracer *tr,
                             int32_t n, double thr) {
  if (rad->nodes[n].child < 0) {
    cell_light cl;
    set_direct(rad, tr, n, can_split(rad, n), &cl);
    if (!(direct_error(rad, n, &cl) > thr) || !can_split(rad, n))
      return ZR_OK;
    if (!zr__rad_subdivide(rad, n))
      return ZR_ENOMEM;
  }
  int32_t first = rad->nodes[n].child;
  for (int k = 0; k < 4; k++) {
    zr_status st = refine_node(rad, tr, first + k, thr);
    if (st != ZR_OK)
      return st;
  }
  return ZR_OK;
}

/* Leaves take their source E + rho hd; every node the area mean. */
static void set_sources(zr_radiosity *rad, int32_t n) {
  zr__rad_node *node = &rad->nodes[n];
  if (node->child < 0) {
    for (int side = 0; side < 2; side++)
      zr__rad_leaf_source(rad, node, side, node->b[side]);
    return;
  }
  double sum[2][3] = {{0}}, area = 0.0;
  int32_t first = node->child;
  for (int k = 0; k < 4; k++) {
    set_sources(rad, first + k);
    const zr__rad_node *ch = &rad->nodes[first + k];
    for (int side = 0; side < 2; side++)
      for (int c = 0; c < 3; c++)
        sum[side][c] += ch->area * ch->b[side][c];
    area += ch->area;
  }
  node = &rad->nodes[n];
  for (int side = 0; side < 2; side++)
    for (int c = 0; c < 3; c++)
      node->b[side][c] = area > 0.0 ? sum[side][c] / area : 0.0;
}

zr_status zr__rad_direct_refine(zr_radiosity *rad) {
  if (rad->scene->n_lights == 0)
    return ZR_OK;
  zr_tracer tr;
  zr_render_stats stats;
  tracer_init(rad, &tr, &stats);
  double thr = rad->params.bf_eps * rad->power_ref;
  for (size_t s = 0; s < rad->n_surfs; s++) {
    zr_status st = refine_node(rad, &tr, rad->surfs[s].root, thr);
    if (st != ZR_OK)
      return st;
  }
  for (size_t s = 0; s < rad->n_surfs; s++)
    set_sources(rad, rad->surfs[s].root);
  return ZR_OK;
}

void zr__rad_direct_update(zr_radiosity *rad) {
  if (rad->scene->n_lights == 0)
    return;
  zr_tracer tr;
  zr_render_stats stats;
  tracer_init(rad, &tr, &stats);
  for (size_t n = 0; n < rad->n_nodes; n++)
    if (rad->nodes[n].child < 0 && !rad->nodes[n].has_direct) {
      cell_light cl;
      set_direct(rad, &tr, (int32_t)n, false, &cl);
    }
}
