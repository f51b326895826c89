/*
 * cache.c - POV-Ray's radiosity block as Ward's irradiance cache.
 *
 * POV-Ray 3.7's manual ("Radiosity", r3_4 3.4.4.3) describes its
 * radiosity as Greg Ward's method: the ambient term of a surface is
 * replaced by the light arriving from every direction of the hemisphere
 * above the point, estimated by `count` rays, kept in a cache and
 * reused nearby while the estimated error stays below `error_bound`.
 * This follows the published method:
 *   - Ward, Rubinstein and Clear, "A Ray Tracing Solution for Diffuse
 *     Interreflection" (1988): a record holds the irradiance E at p
 *     with normal n and the harmonic mean distance R of the surfaces its
 *     rays met; it serves a point p' with normal n' while
 *       eps = |p' - p| / R + sqrt(1 - n.n')  <  error_bound,
 *     and records blend with weights 1/eps - 1/error_bound (zero at the
 *     edge of reuse, so no seam shows where a record stops).
 *   - Ward and Heckbert, "Irradiance Gradients" (1992): the rays are
 *     cosine-weighted and stratified in M x N cells (sin^2 theta in
 *     M bands, phi in N sectors, N about pi M), which gives E and its
 *     rotational and translational gradients from the same rays; a
 *     record extrapolates with them to the point it serves.
 * POV-Ray's items keep their manual meaning: R is clamped between
 * minimum_reuse and maximum_reuse times the distance from the eye;
 * recursion_limit bounces are gathered (a sample ray's hit is shaded
 * with the cache one depth further, the last depth with no indirect
 * light); brightness scales what a depth returns; gray_threshold
 * desaturates it towards its grey (the mean of the channels);
 * max_sample limits each sample's brightest channel, keeping its hue;
 * adc_bailout stops a sample ray's reflected and transmitted rays as
 * the scene's stops a camera ray's (a sample ray weighs 0.5, measured);
 * count's second value widens the pool of directions and
 * nearest_count's stops the pretrace's later passes (see below);
 * normal on uses the perturbed normal; media off keeps sample rays out
 * of media; the pretrace goes over the image in mosaic blocks from
 * pretrace_start to pretrace_end of the image width with error_bound
 * lowered by low_error_factor and adds a record wherever fewer than
 * nearest_count records serve a point; a last pass over every pixel at
 * the full error_bound adds a record where none serves (nearest_count
 * with always_sample on), as povray's final pass does, so that the
 * final pass itself only reads the cache.  At the first bounce the
 * bound grows on dark surfaces (diffuse reflectance below 0.3, at most
 * 4 times), which povray's record counts show (cache_irradiance).  Rays that leave the
 * scene see the sky_sphere or background, so the sky lights the scene
 * (measured: a sphere of diffuse 0.6 inside a white sky_sphere renders
 * 0.6 in povray, and here, tests/test_gi.c).
 *
 * Determinism (ARCHITECTURE.md): a pass's pixels are taken in fixed
 * batches of BATCH pixels; every pixel of a batch sees the cache as the
 * batches before left it plus its own new records, and at the end of
 * the batch the new records join in pixel order.  Sample directions are
 * a pattern turned, or with count's second value shifted, by an amount
 * a hash of the record's point picks.  So the cache, and the
 * picture, are the same bytes for any number of threads, and every rank
 * builds the same cache.  In the final pass a point no record serves
 * gets a record of its own that is used and dropped (as are the deeper
 * records made for it), so the pass never writes to the cache.  Its
 * first-bounce lookups go through an index built when the pretrace ends
 * (zr__gi_cache_freeze), which hands them the same records in the same
 * order as the octree; the pretrace's own first-bounce lookups, whose
 * colour is thrown away, only count the records that serve.
 */
#include "gi/gi.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/team.h"
#include "radiosity/workers.h"
#include "trace/bvh.h"
#include "trace/atmosphere.h"
#include "trace/render.h"
#include "core/context.h"

/* Pixels per batch of a pretrace pass (see the essay). */
#define BATCH 16
/* Stratification: at most this many bands and sectors. */
#define MAX_BANDS 64
#define MAX_SECTORS 256
/* The translational gradient's factor on the published terms (see
   gather()). */
#define TRANS_SCALE (2.0 / (M_PI * M_PI))
/* The deepest octree level below the root, and the most times a root
   doubles (2^64 times the scene's size). */
#define MAX_LEVEL 64
#define MAX_GROW 64
/* The weight a sample ray starts with, against which the block's
   adc_bailout is compared where it spawns reflected or transmitted
   rays: 0.5, measured by bench/gi_adc_probe.sh (povray 3.7 lights a
   floor through a plane of transmit 0.5 up to adc_bailout 0.24, not
   from 0.26, and through transmit 0.8 up to 0.35, not from 0.45,
   whatever count, recursion_limit and the floor's diffuse). */
#define SAMPLE_WEIGHT 0.5
/* The diffuse reflectance from which a record's bound is the block's
   error_bound, and the most it grows on darker surfaces (see
   cache_irradiance; measured by bench/gi_record_probe.py). */
#define REFLECTANCE_FULL 0.3
#define REFLECTANCE_GROWTH 4.0
/* A record's weight in a blend is at most the one it has at this
   fraction of the error bound (see blend_near; measured by
   bench/gi_radset.py, bench/results/gi-2026-12-04-s19.md). */
#define OWN_EPS 0.1
/* The most patterns count's second value makes. */
#define MAX_PATTERNS 4096

bool zr__gi_list_push(zr__gi_list *l, const zr__gi_record *r) {
  if (l->n == l->cap) {
    size_t cap = l->cap ? 2 * l->cap : 16;
    zr__gi_record *v = realloc(l->v, cap * sizeof *v);
    if (!v)
      return false;
    l->v = v;
    l->cap = cap;
  }
  l->v[l->n++] = *r;
  return true;
}

void zr__gi_list_free(zr__gi_list *l) {
  free(l->v);
  memset(l, 0, sizeof *l);
}

/* ---- the octree ---------------------------------------------------- */

static int32_t new_node(zr_gi_cache *c, int d, zr_vec3 centre, double h) {
  if (c->n_nodes[d] == c->cap_nodes[d]) {
    size_t cap = c->cap_nodes[d] ? 2 * c->cap_nodes[d] : 64;
    zr__gi_node *v = realloc(c->nodes[d], cap * sizeof *v);
    if (!v)
      return -1;
    c->nodes[d] = v;
    zr__gi_cube *w = realloc(c->cubes[d], cap * sizeof *w);
    if (!w)
      return -1;
    c->cubes[d] = w;
    int32_t *j = realloc(c->jumps[d], cap * sizeof *j);
    if (!j)
      return -1;
    c->jumps[d] = j;
    c->cap_nodes[d] = cap;
  }
  c->jumps[d][c->n_nodes[d]] = (int32_t)c->n_nodes[d];
  zr__gi_node *n = &c->nodes[d][c->n_nodes[d]];
  c->cubes[d][c->n_nodes[d]] = (zr__gi_cube){centre, h};
  for (int a = 0; a < 3; a++) {
    n->lo[a] = INFINITY;
    n->hi[a] = -INFINITY;
  }
  n->r_max = 0.0f;
  for (int k = 0; k < 8; k++)
    n->child[k] = -1;
  n->first = -1;
  return (int32_t)c->n_nodes[d]++;
}

void zr__gi_cache_extent(zr_gi_cache *c) {
  const zr_scene *s = c->scene;
  zr_vec3 lo = s->camera.location, hi = lo;
  for (size_t i = 0; i < s->n_primitives; i++) {
    zr_vec3 a, b;
    if (!zr__object_bounds(s->primitives[i], &a, &b))
      continue; /* infinite: records outside the root stay at the root */
    if (!(isfinite(a.x) && isfinite(a.y) && isfinite(a.z) &&
          isfinite(b.x) && isfinite(b.y) && isfinite(b.z)))
      continue;
    lo = zr_v3(fmin(lo.x, a.x), fmin(lo.y, a.y), fmin(lo.z, a.z));
    hi = zr_v3(fmax(hi.x, b.x), fmax(hi.y, b.y), fmax(hi.z, b.z));
  }
  c->root_c = zr_v3_scale(zr_v3_add(lo, hi), 0.5);
  double h = fmax(hi.x - lo.x, fmax(hi.y - lo.y, hi.z - lo.z));
  c->root_h = h > 0.0 ? h : 1.0; /* twice the half extent */
}

/* Makes tree d's root (node 0) twice as large, towards q, with the old
   root as the octant that holds its centre. */
static bool grow_root(zr_gi_cache *c, int d, zr_vec3 q) {
  if (!(isfinite(q.x) && isfinite(q.y) && isfinite(q.z)))
    return false;
  zr__gi_cube old = c->cubes[d][0];
  if (!isfinite(2.0 * old.h))
    return false;
  zr_vec3 centre = zr_v3(old.c.x + (q.x > old.c.x ? old.h : -old.h),
                         old.c.y + (q.y > old.c.y ? old.h : -old.h),
                         old.c.z + (q.z > old.c.z ? old.h : -old.h));
  int32_t moved = new_node(c, d, old.c, old.h);
  if (moved < 0)
    return false;
  c->nodes[d][moved] = c->nodes[d][0];
  /* Its chain's end is where it was, unless the chain was the root
     alone; the root's own is set by zr__gi_cache_add. */
  c->jumps[d][moved] = c->jumps[d][0] == 0 ? moved : c->jumps[d][0];
  zr__gi_node *root = &c->nodes[d][0];
  c->cubes[d][0] = (zr__gi_cube){centre, 2.0 * old.h};
  root->first = -1; /* lo, hi and r_max stay the old root's */
  for (int k = 0; k < 8; k++)
    root->child[k] = -1;
  int k = (old.c.x > centre.x) | ((old.c.y > centre.y) << 1) |
          ((old.c.z > centre.z) << 2);
  root->child[k] = moved;
  return true;
}

/* v as a float no greater, and no less (a node's box only ever grows
   by the rounding: a lookup may test a record more, never one less).
   Values beyond the floats' range go to the infinities, not through a
   conversion C leaves undefined; a NaN stays one (fminf and fmaxf skip
   it, as fmin and fmax did). */
static float float_down(double v) {
  if (v > FLT_MAX)
    return FLT_MAX;
  if (v < -FLT_MAX)
    return -INFINITY;
  float f = (float)v;
  return (double)f > v ? nextafterf(f, -INFINITY) : f;
}
static float float_up(double v) {
  if (v > FLT_MAX)
    return INFINITY;
  if (v < -FLT_MAX)
    return -FLT_MAX;
  float f = (float)v;
  return (double)f < v ? nextafterf(f, INFINITY) : f;
}

/* Widens node n's box and radius to hold record r. */
static void node_hold(zr__gi_node *n, const zr__gi_record *r) {
  double p[3] = {r->p.x, r->p.y, r->p.z};
  for (int a = 0; a < 3; a++) {
    n->lo[a] = fminf(n->lo[a], float_down(p[a]));
    n->hi[a] = fmaxf(n->hi[a], float_up(p[a]));
  }
  n->r_max = fmaxf(n->r_max, float_up(r->r));
}

/* Node at's jump (gi.h), from its children's. */
static void set_jump(zr_gi_cache *c, int d, int32_t at) {
  const zr__gi_node *n = &c->nodes[d][at];
  int32_t only = -1;
  int children = 0;
  for (int k = 0; k < 8; k++)
    if (n->child[k] >= 0) {
      only = n->child[k];
      children++;
    }
  c->jumps[d][at] = n->first < 0 && children == 1 ? c->jumps[d][only] : at;
}

static void drop_grid(zr_gi_cache *c);

bool zr__gi_cache_add(zr_gi_cache *c, const zr__gi_record *r) {
  int d = r->depth;
  if (d < 0 || d >= 20)
    return false;
  if (c->n_nodes[d] == 0 && new_node(c, d, c->root_c, c->root_h) < 0)
    return false;
  if (c->grid_nodes || c->grid_a > 0.0)
    drop_grid(c); /* it no longer holds every record */
  size_t idx = c->records.n;
  if (!zr__gi_list_push(&c->records, r))
    return false;
  if (c->near_cap < c->records.cap) {
    zr__gi_near *w = realloc(c->near, c->records.cap * sizeof *w);
    if (!w) {
      c->records.n--;
      return false;
    }
    c->near = w;
    c->near_cap = c->records.cap;
  }
  c->near[idx] = (zr__gi_near){r->p, r->r, -1};
  /* Down to the smallest node whose half-size is still the record's
     farthest reach (error_bound R), while the point is inside it; every
     node on the way widens its box of points and radius to hold it
     (node_hold), and a lookup goes only into nodes whose box, grown by
     its radius, holds the point.  (Stopping at twice the reach took
     2.4 times the node visits and record tests on radiosity2.pov;
     half the reach, more nodes for fewer tests, no faster.) */
  double reach = c->params.error_bound * ldexp(r->r, d); /* see blend */
  int32_t at = 0;
  zr_vec3 q = r->p;
  /* A record outside the root (an infinite plane seen to the horizon
     has no bounds) grows it: the root doubles towards the point, the
     old root becoming one of its octants, as often as needed.  A
     record left at the root would be tested by every lookup (the
     outdoor scene's far floor: 97% of the lookup time before). */
  bool inside = false;
  for (int grow = 0; grow <= MAX_GROW; grow++) {
    const zr__gi_cube *root = &c->cubes[d][0];
    inside = fabs(q.x - root->c.x) <= root->h &&
             fabs(q.y - root->c.y) <= root->h &&
             fabs(q.z - root->c.z) <= root->h;
    if (inside || grow == MAX_GROW || !grow_root(c, d, q))
      break;
  }
  int32_t path[MAX_LEVEL + 1];
  int n_path = 0;
  for (int level = 0; inside && level < MAX_LEVEL; level++) {
    path[n_path++] = at;
    zr__gi_node *n = &c->nodes[d][at];
    node_hold(n, r);
    zr__gi_cube cube = c->cubes[d][at];
    double hc = 0.5 * cube.h;
    if (hc < reach)
      break;
    int k = (q.x > cube.c.x) | ((q.y > cube.c.y) << 1) |
            ((q.z > cube.c.z) << 2);
    if (n->child[k] < 0) {
      zr_vec3 cc = zr_v3(cube.c.x + (k & 1 ? hc : -hc),
                         cube.c.y + (k & 2 ? hc : -hc),
                         cube.c.z + (k & 4 ? hc : -hc));
      int32_t child = new_node(c, d, cc, hc);
      if (child < 0)
        return false;
      c->nodes[d][at].child[k] = child;
    }
    at = c->nodes[d][at].child[k];
  }
  node_hold(&c->nodes[d][at], r);
  c->near[idx].next = c->nodes[d][at].first;
  c->nodes[d][at].first = (int32_t)idx;
  /* Only the chains through the nodes passed can have changed (and the
     root's, when it grew). */
  set_jump(c, d, at);
  while (n_path > 0)
    set_jump(c, d, path[--n_path]);
  set_jump(c, d, 0);
  return true;
}

/* ---- interpolation ----------------------------------------------- */

typedef struct blend {
  zr_vec3 p, n;
  double a;        /* the error bound in force */
  double sum[3];
  double wsum;
  int count;
} blend;

/* fmax(v, 0.0) and fmin(v, hi) without the library calls (a lookup
   blends tens of records; the calls were 4% of sky_outdoor.pov's
   render): the same value for every v that is not a NaN, and a NaN v
   gives 0 and hi as fmax and fmin do. */
static inline double max0(double v) { return v > 0.0 ? v : 0.0; }
static inline double min_hi(double v, double hi) { return v < hi ? v : hi; }

/* Whether record r serves b's point, d = b->p - r->p and dd its
   squared length, once r is known to lie within reach (dd < (a R)^2),
   with its error estimate in *eps. */
static inline bool serves(const blend *b, const zr__gi_record *r,
                          zr_vec3 d, double dd, double *eps) {
  double nn = zr_v3_dot(b->n, r->n);
  if (!(nn > 0.0))
    return false;
  /* A record in front of the point (the point lies below the record's
     plane) sees light the point may not: Ward's test. */
  if (zr_v3_dot(d, zr_v3_scale(zr_v3_add(b->n, r->n), 0.5)) < -0.05 * r->r)
    return false;
  *eps = sqrt(dd) / r->r + sqrt(max0(1.0 - nn));
  return *eps < b->a;
}

/* Record r's share of the blend at b's point (d and dd as above). */
static void blend_near(blend *b, const zr__gi_record *r, zr_vec3 d,
                       double dd) {
  double eps;
  if (!serves(b, r, d, dd, &eps))
    return;
  /* Ward's weight 1 / eps grows without bound at the record's own
     point, and the pixel a record was gathered at (every record is,
     pretrace and final pass alike) showed that record alone, its
     sampling noise undamped by its neighbours': single dark and light
     dots on the walls of radiosity_36.pov, where povray's are smooth.
     So the weight stops growing at OWN_EPS times the bound: SSIM
     against povray over the 17 radiosity scenes was best overall at
     0.1 (0.05 to 0.5 tried); 0.2 and above lowered
     rad_def_test.pov's. */
  double floor_eps = OWN_EPS * b->a;
  double w = 1.0 / (eps > floor_eps ? eps : floor_eps) - 1.0 / b->a;
  zr_vec3 axis = zr_v3_cross(r->n, b->n);
  for (int c = 0; c < 3; c++) {
    double v = r->e[c] + zr_v3_dot(r->grad_r[c], axis) +
               zr_v3_dot(r->grad_t[c], d);
    /* Gradients extrapolate; they must not turn light negative or
       more than double it. */
    v = min_hi(max0(v), 2.0 * r->e[c] + 1e-12);
    b->sum[c] += w * v;
  }
  b->wsum += w;
  b->count++;
}

static void blend_record(blend *b, const zr__gi_record *r) {
  zr_vec3 d = zr_v3_sub(b->p, r->p);
  double reach = b->a * r->r, dd = zr_v3_dot(d, d);
  if (dd < reach * reach) /* the cheap test first: most records are far */
    blend_near(b, r, d, dd);
}

static void blend_tree(blend *b, const zr_gi_cache *c, int d, int32_t at) {
  const zr__gi_node *n = &c->nodes[d][at];
  /* The distance test on the compact copy first: a lookup rejects most
     of the records it meets (about 6 in 7 on sky_outdoor.pov), and a
     whole record is seven times the bytes. */
  for (int32_t i = n->first; i >= 0; i = c->near[i].next) {
    const zr__gi_near *q = &c->near[i];
    zr_vec3 dv = zr_v3_sub(b->p, q->p);
    double reach = b->a * q->r, dd = zr_v3_dot(dv, dv);
    if (dd < reach * reach)
      blend_near(b, &c->records.v[i], dv, dd);
  }
  for (int k = 0; k < 8; k++) {
    int32_t ch = n->child[k];
    if (ch < 0)
      continue;
    const zr__gi_node *m = &c->nodes[d][ch];
    /* The box of the points below, grown by the largest reach among
       them (a hair more, so that rounding never drops a record the
       test above would take).  The node's own cube grown by 1.5 times
       its half-size, the bound the placement allows, had
       radiosity2.pov's lookups visit 108 nodes and test 107 records
       each for 4.6 that pass; now 35 and 27. */
    double reach = b->a * m->r_max * (1.0 + 1e-9);
    if (b->p.x >= m->lo[0] - reach && b->p.x <= m->hi[0] + reach &&
        b->p.y >= m->lo[1] - reach && b->p.y <= m->hi[1] + reach &&
        b->p.z >= m->lo[2] - reach && b->p.z <= m->hi[2] + reach)
      blend_tree(b, c, d, c->jumps[d][ch]);
  }
}

/*
 * The pretrace's lookups at the first bounce only ask whether `want`
 * records serve the point (the colour of a pretrace ray is thrown away;
 * a sample ray's, at the depths below, is not, and those blend in full):
 * this counts them in b->count as blend_tree would, stopping at want.
 * The same records are gathered, so the cache, and the picture, are the
 * same bytes; the blend's sums are left at zero.
 */
static void count_tree(blend *b, const zr_gi_cache *c, int d, int32_t at,
                       int want) {
  const zr__gi_node *n = &c->nodes[d][at];
  for (int32_t i = n->first; i >= 0; i = c->near[i].next) {
    const zr__gi_near *q = &c->near[i];
    zr_vec3 dv = zr_v3_sub(b->p, q->p);
    double reach = b->a * q->r, dd = zr_v3_dot(dv, dv), eps;
    if (dd < reach * reach && serves(b, &c->records.v[i], dv, dd, &eps) &&
        ++b->count >= want)
      return;
  }
  for (int k = 0; k < 8 && b->count < want; k++) {
    int32_t ch = n->child[k];
    if (ch < 0)
      continue;
    const zr__gi_node *m = &c->nodes[d][ch];
    double reach = b->a * m->r_max * (1.0 + 1e-9); /* as blend_tree */
    if (b->p.x >= m->lo[0] - reach && b->p.x <= m->hi[0] + reach &&
        b->p.y >= m->lo[1] - reach && b->p.y <= m->hi[1] + reach &&
        b->p.z >= m->lo[2] - reach && b->p.z <= m->hi[2] + reach)
      count_tree(b, c, d, c->jumps[d][ch], want);
  }
}

/* ---- the final pass's index ---------------------------------------- */

/* A cell holding more records than this is split into octants while
   that shortens its list; the most levels; the most list entries, and
   cells, past 64 a record (which every scene gets). */
#define LEAF_RECORDS 12
#define LEAF_LEVELS 48
#define LEAF_ENTRIES (1u << 20)
#define SPLIT_GROWTH 4.0

static void drop_grid(zr_gi_cache *c) {
  free(c->grid_nodes);
  free(c->grid_idx);
  c->grid_nodes = NULL;
  c->grid_idx = NULL;
  c->grid_n_nodes = c->grid_n_idx = 0;
  c->grid_a = 0.0;
}

/* The records of tree d below node at in the order blend_tree meets
   them (a node's list, then its children in turn): the rank order. */
static void rank_tree(const zr_gi_cache *c, int d, int32_t at,
                      int32_t *order, size_t *n) {
  const zr__gi_node *nd = &c->nodes[d][at];
  for (int32_t i = nd->first; i >= 0; i = c->near[i].next)
    order[(*n)++] = i;
  for (int k = 0; k < 8; k++)
    if (nd->child[k] >= 0)
      rank_tree(c, d, nd->child[k], order, n);
}

/* Record q's reach along an axis where it lies at v, at bound a, a hair
   more (rounding never leaves out a cell the exact test would take). */
static double grid_ext(const zr__gi_near *q, double a, double v) {
  return a * q->r * (1.0 + 1e-6) + 1e-9 * fabs(v);
}

/* Whether record q's reach box meets the cube (centre cc, half-size h),
   grown by a hair. */
static bool grid_meets(const zr__gi_near *q, double a, zr_vec3 cc,
                       double h) {
  double p[3] = {q->p.x, q->p.y, q->p.z}, c[3] = {cc.x, cc.y, cc.z};
  for (int k = 0; k < 3; k++) {
    double e = grid_ext(q, a, p[k]);
    double g = h * (1.0 + 1e-9) + 1e-9 * fabs(c[k]);
    if (p[k] + e < c[k] - g || p[k] - e > c[k] + g)
      return false;
  }
  return true;
}

typedef struct grid_build {
  zr_gi_cache *c;
  size_t cap_nodes, cap_idx, max_idx;
  bool nomem;
} grid_build;

static int32_t grid_node(grid_build *gb, int count) {
  zr_gi_cache *c = gb->c;
  if (c->grid_n_nodes + (size_t)count > gb->cap_nodes) {
    size_t cap = gb->cap_nodes ? 2 * gb->cap_nodes : 64;
    while (cap < c->grid_n_nodes + (size_t)count)
      cap *= 2;
    zr__gi_cell *v = realloc(c->grid_nodes, cap * sizeof *v);
    if (!v) {
      gb->nomem = true;
      return -1;
    }
    c->grid_nodes = v;
    gb->cap_nodes = cap;
  }
  int32_t at = (int32_t)c->grid_n_nodes;
  c->grid_n_nodes += (size_t)count;
  return at;
}

/* Node at (cube centre cc, half-size h) over the list (rank order): a
   leaf holding it, or eight octants each over the records that meet
   it. */
static void grid_fill(grid_build *gb, int32_t at, zr_vec3 cc, double h,
                      const int32_t *list, size_t m, int level) {
  zr_gi_cache *c = gb->c;
  double a = c->grid_a;
  c->grid_nodes[at] = (zr__gi_cell){cc, h, -1, 0, 0};
  int32_t *sub[8] = {NULL};
  size_t ms[8] = {0};
  bool split = m > LEAF_RECORDS && level < LEAF_LEVELS &&
               c->grid_n_idx + 8 * m <= gb->max_idx &&
               c->grid_n_nodes + 8 <= gb->max_idx;
  double hc = 0.5 * h;
  zr_vec3 ccs[8];
  for (int k = 0; split && k < 8; k++) {
    ccs[k] = zr_v3(cc.x + (k & 1 ? hc : -hc), cc.y + (k & 2 ? hc : -hc),
                   cc.z + (k & 4 ? hc : -hc));
    sub[k] = malloc((m ? m : 1) * sizeof *sub[k]);
    if (!sub[k]) {
      gb->nomem = true;
      split = false;
      break;
    }
    for (size_t j = 0; j < m; j++)
      if (grid_meets(&c->near[list[j]], a, ccs[k], hc))
        sub[k][ms[k]++] = list[j];
  }
  /* Only where the octants' lists are together at most SPLIT_GROWTH
     times the cell's (so that lists shorten, and the entries stay a few
     times the records). */
  size_t total = 0;
  for (int k = 0; split && k < 8; k++)
    total += ms[k];
  bool shorter = split && (double)total <= SPLIT_GROWTH * (double)m;
  if (split && shorter) {
    int32_t first = grid_node(gb, 8);
    if (first >= 0) {
      c->grid_nodes[at].child = first;
      for (int k = 0; k < 8; k++)
        grid_fill(gb, first + k, ccs[k], hc, sub[k], ms[k], level + 1);
    }
  } else {
    if (c->grid_n_idx + m > gb->cap_idx) {
      size_t cap = gb->cap_idx ? 2 * gb->cap_idx : 1024;
      while (cap < c->grid_n_idx + m)
        cap *= 2;
      int32_t *v = realloc(c->grid_idx, cap * sizeof *v);
      if (!v)
        gb->nomem = true;
      else {
        c->grid_idx = v;
        gb->cap_idx = cap;
      }
    }
    if (!gb->nomem) {
      c->grid_nodes[at].start = (uint32_t)c->grid_n_idx;
      if (m > 0) /* an empty leaf may come before any list is held */
        memcpy(c->grid_idx + c->grid_n_idx, list, m * sizeof *list);
      c->grid_n_idx += m;
      c->grid_nodes[at].end = (uint32_t)c->grid_n_idx;
    }
  }
  for (int k = 0; k < 8; k++)
    free(sub[k]);
}

bool zr__gi_cache_freeze(zr_gi_cache *c) {
  drop_grid(c);
  const int d = 0;
  if (c->n_nodes[d] == 0)
    return false;
  double a = c->params.error_bound;
  size_t n = 0;
  for (size_t i = 0; i < c->records.n; i++)
    n += c->records.v[i].depth == d;
  if (n == 0 || n > (size_t)INT32_MAX / 2)
    return false;
  int32_t *order = malloc(n * sizeof *order);
  if (!order)
    return false;
  size_t m = 0;
  rank_tree(c, d, 0, order, &m);
  bool ok = m == n;
  /* The root: the records' reach boxes. */
  double lo[3] = {INFINITY, INFINITY, INFINITY};
  double hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (size_t j = 0; ok && j < n; j++) {
    const zr__gi_near *q = &c->near[order[j]];
    double p[3] = {q->p.x, q->p.y, q->p.z};
    for (int k = 0; k < 3; k++) {
      double e = grid_ext(q, a, p[k]);
      if (!(fabs(p[k]) < 1e300) || !(e < 1e300))
        ok = false;
      lo[k] = fmin(lo[k], p[k] - e);
      hi[k] = fmax(hi[k], p[k] + e);
    }
  }
  if (!ok) {
    free(order);
    return false;
  }
  double h = 0.0;
  for (int k = 0; k < 3; k++)
    h = fmax(h, 0.5 * (hi[k] - lo[k]));
  h = h * (1.0 + 1e-6) + 1e-300;
  c->grid_a = a;
  /* The entries' (and cells') cap; uint32_t offsets. */
  size_t max_idx = (size_t)LEAF_ENTRIES + 64 * n;
  if (max_idx > UINT32_MAX / 2)
    max_idx = UINT32_MAX / 2;
  grid_build gb = {c, 0, 0, max_idx, false};
  int32_t root = grid_node(&gb, 1);
  if (root == 0)
    grid_fill(&gb, 0,
              zr_v3(0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]),
                    0.5 * (lo[2] + hi[2])),
              h, order, n, 0);
  free(order);
  if (gb.nomem || root != 0) {
    drop_grid(c);
    return false;
  }
  return true;
}

/* blend_tree through the index: the records of the point's leaf, in rank
   order, the same tests. */
static void blend_grid(blend *b, const zr_gi_cache *c) {
  const zr__gi_cell *cell = &c->grid_nodes[0];
  if (!(fabs(b->p.x - cell->c.x) <= cell->h &&
        fabs(b->p.y - cell->c.y) <= cell->h &&
        fabs(b->p.z - cell->c.z) <= cell->h))
    return; /* beyond every record's reach */
  while (cell->child >= 0) {
    int k = (b->p.x > cell->c.x) | ((b->p.y > cell->c.y) << 1) |
            ((b->p.z > cell->c.z) << 2);
    cell = &c->grid_nodes[cell->child + k];
  }
  for (uint32_t j = cell->start; j < cell->end; j++) {
    int32_t i = c->grid_idx[j];
    const zr__gi_near *q = &c->near[i];
    zr_vec3 dv = zr_v3_sub(b->p, q->p);
    double reach = b->a * q->r, dd = zr_v3_dot(dv, dv);
    if (dd < reach * reach)
      blend_near(b, &c->records.v[i], dv, dd);
  }
}

/* Whether a final pass's lookup at depth d may take the index: the
   first bounce, an error bound within the index's, a finite point. */
static bool grid_serves(const zr_gi_cache *c, const blend *b, int d) {
  return d == 0 && c->grid_a > 0.0 && b->a <= c->grid_a &&
         isfinite(b->p.x) && isfinite(b->p.y) && isfinite(b->p.z) &&
         fabs(b->p.x) < 1e300 && fabs(b->p.y) < 1e300 && fabs(b->p.z) < 1e300;
}

void zr__gi_cache_lookup(const zr_gi_cache *c, int d, zr_vec3 p, zr_vec3 n,
                         double a, bool via_grid, int want, double sum[3],
                         double *wsum, int *count) {
  blend b;
  memset(&b, 0, sizeof b);
  b.p = p;
  b.n = n;
  b.a = a;
  if (want > 0) {
    if (d >= 0 && d < 20 && c->n_nodes[d] > 0)
      count_tree(&b, c, d, c->jumps[d][0], want);
  } else if (via_grid && grid_serves(c, &b, d)) {
    blend_grid(&b, c);
  } else if (d >= 0 && d < 20 && c->n_nodes[d] > 0) {
    blend_tree(&b, c, d, c->jumps[d][0]);
  }
  for (int k = 0; k < 3; k++)
    sum[k] = b.sum[k];
  *wsum = b.wsum;
  *count = b.count;
}

/* ---- gathering a record ------------------------------------------ */

/* Per-thread state while a pixel is traced: the records it made. */
typedef struct gi_scratch {
  zr__gi_list local;
  uint64_t rays;
} gi_scratch;

static bool cache_irradiance(const zr_indirect *self,
                             const zr_tracer *tracer,
                             const zr_indirect_query *q, zr_rgb *out);

static uint64_t mix64(uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9u;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebu;
  x ^= x >> 31;
  return x;
}

/* A seed from the point's bits and the depth. */
static uint64_t point_seed(zr_vec3 p, int depth) {
  double v[3] = {p.x, p.y, p.z};
  uint64_t h = 0x243f6a8885a308d3u + (uint64_t)depth;
  for (int i = 0; i < 3; i++) {
    uint64_t bits;
    memcpy(&bits, &v[i], sizeof bits);
    h = mix64(h ^ bits);
  }
  return h;
}

/* Two unit vectors that make an orthonormal frame with n. */
static void frame(zr_vec3 n, zr_vec3 *t1, zr_vec3 *t2) {
  zr_vec3 a = fabs(n.x) < 0.6 ? zr_v3(1, 0, 0)
              : fabs(n.y) < 0.6 ? zr_v3(0, 1, 0)
                                : zr_v3(0, 0, 1);
  *t1 = zr_v3_norm(zr_v3_cross(a, n));
  *t2 = zr_v3_cross(n, *t1);
}

/* The light a sample's colour stands for, limited by max_sample. */
static zr_rgb limit_sample(const zr_gi_params *gp, zr_rgb l) {
  double m = fmax(l.r, fmax(l.g, l.b));
  if (gp->max_sample > 0.0 && m > gp->max_sample)
    l = zr_rgb_scale(l, gp->max_sample / m);
  return l;
}

/* The integral of tan(theta) d(sin^2 theta) from 0 to s = sin^2 theta. */
static double tan_integral(double s) {
  s = fmin(fmax(s, 0.0), 1.0);
  return asin(sqrt(s)) - sqrt(s * (1.0 - s));
}

/*
 * Gathers a new record at q for depth d: M x N cosine-weighted,
 * stratified rays, E, R and the gradients of Ward and Heckbert (1992,
 * equations for the cosine-weighted case; everything is divided by pi
 * to keep mean radiance).
 */
static void gather(const zr_gi_cache *c, const zr_tracer *tracer,
                   const zr_indirect_query *q, zr_vec3 n, gi_scratch *sc,
                   zr__gi_record *rec) {
  const zr_gi_params *gp = &c->params;
  int d = tracer->gi_depth;
  /* Each depth takes half the rays of the one above, at least 16:
     povray's statistics for radiosity/cornell.pov (count 200) show 200
     rays a record at depth 0 and 94 on average at depths 1 and 2. */
  double count = fmax(fmin(16.0, gp->count), ldexp(gp->count, -d));
  int m = (int)floor(sqrt(count / M_PI) + 0.5);
  m = m < 1 ? 1 : m > MAX_BANDS ? MAX_BANDS : m;
  int nn = (int)floor(count / m + 0.5);
  nn = nn < 3 ? 3 : nn > MAX_SECTORS ? MAX_SECTORS : nn;
  zr_vec3 t1, t2;
  frame(n, &t1, &t2);
  /* The pattern of directions.  POV-Ray's manual ("count"): one
     value, every record shoots the same set of directions (here, in
     its frame, up to a turn: see below); a second value, the total
     number of directions they are drawn from.  Here
     the pool is K = pool / count shifts (u0, v0) of the stratified
     pattern, a rank-1 lattice in the cell, so the K patterns together
     cover every cell evenly; a record takes the shift its position
     hashes to (POV-Ray takes them in turn, which would make the cache
     depend on the order threads add records). */
  double u0, v0;
  uint64_t rng = point_seed(q->p, d);
  if (gp->count_pool > gp->count) {
    long kk = lround((double)gp->count_pool / gp->count);
    kk = kk < 1 ? 1 : kk > MAX_PATTERNS ? MAX_PATTERNS : kk;
    long k = (long)(mix64(rng) % (uint64_t)kk);
    u0 = (k + 0.5) / (double)kk;
    v0 = fmod(0.5 + k * 0.6180339887498949, 1.0);
  } else {
    /* One value: the sectors turned by an angle the record's point
       hashes to (the bands stay at their centres).  With every record
       on the sectors' centres, a whole surface's records shoot the
       same directions, and the roofs, walls and openings parallel to
       the frame's axes are hit or missed by all of them together:
       radiosity_36.pov's shadowed pillars came out at a third of
       povray's indirect light at count 50 (8-bit 9.6 -> 5.7 in the
       middle pillar, no fog), while povray's count 50 is within 10% of
       its count 600 and ours at count 600 agrees with it
       (tests/test_gi_pattern.sh measures a hall built the same way).
       A turn per record makes that error noise that the blend of
       several records averages.  Turning the bands too (a shift of
       sin^2 theta as well) made the noise show as speckles on sky-lit
       floors where povray is smooth: radiosity2.pov 0.9892 -> 0.9806
       and radiosity3.pov 0.9457 -> 0.9315 against povray, where the
       turn alone gains (bench/results/gi-2026-12-04-s19.md). */
    u0 = 0.5;
    v0 = (double)(mix64(rng ^ 0x9e3779b97f4a7c15u) >> 11) * 0x1.0p-53;
  }

  zr_indirect deeper = {cache_irradiance, c, sc, NULL, NULL};
  zr_tracer sub = *tracer;
  sub.indirect = &deeper;
  sub.skip_direct = false;
  sub.gi_depth = d + 1;
  sub.path = q->path;
  sub.hide = 0;
  sub.no_media = tracer->no_media || !gp->media;
  /* povray fogs no sample ray (measured: tests/test_gi_fog.sh). */
  sub.no_fog = true;
  /* The block's adc_bailout (0: no bailout at all). */
  sub.bailout = gp->adc_bailout > 0.0 ? gp->adc_bailout : DBL_MIN;
  zr_vec3 origin = zr_v3_madd(q->p, q->n_geo, zr__surface_offset(q->p));
  if (zr_v3_dot(q->n_geo, n) < 0.0)
    origin = zr_v3_madd(q->p, n, zr__surface_offset(q->p));

  /* Each depth's gather has its own arrays: gathering recurses. */
  zr_rgb *lum = malloc((size_t)(m * nn) * sizeof *lum);
  double *dist = malloc((size_t)(m * nn) * sizeof *dist);
  if (!lum || !dist) {
    free(lum);
    free(dist);
    memset(rec, 0, sizeof *rec);
    rec->p = q->p;
    rec->n = n;
    rec->depth = d;
    rec->r = 1e-9; /* out of memory: a dark record nobody reuses */
    return;
  }
  /* Each sector's cos and sin of phi, once (not once a band: the
     calls were 2% of radiosity2.pov). */
  double cos_phi[MAX_SECTORS], sin_phi[MAX_SECTORS];
  for (int k = 0; k < nn; k++) {
    double phi = 2.0 * M_PI * (k + v0) / nn;
    cos_phi[k] = cos(phi);
    sin_phi[k] = sin(phi);
  }
  double sum[3] = {0, 0, 0}, inv_r = 0.0;
  for (int j = 0; j < m; j++)
    for (int k = 0; k < nn; k++) {
      double s2 = (j + u0) / m;
      double st = sqrt(s2), ct = sqrt(fmax(0.0, 1.0 - s2));
      zr_vec3 dir = zr_v3_add(
          zr_v3_add(zr_v3_scale(t1, st * cos_phi[k]),
                    zr_v3_scale(t2, st * sin_phi[k])),
          zr_v3_scale(n, ct));
      zr_ray ray = {origin, dir};
      double t = INFINITY;
      zr_rgb l;
      if (gp->sky_only) {
        zr_hit hit;
        if (zr__bvh_nearest(c->scene->bvh, &ray, 0.0, INFINITY, &hit)) {
          t = hit.t;
          l = zr_rgb3(0, 0, 0);
        } else {
          l = zr__sky_colour(c->scene, dir);
        }
      } else {
        l = zr__trace_ray_hit(&sub, &ray, 1, SAMPLE_WEIGHT, NULL, &t);
      }
      l = limit_sample(gp, l);
      int i = j * nn + k;
      lum[i] = l;
      dist[i] = t;
      sum[0] += l.r, sum[1] += l.g, sum[2] += l.b;
      if (isfinite(t) && t > 0.0)
        inv_r += 1.0 / t;
    }
  if (sc)
    sc->rays += (uint64_t)(m * nn);
  int total = m * nn;
  memset(rec, 0, sizeof *rec);
  rec->p = q->p;
  rec->n = n;
  rec->depth = d;
  for (int ch = 0; ch < 3; ch++)
    rec->e[ch] = sum[ch] / total;

  /* The reuse radius: harmonic mean distance, clamped by the reuse
     bounds times the distance from the eye. */
  double r = inv_r > 0.0 ? total / inv_r : INFINITY;
  double eye = q->path > 0.0 ? q->path : 1.0;
  double rmin = gp->minimum_reuse * eye, rmax = gp->maximum_reuse * eye;
  if (rmin > rmax)
    rmin = rmax;
  r = fmin(fmax(r, rmin), rmax);
  rec->r = r > 0.0 ? r : 1e-9;

  /* Gradients (Ward and Heckbert 1992).  Checked against the exact
   irradiance of a point on a floor beside a black wall under a white
   sky (the polygon form factor, differentiated numerically): the
   rotational gradient with +tan(theta) agrees to 2% in both
   directions of tilt; the translational terms as printed, divided by
   pi for mean radiance, came out pi/2 too steep at every distance
   tried, hence 2 / pi^2; they then agree to about 20%, the sample
   noise of 1000 rays. */
  /* tan(theta) averaged over each band (sin^2 theta from j / m to
     (j + 1) / m): the integral of sqrt(s / (1 - s)) is asin(sqrt(s)) -
     sqrt(s (1 - s)).  The sample's own tan(theta) is right only on
     average over a jitter, and at the band's centre reads the grazing
     band, where it grows without bound, 13% low on the whole gradient
     (tests/test_gi.c). */
  double tan_band[MAX_BANDS];
  for (int j = 0; j < m; j++)
    tan_band[j] = m * (tan_integral((double)(j + 1) / m) -
                       tan_integral((double)j / m));
  for (int k = 0; k < nn; k++) {
    double phi_m = 2.0 * M_PI * k / nn;
    zr_vec3 uk = zr_v3_add(zr_v3_scale(t1, cos_phi[k]),
                           zr_v3_scale(t2, sin_phi[k]));
    zr_vec3 vk = zr_v3_add(zr_v3_scale(t1, -sin_phi[k]),
                           zr_v3_scale(t2, cos_phi[k]));
    zr_vec3 vkm = zr_v3_add(zr_v3_scale(t1, -sin(phi_m)),
                            zr_v3_scale(t2, cos(phi_m)));
    int kp = (k + nn - 1) % nn;
    for (int j = 0; j < m; j++) {
      int i = j * nn + k;
      double s2 = (j + u0) / m;
      double st = sqrt(s2);
      double tan_t = tan_band[j];
      double l[3] = {lum[i].r, lum[i].g, lum[i].b};
      for (int ch = 0; ch < 3; ch++)
        rec->grad_r[ch] = zr_v3_madd(rec->grad_r[ch], vk,
                                     tan_t * l[ch] / total);
      /* Between bands j - 1 and j along sector k. */
      if (j > 0) {
        int im = (j - 1) * nn + k;
        double sm2 = (double)j / m;
        double sm = sqrt(sm2), cm2 = 1.0 - sm2;
        double rr = fmin(dist[i], dist[im]);
        if (isfinite(rr) && rr > 0.0) {
          double f = (2.0 * M_PI / nn) * sm * cm2 / rr * TRANS_SCALE;
          double lm[3] = {lum[im].r, lum[im].g, lum[im].b};
          for (int ch = 0; ch < 3; ch++)
            rec->grad_t[ch] = zr_v3_madd(rec->grad_t[ch], uk,
                                         f * (l[ch] - lm[ch]));
        }
      }
      /* Between sectors k - 1 and k in band j. */
      {
        int ik = j * nn + kp;
        double cm = sqrt(fmax(0.0, 1.0 - (double)j / m));
        double cp = sqrt(fmax(0.0, 1.0 - (double)(j + 1) / m));
        double rr = fmin(dist[i], dist[ik]);
        if (isfinite(rr) && rr > 0.0 && st > 1e-6) {
          double f = (cm - cp) / (st * rr) * TRANS_SCALE;
          double lk[3] = {lum[ik].r, lum[ik].g, lum[ik].b};
          for (int ch = 0; ch < 3; ch++)
            rec->grad_t[ch] = zr_v3_madd(rec->grad_t[ch], vkm,
                                         f * (l[ch] - lk[ch]));
        }
      }
    }
  }
  /* The translational gradient may not change the value by more than
     itself across the reuse radius (the clamped R can be far above the
     distance of a close occluder, where the gradient is steep):
     Krivanek et al.'s gradient limit, |grad| R <= E. */
  for (int ch = 0; ch < 3; ch++) {
    double g = zr_v3_len(rec->grad_t[ch]);
    if (g * rec->r > rec->e[ch])
      rec->grad_t[ch] = zr_v3_scale(rec->grad_t[ch],
                                    g > 0.0 ? rec->e[ch] / (g * rec->r) : 0.0);
  }
  free(lum);
  free(dist);
}

/* What a depth hands upwards: grey-shifted and brightened. */
static zr_rgb finish_light(const zr_gi_params *gp, const double e[3]) {
  double grey = (e[0] + e[1] + e[2]) / 3.0, g = gp->gray_threshold;
  return zr_rgb3(gp->brightness * (g * grey + (1.0 - g) * e[0]),
                 gp->brightness * (g * grey + (1.0 - g) * e[1]),
                 gp->brightness * (g * grey + (1.0 - g) * e[2]));
}

static bool cache_irradiance(const zr_indirect *self,
                             const zr_tracer *tracer,
                             const zr_indirect_query *q, zr_rgb *out) {
  const zr_gi_cache *c = self->provider;
  const zr_gi_params *gp = &c->params;
  int d = tracer->gi_depth;
  if (d >= gp->recursion_limit || d >= 20)
    return false; /* the last depth: no indirect light */
  gi_scratch *sc = self->scratch;
  blend b;
  memset(&b, 0, sizeof b);
  b.p = q->p;
  /* With normal off (the default) the hemisphere is the surface's own,
     whatever the normal { } does: a bump that tilts the shading normal
     past 90 degrees (granite 0.95 scale 0.05 on the corpus'
     pneumaticBoat.pov sand) turned it, before, to the side under the
     surface, which saw the water plane's dark underside - black pixels
     where povray 3.7 shows the sky's light (tests/test_gi_normal_off.sh). */
  b.n = gp->normal ? q->n : q->n_geo;
  /* The pretrace lowers the bound (low_error_factor) and wants
     nearest_count records; the final pass takes any. */
  bool pretrace = c->pretracing == 1;
  b.a = gp->error_bound * (pretrace ? gp->low_error_factor : 1.0);
  /* Deeper bounces are seen only through the diffuse blur of the ones
     above: each depth doubles the bound and takes one record where
     POV-Ray's nearest_count asks several at the first (zRcube's
     choice, after Ward's relaxed accuracy for interreflected light;
     bench/gi.sh measures what it costs in SSIM against povray). */
  for (int k = 0; k < d; k++)
    b.a *= 2.0;
  /* A dark surface shows little of its indirect light, and povray
     spends fewer records on it: at the first bounce the bound grows as
     the surface's diffuse reflectance w (diffuse times the pigment's
     mean) falls below REFLECTANCE_FULL, by REFLECTANCE_FULL / w, at
     most REFLECTANCE_GROWTH times.  Fitted by
     bench/gi_record_probe.py --reflectance to povray's record counts
     on a sky-lit plane (w 0.3, 0.12, 0.03, 0.012; nearest_count 1, 3
     and 9), whose counts fall to a third as w goes from 0.3 to 0.03;
     pneumaticBoat's dark water (w about 0.008) made 3,498 of our 6,663
     records against povray's 3,956 in all. */
  if (d == 0) {
    double w = (q->reflectance.r + q->reflectance.g + q->reflectance.b) /
               3.0;
    if (!(w >= REFLECTANCE_FULL))
      b.a *= w > REFLECTANCE_FULL / REFLECTANCE_GROWTH
                 ? REFLECTANCE_FULL / w
                 : REFLECTANCE_GROWTH;
  }
  int want = d == 0 && (pretrace || (c->pretracing == 2 &&
                                     gp->always_sample))
                 ? gp->nearest_count
                 : 1;
  /* A pretrace ray's own colour is thrown away: at the first bounce it
     only asks how many records serve (count_tree). */
  bool counting = c->pretracing != 0 && d == 0;
  if (counting) {
    if (want > 0 && c->n_nodes[d] > 0)
      count_tree(&b, c, d, c->jumps[d][0], want);
    for (size_t i = 0; sc && i < sc->local.n && b.count < want; i++) {
      const zr__gi_record *r = &sc->local.v[i];
      zr_vec3 dv = zr_v3_sub(b.p, r->p);
      double reach = b.a * r->r, dd = zr_v3_dot(dv, dv), eps;
      if (r->depth == d && dd < reach * reach && serves(&b, r, dv, dd, &eps))
        b.count++;
    }
  } else {
    if (c->pretracing == 0 && grid_serves(c, &b, d))
      blend_grid(&b, c);
    else if (d < 20 && c->n_nodes[d] > 0)
      blend_tree(&b, c, d, c->jumps[d][0]);
    if (sc)
      for (size_t i = 0; i < sc->local.n; i++)
        if (sc->local.v[i].depth == d)
          blend_record(&b, &sc->local.v[i]);
  }
  /* nearest_count's second value (POV-Ray's manual: the adaptive
     pretrace "will stop re-iterating over areas where ... that many
     ... samples are already present"): from the second pass on, a
     camera-visible point served by that many records gathers no more,
     however many the first value asks for.  (Per point, not averaged
     over an area, and without POV-Ray's weighting by sample
     quality.) */
  if (d == 0 && pretrace && c->pretrace_pass > 0 &&
      gp->nearest_count_stop > 0 && b.count >= gp->nearest_count_stop)
    want = 0;
  if (b.count < want) {
    gi_scratch tmp;
    memset(&tmp, 0, sizeof tmp);
    gi_scratch *use = sc ? sc : &tmp;
    zr__gi_record rec;
    gather(c, tracer, q, b.n, use, &rec);
    if (!zr__gi_list_push(&use->local, &rec)) {
      /* Out of memory: use the record once without keeping it. */
    }
    zr__gi_list_free(&tmp.local);
    if (counting) {
      *out = finish_light(gp, rec.e);
      return true;
    }
    blend_record(&b, &rec);
    if (!(b.wsum > 0.0)) {
      *out = finish_light(gp, rec.e);
      return true;
    }
  }
  if (counting || !(b.wsum > 0.0))
    return false;
  double e[3] = {b.sum[0] / b.wsum, b.sum[1] / b.wsum, b.sum[2] / b.wsum};
  *out = finish_light(gp, e);
  return true;
}

/* ---- the public side ---------------------------------------------- */

const zr_indirect *zr__gi_indirect_for(const zr_gi_cache *cache,
                                       const zr_scene *scene) {
  return cache && cache->scene == scene ? &cache->indirect : NULL;
}

static zr_status check_params(zr_context *ctx, const zr_gi_params *p) {
  const char *what = NULL;
  if (p->count < 1 || p->count > 1000000)
    what = "count must be 1 to 1000000";
  else if (p->recursion_limit < 1 || p->recursion_limit > 20)
    what = "recursion_limit must be 1 to 20";
  else if (p->nearest_count < 1 || p->nearest_count > 20)
    what = "nearest_count must be 1 to 20";
  else if (p->nearest_count_stop < 0 || p->nearest_count_stop > 20)
    what = "nearest_count's second value must be 1 to 20 (0: none)";
  else if (p->count_pool < 0 || p->count_pool > 100000000)
    what = "count's second value must be up to 100000000 (0: none)";
  else if (!(p->adc_bailout >= 0.0 && p->adc_bailout <= 1.0))
    what = "adc_bailout must be in [0, 1]";
  else if (!(p->error_bound > 0.0) || !isfinite(p->error_bound))
    what = "error_bound must be a number > 0";
  else if (!(p->low_error_factor > 0.0 && p->low_error_factor <= 1.0))
    what = "low_error_factor must be in (0, 1]";
  else if (!(p->gray_threshold >= 0.0 && p->gray_threshold <= 1.0))
    what = "gray_threshold must be in [0, 1]";
  else if (!(p->brightness >= 0.0) || !isfinite(p->brightness))
    what = "brightness must be a number >= 0";
  else if (!(p->minimum_reuse >= 0.0 && p->maximum_reuse > 0.0))
    what = "minimum_reuse must be >= 0 and maximum_reuse > 0";
  else if (!(p->pretrace_start > 0.0 && p->pretrace_start <= 1.0 &&
             p->pretrace_end > 0.0 && p->pretrace_end <= 1.0))
    what = "pretrace_start and pretrace_end must be in (0, 1]";
  if (!what)
    return ZR_OK;
  return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL,
                  "irradiance cache: %s", what);
}

ZR_API zr_status zr_gi_cache_new(zr_context *ctx, const zr_scene *scene,
                                 const zr_gi_params *params,
                                 zr_gi_cache **out) {
  if (!scene || !out)
    return ZR_EINVAL;
  *out = NULL;
  /* The caller's parameters over the defaults (zrcube.h: a struct's
     size says which members it has). */
  zr_gi_params taken;
  zr_gi_params_init(&taken, scene);
  if (params &&
      zr__params_take(&taken, sizeof taken, params, sizeof taken) != ZR_OK)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL,
                    "irradiance cache: the parameters were not made by "
                    "zr_gi_params_init() (their size is %zu)",
                    params->size);
  params = &taken;
  zr_status s = check_params(ctx, params);
  if (s != ZR_OK)
    return s;
  zr_gi_cache *c = calloc(1, sizeof *c);
  if (!c)
    return ZR_ENOMEM;
  c->scene = scene;
  c->params = *params;
  c->indirect.irradiance = cache_irradiance;
  c->indirect.provider = c;
  c->indirect.scratch = NULL;
  zr__gi_cache_extent(c);
  *out = c;
  return ZR_OK;
}

ZR_API void zr_gi_cache_free(zr_gi_cache *c) {
  if (!c)
    return;
  zr__gi_list_free(&c->records);
  free(c->near);
  drop_grid(c);
  for (int d = 0; d < 20; d++) {
    free(c->nodes[d]);
    free(c->cubes[d]);
    free(c->jumps[d]);
  }
  free(c);
}

ZR_API void zr_gi_cache_get_stats(const zr_gi_cache *c, zr_gi_stats *st) {
  memset(st, 0, sizeof *st);
  if (!c)
    return;
  st->records = c->records.n;
  for (size_t i = 0; i < c->records.n; i++)
    if (c->records.v[i].depth == 0)
      st->records_depth0++;
  st->pretrace_passes = c->pretrace_passes;
  st->sample_rays = c->sample_rays;
}

/* One batch of a pretrace pass: its pixels and what each made. */
typedef struct batch_job {
  const zr_gi_cache *cache;
  const zr_render_params *render;
  const zr_media *camera_media;
  const uint32_t *pixels;
  gi_scratch *slots;
} batch_job;

/*
 * The last pass at a pixel of a mesh camera traces every ray the final
 * pass will (render.c's mesh_sample: one a mesh, povray's way of
 * antialiasing with copies of a mesh), so that the final pass finds
 * records where each lands.  With the first ray alone,
 * camera/mesh_camera/meshcam_persp_demo.pov's six meshes left five
 * rays a pixel to gather records of their own in the final pass, which
 * keeps none: 11.4 CPU s of rendering after a 4.3 s pretrace.
 */
static void mesh_rays(const zr_tracer *tr, const zr_camera *cam, int w,
                      int h, double x, double y, const zr_media *media) {
  int rays = zr__camera_mesh_rays(cam);
  for (int k = 0; k < rays; k++) {
    zr_ray ray;
    if (!zr__camera_mesh_ray(cam, w, h, x, y, k, &ray))
      continue;
    if (cam->mesh->max_distance > 0.0)
      (void)zr__trace_camera_ray_within(tr, &ray, cam->mesh->max_distance,
                                        media);
    else
      (void)zr__trace_ray(tr, &ray, 1, 1.0, media);
  }
}

static void trace_batch(void *user, size_t begin, size_t end, int worker) {
  (void)worker;
  batch_job *job = user;
  const zr_gi_cache *c = job->cache;
  for (size_t i = begin; i < end; i++) {
    gi_scratch *sc = &job->slots[i];
    zr_indirect ind = {cache_irradiance, c, sc, NULL, NULL};
    zr_render_stats stats;
    memset(&stats, 0, sizeof stats);
    zr_tracer tr;
    memset(&tr, 0, sizeof tr);
    tr.scene = c->scene;
    tr.stats = &stats;
    tr.indirect = &ind;
    tr.hide = ZR_HIDE_IMAGE;
    tr.skip_direct = true;
    /* The sample rays' shadow hints (lib/trace/shade.h): they change
       no result, and spare a group of area lights' shaft tests. */
    zr_shadow_cache shadows;
    memset(&shadows, 0, sizeof shadows);
    tr.shadow_cache = &shadows;
    int w = job->render->width, h = job->render->height;
    uint32_t px = job->pixels[i];
    double x = px % (uint32_t)w + 0.5, y = px / (uint32_t)w + 0.5;
    const zr_camera *cam = &c->scene->camera;
    if (cam->kind == ZR_CAMERA_MESH && c->pretracing == 2) {
      mesh_rays(&tr, cam, w, h, x, y, job->camera_media);
      continue;
    }
    zr_ray ray = zr__camera_ray(cam, w, h, x, y);
    if (zr_v3_len(ray.dir) > 0.0)
      (void)zr__trace_ray(&tr, &ray, 1, 1.0, job->camera_media);
  }
}

/* The pixels at the centres of a mosaic of blocks of side `block`. */
static size_t mosaic(int w, int h, double block, uint32_t *out) {
  size_t n = 0;
  int nx = (int)ceil(w / block), ny = (int)ceil(h / block);
  for (int j = 0; j < ny; j++)
    for (int i = 0; i < nx; i++) {
      /* The centre of the block's part inside the image: a block cut
         by the right or bottom edge has its pixel too, as povray's
         passes do (bench/gi_record_probe.py: 6, 20, 80 and 300 records
         in the passes of 64 to 8 pixels at 160 x 120, one a block;
         the centre of the whole block left out the cut ones). */
      double x0 = i * block, x1 = fmin((i + 1) * block, w);
      double y0 = j * block, y1 = fmin((j + 1) * block, h);
      int x = (int)floor(0.5 * (x0 + x1)), y = (int)floor(0.5 * (y0 + y1));
      if (x >= w || y >= h)
        continue;
      if (out)
        out[n] = (uint32_t)y * (uint32_t)w + (uint32_t)x;
      n++;
    }
  return n;
}

/*
 * A batch across a team (zr_team, core/team.h): member r of n traces the
 * batch's pixels r, r + n, ... (each pixel's slot is its own, as with
 * threads), sends each of its slots' records and ray count, and every
 * member reads every slot back; the records then join in pixel order
 * on every member as alone.  A pixel's records depend on the cache the
 * batch started from and on the pixel alone, so they are the same bytes
 * whoever traced them, and every member keeps the same cache.
 */
typedef struct team_batch {
  batch_job job;
  size_t mine[BATCH]; /* slots this member traces */
} team_batch;

static void trace_mine(void *user, size_t begin, size_t end, int worker) {
  team_batch *tb = user;
  for (size_t k = begin; k < end; k++)
    trace_batch(&tb->job, tb->mine[k], tb->mine[k] + 1, worker);
}

/* pending: this member's failure in the batch before (a record it
   could not add), which the exchange tells the others. */
static zr_status team_slots(const zr_gi_cache *c, batch_job *job, size_t m,
                            zr_status pending) {
  const zr_team *team = c->params.team;
  int n = zr__team_size(team), me = zr__team_rank(team);
  team_batch tb;
  tb.job = *job;
  size_t n_mine = 0;
  for (size_t i = (size_t)me; pending == ZR_OK && i < m; i += (size_t)n)
    tb.mine[n_mine++] = i;
  zr__rad_parallel(c->params.threads, n_mine, 1, trace_mine, &tb);
  zr__pack pack = {0};
  for (size_t k = 0; k < n_mine; k++) {
    const gi_scratch *sc = &job->slots[tb.mine[k]];
    uint64_t count = sc->local.n;
    zr__pack_put(&pack, &sc->rays, sizeof sc->rays);
    zr__pack_put(&pack, &count, sizeof count);
    if (count > 0)
      zr__pack_put(&pack, sc->local.v, sc->local.n * sizeof *sc->local.v);
  }
  zr__team_parts parts;
  zr_status s = zr__team_exchange(team, pending != ZR_OK ? pending
                                        : pack.nomem   ? ZR_ENOMEM
                                                       : ZR_OK,
                                  pack.bytes, pack.n, &parts);
  zr__pack_free(&pack);
  for (int r = 0; s == ZR_OK && r < n; r++) {
    const char *at = parts.bytes + parts.offset[r];
    const char *end = parts.bytes + parts.offset[r + 1];
    for (size_t i = (size_t)r; s == ZR_OK && i < m; i += (size_t)n) {
      gi_scratch *sc = &job->slots[i];
      uint64_t count = 0;
      if (!zr__unpack(&at, end, &sc->rays, sizeof sc->rays) ||
          !zr__unpack(&at, end, &count, sizeof count) ||
          (uint64_t)(end - at) / sizeof(zr__gi_record) < count) {
        s = ZR_EMPI;
        break;
      }
      if (r == me) {
        at += count * sizeof(zr__gi_record); /* already in the slot */
        continue;
      }
      for (uint64_t k = 0; k < count && s == ZR_OK; k++) {
        zr__gi_record rec;
        memcpy(&rec, at, sizeof rec);
        at += sizeof rec;
        if (!zr__gi_list_push(&sc->local, &rec))
          s = ZR_ENOMEM;
      }
    }
    if (s == ZR_OK && at != end)
      s = ZR_EMPI;
  }
  zr__team_parts_free(&parts);
  return s;
}

/* The pretrace's progress: pixels of all passes, done of total. */
typedef struct pretrace_progress {
  zr_context *ctx;
  uint64_t done, total;
} pretrace_progress;

static zr_status run_pass(zr_gi_cache *c, const zr_render_params *render,
                          const zr_media *camera_media,
                          const uint32_t *pixels, size_t n,
                          pretrace_progress *progress) {
  gi_scratch slots[BATCH];
  int team = zr__team_size(c->params.team) > 1;
  zr_status pending = ZR_OK; /* a team member's failure to add */
  for (size_t at = 0; at < n; at += BATCH) {
    zr_status ps = zr__progress(progress->ctx, ZR_PHASE_PRETRACE,
                                progress->done, progress->total);
    if (ps != ZR_OK)
      return ps;
    size_t m = n - at < BATCH ? n - at : BATCH;
    memset(slots, 0, sizeof slots);
    batch_job job = {c, render, camera_media, pixels + at, slots};
    /* A team's exchange fails on every member alike. */
    zr_status exchanged = ZR_OK;
    if (team)
      exchanged = team_slots(c, &job, m, pending);
    else
      zr__rad_parallel(c->params.threads, m, 1, trace_batch, &job);
    zr_status s = exchanged;
    for (size_t i = 0; i < m; i++) {
      for (size_t k = 0; k < slots[i].local.n && s == ZR_OK; k++)
        if (!zr__gi_cache_add(c, &slots[i].local.v[k]))
          s = ZR_ENOMEM;
      c->sample_rays += slots[i].rays;
      zr__gi_list_free(&slots[i].local);
    }
    if (exchanged != ZR_OK)
      return exchanged;
    /* A member that could not add a record tells the others in the
       next batch's exchange (or the agreement after the last one), and
       all stop there together. */
    if (team && s != ZR_OK) {
      pending = s;
      continue;
    }
    if (s != ZR_OK)
      return s;
    progress->done += m;
  }
  if (team && zr__team_agree(c->params.team, pending) != ZR_OK)
    return pending != ZR_OK ? pending : ZR_ENOMEM;
  c->pretrace_passes++;
  return ZR_OK;
}

/* The pixels of every pass of the pretrace (the passes below). */
static uint64_t pretrace_pixels(const zr_gi_cache *c, int w, int h) {
  uint64_t total = 0;
  double block = c->params.pretrace_start * w;
  double last = c->params.pretrace_end * w;
  for (;;) {
    double b = fmax(block, 1.0);
    total += mosaic(w, h, b, NULL);
    if (b <= 1.0 || block * 0.5 < last * (1.0 - 1e-9))
      break;
    block *= 0.5;
  }
  return total + (uint64_t)w * (uint64_t)h;
}

ZR_API zr_status zr_gi_cache_pretrace(zr_gi_cache *c,
                                      const zr_render_params *params) {
  zr_render_params taken;
  zr_render_params_init(&taken);
  if (!c || zr__params_take(&taken, sizeof taken, params, sizeof taken) !=
                ZR_OK)
    return ZR_EINVAL;
  const zr_render_params *render = &taken;
  if (render->width <= 0 || render->height <= 0)
    return ZR_EINVAL;
  if (!c->scene->bvh && c->scene->n_primitives > 0)
    return ZR_ESCENE;
  int w = render->width, h = render->height;
  uint32_t *pixels = malloc((size_t)w * (size_t)h * sizeof *pixels);
  if (!pixels)
    return ZR_ENOMEM;
  zr_media camera_media;
  zr__camera_media(c->scene, &camera_media);
  pretrace_progress progress = {render->context, 0,
                                pretrace_pixels(c, w, h)};
  zr_status s = ZR_OK;
  c->pretracing = 1;
  c->pretrace_pass = 0;
  /* Blocks of pretrace_start of the image width, halved until they
     are pretrace_end (POV-Ray's mosaic preview). */
  double block = c->params.pretrace_start * w;
  double last = c->params.pretrace_end * w;
  for (;;) {
    double b = fmax(block, 1.0);
    size_t n = mosaic(w, h, b, pixels);
    s = run_pass(c, render, &camera_media, pixels, n, &progress);
    if (s != ZR_OK || b <= 1.0 || block * 0.5 < last * (1.0 - 1e-9))
      break;
    block *= 0.5;
    c->pretrace_pass++;
  }
  if (s == ZR_OK) {
    /* The final pass's new samples, gathered before it at every pixel
       with the full error_bound, in batches as above, so the final
       pass only reads.  povray 3.7 adds records in its final pass too
       (radiosity2.pov: 650 in the pretrace, 3121 in the final pass,
       always_sample off); with always_sample on a point there wants
       nearest_count records, as in the pretrace. */
    c->pretracing = 2;
    size_t n = mosaic(w, h, 1.0, pixels);
    s = run_pass(c, render, &camera_media, pixels, n, &progress);
  }
  /* The final pass only reads the cache: its index (none is no error:
     lookups then walk the octree). */
  if (s == ZR_OK)
    (void)zr__gi_cache_freeze(c);
  if (s == ZR_OK)
    s = zr__progress(progress.ctx, ZR_PHASE_PRETRACE, progress.total,
                     progress.total);
  if (s == ZR_ECANCELLED)
    zr__diag(progress.ctx, ZR_DIAG_ERROR, s, NULL,
             "irradiance cache: the pretrace was cancelled");
  c->pretracing = 0;
  free(pixels);
  return s;
}
