/*
 * lights.c - the light that reaches a surface point from each kind of
 * POV-Ray 3.7 light source (reference manual, "Light Source":
 * "Spotlights", "Cylindrical Lights", "Parallel Lights", "Area Lights",
 * "Light Fading").
 *
 * The manual gives the shape of each effect (its figures of the
 * spotlight curve have no formula); the exact curves were measured from
 * povray 3.7 renders of a white plane (diffuse 1, ambient 0) under a
 * light 10 units above it, and these formulas reproduce the measured
 * factors to 1e-5 (bench/provenance/probe.py spotlight_curve and
 * cylinder_curve print both):
 *   - spotlight: with c = cos(angle from the axis), full light inside
 *     radius, none beyond falloff, and between them the smoothstep
 *     3 t^2 - 2 t^3 of t = (c - cos falloff) / (cos radius - cos
 *     falloff); all of it times c^tightness.
 *   - cylinder: the same smoothstep of t = (falloff - d) / (falloff -
 *     radius) in the distance d from the axis, times (1 - d /
 *     falloff)^tightness; the light arrives along the axis (the plane
 *     under a cylinder light is lit at normal incidence, N.L = 1), so it
 *     shades like a parallel light.
 *   - fading: 2 / (1 + (d / fade_distance)^fade_power), d the distance
 *     to the light's location: the manual's formula (the figure in
 *     "Light Fading", 3.4.4.1.9), and povray gives
 *     0.4 at d = 10, fade_distance 5, power 2.
 *   - parallel: the direction location - point_at everywhere.  Shadow
 *     rays run parallel to it up to the plane through location; points
 *     above that plane are lit and unshadowed, as the manual says.
 * An area light is a grid of size1 x size2 points spanning axis1 and
 * axis2 centred on location; shading uses its centre and shadows the
 * average visibility of the grid points.  Without adaptive every point
 * is tested; with adaptive N the grid is split recursively, testing the
 * four corners of each cell and splitting only cells whose corners
 * disagree, never coarser than 2^N + 1 points a side (the manual's "adaptive
 * 0 shoots 4 rays, 1 shoots 9, 2 shoots 25").  jitter moves each point
 * within its cell by a hash of the surface point, so a picture is the
 * same on any number of threads or ranks (POV-Ray's jitter is random
 * from render to render).  circular squashes the square grid into the
 * inscribed ellipse; orient turns the grid to face the point lit.
 * Measured against povray: adaptive 0, 1 and 2 renders agree with its
 * pixel for pixel; the full grid and circular lights differ in a pixel
 * or two along a shadow's edge (the manual does not say where the
 * points of a full grid or of a circular light lie, and the grid and
 * circle mapping here are our own).  area_illumination is parsed with a
 * warning: shading still comes from the light's centre.
 *
 * projected_through ("Projected_Through"): a point is lit only when its
 * shadow ray crosses the object, and only what lies between the point
 * and the object's nearest surface along the ray shadows it; objects
 * inside the object or between it and the light do not, and neither
 * does the object itself.  Measured with POV-Ray 3.7: a light 10 above
 * a floor projected through a sphere halfway down lights a disc, which
 * a plate under the sphere shadows while a plate over it, a ball
 * inside it and a copy of the sphere itself do not; transforms of the
 * light move the object with it.  Each area light point is projected
 * on its own, so the spot's edge is soft.
 */
#include "trace/lights.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "trace/intersect.h"
#include "trace/render.h"
#include "trace/shaft.h"

static double smoothstep01(double t) {
  if (t <= 0.0)
    return 0.0;
  if (t >= 1.0)
    return 1.0;
  return t * t * (3.0 - 2.0 * t);
}

/* The unit axis of a spot, cylinder or parallel light: from point_at
   toward the light (so dot(axis, l) > 0 for a lit point), derived when
   the light was added to the scene (zr__light_derive()). */
static zr_vec3 light_axis(const zr_light *light) { return light->axis; }

double zr__light_cone(const zr_light *light, zr_vec3 p) {
  /* A point light shines every way: nothing to weigh. */
  if (light->kind != ZR_LIGHT_SPOT && light->kind != ZR_LIGHT_CYLINDER)
    return 1.0;
  zr_vec3 axis = light_axis(light);
  zr_vec3 to_p = zr_v3_sub(p, light->location);
  if (light->kind == ZR_LIGHT_SPOT) {
    double len = zr_v3_len(to_p);
    if (len == 0.0)
      return 1.0;
    double c = -zr_v3_dot(to_p, axis) / len;
    double cf = light->cos_falloff, cr = light->cos_radius;
    double f;
    if (c <= cf)
      return 0.0;
    if (c >= cr || cr <= cf)
      f = 1.0;
    else
      f = smoothstep01((c - cf) / (cr - cf));
    if (light->tightness != 0.0)
      f *= pow(c, light->tightness);
    return f;
  }
  if (light->kind == ZR_LIGHT_CYLINDER) {
    double along = -zr_v3_dot(to_p, axis);
    if (along <= 0.0)
      return 0.0; /* behind the light */
    zr_vec3 off = zr_v3_madd(to_p, axis, along);
    double d = zr_v3_len(off);
    if (d >= light->falloff)
      return 0.0;
    double f = d <= light->radius || light->falloff <= light->radius
                   ? 1.0
                   : smoothstep01((light->falloff - d) /
                                  (light->falloff - light->radius));
    if (light->tightness != 0.0)
      f *= pow(1.0 - d / light->falloff, light->tightness);
    return f;
  }
  return 1.0;
}

/* A negative fade_distance is not refused: povray 3.7 puts it into the
   formula as it is (bench/conform/light_fade_negative.sh): with an even
   power it fades as the positive distance does, with an odd one the
   ratio's power is negative, so the light grows towards infinity as d
   nears -fade_distance and beyond it turns negative and takes light away
   from the other lights; a power that is no integer gives no real power
   of a negative ratio, and such a light adds nothing. */
double zr__light_fade(const zr_light *light, double distance) {
  if (light->fade_distance == 0.0 || light->fade_power == 0.0)
    return 1.0;
  double f = 2.0 / (1.0 + pow(distance / light->fade_distance,
                              light->fade_power));
  return isnan(f) ? 0.0 : f;
}

/* Lights whose rays all run along one direction. */
static bool is_directional(const zr_light *light) {
  return light->parallel || light->kind == ZR_LIGHT_CYLINDER;
}

bool zr__light_arrive_way(const zr_light *light, zr_vec3 p,
                          const zr_light_way *way, zr_vec3 *l,
                          zr_rgb *colour) {
  *l = is_directional(light) ? light_axis(light)
                             : zr_v3_scale(way->to_light, way->inv_distance);
  /* zr__light_cone's and zr__light_fade's answers for a light with no
     cone and no fading (1) without the calls, which every lit point
     made for every light (~25 instructions each). */
  double k = light->kind == ZR_LIGHT_SPOT || light->kind == ZR_LIGHT_CYLINDER
                 ? zr__light_cone(light, p)
                 : 1.0;
  if (!(k > 0.0))
    return false;
  if (light->fade_distance != 0.0 && light->fade_power != 0.0)
    k *= zr__light_fade(light, way->distance);
  *colour = zr_rgb_scale(light->colour, k);
  return true;
}

bool zr__light_arrive(const zr_light *light, zr_vec3 p, zr_vec3 *l,
                      zr_rgb *colour) {
  zr_light_way way;
  zr__light_way(light, p, &way);
  return zr__light_arrive_way(light, p, &way, l, colour);
}

/* A deterministic number in [0, 1) from the bits of a point and a
   sample index: area light jitter that no thread order can change. */
static double point_hash(zr_vec3 p, uint32_t sample, uint32_t axis) {
  uint64_t bits[3];
  memcpy(&bits[0], &p.x, sizeof bits[0]);
  memcpy(&bits[1], &p.y, sizeof bits[1]);
  memcpy(&bits[2], &p.z, sizeof bits[2]);
  uint32_t h = 0x811c9dc5U;
  for (int i = 0; i < 3; i++)
    h = (uint32_t)(h * 0x01000193U) ^ (uint32_t)(bits[i] ^ (bits[i] >> 32));
  return zr__hash_uniform(h, sample, axis);
}

/* The grid position of index i of n in [-0.5, 0.5]. */
static double grid_pos(int i, int n) {
  return n > 1 ? (double)i / (n - 1) - 0.5 : 0.0;
}

zr_vec3 zr__area_light_point(const zr_light *light, zr_vec3 p, int i,
                             int j) {
  double a = grid_pos(i, light->size1), b = grid_pos(j, light->size2);
  if (light->jitter) {
    uint32_t k = (uint32_t)(j * light->size1 + i);
    if (light->size1 > 1)
      a += (point_hash(p, k, 0) - 0.5) / (light->size1 - 1);
    if (light->size2 > 1)
      b += (point_hash(p, k, 1) - 0.5) / (light->size2 - 1);
  }
  if (light->circular) {
    /* Squash the square [-0.5, 0.5]^2 into its inscribed disc. */
    double x = 2 * a, y = 2 * b;
    a = 0.5 * x * sqrt(fmax(0.0, 1.0 - 0.5 * y * y));
    b = 0.5 * y * sqrt(fmax(0.0, 1.0 - 0.5 * x * x));
  }
  zr_vec3 ax1 = light->axis1, ax2 = light->axis2;
  if (light->orient) {
    /* Turn the grid to face p, keeping the axes' lengths. */
    zr_vec3 d = zr_v3_sub(light->location, p);
    if (zr_v3_len(d) > 0.0) {
      d = zr_v3_norm(d);
      zr_vec3 helper = fabs(d.y) < 0.9 ? zr_v3(0, 1, 0) : zr_v3(1, 0, 0);
      zr_vec3 u = zr_v3_norm(zr_v3_cross(helper, d));
      zr_vec3 v = zr_v3_cross(d, u);
      ax1 = zr_v3_scale(u, zr_v3_len(light->axis1));
      ax2 = zr_v3_scale(v, zr_v3_len(light->axis2));
    }
  }
  return zr_v3_madd(zr_v3_madd(light->location, ax1, a), ax2, b);
}

/* Where a shadow ray toward light point s from lit_from ends, or false
   when the point is not shadowed at all (above a parallel light's
   plane). */
static bool shadow_target(const zr_light *light, zr_vec3 s,
                          zr_vec3 lit_from, zr_vec3 *target) {
  if (!is_directional(light)) {
    *target = s;
    return true;
  }
  zr_vec3 axis = light_axis(light);
  double h = zr_v3_dot(zr_v3_sub(light->location, lit_from), axis);
  if (!(h > 0.0))
    return false;
  /* Parallel to the axis up to the light's plane, shifted by the area
     point's offset from the centre. */
  *target = zr_v3_add(zr_v3_madd(lit_from, axis, h),
                      zr_v3_sub(s, light->location));
  return true;
}

/* What a light projected through an object does to the shadow ray from
   lit_from to target. */
typedef enum projection {
  PROJECTION_MISSES,     /* the ray misses the object: no light */
  PROJECTION_INSIDE,     /* lit_from is inside it: nothing shadows */
  PROJECTION_SHORTENED   /* *target moved to where the ray meets it */
} projection;

static projection projected_target(const zr_light *light, zr_vec3 lit_from,
                                   zr_vec3 *target) {
  const zr_object *o = light->projected_through;
  zr_ray ray = {lit_from, zr_v3_sub(*target, lit_from)};
  zr_hit hits[ZR_MAX_CROSSINGS];
  if (zr__intersect(o, &ray, 0.0, 1.0, hits) == 0)
    return PROJECTION_MISSES;
  if (zr__inside(o, lit_from))
    return PROJECTION_INSIDE;
  /* Stop short of the surface, so that a copy of the object in the
     scene (projected_through.pov shows one) does not shadow through
     rounding: a hundred times the tracer's surface offset. */
  zr_vec3 at = zr_v3_madd(lit_from, ray.dir, hits[0].t);
  double back = 1e2 * zr__surface_offset(at) / zr_v3_len(ray.dir);
  *target = zr_v3_madd(lit_from, ray.dir, fmax(hits[0].t - back, 0.0));
  return PROJECTION_SHORTENED;
}

static zr_rgb sample_visibility(const zr_tracer *tr, const zr_light *light,
                                zr_vec3 s, zr_vec3 lit_from) {
  zr_vec3 target;
  if (!shadow_target(light, s, lit_from, &target)) {
    /* Above a parallel light's plane: lit, even through an object. */
    return zr_rgb3(1, 1, 1);
  }
  if (light->projected_through) {
    projection pr = projected_target(light, lit_from, &target);
    if (pr == PROJECTION_MISSES)
      return zr_rgb3(0, 0, 0);
    if (pr == PROJECTION_INSIDE)
      return zr_rgb3(1, 1, 1);
  }
  if (light->shadowless)
    return zr_rgb3(1, 1, 1);
  return zr__shadow_transmission(tr, light, target, lit_from);
}

/* The visibility of light point s: by the shadow walk, or against
   the few objects a shaft left (lib/trace/shaft.c), which gives the
   walk's answer (each of them stops any ray it crosses, and nothing
   else can be crossed). */
static zr_rgb point_visibility(const zr_tracer *tr, const zr_light *light,
                               const zr_shaft_plan *plan, zr_vec3 s,
                               zr_vec3 lit_from) {
  if (plan && plan->n > 0)
    return zr__shaft_blocks(tr, plan, lit_from, s) ? zr_rgb3(0, 0, 0)
                                                    : zr_rgb3(1, 1, 1);
  return sample_visibility(tr, light, s, lit_from);
}

/* The grid's visibilities, filled on demand (cells share corners). */
typedef struct area_cache {
  const zr_tracer *tr;
  const zr_light *light;
  const zr_shaft_plan *plan;
  zr_vec3 p, lit_from;
  zr_rgb *values;
  unsigned char *done;
} area_cache;

static zr_rgb area_at(area_cache *c, int i, int j) {
  size_t k = (size_t)j * (size_t)c->light->size1 + (size_t)i;
  if (!c->done[k]) {
    zr_vec3 s = zr__area_light_point(c->light, c->p, i, j);
    c->values[k] = point_visibility(c->tr, c->light, c->plan, s,
                                    c->lit_from);
    c->done[k] = 1;
  }
  return c->values[k];
}

static bool close_rgb(zr_rgb a, zr_rgb b) {
  const double eps = 1.0 / 512.0; /* below a displayable step */
  return fabs(a.r - b.r) < eps && fabs(a.g - b.g) < eps &&
         fabs(a.b - b.b) < eps;
}

/* The average visibility over cell [i0, i1] x [j0, j1] of the grid,
   split while its corners disagree or depth is below min_depth. */
static zr_rgb area_cell(area_cache *c, int i0, int i1, int j0, int j1,
                        int depth, int min_depth) {
  zr_rgb a = area_at(c, i0, j0), b = area_at(c, i1, j0);
  zr_rgb d = area_at(c, i0, j1), e = area_at(c, i1, j1);
  bool can_split = i1 - i0 > 1 || j1 - j0 > 1;
  bool agree = close_rgb(a, b) && close_rgb(a, d) && close_rgb(a, e);
  if (!can_split || (agree && depth >= min_depth))
    return zr_rgb_scale(zr_rgb_add(zr_rgb_add(a, b), zr_rgb_add(d, e)),
                        0.25);
  /* Halve each side that spans more than one step. */
  int ni = i1 - i0 > 1 ? 2 : 1, nj = j1 - j0 > 1 ? 2 : 1;
  int is[3] = {i0, ni == 2 ? (i0 + i1) / 2 : i1, i1};
  int js[3] = {j0, nj == 2 ? (j0 + j1) / 2 : j1, j1};
  zr_rgb sum = zr_rgb3(0, 0, 0);
  int n = 0;
  for (int y = 0; y < nj; y++)
    for (int x = 0; x < ni; x++) {
      sum = zr_rgb_add(sum, area_cell(c, is[x], is[x + 1], js[y],
                                      js[y + 1], depth + 1, min_depth));
      n++;
    }
  return zr_rgb_scale(sum, 1.0 / n);
}

/* The largest grid the cache holds on the stack; bigger ones are
   sampled in full without caching. */
#define AREA_CACHE_MAX 4096

static zr_rgb area_visibility(const zr_tracer *tr, const zr_light *light,
                              const zr_shaft_plan *plan, zr_vec3 p,
                              zr_vec3 lit_from) {
  int n1 = light->size1 > 0 ? light->size1 : 1;
  int n2 = light->size2 > 0 ? light->size2 : 1;
  size_t n = (size_t)n1 * (size_t)n2;
  if (light->adaptive < 0 || n > AREA_CACHE_MAX || n1 < 2 || n2 < 2) {
    zr_rgb sum = zr_rgb3(0, 0, 0);
    for (int j = 0; j < n2; j++)
      for (int i = 0; i < n1; i++)
        sum = zr_rgb_add(sum, point_visibility(
                                  tr, light, plan,
                                  zr__area_light_point(light, p, i, j),
                                  lit_from));
    return zr_rgb_scale(sum, 1.0 / (double)n);
  }
  zr_rgb values[AREA_CACHE_MAX];
  unsigned char done[AREA_CACHE_MAX];
  memset(done, 0, n);
  area_cache c = {tr, light, plan, p, lit_from, values, done};
  return area_cell(&c, 0, n1 - 1, 0, n2 - 1, 0, light->adaptive);
}

/* What area_visibility gives when every ray finds the light: 1, or for
   a full grid the sum of its n ones times 1 / n, as there. */
static zr_rgb area_all_lit(const zr_light *light) {
  int n1 = light->size1 > 0 ? light->size1 : 1;
  int n2 = light->size2 > 0 ? light->size2 : 1;
  size_t n = (size_t)n1 * (size_t)n2;
  if (light->adaptive < 0 || n > AREA_CACHE_MAX || n1 < 2 || n2 < 2)
    return zr_rgb_scale(zr_rgb3((double)n, (double)n, (double)n),
                        1.0 / (double)n);
  return zr_rgb3(1, 1, 1);
}

zr_rgb zr__light_visibility(const zr_tracer *tracer, const zr_light *light,
                            zr_vec3 p, zr_vec3 lit_from) {
  /* What the steps below come to for such a light (point_visibility,
     sample_visibility, shadow_target give the same ray). */
  if (zr__light_one_ray(tracer, light))
    return zr__shadow_transmission(tracer, light, light->location,
                                   lit_from);
  if ((light->shadowless || tracer->no_shadows) &&
      !light->projected_through)
    return zr_rgb3(1, 1, 1);
  /* The rays an irradiance cache gathers with (gi_depth > 0) see an
     area light's shadow through the cache's blur: one ray to its
     centre stands for the grid there (radiosity/cornell.pov, nine 4 x 4
     area lights: 7.7 s of CPU against povray's 4.2 before, SSIM
     against povray unchanged to 0.001; bench/gi.sh). */
  if (light->area && (light->size1 > 1 || light->size2 > 1) &&
      tracer->indirect && tracer->indirect->next_uniform) {
    /* A path tracer (lib/gi/path.c): one point of the grid, picked
       uniformly, estimates the mean of all of them without bias. */
    int n1 = light->size1 > 0 ? light->size1 : 1;
    int n2 = light->size2 > 0 ? light->size2 : 1;
    double u = tracer->indirect->next_uniform(tracer->indirect);
    long k = (long)(u * (double)n1 * (double)n2);
    if (k >= (long)n1 * n2)
      k = (long)n1 * n2 - 1;
    zr_shaft_plan plan;
    zr__shaft_plan(tracer, light, lit_from, false, &plan);
    return point_visibility(
        tracer, light, &plan,
        zr__area_light_point(light, p, (int)(k % n1), (int)(k / n1)),
        lit_from);
  }
  if (light->area && (light->size1 > 1 || light->size2 > 1) &&
      tracer->gi_depth == 0 && !tracer->point_area_lights) {
    /* What the rays can meet, from one test of their shaft
       (lib/trace/shaft.c): nothing gives what their average would. */
    zr_shaft_plan plan;
    zr__shaft_plan(tracer, light, lit_from, true, &plan);
    if (plan.n == 0)
      return area_all_lit(light);
    return area_visibility(tracer, light, &plan, p, lit_from);
  }
  /* One ray to the centre: the group's shaft, tested once from this
     point for all its lights, may answer it. */
  zr_shaft_plan plan;
  plan.n = -1;
  if (light->area)
    zr__shaft_plan(tracer, light, lit_from, false, &plan);
  if (plan.n == 0)
    return zr_rgb3(1, 1, 1);
  return point_visibility(tracer, light, &plan, light->location, lit_from);
}
