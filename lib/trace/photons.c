/*
 * photons.c - caustics by photon mapping (Jensen, "Global Illumination
 * using Photon Maps", 1996), with the meaning POV-Ray 3.7's reference
 * gives the photons blocks ("Photons") and what its renders show.
 *
 * Shooting.  Each light whose photons may be reflected or refracted
 * shoots at each target primitive (a union's block is pushed into its
 * parts, so each part is a target of its own) through the sphere about
 * the primitive's bounding box.  A point light's directions cover the
 * cone that sphere subtends (every direction when the light is inside
 * it), one per solid angle (spacing / distance)^2, on a Fibonacci
 * lattice of the spherical cap (equal solid angle per point, rotated by
 * the golden angle); a parallel light's rays leave its plane through a
 * sunflower lattice of the sphere's disc, one per spacing^2.  jitter
 * moves each direction or point by up to jitter cells, from a hash of
 * light, target and index, so the photons are the same in every run.
 * A lattice ray that misses the target's box is not traced, and a
 * photon whose first surface (pass_through ones aside) is not the
 * target's is dropped: each target's lattice brings the light that meets
 * it first, as povray 3.7's counts and pictures show for overlapping
 * targets (bench/photon_targets.sh).  Shadowless lights shoot none.
 * With count instead of spacing, one spacing for all targets is chosen
 * so that the lattices hold about count photons together.
 *
 * Power.  POV-Ray's lights do not fall off with distance: a surface
 * facing a light gets the light's colour at any distance unless
 * fade_power says otherwise.  So a photon's power is the light's colour
 * times the area its solid angle covers where it lands, omega D^2 for
 * the whole path length D (parallel light: the cell's area), times the
 * light's fading at D and its spot cone.  povray 3.7 agrees: behind a
 * clear slab of ior 1 that is a target, the photons give the light the
 * floor gets without the slab, both with the slab near the floor and
 * with it three times nearer the light than the floor (measured, see
 * tests/test_photons.sh), which photons of a fixed power would light
 * nine times less.
 *
 * Tracing.  A photon follows the tracer's rules: an object that
 * refracts photons (photons { refraction on }) passes it on through its
 * ior with its filter and transmit (f * C + t) and its interior's
 * fading; one that reflects photons passes on the reflection amount of
 * its finish; both may split a photon in two.  Objects that neither
 * reflect nor refract stop it.  pass_through objects (no_shadow ones by
 * default) let photons that have not yet met a target cross unchanged.
 * A photon is stored where it lands on a collecting object once it has
 * been reflected or refracted: the light that arrives straight from a
 * light is the light sources' business.  Its path ends after the
 * photons' max_trace_level (the scene's by default; the ray from the
 * light is the first level) or when it falls below the photons'
 * adc_bailout by povray 3.7's measured rule (bench/photon_bailout.sh):
 * a branch is kept while S max(C) >= adc_bailout, where C is its colour
 * relative to what it left the light with (every reflection amount,
 * metallic tint included, and every filter met: a clear slab counts its
 * transmit at both faces) and S the product of its reflections' weights
 * (the larger of the reflection block's min and max colours' largest
 * channel; with fresnel, the amount at the angle without the metallic
 * tint).  So a single plain mirror of reflection R keeps its photons
 * only when R^2 >= adc_bailout (R >= 0.0627 at the default 1/255),
 * whatever the light's colour.  Photon rays do not see no_image
 * objects (povray 3.7 shows neither a caustic nor a photon shadow
 * behind a no_image target lens).
 *
 * Gathering.  The photons are kept in a balanced kd-tree.  At a point,
 * up to gather_max of the nearest photons within the gather radius R
 * that arrived on the side the normal faces are summed and divided by
 * pi r^2 (r: R, or the distance of the farthest when gather_max were
 * found).  When fewer than gather_min are found, the search is redone
 * at 2R and kept when the density it finds is at most expand_increase
 * above the first's, or when it found fewer than expand_min photons
 * ("Adaptive Search Radius").  R is given by radius, or found: the
 * median, over up to 1000 stored photons spread through the map, of
 * the distance to the gather_max-th nearest photon, times the radius
 * multiplier.  With media photons the radius is not expanded ("Unless
 * photons are interacting with media, POV-Ray uses an adaptive search
 * radius").
 *
 * Media ("Photons and Media", global photons { media MAX_STEPS, FACTOR
 * }).  Along each stretch of a photon's path through scattering media
 * (once it has met its target) photons are stored every spacing *
 * FACTOR, at most MAX_STEPS a stretch, each standing for the light
 * crossing its step (store_media); media sampling gathers the
 * gather_max nearest and divides by the volume of their sphere
 * (zr__photons_media_light).  A target without photon refraction or
 * reflection (a clear box of fog) lets photons through as PLAIN ones,
 * which every surface reflects and lets through by its finish until a
 * flagged object refracts or reflects them (follow()); what povray 3.7
 * showed of all this is in bench/photon_media.sh.
 */
#include "trace/photons.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/context.h"
#include "scene/texture.h"
#include "trace/bvh.h"
#include "trace/lights.h"
#include "trace/media.h"
#include "trace/render.h"
#include "trace/shade.h"

/* One stored photon; axis is its kd-tree node's split axis. */
typedef struct photon {
  float p[3];
  float power[3];
  float dir[3]; /* direction of travel, unit */
  uint8_t axis;
} photon;

typedef struct zr_photon_map zr_photon_map;
struct zr_photon_map {
  photon *v;
  size_t n, cap;
  double radius; /* gather radius R */
  int gather_min, gather_max, expand_min;
  double expand_increase;
  /* The surface map's media photons (global photons { media N }), NULL
     when none were stored; a media map holds none of its own. */
  struct zr_photon_map *media;
  /* Whether the search radius is fixed: "Unless photons are interacting
     with media, POV-Ray uses an adaptive search radius" ("Adaptive
     Search Radius"), so with media N it is not expanded. */
  bool fixed_radius;
};

/* The most photons one map holds (44 bytes each: 1.4 GB); beyond it the
   shooting stops with a warning.  Our own bound, not POV-Ray's. */
#define PHOTONS_MAX ((size_t)1 << 25)
/* How far the search radius grows when too few photons are found, and
   how often.  The manual says the radius is expanded but not by how
   much; these are our choice, judged on tests/photons_check.pov's lens
   (SSIM 0.97 against povray, which is the spread povray's own pictures
   show between radius settings there; one expansion left the sparse
   edge of the caustic dotted: 0.82). */
#define EXPAND_FACTOR 2.0
#define EXPANSIONS 3

static const double GOLDEN_ANGLE = 2.39996322972865332; /* pi (3 - sqrt 5) */

/* ---- shooting ---- */

typedef struct shooter {
  const zr_scene *scene;
  zr_photon_map *map;
  zr_tracer tracer;
  zr_render_stats stats;
  const zr_light *light;
  /* The primitive being shot at, and its box: a photon whose first
     surface (pass_through ones aside) is not this target's is dropped,
     and a lattice ray that misses the box is not traced at all. */
  const zr_object *target;
  zr_vec3 target_lo, target_hi;
  int max_level;
  double bailout;
  zr_rgb start; /* the power of the photon being followed at the light */
  /* Media photons: their map (NULL: media N was not given), the most
     stored along one stretch of a path through media, and the distance
     between them (the lattice's spacing times the media factor). */
  zr_photon_map *media_map;
  int media_steps;
  double media_step;
  uint32_t li, ti; /* the light and target being shot (hash keys) */
  size_t k;        /* the photon of the lattice being followed */
  uint32_t stretches; /* its stretches through media so far */
  double refind; /* 1 + the target box's diagonal (refind_hit) */
  unsigned long long shot; /* photons that left a light */
  bool full; /* PHOTONS_MAX reached */
  bool oom;
} shooter;

/* A uniform number in [0, 1) from light li, target ti, photon k and an
   axis: the tracer's hash (lib/trace/render.c). */
static double hash01(uint32_t li, uint32_t ti, size_t k, uint32_t axis) {
  return zr__hash_uniform((uint32_t)k, (li << 20) ^ ti, axis);
}

/* Two unit vectors that make a right-handed frame with unit w. */
static void frame(zr_vec3 w, zr_vec3 *u, zr_vec3 *v) {
  zr_vec3 a = fabs(w.x) < 0.6 ? zr_v3(1, 0, 0) : zr_v3(0, 1, 0);
  *u = zr_v3_norm(zr_v3_cross(a, w));
  *v = zr_v3_cross(w, *u);
}

static void store_in(shooter *sh, zr_photon_map *m, zr_vec3 p, zr_vec3 d,
                     zr_rgb power) {
  if (m->n == m->cap) {
    if (m->cap >= PHOTONS_MAX) {
      sh->full = true;
      return;
    }
    size_t cap = m->cap ? 2 * m->cap : 4096;
    photon *v = realloc(m->v, cap * sizeof *v);
    if (!v) {
      sh->oom = true;
      return;
    }
    m->v = v;
    m->cap = cap;
  }
  photon *ph = &m->v[m->n++];
  ph->p[0] = (float)p.x, ph->p[1] = (float)p.y, ph->p[2] = (float)p.z;
  ph->power[0] = (float)power.r, ph->power[1] = (float)power.g;
  ph->power[2] = (float)power.b;
  ph->dir[0] = (float)d.x, ph->dir[1] = (float)d.y, ph->dir[2] = (float)d.z;
  ph->axis = 0;
}

static void store(shooter *sh, zr_vec3 p, zr_vec3 d, zr_rgb power) {
  store_in(sh, sh->map, p, d, power);
}

static double rgb_max3(zr_rgb c) { return fmax(c.r, fmax(c.g, c.b)); }

/* Whether a photon branch of power w whose reflections' weights
   multiply to s goes on: povray 3.7's rule, measured by
   bench/photon_bailout.sh (the module's essay gives it). */
static bool branch_kept(const shooter *sh, zr_rgb w, double s) {
  double rel = 0.0;
  if (sh->start.r > 0.0)
    rel = fmax(rel, w.r / sh->start.r);
  if (sh->start.g > 0.0)
    rel = fmax(rel, w.g / sh->start.g);
  if (sh->start.b > 0.0)
    rel = fmax(rel, w.b / sh->start.b);
  return s * rel >= sh->bailout;
}

/* The weight a reflection by finish f adds to a photon branch's
   bailout test: the largest channel of the larger of the reflection
   block's colours, or with fresnel of the amount at the angle (no
   metallic tint in either).  Measured, bench/photon_bailout.sh. */
static double reflection_weight(const zr_finish *f, zr_vec3 d, zr_vec3 n,
                                double n1, double n2) {
  zr_rgb lo = f->reflection, hi = f->reflection_max;
  if (!f->reflection_fresnel)
    return fmax(rgb_max3(lo), rgb_max3(hi));
  double w = zr__fresnel(fmin(1.0, fabs(zr_v3_dot(d, n))), n1, n2);
  return rgb_max3(zr_rgb3(lo.r + (hi.r - lo.r) * w, lo.g + (hi.g - lo.g) * w,
                          lo.b + (hi.b - lo.b) * w));
}

/* The nearest surface a photon ray meets (no_image objects unseen). */
static bool photon_hit(const shooter *sh, const zr_ray *ray, zr_hit *hit) {
  double from = 0.0;
  for (int guard = 0; guard < 64; guard++) {
    if (!zr__bvh_nearest(sh->scene->bvh, ray, from, INFINITY, hit))
      return false;
    if (!hit->object->no_image)
      return true;
    from = nextafter(hit->t, INFINITY);
  }
  return false;
}

/* Whether a hit on object o is a hit on the target being shot at: o is
   the target, a part of it (CSG), or one of the copies a mesh with
   per-triangle textures reports its hits by (they share its list). */
static bool is_shot_target(const shooter *sh, const zr_object *o) {
  const zr_object *h = o->solid ? o->solid : o;
  const zr_object *t = sh->target;
  if (h == t)
    return true;
  return h->kind == ZR_OBJ_MESH && t->kind == ZR_OBJ_MESH &&
         h->u.mesh.textured && h->u.mesh.textured == t->u.mesh.textured;
}

/*
 * Finds a photon's first hit on its target again from near it.  The
 * light may be far away (the benchmark's is 150000 units off), and a
 * curved surface's hit found from there is off the surface by about
 * 1e-16 t^2 / size (the sphere's discriminant loses the digits): a
 * few 1e-6 there, 100 times zr__surface_offset, so the reflected
 * photon started inside the ring or ball and bounced on inside it,
 * stored at each bounce (a metal ball stored as many photons as were
 * shot at it, povray a sixth as many).  *hit, *p (the hit point) and
 * *d_total (distance from the light) are replaced when the new search
 * meets the target.
 */
static void refind_hit(const shooter *sh, const zr_ray *ray, zr_hit *hit,
                       zr_vec3 *p, double *d_total) {
  zr_ray near = {zr_v3_madd(*p, ray->dir, -sh->refind), ray->dir};
  zr_hit again;
  if (!photon_hit(sh, &near, &again) || !is_shot_target(sh, again.object))
    return;
  *d_total += again.t - sh->refind;
  *p = zr_v3_madd(near.origin, ray->dir, again.t);
  *hit = again;
}

/* ---- media photons ---- */

/*
 * The media a stretch of a photon's path crosses, as a camera ray sees
 * them (lib/trace/media.c zr__media_along): the interiors' media when
 * every object the photon is in is hollow, and the atmosphere's ("photons
 * also interact fully with media"; not measured against povray: no
 * stock scene has both).  Only media that scatter and collect photons
 * store any ("Photons and Media"); the others still dim the photon.
 * Returns how many, with *collects whether one of them stores photons.
 */
static size_t stretch_media(const shooter *sh, const zr_media *inside,
                            const zr_medium **list, bool *collects) {
  const zr_settings *st = &sh->scene->settings;
  size_t n = 0;
  *collects = false;
  for (int i = 0; inside && i < inside->n; i++)
    if (!inside->objects[i]->hollow)
      return 0;
  for (int i = 0; inside && i < inside->n; i++) {
    const zr_interior *in = inside->interiors[i];
    for (size_t k = 0; in && k < in->n_media && n < ZR_MEDIA_LIST_MAX; k++)
      list[n++] = in->media[k];
  }
  for (size_t k = 0; k < st->n_media && n < ZR_MEDIA_LIST_MAX; k++)
    list[n++] = st->media[k];
  for (size_t k = 0; k < n; k++)
    if (!list[k]->photons_ignored && rgb_max3(list[k]->scattering) > 0.0)
      *collects = true;
  return n;
}

/*
 * Stores media photons along the stretch of length len from origin
 * along unit dir ("Photons and Media": "as a light ray passes through a
 * section of media, the photons are deposited, separated by
 * approximately the same distance that separates surface photons", at
 * most MAX_STEPS of them per section).  Steps of sh->media_step (fewer
 * and longer when more than media_steps would be needed; at least one)
 * each hold a photon at a hashed place inside the step.  A photon
 * stands for the light crossing its step: flux times the step's length
 * (area times length: a density over volume then gives the light that
 * arrives at a point, as zr__photons_media_light says), dimmed by the
 * media's extinction up to it; *power leaves dimmed by all of the
 * stretch.  path is the distance the photon had travelled at origin.
 */
static void store_media(shooter *sh, zr_vec3 origin, zr_vec3 dir,
                        double len, zr_rgb *power, double flux,
                        bool parallel, double path, const zr_media *inside) {
  const zr_medium *list[ZR_MEDIA_LIST_MAX];
  bool collects;
  size_t nm = stretch_media(sh, inside, list, &collects);
  if (nm == 0 || !(len > 0.0) || !isfinite(len))
    return;
  double want = ceil(len / sh->media_step);
  int steps = want < 1.0 ? 1
              : want > sh->media_steps ? sh->media_steps : (int)want;
  double h = len / steps;
  double u = hash01(sh->li, sh->ti, sh->k, 2 + sh->stretches++);
  zr_rgb t = zr_rgb3(1, 1, 1); /* the extinction of the steps before */
  for (int i = 0; i < steps && !sh->full && !sh->oom; i++) {
    double s = (i + u) * h;
    zr_vec3 p = zr_v3_madd(origin, dir, s);
    zr_rgb k = zr_rgb3(0, 0, 0);
    bool scatters = false;
    for (size_t q = 0; q < nm; q++) {
      zr_rgb d = zr__media_density(list[q], p);
      k = zr_rgb_add(k, zr_rgb_mul(d, zr_rgb_madd(list[q]->absorption,
                                                 list[q]->scattering,
                                                 list[q]->extinction)));
      if (!list[q]->photons_ignored &&
          rgb_max3(zr_rgb_mul(d, list[q]->scattering)) > 0.0)
        scatters = true;
    }
    /* A step's extinction is taken where its photon lies. */
    if (collects && scatters) {
      double d = path + s;
      double area = parallel ? flux : flux * d * d;
      double w = area * h * zr__light_fade(sh->light, d);
      zr_rgb here = zr_rgb3(t.r * exp(-k.r * u * h), t.g * exp(-k.g * u * h),
                            t.b * exp(-k.b * u * h));
      store_in(sh, sh->media_map, p, dir,
               zr_rgb_scale(zr_rgb_mul(*power, here), w));
    }
    t = zr_rgb3(t.r * exp(-k.r * h), t.g * exp(-k.g * h),
                t.b * exp(-k.b * h));
  }
  *power = zr_rgb_mul(*power, t);
}

/*
 * Where a photon stands.  FROM_LIGHT: on its way from the light to the
 * target it was shot at.  PLAIN: it went through a target that neither
 * refracts nor reflects photons (photons { target } alone, as the
 * foggy box of advanced/optics.pov), and has met since only surfaces
 * without a photons { refraction } or { reflection } of their own:
 * such a photon is reflected by every surface's finish and goes
 * through every clear one (bent by its ior), unless the object's block
 * turns the one or the other off.  CAUSTIC: reflected or refracted by
 * an object whose block turns it on; only such objects pass it on.
 * povray 3.7 shows both (bench/photon_media.sh): a mirror without a
 * photons block in a clear target box reflects a beam of media
 * photons, as with reflection on and unlike with reflection off, where
 * under a target lens the same mirror stores no more photons than
 * with nothing behind it.
 */
enum { FROM_LIGHT, PLAIN, CAUSTIC };

/*
 * Follows one photon from origin along unit dir.  power is what it
 * carries per unit of flux (the light's colour times the filters met so
 * far), flux the solid angle (point light: times D^2 when stored) or the
 * area (parallel light) it stands for, path the distance it travelled,
 * state where it stands (see above), level its depth, s the product of
 * its reflections' weights (branch_kept).
 */
static void follow(shooter *sh, zr_vec3 origin, zr_vec3 dir, zr_rgb power,
                   double flux, bool parallel, double path, int state,
                   int level, const zr_media *media, double s) {
  const zr_light *light = sh->light;
  bool bounced = state != FROM_LIGHT;
  for (int passes = 0; passes < ZR_PASS_MAX; passes++) {
    zr_ray ray = {origin, dir};
    zr_hit hit;
    if (!photon_hit(sh, &ray, &hit))
      return;
    const zr_object *o = hit.object;
    const zr_photon_object *po = o->photons;
    zr_vec3 p = zr_v3_madd(origin, dir, hit.t);
    double d_total = path + hit.t;
    if (sh->media_map && bounced)
      store_media(sh, origin, dir, hit.t, &power, flux, parallel, path,
                  media);
    if (media && media->n > 0)
      power = zr__exit_fade(sh->scene, media, o, hit.t, power);
    bool pass = po ? po->pass_through : o->no_shadow;
    if (pass && !bounced) {
      origin = zr_v3_madd(p, dir, zr__surface_offset(p));
      path = d_total;
      continue;
    }
    /* Each target's lattice brings the light that meets that target
       first: a photon shot at one target that meets another (or any
       other surface) first is dropped, since that surface's light is
       its own lattice's or the light source's.  povray 3.7 does so: two
       overlapping clear slabs, each a target, light the floor under
       their overlap as one slab does, not twice (bench/photon_targets.sh). */
    if (!bounced && !is_shot_target(sh, o))
      return;
    if (!bounced && hit.t > 2.0 * sh->refind)
      refind_hit(sh, &ray, &hit, &p, &d_total);
    o = hit.object;
    po = o->photons;
    if (bounced && (!po || po->collect)) {
      double area = parallel ? flux : flux * d_total * d_total;
      double k = area * zr__light_fade(light, d_total);
      store(sh, p, dir, zr_rgb_scale(power, k));
      if (sh->full || sh->oom)
        return;
    }
    /* The ray from the light is the first level, as for a camera ray:
       povray 3.7 stores as many photons behind a glass ball at
       max_trace_level n + 1 as a count from this hit as level 0 gives
       at n (bench/photon_targets.sh). */
    if (level + 1 >= sh->max_level)
      return;
    bool refr_on = po && po->refraction, refl_on = po && po->reflection;
    /* A target that neither refracts nor reflects photons lets them
       on as PLAIN ones: povray 3.7 stores photons on a floor under a
       clear box that is a target, and under a lens inside it, where
       without the box's target none reach the lens
       (bench/photon_media.sh). */
    bool plain = state == PLAIN || (state == FROM_LIGHT && !refr_on &&
                                    !refl_on);
    bool refracts = light->photon_refraction &&
                    (refr_on || (plain && !(po && po->refraction_set)));
    bool reflects = light->photon_reflection &&
                    (refl_on || (plain && !(po && po->reflection_set)));
    if (!refracts && !reflects)
      return;
    int next_state = refr_on || refl_on ? CAUSTIC : plain ? PLAIN : CAUSTIC;
    /* The surface as the shader sees it: normal facing the photon,
       perturbed by normal { }, the pigment and finish there. */
    bool entering = zr_v3_dot(hit.normal, dir) < 0.0;
    zr_vec3 ng = entering ? hit.normal : zr_v3_neg(hit.normal);
    const zr_texture *tx = o->texture;
    if (!entering && o->interior_texture)
      tx = o->interior_texture;
    if (tx->map) {
      const zr_texture *second;
      double t;
      tx = zr__texture_pick_n(tx, p, ng, &second, &t);
      if (second && t > 0.5)
        tx = second;
    }
    zr_vec3 n = ng;
    if (tx->normal) {
      zr_vec3 np = zr__normal_perturb(tx->normal, p, hit.normal);
      n = entering ? np : zr_v3_neg(np);
    }
    zr_colour col = zr__pigment_eval_n(tx->pigment, p, n);
    const zr_finish *f = tx->finish;
    /* In or out as a camera ray would go (lib/trace/shade.c). */
    zr_media next;
    zr__media_cross(sh->scene, media, o, &next);
    double n1 = zr__media_ior(media), n2 = zr__media_ior(&next);
    zr_rgb refl = reflects ? zr__reflection_amount(f, col, dir, n, n1, n2)
                           : zr_rgb3(0, 0, 0);
    zr_rgb trans = zr_rgb3(0, 0, 0);
    if (refracts)
      trans = zr_rgb3(col.f * col.r + col.t, col.f * col.g + col.t,
                      col.f * col.b + col.t);
    if (f->conserve_energy)
      trans = zr_rgb3(trans.r * (1.0 - refl.r), trans.g * (1.0 - refl.g),
                      trans.b * (1.0 - refl.b));
    double off = zr__surface_offset(p);
    zr_vec3 mirror = zr__reflect(dir, n);
    zr_vec3 above = zr_v3_madd(p, ng, off), below = zr_v3_madd(p, ng, -off);
    if (rgb_max3(trans) > 0.0) {
      zr_vec3 refr = dir;
      if (n1 != n2 && !zr__refract(dir, n, n1 / n2, &refr)) {
        /* Total internal reflection: the light stays inside. */
        zr_rgb w = zr_rgb_mul(power, trans);
        if (branch_kept(sh, w, s))
          follow(sh, above, mirror, w, flux, parallel, d_total, next_state,
                 level + 1, media, s);
      } else {
        zr_rgb w = zr_rgb_mul(power, trans);
        if (branch_kept(sh, w, s))
          follow(sh, below, refr, w, flux, parallel, d_total, next_state,
                 level + 1, &next, s);
      }
    }
    if (rgb_max3(refl) > 0.0) {
      zr_rgb w = zr_rgb_mul(power, refl);
      double s_refl = s * reflection_weight(f, dir, n, n1, n2);
      if (branch_kept(sh, w, s_refl))
        follow(sh, above, mirror, w, flux, parallel, d_total, next_state,
               level + 1, media, s_refl);
    }
    return;
  }
}

/* The sphere about a target primitive's box; false when unbounded. */
static bool target_sphere(const zr_object *o, zr_vec3 *c, double *r) {
  zr_vec3 lo, hi;
  if (!zr__object_bounds(o, &lo, &hi))
    return false;
  *c = zr_v3_scale(zr_v3_add(lo, hi), 0.5);
  *r = 0.5 * zr_v3_len(zr_v3_sub(hi, lo));
  return isfinite(*r) && *r > 0.0;
}

/* Whether the ray from origin along dir meets the target's box (slab
   test; a photon that misses it cannot meet the target first). */
static bool meets_target_box(const shooter *sh, zr_vec3 origin,
                             zr_vec3 dir) {
  const double o[3] = {origin.x, origin.y, origin.z};
  const double d[3] = {dir.x, dir.y, dir.z};
  const double lo[3] = {sh->target_lo.x, sh->target_lo.y, sh->target_lo.z};
  const double hi[3] = {sh->target_hi.x, sh->target_hi.y, sh->target_hi.z};
  double t0 = 0.0, t1 = INFINITY;
  for (int a = 0; a < 3; a++) {
    if (d[a] == 0.0) {
      if (o[a] < lo[a] || o[a] > hi[a])
        return false;
      continue;
    }
    double inv = 1.0 / d[a];
    double ta = (lo[a] - o[a]) * inv, tb = (hi[a] - o[a]) * inv;
    if (ta > tb) {
      double t = ta;
      ta = tb;
      tb = t;
    }
    /* A little slack: the box is the bound, not the surface. */
    double slack = 1e-9 * (fabs(ta) + fabs(tb) + 1.0);
    t0 = fmax(t0, ta - slack);
    t1 = fmin(t1, tb + slack);
    if (t0 > t1)
      return false;
  }
  return true;
}

/* Whether the light shoots photons.  A shadowless light does not: povray
   3.7 shoots no more photons at a target lens with a shadowless light
   added than without it, and twice as many with a plain one
   (bench/photon_targets.sh). */
static bool shoots(const zr_light *l) {
  return (l->photon_refraction || l->photon_reflection) && !l->shadowless;
}

static bool is_target(const zr_object *o) {
  return o->photons && o->photons->target && !o->no_image;
}

/* A light's rays are parallel (parallel lights and cylinder lights). */
static bool light_parallel(const zr_light *l) {
  return l->parallel || l->kind == ZR_LIGHT_CYLINDER;
}

/* The measure a (light, target) pair's lattice covers, in units of
   spacing^2 at spacing multiplier 1: solid angle times distance^2, or
   the disc's area. */
static double pair_measure(const zr_light *l, zr_vec3 c, double r,
                           double mult) {
  if (light_parallel(l))
    return M_PI * r * r / (mult * mult);
  double d = zr_v3_len(zr_v3_sub(c, l->location));
  double cos_a = d > r ? sqrt(1.0 - (r / d) * (r / d)) : -1.0;
  double scale = fmax(d, r);
  return 2.0 * M_PI * (1.0 - cos_a) * scale * scale / (mult * mult);
}

static void shoot_pair(shooter *sh, uint32_t li, uint32_t ti, zr_vec3 c,
                       double r, double spacing) {
  const zr_light *l = sh->light;
  const zr_photon_settings *ps = &sh->scene->settings.photons;
  zr_rgb colour = l->colour;
  if (light_parallel(l)) {
    zr_vec3 w = zr_v3_sub(l->point_at, l->location);
    if (!(zr_v3_len(w) > 0.0))
      return;
    w = zr_v3_norm(w);
    zr_vec3 e1, e2;
    frame(w, &e1, &e2);
    double cell = spacing * spacing;
    double n_real = M_PI * r * r / cell;
    size_t n = n_real < 1.0 ? 1 : (size_t)ceil(n_real);
    for (size_t k = 0; k < n && !sh->full && !sh->oom; k++) {
      double rr = r * sqrt((k + 0.5) / (double)n);
      double phi = k * GOLDEN_ANGLE;
      double jx = ps->jitter * spacing * (hash01(li, ti, k, 0) - 0.5);
      double jy = ps->jitter * spacing * (hash01(li, ti, k, 1) - 0.5);
      zr_vec3 q = zr_v3_madd(zr_v3_madd(c, e1, rr * cos(phi) + jx), e2,
                             rr * sin(phi) + jy);
      /* From the light's plane (the plane through location, across w):
         what lies behind it gets no light. */
      double back = zr_v3_dot(zr_v3_sub(q, l->location), w);
      if (back <= 0.0)
        continue;
      zr_vec3 origin = zr_v3_madd(q, w, -back);
      double cone = zr__light_cone(l, q);
      if (!(cone > 0.0))
        continue;
      sh->shot++;
      sh->start = zr_rgb_scale(colour, cone);
      sh->k = k, sh->stretches = 0;
      if (meets_target_box(sh, origin, w))
        follow(sh, origin, w, sh->start, cell, true, 0.0, FROM_LIGHT, 0,
               NULL, 1.0);
    }
    return;
  }
  zr_vec3 to = zr_v3_sub(c, l->location);
  double d = zr_v3_len(to);
  double cos_a = d > r ? sqrt(1.0 - (r / d) * (r / d)) : -1.0;
  zr_vec3 w = d > 0.0 ? zr_v3_scale(to, 1.0 / d) : zr_v3(0, 0, 1);
  zr_vec3 e1, e2;
  frame(w, &e1, &e2);
  double scale = fmax(d, r);
  double omega = (spacing / scale) * (spacing / scale);
  double n_real = 2.0 * M_PI * (1.0 - cos_a) / omega;
  size_t n = n_real < 1.0 ? 1 : (size_t)ceil(n_real);
  double cell = sqrt(omega);
  for (size_t k = 0; k < n && !sh->full && !sh->oom; k++) {
    double z = 1.0 - (1.0 - cos_a) * (k + 0.5) / (double)n;
    double s = sqrt(fmax(0.0, 1.0 - z * z));
    double phi = k * GOLDEN_ANGLE;
    zr_vec3 dir = zr_v3_add(zr_v3_scale(w, z),
                            zr_v3_add(zr_v3_scale(e1, s * cos(phi)),
                                      zr_v3_scale(e2, s * sin(phi))));
    if (ps->jitter > 0.0) {
      zr_vec3 t1, t2;
      frame(dir, &t1, &t2);
      double jx = ps->jitter * cell * (hash01(li, ti, k, 0) - 0.5);
      double jy = ps->jitter * cell * (hash01(li, ti, k, 1) - 0.5);
      dir = zr_v3_norm(zr_v3_madd(zr_v3_madd(dir, t1, jx), t2, jy));
    }
    double cone = zr__light_cone(l, zr_v3_add(l->location, dir));
    if (!(cone > 0.0))
      continue;
    sh->shot++;
    sh->start = zr_rgb_scale(colour, cone);
    sh->k = k, sh->stretches = 0;
    if (meets_target_box(sh, l->location, dir))
      follow(sh, l->location, dir, sh->start, omega, false, 0.0, FROM_LIGHT,
             0, NULL, 1.0);
  }
}

/* ---- the kd-tree ---- */

static float coord(const photon *ph, int axis) { return ph->p[axis]; }

/* Reorders v[lo, hi) so that v[k] holds the k-th smallest on axis. */
static void select_kth(photon *v, size_t lo, size_t hi, size_t k, int axis) {
  while (hi - lo > 1) {
    float pivot = coord(&v[lo + (hi - lo) / 2], axis);
    size_t i = lo, j = hi - 1;
    while (i <= j) {
      while (coord(&v[i], axis) < pivot)
        i++;
      while (coord(&v[j], axis) > pivot)
        j--;
      if (i <= j) {
        photon t = v[i];
        v[i] = v[j];
        v[j] = t;
        i++;
        if (j == 0)
          break;
        j--;
      }
    }
    if (k <= j)
      hi = j + 1;
    else if (k >= i)
      lo = i;
    else
      return;
  }
}

/* Node of [lo, hi) at its middle, split on the box's longest axis. */
static void build_tree(photon *v, size_t lo, size_t hi) {
  while (hi - lo > 1) {
    float mn[3] = {INFINITY, INFINITY, INFINITY};
    float mx[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = lo; i < hi; i++)
      for (int a = 0; a < 3; a++) {
        mn[a] = fminf(mn[a], v[i].p[a]);
        mx[a] = fmaxf(mx[a], v[i].p[a]);
      }
    int axis = 0;
    for (int a = 1; a < 3; a++)
      if (mx[a] - mn[a] > mx[axis] - mn[axis])
        axis = a;
    size_t mid = lo + (hi - lo) / 2;
    select_kth(v, lo, hi, mid, axis);
    v[mid].axis = (uint8_t)axis;
    build_tree(v, lo, mid);
    lo = mid + 1;
  }
}

/* The gathered photons: a max-heap on distance^2 of at most cap. */
typedef struct heap {
  const photon **ph;
  float *d2;
  int n, cap;
  float max_d2; /* search radius^2, shrinking once the heap is full */
} heap;

static void heap_push(heap *h, const photon *ph, float d2) {
  if (h->n < h->cap) {
    int i = h->n++;
    while (i > 0 && h->d2[(i - 1) / 2] < d2) {
      h->ph[i] = h->ph[(i - 1) / 2];
      h->d2[i] = h->d2[(i - 1) / 2];
      i = (i - 1) / 2;
    }
    h->ph[i] = ph;
    h->d2[i] = d2;
    if (h->n == h->cap)
      h->max_d2 = h->d2[0];
    return;
  }
  if (d2 >= h->d2[0])
    return;
  int i = 0;
  for (;;) {
    int c = 2 * i + 1;
    if (c >= h->n)
      break;
    if (c + 1 < h->n && h->d2[c + 1] > h->d2[c])
      c++;
    if (h->d2[c] <= d2)
      break;
    h->ph[i] = h->ph[c];
    h->d2[i] = h->d2[c];
    i = c;
  }
  h->ph[i] = ph;
  h->d2[i] = d2;
  h->max_d2 = h->d2[0];
}

static void search(const photon *v, size_t lo, size_t hi, const float q[3],
                   const float n[3], heap *h) {
  while (hi > lo) {
    size_t mid = lo + (hi - lo) / 2;
    const photon *ph = &v[mid];
    int axis = ph->axis;
    float delta = q[axis] - ph->p[axis];
    float dx = q[0] - ph->p[0], dy = q[1] - ph->p[1], dz = q[2] - ph->p[2];
    float d2 = dx * dx + dy * dy + dz * dz;
    if (d2 < h->max_d2 &&
        (!n || ph->dir[0] * n[0] + ph->dir[1] * n[1] + ph->dir[2] * n[2] <
                   0.0f))
      heap_push(h, ph, d2);
    if (hi - lo == 1)
      return;
    size_t near_lo = delta < 0 ? lo : mid + 1;
    size_t near_hi = delta < 0 ? mid : hi;
    size_t far_lo = delta < 0 ? mid + 1 : lo;
    size_t far_hi = delta < 0 ? hi : mid;
    search(v, near_lo, near_hi, q, n, h);
    if (delta * delta >= h->max_d2)
      return;
    lo = far_lo, hi = far_hi;
  }
}

/* Gathers up to cap photons within r of q arriving against n (NULL:
   any); returns how many, with their heap in h. */
static int gather(const zr_photon_map *m, const float q[3], const float *n,
                  double r, int cap, const photon **ph, float *d2, heap *h) {
  h->ph = ph;
  h->d2 = d2;
  h->n = 0;
  h->cap = cap;
  h->max_d2 = (float)(r * r);
  search(m->v, 0, m->n, q, n, h);
  return h->n;
}

/* The median distance to the gather_max-th nearest photon, over up to
   1000 photons spread through the map. */
static double found_radius(const zr_photon_map *m) {
  size_t samples = m->n < 1000 ? m->n : 1000;
  int k = m->gather_max + 1; /* the photon itself is found too */
  const photon **ph = malloc((size_t)k * sizeof *ph);
  float *d2 = malloc((size_t)k * sizeof *d2);
  double *dist = malloc(samples * sizeof *dist);
  double r = 0.0;
  if (ph && d2 && dist) {
    size_t got = 0;
    for (size_t i = 0; i < samples; i++) {
      const photon *s = &m->v[i * m->n / samples];
      heap h;
      if (gather(m, s->p, NULL, INFINITY, k, ph, d2, &h) == k)
        dist[got++] = sqrt(h.d2[0]);
    }
    if (got > 0) {
      /* The median, by sorting (got is at most 1000). */
      for (size_t i = 1; i < got; i++) {
        double x = dist[i];
        size_t j = i;
        for (; j > 0 && dist[j - 1] > x; j--)
          dist[j] = dist[j - 1];
        dist[j] = x;
      }
      r = dist[got / 2];
    }
  }
  free(ph);
  free(d2);
  free(dist);
  return r;
}

/* ---- the map ---- */

/*
 * The media radius found when radius's third value is not given: this
 * many times the surface map's rule (the median distance to the
 * gather_max-th nearest photon).  Measured black-box: povray 3.7 draws
 * tests/media_photons.pov's beams the same for every media radius from
 * 0.45 up (radius 0, 1, R, 1; identical pictures at 0.45 and 0.6, and
 * its own choice is that picture), its gather_max bounding the count
 * (gather 20, 400 blurs the beams, 10, 25 sharpens them); the rule's
 * median there is 0.077.  So the radius only needs to be large enough
 * for gather_max to decide: 8 times (0.61 there) gives its pictures
 * (SSIM 0.988 and 0.987 against 0.871 and 0.896 at 1 time), and
 * optics.pov's is the same from 6 times up.
 */
#define MEDIA_RADIUS_FACTOR 8.0

/* The media map's kd-tree and gather radius: radius's third value, or
   found (MEDIA_RADIUS_FACTOR), times its fourth; NULL (and freed) when
   it holds no photon. */
static zr_photon_map *finish_media(zr_photon_map *mm,
                                   const zr_photon_settings *ps) {
  if (!mm)
    return NULL;
  if (mm->n > 0) {
    build_tree(mm->v, 0, mm->n);
    mm->radius = ps->media_radius > 0.0
                     ? ps->media_radius
                     : MEDIA_RADIUS_FACTOR * found_radius(mm);
    mm->radius *= ps->media_radius_multiplier > 0.0
                      ? ps->media_radius_multiplier
                      : 1.0;
  }
  if (!(mm->radius > 0.0)) {
    free(mm->v);
    free(mm);
    return NULL;
  }
  return mm;
}

zr_status zr__photons_build(zr_scene *scene, zr_context *ctx) {
  const zr_photon_settings *ps = &scene->settings.photons;
  if (!ps->on || scene->photons)
    return ZR_OK;
  zr_photon_map *m = calloc(1, sizeof *m);
  if (!m)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL,
                    "out of memory for the photon map");
  m->gather_min = ps->gather_min > 0 ? ps->gather_min : 20;
  m->gather_max = ps->gather_max >= m->gather_min ? ps->gather_max
                                                  : m->gather_min;
  m->expand_min = ps->expand_min;
  m->expand_increase = ps->expand_increase;
  m->fixed_radius = ps->media_steps > 0;
  shooter sh;
  memset(&sh, 0, sizeof sh);
  sh.scene = scene;
  sh.map = m;
  if (ps->media_steps > 0) {
    sh.media_map = calloc(1, sizeof *sh.media_map);
    if (!sh.media_map) {
      free(m);
      return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL,
                      "out of memory for the photon map");
    }
    sh.media_map->gather_min = m->gather_min;
    sh.media_map->gather_max = m->gather_max;
    sh.media_steps = ps->media_steps;
  }
  sh.tracer.scene = scene;
  sh.tracer.stats = &sh.stats;
  sh.max_level = ps->max_trace_level > 0 ? ps->max_trace_level
                                         : scene->settings.max_trace_level;
  sh.bailout = ps->adc_bailout >= 0.0 ? ps->adc_bailout
                                      : scene->settings.adc_bailout;
  /* One spacing for every target when count is given: the lattices'
     measures (in spacing^2) add up to about count photons. */
  double spacing = ps->spacing;
  if (!(spacing > 0.0)) {
    double total = 0.0;
    for (size_t li = 0; li < scene->n_lights; li++) {
      const zr_light *l = &scene->lights[li];
      if (!shoots(l))
        continue;
      for (size_t ti = 0; ti < scene->n_primitives; ti++) {
        const zr_object *o = scene->primitives[ti];
        zr_vec3 c;
        double r;
        if (is_target(o) && target_sphere(o, &c, &r))
          total += pair_measure(l, c, r, o->photons->spacing);
      }
    }
    if (!(total > 0.0) || !(ps->count > 0.0)) {
      free(sh.media_map);
      free(m);
      return ZR_OK;
    }
    spacing = sqrt(total / ps->count);
  }
  for (size_t li = 0; li < scene->n_lights && !sh.full && !sh.oom; li++) {
    const zr_light *l = &scene->lights[li];
    if (!shoots(l))
      continue;
    sh.light = l;
    for (size_t ti = 0; ti < scene->n_primitives && !sh.full && !sh.oom;
         ti++) {
      const zr_object *o = scene->primitives[ti];
      zr_vec3 c;
      double r;
      if (!is_target(o) || !target_sphere(o, &c, &r) ||
          !zr__object_bounds(o, &sh.target_lo, &sh.target_hi))
        continue;
      sh.target = o;
      sh.li = (uint32_t)li, sh.ti = (uint32_t)ti;
      sh.media_step = spacing * o->photons->spacing * ps->media_factor;
      sh.refind = 1.0 + zr_v3_len(zr_v3_sub(sh.target_hi, sh.target_lo));
      shoot_pair(&sh, (uint32_t)li, (uint32_t)ti, c, r,
                 spacing * o->photons->spacing);
    }
  }
  scene->photons_shot = sh.shot;
  scene->photons_stored = m->n;
  scene->media_photons_stored = sh.media_map ? sh.media_map->n : 0;
  m->media = finish_media(sh.media_map, ps);
  scene->media_photons_radius = m->media ? m->media->radius : 0.0;
  if (sh.oom) {
    zr__photons_free(m);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL,
                    "out of memory for the photon map");
  }
  if (sh.full)
    zr__diag(ctx, ZR_DIAG_WARNING, ZR_OK, NULL,
             "photons: the map is full at %zu photons; the rest were not "
             "shot (raise spacing or lower count)",
             m->n);
  if (m->n > 0) {
    build_tree(m->v, 0, m->n);
    m->radius = ps->radius > 0.0 ? ps->radius : found_radius(m);
    m->radius *= ps->radius_multiplier > 0.0 ? ps->radius_multiplier : 1.0;
  }
  if (!(m->radius > 0.0)) {
    /* No surface photons to gather: the map stays only for its media
       photons (a scene without them keeps no map, as before). */
    free(m->v);
    m->v = NULL;
    m->n = 0;
    if (!m->media) {
      free(m);
      return ZR_OK;
    }
  }
  scene->photons = m;
  return ZR_OK;
}

void zr__photons_free(zr_photon_map *map) {
  if (!map)
    return;
  zr__photons_free(map->media);
  free(map->v);
  free(map);
}

size_t zr__photons_stored(const zr_photon_map *map) {
  return map ? map->n : 0;
}

double zr__photons_radius(const zr_photon_map *map) {
  return map ? map->radius : 0.0;
}

/* The density estimate of the heap's photons over a disc of radius r. */
static zr_rgb estimate(const heap *h, zr_vec3 n, double brilliance,
                       double r) {
  zr_rgb sum = zr_rgb3(0, 0, 0);
  for (int i = 0; i < h->n; i++) {
    const photon *ph = h->ph[i];
    double w = 1.0;
    if (brilliance != 1.0) {
      double c = -(ph->dir[0] * n.x + ph->dir[1] * n.y + ph->dir[2] * n.z);
      w = c > 0.0 ? pow(c, brilliance - 1.0) : 0.0;
    }
    sum.r += w * ph->power[0];
    sum.g += w * ph->power[1];
    sum.b += w * ph->power[2];
  }
  return zr_rgb_scale(sum, 1.0 / (M_PI * r * r));
}

/* The room a gather of up to cap photons works in: on the stack up to
   NEAREST_STACK photons, else on the heap. */
enum { NEAREST_STACK = 256 };
typedef struct nearest {
  const photon *ph_stack[NEAREST_STACK];
  float d2_stack[NEAREST_STACK];
  const photon **ph;
  float *d2;
  int cap;
} nearest;

/* False when out of memory (nothing to free then). */
static bool nearest_init(nearest *b, int cap) {
  b->cap = cap;
  b->ph = b->ph_stack;
  b->d2 = b->d2_stack;
  if (cap <= NEAREST_STACK)
    return true;
  b->ph = malloc((size_t)cap * sizeof *b->ph);
  b->d2 = malloc((size_t)cap * sizeof *b->d2);
  if (b->ph && b->d2)
    return true;
  free(b->ph);
  free(b->d2);
  return false;
}

static void nearest_free(nearest *b) {
  if (b->ph != b->ph_stack) {
    free(b->ph);
    free(b->d2);
  }
}

zr_rgb zr__photons_gather(const zr_photon_map *m, zr_vec3 p, zr_vec3 n,
                          double brilliance) {
  if (!m || m->n == 0)
    return zr_rgb3(0, 0, 0);
  nearest b;
  if (!nearest_init(&b, m->gather_max))
    return zr_rgb3(0, 0, 0);
  int cap = b.cap;
  const photon **ph = b.ph;
  float *d2 = b.d2;
  float q[3] = {(float)p.x, (float)p.y, (float)p.z};
  float nf[3] = {(float)n.x, (float)n.y, (float)n.z};
  heap h;
  double r = m->radius;
  int found = gather(m, q, nf, r, cap, ph, d2, &h);
  double r_used = found == cap ? sqrt(h.max_d2) : r;
  zr_rgb e = found > 0 ? estimate(&h, n, brilliance, r_used)
                       : zr_rgb3(0, 0, 0);
  /* Too few: search again at EXPAND_FACTOR times the radius, up to
     EXPANSIONS times, while the new search is not rejected. */
  int expansions = m->fixed_radius ? 0 : EXPANSIONS;
  for (int x = 0; x < expansions && found < m->gather_min; x++) {
    r *= EXPAND_FACTOR;
    heap h2;
    int found2 = gather(m, q, nf, r, cap, ph, d2, &h2);
    if (found2 <= found)
      continue;
    double r2_used = found2 == cap ? sqrt(h2.max_d2) : r;
    zr_rgb e2 = estimate(&h2, n, brilliance, r2_used);
    if (found2 >= m->expand_min &&
        rgb_max3(e2) > rgb_max3(e) * (1.0 + m->expand_increase))
      break; /* the wider search sees a brighter region: keep ours */
    e = e2;
    found = found2;
  }
  nearest_free(&b);
  return e;
}

/* ---- gathering in media ---- */

bool zr__photons_in_media(const zr_photon_map *map) {
  return map && map->media;
}

/*
 * A media photon of power P stands for the light P / (area of its
 * lattice cell) crossing a step of length h (store_media): over a
 * volume V the photons' sum of P is the light arriving at a point
 * (what zr__light_arrive gives a media sample for a light) times V,
 * so sum / V replaces the light's colour in the scattering term, each
 * photon with the phase for its own direction (toward the light is
 * against its travel).
 */
zr_rgb zr__photons_media_light(const zr_photon_map *map, zr_vec3 p,
                               zr_vec3 dir, const zr_medium *const *list,
                               size_t n, const zr_rgb *density) {
  zr_rgb out = zr_rgb3(0, 0, 0);
  const zr_photon_map *m = map ? map->media : NULL;
  if (!m || m->n == 0)
    return out;
  bool collects = false;
  for (size_t i = 0; i < n; i++)
    if (!list[i]->photons_ignored &&
        rgb_max3(zr_rgb_mul(density[i], list[i]->scattering)) > 0.0)
      collects = true;
  if (!collects)
    return out;
  nearest b;
  if (!nearest_init(&b, m->gather_max))
    return out;
  int cap = b.cap;
  const photon **ph = b.ph;
  float *d2 = b.d2;
  float q[3] = {(float)p.x, (float)p.y, (float)p.z};
  heap h;
  int found = gather(m, q, NULL, m->radius, cap, ph, d2, &h);
  if (found > 0) {
    double r = found == cap ? sqrt(h.max_d2) : m->radius;
    double volume = 4.0 / 3.0 * M_PI * r * r * r;
    for (size_t i = 0; i < n; i++) {
      zr_rgb sc = zr_rgb_mul(density[i], list[i]->scattering);
      if (!(rgb_max3(sc) > 0.0))
        continue;
      zr_rgb sum = zr_rgb3(0, 0, 0);
      for (int k = 0; k < found; k++) {
        const photon *f = h.ph[k];
        double c = -(f->dir[0] * dir.x + f->dir[1] * dir.y +
                     f->dir[2] * dir.z);
        double w = zr__media_phase(list[i], c);
        sum.r += w * f->power[0];
        sum.g += w * f->power[1];
        sum.b += w * f->power[2];
      }
      out = zr_rgb_add(out, zr_rgb_scale(zr_rgb_mul(sc, sum), 1.0 / volume));
    }
  }
  nearest_free(&b);
  return out;
}
