/*
 * obj_height_field.c - the height field (POV-Ray 3.7 reference, "Height
 * Field"): a grid of heights in [0, 1] over the unit square of the x-z
 * plane, each square of four neighbouring samples cut into two
 * triangles along the diagonal from (i + 1, j) to (i, j + 1).  The
 * samples are built by lib/sdl/build_hf.c; smooth gives the triangles
 * normals blended from normals at the grid points, made as POV-Ray makes
 * them (vertex_normal).
 *
 * The triangles are never stored: a grid of w x h samples would make
 * 2 (w - 1)(h - 1) of them, 50 bytes each with their BVH, where the
 * samples take one or two bytes.  A ray walks instead a hierarchy of
 * blocks over the grid (struct zr_hf_grid): a leaf block holds 8 x 8
 * squares and the least and greatest height in it, each level above
 * joins 2 x 2 blocks.  A block the ray's box test misses is skipped;
 * within a leaf the ray steps from square to square in the x-z plane
 * (a 2-D DDA), and the two triangles of a square are made from its four
 * samples and tested as a mesh's faces are (Moller-Trumbore, with the
 * same corners in the same order, so crossings are those of the mesh
 * this file used to build).  Radiosity, which needs the faces, gets
 * them as a mesh from zr__height_field_mesh().
 *
 * What the file adds to the triangles is the height field's own rules:
 * water_level hides the surface below it (triangles wholly under it are
 * left out, crossings under it are skipped), and the solid is what lies
 * under the surface within the unit square, however far below, so
 * height fields take part in CSG.
 */
#include "trace/obj_isosurface.h"

#include <math.h>
#include <string.h>

#include "scene/shapes.h"
#include "trace/obj_mesh.h"
#include "trace/shape.h"

/* The sample at grid point (i, j), z = j / (h - 1); the samples are in
   image order (row r at z = 1 - r / (h - 1)). */
static inline double sample_at(const struct zr_hf_grid *g, int i, int j) {
  size_t k = (size_t)(g->h - 1 - j) * (size_t)g->w + (size_t)i;
  switch (g->bits) {
  case 8:
    return ((const uint8_t *)g->samples)[k] / 255.0;
  case 16:
    return ((const uint16_t *)g->samples)[k] / 65535.0;
  default:
    return ((const float *)g->samples)[k];
  }
}

zr_status zr__height_field_grid(zr_arena *arena, const void *samples,
                                int bits, int w, int h,
                                const struct zr_hf_grid **out) {
  *out = NULL;
  struct zr_hf_grid *g = zr__arena_alloc(arena, sizeof *g);
  if (!g)
    return ZR_ENOMEM;
  g->samples = samples;
  g->bits = bits;
  g->w = w;
  g->h = h;
  int nx = (w - 2) / ZR_HF_BLOCK + 1, nz = (h - 2) / ZR_HF_BLOCK + 1;
  size_t total = 0;
  int levels = 0;
  for (;;) {
    if (levels == ZR_HF_MAX_LEVELS)
      return ZR_ELIMIT;
    g->level[levels].start = total;
    g->level[levels].nx = nx;
    g->level[levels].nz = nz;
    total += (size_t)nx * (size_t)nz;
    levels++;
    if (nx == 1 && nz == 1)
      break;
    nx = (nx + 1) / 2;
    nz = (nz + 1) / 2;
  }
  g->levels = levels;
  g->range = zr__arena_alloc(arena, 2 * total * sizeof *g->range);
  if (!g->range)
    return ZR_ENOMEM;
  /* Leaf blocks: the samples of their squares, edges shared. */
  float *r = g->range;
  for (int bz = 0; bz < g->level[0].nz; bz++)
    for (int bx = 0; bx < g->level[0].nx; bx++) {
      int i0 = bx * ZR_HF_BLOCK, j0 = bz * ZR_HF_BLOCK;
      int i1 = i0 + ZR_HF_BLOCK < w - 1 ? i0 + ZR_HF_BLOCK : w - 1;
      int j1 = j0 + ZR_HF_BLOCK < h - 1 ? j0 + ZR_HF_BLOCK : h - 1;
      double lo = INFINITY, hi = -INFINITY;
      for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++) {
          double y = sample_at(g, i, j);
          lo = fmin(lo, y);
          hi = fmax(hi, y);
        }
      size_t k = (size_t)bz * (size_t)g->level[0].nx + (size_t)bx;
      r[2 * k] = (float)lo;
      r[2 * k + 1] = (float)hi;
    }
  for (int l = 1; l < levels; l++) {
    const float *below = g->range + 2 * g->level[l - 1].start;
    float *here = g->range + 2 * g->level[l].start;
    int bnx = g->level[l - 1].nx, bnz = g->level[l - 1].nz;
    for (int bz = 0; bz < g->level[l].nz; bz++)
      for (int bx = 0; bx < g->level[l].nx; bx++) {
        float lo = INFINITY, hi = -INFINITY;
        for (int cz = 2 * bz; cz < 2 * bz + 2 && cz < bnz; cz++)
          for (int cx = 2 * bx; cx < 2 * bx + 2 && cx < bnx; cx++) {
            size_t c = (size_t)cz * (size_t)bnx + (size_t)cx;
            lo = fminf(lo, below[2 * c]);
            hi = fmaxf(hi, below[2 * c + 1]);
          }
        size_t k = (size_t)bz * (size_t)g->level[l].nx + (size_t)bx;
        here[2 * k] = lo;
        here[2 * k + 1] = hi;
      }
  }
  const float *top = g->range + 2 * g->level[levels - 1].start;
  g->lo = top[0];
  g->hi = top[1];
  *out = g;
  return ZR_OK;
}

/* ---- crossings ---- */

/* The nearest crossings found so far (at most `most`, 1 or 2), nearest
   first.  A crossing keeps its triangle's corners and (u, v); its
   normal, smooth or flat, is made once the search is over and only when
   asked for (the nearest-surface search asks for t alone). */
typedef struct hf_search {
  const struct zr_hf_grid *g;
  zr_vec3 org, dir;
  double tmin, limit; /* limit: tmax, then the last kept crossing's t */
  double water;
  bool smooth;
  double dx, dz;
  double inv[3]; /* 1 / dir, for the box tests */
  bool flat[3];  /* dir's component is 0 */
  int n, most;
  double t[2];
  zr_vec3 normal[2]; /* the flat normal */
  double u[2], v[2];
  int vi[2][3], vj[2][3];
} hf_search;

/* The sample at grid point (i, j) in 16-bit units (0 .. 65535): the code
   of a 16-bit field, an 8-bit code times 257, a float times 65535. */
static inline double code_at(const struct zr_hf_grid *g, int i, int j) {
  size_t k = (size_t)(g->h - 1 - j) * (size_t)g->w + (size_t)i;
  switch (g->bits) {
  case 8:
    return ((const uint8_t *)g->samples)[k] * 257.0;
  case 16:
    return ((const uint16_t *)g->samples)[k];
  default:
    return ((const float *)g->samples)[k] * 65535.0;
  }
}

/*
 * The smooth normal at grid point (i, j), a unit vector in the field's
 * own coordinates, as POV-Ray 3.7 makes it (measured with trace() through
 * #debug on function height fields of 5 x 5 and 9 x 9 samples; the
 * manual does not say).  In grid units - one unit a sample along x and
 * z, one a 16-bit code along y, so that every slope is steep - each of
 * the four quarters between the neighbours east, north, west and south
 * (those the grid has) gives the unit normal of the triangle from the
 * point to its two neighbours; their sum, made a unit vector, is kept
 * as whole multiples of 1/32767 (rounded toward zero, as a 16-bit
 * integer would hold it), then mapped to the field's coordinates.  The
 * rounding is what the measurements show: along a ramp h = s x of 5
 * samples the vertex slopes are 2 / k for whole k (s = 1: 2, not 1; s =
 * 0.7, 0.8 and 0.9: 1; s = 0.5 and 0.6: 2/3; s = 0.1: 2/19), and a step
 * of one sample gives a nearly vertical normal on both sides of it,
 * where central differences give the step's slope (stock
 * advanced/glasschess.pov's checker board: flat glass, not ridged).  On
 * 0.3 x y + 0.6 x^2 - 0.4 y^3 + 0.3 the normals at the 7 vertices tried
 * equal povray's to 4 decimals; central differences, or the sum over the
 * six triangles at the point, or the eight of its four squares, do not.
 */
static zr_vec3 vertex_normal(const hf_search *s, int i, int j) {
  static const int di[4] = {1, 0, -1, 0}, dj[4] = {0, 1, 0, -1};
  const struct zr_hf_grid *g = s->g;
  double h = code_at(g, i, j);
  zr_vec3 sum = zr_v3(0, 0, 0);
  for (int k = 0; k < 4; k++) {
    int ia = i + di[k], ja = j + dj[k];
    int ib = i + di[(k + 1) & 3], jb = j + dj[(k + 1) & 3];
    if (ia < 0 || ia >= g->w || ja < 0 || ja >= g->h || ib < 0 ||
        ib >= g->w || jb < 0 || jb >= g->h)
      continue;
    zr_vec3 ea = zr_v3(di[k], code_at(g, ia, ja) - h, dj[k]);
    zr_vec3 eb = zr_v3(di[(k + 1) & 3], code_at(g, ib, jb) - h,
                       dj[(k + 1) & 3]);
    zr_vec3 n = zr_v3_cross(ea, eb);
    if (n.y < 0.0)
      n = zr_v3_neg(n);
    sum = zr_v3_add(sum, zr_v3_norm(n));
  }
  if (!(zr_v3_dot(sum, sum) > 0.0))
    return zr_v3(0, 1, 0); /* a grid of one sample along x or z */
  sum = zr_v3_norm(sum);
  zr_vec3 q = zr_v3(trunc(sum.x * 32767.0), trunc(sum.y * 32767.0),
                    trunc(sum.z * 32767.0));
  zr_vec3 n = zr_v3(q.x / s->dx, q.y * 65535.0, q.z / s->dz);
  return zr_v3_dot(n, n) > 0.0 ? zr_v3_norm(n) : zr_v3(0, 1, 0);
}

/* One triangle p0 p1 p2 (grid points vi[], vj[]), as a mesh's face. */
static void face(hf_search *s, const zr_vec3 p[3], const int vi[3],
                 const int vj[3]) {
  if (p[0].y < s->water && p[1].y < s->water && p[2].y < s->water)
    return; /* wholly under the water: no triangle */
  zr_vec3 e1 = zr_v3_sub(p[1], p[0]);
  zr_vec3 e2 = zr_v3_sub(p[2], p[0]);
  zr_vec3 pv = zr_v3_cross(s->dir, e2);
  double det = zr_v3_dot(e1, pv);
  if (det == 0.0 || !isfinite(det))
    return;
  double inv = 1.0 / det;
  zr_vec3 tv = zr_v3_sub(s->org, p[0]);
  double u = zr_v3_dot(tv, pv) * inv;
  if (u < 0.0 || u > 1.0)
    return;
  zr_vec3 qv = zr_v3_cross(tv, e1);
  double v = zr_v3_dot(s->dir, qv) * inv;
  if (v < 0.0 || u + v > 1.0)
    return;
  double t = zr_v3_dot(e2, qv) * inv;
  if (!(t > s->tmin && t < s->limit))
    return;
  if (s->water > 0.0 && s->org.y + t * s->dir.y < s->water)
    return;
  /* A ray through an edge or corner meets the triangles that share it
     at one t: one crossing. */
  for (int k = 0; k < s->n; k++)
    if (fabs(t - s->t[k]) <= 1e-12 * fmax(1.0, fabs(t)))
      return;
  /* Insertion among the kept crossings; the farthest drops out when
     they are `most` already (it is beyond t: limit is its t). */
  int at = s->n < s->most ? s->n++ : s->most - 1;
  while (at > 0 && s->t[at - 1] > t) {
    s->t[at] = s->t[at - 1];
    s->normal[at] = s->normal[at - 1];
    s->u[at] = s->u[at - 1];
    s->v[at] = s->v[at - 1];
    memcpy(s->vi[at], s->vi[at - 1], sizeof s->vi[at]);
    memcpy(s->vj[at], s->vj[at - 1], sizeof s->vj[at]);
    at--;
  }
  s->t[at] = t;
  s->normal[at] = zr_v3_cross(e1, e2);
  s->u[at] = u;
  s->v[at] = v;
  memcpy(s->vi[at], vi, sizeof s->vi[at]);
  memcpy(s->vj[at], vj, sizeof s->vj[at]);
  if (s->n == s->most)
    s->limit = s->t[s->n - 1];
}

/* Crossing k's normal: the flat one, or with smooth the grid's normals
   at the four corners of its square blended bilinearly by where it lies
   in the square, as POV-Ray 3.7 blends them (on the function of
   vertex_normal's note, at 4 points inside squares, both triangles:
   equal to povray's normals to 4 decimals, where the blend of the
   triangle's three corners by its (u, v) was off by up to 0.006). */
static zr_vec3 crossing_normal(const hf_search *s, int k) {
  zr_vec3 n = s->normal[k];
  if (s->smooth) {
    double w[3] = {1.0 - s->u[k] - s->v[k], s->u[k], s->v[k]};
    int i0 = s->vi[k][0], j0 = s->vj[k][0];
    double fx = 0.0, fz = 0.0;
    for (int c = 0; c < 3; c++) {
      i0 = s->vi[k][c] < i0 ? s->vi[k][c] : i0;
      j0 = s->vj[k][c] < j0 ? s->vj[k][c] : j0;
      fx += w[c] * s->vi[k][c];
      fz += w[c] * s->vj[k][c];
    }
    double a = fmin(fmax(fx - i0, 0.0), 1.0), b = fmin(fmax(fz - j0, 0.0), 1.0);
    zr_vec3 sn = zr_v3_scale(vertex_normal(s, i0, j0), (1 - a) * (1 - b));
    sn = zr_v3_madd(sn, vertex_normal(s, i0 + 1, j0), a * (1 - b));
    sn = zr_v3_madd(sn, vertex_normal(s, i0, j0 + 1), (1 - a) * b);
    sn = zr_v3_madd(sn, vertex_normal(s, i0 + 1, j0 + 1), a * b);
    if (zr_v3_dot(sn, sn) > 0.0 && isfinite(zr_v3_dot(sn, sn)))
      n = sn;
  }
  return n;
}

/* The two triangles of square (i, j), as lib/sdl/build_hf.c made them:
   a c b and b c d, a = (i, j), b = (i + 1, j), c = (i, j + 1),
   d = (i + 1, j + 1), both facing up. */
static void square(hf_search *s, int i, int j) {
  const struct zr_hf_grid *g = s->g;
  zr_vec3 a = zr_v3(i * s->dx, sample_at(g, i, j), j * s->dz);
  zr_vec3 b = zr_v3((i + 1) * s->dx, sample_at(g, i + 1, j), j * s->dz);
  zr_vec3 c = zr_v3(i * s->dx, sample_at(g, i, j + 1), (j + 1) * s->dz);
  zr_vec3 d =
      zr_v3((i + 1) * s->dx, sample_at(g, i + 1, j + 1), (j + 1) * s->dz);
  const zr_vec3 f1[3] = {a, c, b}, f2[3] = {b, c, d};
  const int i1[3] = {i, i, i + 1}, j1[3] = {j, j + 1, j};
  const int i2[3] = {i + 1, i, i + 1}, j2[3] = {j, j + 1, j + 1};
  face(s, f1, i1, j1);
  face(s, f2, i2, j2);
}

/* The ray's entry into the box [lo, hi] within (tmin, limit), or
   INFINITY when it misses; *exit gets where it leaves.  The slabs are
   cut with the direction's reciprocals (s->inv, 0 where the direction
   has no component) and compared without fmin/fmax, which the compiler
   leaves as library calls (8% of pneumaticBoat's render); a NaN keeps
   the bound as fmax/fmin would. */
static double box_entry(const hf_search *s, zr_vec3 lo, zr_vec3 hi,
                        double *exit) {
  double t0 = s->tmin, t1 = s->limit;
  const double o[3] = {s->org.x, s->org.y, s->org.z};
  const double l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
  for (int k = 0; k < 3; k++) {
    if (s->flat[k]) {
      if (o[k] < l[k] || o[k] > h[k])
        return INFINITY;
      continue;
    }
    double a = (l[k] - o[k]) * s->inv[k], b = (h[k] - o[k]) * s->inv[k];
    if (a > b) {
      double t = a;
      a = b;
      b = t;
    }
    t0 = a > t0 ? a : t0;
    t1 = b < t1 ? b : t1;
    if (!(t0 <= t1))
      return INFINITY;
  }
  *exit = t1;
  return t0;
}

/* Steps through the squares [i0, i1) x [j0, j1) of a leaf block the ray
   crosses in the x-z plane, from its entry at t = ta to its exit from
   the block's box at tb: a square the ray enters past tb is above or
   below every triangle of the block (the sample rays that leave
   pneumaticBoat's nearly flat sand went on through every square of the
   block, 2.3 times the triangle tests). */
static void walk_leaf(hf_search *s, int i0, int i1, int j0, int j1,
                      double ta, double tb) {
  double px = s->org.x + ta * s->dir.x, pz = s->org.z + ta * s->dir.z;
  int i = (int)floor(px / s->dx), j = (int)floor(pz / s->dz);
  i = i < i0 ? i0 : i >= i1 ? i1 - 1 : i;
  j = j < j0 ? j0 : j >= j1 ? j1 - 1 : j;
  int si = s->dir.x > 0.0 ? 1 : s->dir.x < 0.0 ? -1 : 0;
  int sj = s->dir.z > 0.0 ? 1 : s->dir.z < 0.0 ? -1 : 0;
  double tx = si ? ((i + (si > 0)) * s->dx - s->org.x) / s->dir.x
                 : INFINITY;
  double tz = sj ? ((j + (sj > 0)) * s->dz - s->org.z) / s->dir.z
                 : INFINITY;
  double step_x = si ? s->dx / fabs(s->dir.x) : INFINITY;
  double step_z = sj ? s->dz / fabs(s->dir.z) : INFINITY;
  /* Bounded by the squares of the block (a diagonal step visits one). */
  for (int left = 2 * ZR_HF_BLOCK + 2; left > 0; left--) {
    square(s, i, j);
    double next = fmin(tx, tz);
    if (!(next < s->limit && next <= tb))
      return;
    if (tx <= tz) {
      i += si;
      tx += step_x;
    } else {
      j += sj;
      tz += step_z;
    }
    if (i < i0 || i >= i1 || j < j0 || j >= j1)
      return;
  }
}

/* Block (l, bx, bz) of the field's hierarchy, grown by pad: false when
   it holds nothing above the water or the ray misses its box; else its
   sample range [i0, i1] x [j0, j1] and the ray's stretch in it. */
static bool block_entry(hf_search *s, int l, int bx, int bz, double pad,
                        int ij[4], double *ta, double *exit) {
  const struct zr_hf_grid *g = s->g;
  const float *r = g->range + 2 * (g->level[l].start +
                                   (size_t)bz * (size_t)g->level[l].nx +
                                   (size_t)bx);
  if (r[1] < s->water)
    return false; /* every triangle in it is under the water */
  int side = ZR_HF_BLOCK << l;
  int i0 = bx * side, j0 = bz * side;
  int i1 = i0 + side < g->w - 1 ? i0 + side : g->w - 1;
  int j1 = j0 + side < g->h - 1 ? j0 + side : g->h - 1;
  zr_vec3 lo = zr_v3(i0 * s->dx - pad, r[0] - pad, j0 * s->dz - pad);
  zr_vec3 hi = zr_v3(i1 * s->dx + pad, r[1] + pad, j1 * s->dz + pad);
  *ta = box_entry(s, lo, hi, exit);
  ij[0] = i0, ij[1] = i1, ij[2] = j0, ij[3] = j1;
  return *ta != INFINITY;
}

/* The most leaf blocks a ray's crossing of the slab of heights may
   cover for them to be tested without the descent. */
#define FEW_BLOCKS 16

/* The search's crossings into t[] and, when asked, normal[]. */
static int found(const hf_search *s, double t[4], zr_vec3 normal[4]) {
  for (int k = 0; k < s->n; k++) {
    t[k] = s->t[k];
    if (normal)
      normal[k] = crossing_normal(s, k);
  }
  return s->n;
}

/*
 * The nearest max_found crossings (1, or 2 for anything more), normals
 * only when normal is not NULL (shape.h's search_upto).  With one
 * wanted the walk stops at the first crossing: a ray that enters a
 * nearly flat field at a grazing angle would otherwise walk on under the
 * surface, through every block whose heights its path stays within,
 * looking for the second (pneumaticBoat's sand: 26% of the render).
 * The crossings are the triangles' own t, whatever the interval and
 * max_found, as the contract asks.
 */
static int hf_search_upto(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                          double tmin, double tmax, int max_found,
                          double t[4], zr_vec3 normal[4]) {
  const struct zr_hf_grid *g = o->u.height_field.grid;
  double water = o->u.height_field.water_level;
  if (!g || g->hi < water || max_found < 1)
    return 0;
  hf_search s = {.g = g, .org = org, .dir = dir, .tmin = tmin,
                 .limit = tmax, .water = water,
                 .smooth = o->u.height_field.smooth,
                 .dx = 1.0 / (g->w - 1), .dz = 1.0 / (g->h - 1),
                 .most = max_found < 2 ? max_found : 2};
  const double d3[3] = {dir.x, dir.y, dir.z};
  for (int k = 0; k < 3; k++) {
    s.flat[k] = d3[k] == 0.0;
    s.inv[k] = s.flat[k] ? 0.0 : 1.0 / d3[k];
  }
  /* Boxes grow by this much: the ranges are floats, the samples
     doubles. */
  const double pad = 1e-6;
  /* A ray that crosses the field's slab of heights over a few leaf
     blocks (a sample ray leaving the surface, steep in the unit square
     of a wide field) tests those blocks alone: the descent from the
     root tested four boxes a level on the way down to them
     (pneumaticBoat's sand: 21 box tests a ray, 4 million rays).  The
     crossings are the same whatever order the blocks are tested in:
     each keeps the nearest. */
  {
    double out;
    double in = box_entry(&s, zr_v3(-pad, g->lo - pad, -pad),
                          zr_v3(1 + pad, g->hi + pad, 1 + pad), &out);
    if (in == INFINITY)
      return 0;
    double side_x = ZR_HF_BLOCK * s.dx, side_z = ZR_HF_BLOCK * s.dz;
    double xa = org.x + in * dir.x, xb = org.x + out * dir.x;
    double za = org.z + in * dir.z, zb = org.z + out * dir.z;
    double fx0 = floor((fmin(xa, xb) - pad) / side_x);
    double fx1 = floor((fmax(xa, xb) + pad) / side_x);
    double fz0 = floor((fmin(za, zb) - pad) / side_z);
    double fz1 = floor((fmax(za, zb) + pad) / side_z);
    int nx = g->level[0].nx, nz = g->level[0].nz;
    fx0 = fmax(fx0, 0.0), fz0 = fmax(fz0, 0.0);
    fx1 = fmin(fx1, nx - 1.0), fz1 = fmin(fz1, nz - 1.0);
    if ((fx1 - fx0 + 1.0) * (fz1 - fz0 + 1.0) <= FEW_BLOCKS) {
      int bx0 = (int)fx0, bx1 = (int)fx1, bz0 = (int)fz0, bz1 = (int)fz1;
      for (int bz = bz0; bz <= bz1; bz++)
        for (int bx = bx0; bx <= bx1; bx++) {
          /* Nearest first along each axis, as the descent goes. */
          int cx = dir.x >= 0.0 ? bx : bx0 + bx1 - bx;
          int cz = dir.z >= 0.0 ? bz : bz0 + bz1 - bz;
          int ij[4];
          double ta, exit;
          if (block_entry(&s, 0, cx, cz, pad, ij, &ta, &exit))
            walk_leaf(&s, ij[0], ij[1], ij[2], ij[3], ta, exit);
        }
      return found(&s, t, normal);
    }
  }
  /* Blocks as (level, bx, bz); children are pushed far first so that
     the nearest is walked first and the second crossing found early
     narrows the rest. */
  struct {
    int level, bx, bz;
  } stack[4 * ZR_HF_MAX_LEVELS];
  int sp = 0;
  stack[sp].level = g->levels - 1;
  stack[sp].bx = stack[sp].bz = 0;
  sp++;
  int near_x = dir.x >= 0.0 ? 0 : 1, near_z = dir.z >= 0.0 ? 0 : 1;
  while (sp > 0) {
    sp--;
    int l = stack[sp].level, bx = stack[sp].bx, bz = stack[sp].bz;
    int ij[4];
    double ta, exit;
    if (!block_entry(&s, l, bx, bz, pad, ij, &ta, &exit))
      continue;
    if (l == 0) {
      walk_leaf(&s, ij[0], ij[1], ij[2], ij[3], ta, exit);
      continue;
    }
    for (int k = 3; k >= 0; k--) {
      /* k = 0 is the child nearest the ray's origin, 3 the farthest. */
      int cx = 2 * bx + ((k & 1) ^ near_x);
      int cz = 2 * bz + (((k >> 1) & 1) ^ near_z);
      if (cx < g->level[l - 1].nx && cz < g->level[l - 1].nz) {
        stack[sp].level = l - 1;
        stack[sp].bx = cx;
        stack[sp].bz = cz;
        sp++;
      }
    }
  }
  return found(&s, t, normal);
}

int zr__height_field_crossings(const zr_object *o, zr_vec3 org,
                               zr_vec3 dir, double tmin, double tmax,
                               double t[4], zr_vec3 normal[4]) {
  return hf_search_upto(o, org, dir, tmin, tmax, 2, t, normal);
}

double zr__height_field_height(const zr_object *o, double x, double z) {
  const struct zr_hf_grid *g = o->u.height_field.grid;
  int w = g->w, h = g->h;
  double fx = fmin(fmax(x, 0.0), 1.0) * (w - 1);
  double fz = fmin(fmax(z, 0.0), 1.0) * (h - 1);
  int i = (int)fx, j = (int)fz;
  if (i > w - 2)
    i = w - 2;
  if (j > h - 2)
    j = h - 2;
  double u = fx - i, v = fz - j;
  double h00 = sample_at(g, i, j), h10 = sample_at(g, i + 1, j);
  double h01 = sample_at(g, i, j + 1), h11 = sample_at(g, i + 1, j + 1);
  /* The square's diagonal runs from (i + 1, j) to (i, j + 1), as the
     crossings cut it. */
  if (u + v <= 1.0)
    return h00 + u * (h10 - h00) + v * (h01 - h00);
  return h11 + (1.0 - u) * (h01 - h11) + (1.0 - v) * (h10 - h11);
}

/* Inside: over the unit square and below the surface, however far below:
   POV-Ray 3.7 draws the face z = 0.1 of intersection { height_field {
   function 8, 8 { 0.5 + 0.1*x } } box { <-0.5, -1.4, 0.1>, <1.5, 1.4,
   0.9> } } for 0 <= x <= 1 from the field down to the box's bottom at
   y = -1.4, with water_level 0.2 too (tests/csg_inside.pov); the manual
   does not say. */
bool zr__height_field_inside(const zr_object *o, zr_vec3 p) {
  if (!(p.x >= 0.0 && p.x <= 1.0 && p.z >= 0.0 && p.z <= 1.0))
    return false;
  return p.y < zr__height_field_height(o, p.x, p.z);
}

bool zr__height_field_bounds(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  const struct zr_hf_grid *g = o->u.height_field.grid;
  double water = o->u.height_field.water_level;
  /* Every sample is a corner of a triangle: none is left when all lie
     under the water. */
  if (!g || g->hi < water)
    return false;
  *lo = zr_v3(0, fmax(g->lo, water), 0);
  *hi = zr_v3(1, fmax(g->hi, lo->y), 1);
  return true;
}

/* ---- the triangles as a mesh, for radiosity ---- */

zr_status zr__height_field_mesh(const zr_object *o, zr_arena *arena,
                                const struct zr_mesh **out) {
  *out = NULL;
  const struct zr_hf_grid *g = o->u.height_field.grid;
  int w = g->w, h = g->h;
  bool smooth = o->u.height_field.smooth;
  double water = o->u.height_field.water_level;
  size_t nv = (size_t)w * (size_t)h;
  size_t nf = 2 * (size_t)(w - 1) * (size_t)(h - 1);
  if (nv > UINT32_MAX)
    return ZR_ELIMIT;
  struct zr_mesh *m = zr__arena_alloc(arena, sizeof *m);
  if (!m)
    return ZR_ENOMEM;
  memset(m, 0, sizeof *m);
  m->vertices = zr__arena_alloc(arena, nv * sizeof *m->vertices);
  m->faces = zr__arena_alloc(arena, nf * sizeof *m->faces);
  if (smooth) {
    m->normals = zr__arena_alloc(arena, nv * sizeof *m->normals);
    m->face_normals = zr__arena_alloc(arena, nf * sizeof *m->face_normals);
  }
  if (!m->vertices || !m->faces ||
      (smooth && (!m->normals || !m->face_normals)))
    return ZR_ENOMEM;
  hf_search s = {.g = g, .dx = 1.0 / (w - 1), .dz = 1.0 / (h - 1)};
  for (int j = 0; j < h; j++)
    for (int i = 0; i < w; i++) {
      size_t k = (size_t)j * w + i;
      m->vertices[k] = zr_v3(i * s.dx, sample_at(g, i, j), j * s.dz);
      if (smooth)
        m->normals[k] = vertex_normal(&s, i, j);
    }
  m->n_vertices = m->cap_vertices = nv;
  m->n_normals = m->cap_normals = smooth ? nv : 0;
  m->cap_faces = nf;
  for (int j = 0; j + 1 < h; j++)
    for (int i = 0; i + 1 < w; i++) {
      uint32_t a = (uint32_t)((size_t)j * w + i), b = a + 1;
      uint32_t c = a + (uint32_t)w, d = c + 1;
      const uint32_t tri[2][3] = {{a, c, b}, {b, c, d}};
      for (int k = 0; k < 2; k++) {
        const uint32_t *v = tri[k];
        if (m->vertices[v[0]].y < water && m->vertices[v[1]].y < water &&
            m->vertices[v[2]].y < water)
          continue;
        size_t f = m->n_faces++;
        memcpy(m->faces[f], v, sizeof m->faces[f]);
        if (m->face_normals)
          memcpy(m->face_normals[f], v, sizeof m->face_normals[f]);
      }
    }
  size_t bad = 0;
  zr_status st = zr__mesh_build(m, arena, 1, &bad);
  if (st != ZR_OK)
    return st;
  *out = m;
  return ZR_OK;
}

/* The operations the tracer calls through (lib/trace/shape.h). */
const zr_shape_ops zr__shape_height_field = {
    .name = "a height_field",
    .search = zr__height_field_crossings,
    .search_upto = hf_search_upto,
    .inside = zr__height_field_inside,
    .bounds = zr__height_field_bounds,
};
