/*
 * bvh_wide.h - the four-wide nodes both of the tracer's hierarchies
 * walk: the scene's (bvh.c, over primitives) and each mesh's
 * (obj_mesh.c, over triangles).  Each builds a binary tree with the
 * binned surface area heuristic, then zr__bvh_collapse makes it four
 * wide; the slab test of a node's four children is zr__slab_entries.
 * Only lib/trace includes this.
 */
#ifndef ZR_TRACE_BVH_WIDE_H
#define ZR_TRACE_BVH_WIDE_H

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "trace/intersect.h"

enum {
  ZR_WIDE_WIDTH = 4, /* children of a wide node */
  ZR_WIDE_NO_CHILD = UINT16_MAX
};

/* A node of a binary tree as the builders make it, in one array in
   depth-first order: an inner node's left child follows it. */
typedef struct zr_bvh_bin_node {
  double lo[3], hi[3];
  uint32_t first; /* leaf: first primitive; inner: right child index */
  uint32_t count; /* leaf: number of primitives; inner: 0 */
} zr_bvh_bin_node;

/*
 * A node of the wide tree the tracer walks: up to ZR_WIDE_WIDTH children, each a
 * node of the binary tree the builder made, found by opening the binary
 * children with the largest surface area until ZR_WIDE_WIDTH are reached (the
 * collapse of Wald, Benthin and Boulos, "Getting rid of packets", 2008),
 * kept in the binary tree's left-to-right order.  The boxes are stored
 * one axis and one side at a time for the four children (structure of
 * arrays), in single precision rounded outward (each float box holds
 * the double one), so a node is two cache lines and the slab test of
 * all four children is one loop over four float lanes, which GCC makes
 * one SSE instruction an operation (x86-64's baseline: no dispatch, and
 * the same arithmetic on any machine, -std=c11 keeping
 * -ffp-contract=off).  The test is made conservative by a margin (see
 * zr_slab_ray): it may open a box the exact test would skip, never skip
 * one the exact test opens, so the primitives tested, hence the
 * crossings found, are the double test's (test_bvh's
 * float_boxes_never_miss fails without the margin).  With the two fast
 * paths of bvh.c (plane, normals), bench/peers.sh's sphereflake at 2048^2
 * took 4.94 s of CPU against the double nodes' 6.63 s in one run
 * (bench/results/peers-cpu-2026-12-02-kernel.txt).
 */
typedef struct zr_wide_node {
  float lo[3][ZR_WIDE_WIDTH], hi[3][ZR_WIDE_WIDTH];
  uint32_t child[ZR_WIDE_WIDTH]; /* leaf: first primitive; inner: wide node */
  /* Leaf: number of primitives (at most 16 in the scene's tree, 8 in
     a mesh's: their builders' leaves);
     inner: 0; ZR_WIDE_NO_CHILD: an unused lane. */
  uint16_t count[ZR_WIDE_WIDTH];
  float extent; /* the largest magnitude of a coordinate of the boxes */
} zr_wide_node;



/*
 * Collapses the binary tree nodes[] (nodes[0] its root) into wide nodes
 * written to out, which has room for one per binary node; returns how
 * many were written (out[0] is the root).  A leaf's count must be at
 * most UINT16_MAX - 1.  Children keep the binary tree's left-to-right
 * order, so the leaves do too.
 */
size_t zr__bvh_collapse(const zr_bvh_bin_node *nodes, zr_wide_node *out);

/* The float after f (f itself for a NaN or +inf), without a call to
   nextafterf: the tracer rounds each ray's interval this way. */
static inline float zr__float_after(float f) {
  if (f != f || f == INFINITY)
    return f;
  if (f == 0.0f)
    return FLT_TRUE_MIN;
  uint32_t bits;
  memcpy(&bits, &f, sizeof bits);
  bits = f > 0.0f ? bits + 1 : bits - 1;
  memcpy(&f, &bits, sizeof f);
  return f;
}

/* Single precision bounds that still hold the double value (a value
   beyond the largest float gets an infinity). */
static inline float zr__float_down(double x) {
  float f = (float)x;
  return (double)f > x ? -zr__float_after(-f) : f;
}

static inline float zr__float_up(double x) {
  float f = (float)x;
  return (double)f < x ? zr__float_after(f) : f;
}

/*
 * The ray in the form the float slab test wants, and that test's margin.
 * The exact distances along axis a are (box - org) / dir; the test
 * computes them from org and 1 / dir in float, the box's coordinates
 * being floats already (that hold the double boxes).  Rounding org moves
 * t by at most u |org| |inv| (u = 2^-24, float's unit roundoff); the
 * subtraction, the product and 1 / dir (d rounded to float, then the
 * division) by at most about 4u |t|, and |t| <= (|box| + |org|) |inv|.
 * So every distance is within 5u (E + |org|) |inv| of the exact one, E
 * the node's largest coordinate magnitude (zr_wide_node.extent), and
 * entries lowered and exits raised by 2^-19 (E + |org|) |inv| (32u,
 * leaving room for the rounding of the margin's own arithmetic) give a
 * test that never misses a box the exact test meets.  A direction
 * component of 0 or nearly so gets +-1e30 for 1 / dir, which keeps the
 * products finite (no 0 * inf = NaN) and makes the margin so wide that
 * the axis limits nothing within any distance a scene has.
 */
typedef struct zr_slab_ray {
  float org[3], inv[3];
  float org_pad[3]; /* 2^-19 |org| |inv| */
  float ext_pad[3]; /* 2^-19 |inv|, times a node's extent */
#ifdef __SSE2__
  /* The same four times over, one row an axis, so the SSE test loads
     its operands rather than broadcasting them at every node. */
  __m128 org4[3], inv4[3], org_pad4[3], ext_pad4[3];
#endif
} zr_slab_ray;

/* zr__make_slab_ray one axis at a time, in plain C: the definition the
   SSE version below must match bit for bit (test_bvh's
   slab_ray_matches_scalar), and the version without SSE.  A lane of 0
   (or a NaN) gets +-1e30 for its reciprocal rather than an infinity. */
static inline void zr__make_slab_ray_scalar(const zr_ray *ray,
                                            zr_slab_ray *s) {
  double o[3] = {ray->origin.x, ray->origin.y, ray->origin.z};
  double d[3] = {ray->dir.x, ray->dir.y, ray->dir.z};
  for (int a = 0; a < 3; a++) {
    float df = (float)d[a];
    float inv = fabsf(df) > 1e-30f ? 1.0f / df : copysignf(1e30f, df);
    s->org[a] = (float)o[a];
    s->inv[a] = inv;
    double scale = 0x1p-19 * fabs((double)inv);
    s->org_pad[a] = (float)(scale * fabs(o[a]));
    s->ext_pad[a] = (float)scale;
#ifdef __SSE2__
    s->org4[a] = _mm_set1_ps(s->org[a]);
    s->inv4[a] = _mm_set1_ps(s->inv[a]);
    s->org_pad4[a] = _mm_set1_ps(s->org_pad[a]);
    s->ext_pad4[a] = _mm_set1_ps(s->ext_pad[a]);
#endif
  }
}

#ifdef __SSE2__
/* Lane a of x in all four lanes. */
#define ZR__LANE4(x, a) _mm_shuffle_ps((x), (x), (a) * 0x55)

/* Writes the three floats of lanes 0..2 of x to out[0..2]. */
static inline void zr__store3(float out[3], __m128 x) {
  float all[4];
  _mm_storeu_ps(all, x);
  out[0] = all[0];
  out[1] = all[1];
  out[2] = all[2];
}
#endif

/*
 * The slab ray of ray.  Every ray the tracer walks, camera, shadow or
 * reflected, starts here, and most walk only four or five nodes (the
 * sphereflake's shadow rays 3.6, its nearest searches 5), so the
 * axis-by-axis loop, ~106 instructions with a branch an axis, was some
 * 5% of the sphereflake's instructions (callgrind, 512^2).  With SSE2
 * the three axes go through each operation at once: the same IEEE
 * conversions, reciprocals (divps is the lane-wise IEEE division), sign
 * copies, double products and roundings to float as the scalar
 * definition above, so the same floats bit for bit.
 */
static inline void zr__make_slab_ray(const zr_ray *ray, zr_slab_ray *s) {
#ifdef __SSE2__
  const __m128d o01 = _mm_setr_pd(ray->origin.x, ray->origin.y);
  const __m128d o2 = _mm_set_sd(ray->origin.z);
  /* The direction in float, with 1 in the unused lane 3. */
  const __m128 df = _mm_movelh_ps(
      _mm_cvtpd_ps(_mm_setr_pd(ray->dir.x, ray->dir.y)),
      _mm_cvtpd_ps(_mm_setr_pd(ray->dir.z, 1.0)));
  const __m128 sign = _mm_set1_ps(-0.0f);
  const __m128 recip = _mm_div_ps(_mm_set1_ps(1.0f), df);
  /* fabsf(df) > 1e-30f (false for a NaN), else copysignf(1e30f, df). */
  const __m128 big = _mm_cmpgt_ps(_mm_andnot_ps(sign, df),
                                  _mm_set1_ps(1e-30f));
  const __m128 signed_huge =
      _mm_or_ps(_mm_and_ps(df, sign), _mm_set1_ps(1e30f));
  const __m128 inv = _mm_or_ps(_mm_and_ps(big, recip),
                               _mm_andnot_ps(big, signed_huge));
  const __m128 org = _mm_movelh_ps(_mm_cvtpd_ps(o01), _mm_cvtpd_ps(o2));
  /* 0x1p-19 * fabs((double)inv), in double, then its products with
     fabs(o) in double, each rounded to float once. */
  const __m128d dsign = _mm_set1_pd(-0.0), k = _mm_set1_pd(0x1p-19);
  const __m128d scale01 =
      _mm_mul_pd(k, _mm_andnot_pd(dsign, _mm_cvtps_pd(inv)));
  const __m128d scale2 = _mm_mul_pd(
      k, _mm_andnot_pd(dsign, _mm_cvtps_pd(_mm_movehl_ps(inv, inv))));
  const __m128 org_pad = _mm_movelh_ps(
      _mm_cvtpd_ps(_mm_mul_pd(scale01, _mm_andnot_pd(dsign, o01))),
      _mm_cvtpd_ps(_mm_mul_pd(scale2, _mm_andnot_pd(dsign, o2))));
  const __m128 ext_pad =
      _mm_movelh_ps(_mm_cvtpd_ps(scale01), _mm_cvtpd_ps(scale2));
  zr__store3(s->org, org);
  zr__store3(s->inv, inv);
  zr__store3(s->org_pad, org_pad);
  zr__store3(s->ext_pad, ext_pad);
  s->org4[0] = ZR__LANE4(org, 0);
  s->org4[1] = ZR__LANE4(org, 1);
  s->org4[2] = ZR__LANE4(org, 2);
  s->inv4[0] = ZR__LANE4(inv, 0);
  s->inv4[1] = ZR__LANE4(inv, 1);
  s->inv4[2] = ZR__LANE4(inv, 2);
  s->org_pad4[0] = ZR__LANE4(org_pad, 0);
  s->org_pad4[1] = ZR__LANE4(org_pad, 1);
  s->org_pad4[2] = ZR__LANE4(org_pad, 2);
  s->ext_pad4[0] = ZR__LANE4(ext_pad, 0);
  s->ext_pad4[1] = ZR__LANE4(ext_pad, 1);
  s->ext_pad4[2] = ZR__LANE4(ext_pad, 2);
#else
  zr__make_slab_ray_scalar(ray, s);
#endif
}

/* SSE's minps and maxps, lane by lane: the second operand when the
   comparison fails (a NaN included), so the plain C path below gives
   the SSE path's floats, bit for bit. */
static inline float zr__min_lane(float a, float b) { return a < b ? a : b; }
static inline float zr__max_lane(float a, float b) { return a > b ? a : b; }

#ifdef __SSE2__
/* One axis of zr__slab_entries' SSE test: narrows [*t0, *t1], lane by
   lane, to the four children's slabs along axis a. */
static inline void zr__slab_axis(const zr_wide_node *w, const zr_slab_ray *r,
                                 int a, __m128 extent, __m128 *t0,
                                 __m128 *t1) {
  __m128 org = r->org4[a], inv = r->inv4[a];
  __m128 pad = _mm_add_ps(r->org_pad4[a], _mm_mul_ps(r->ext_pad4[a], extent));
  __m128 ta = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(w->lo[a]), org), inv);
  __m128 tb = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(w->hi[a]), org), inv);
  __m128 near = _mm_sub_ps(_mm_min_ps(ta, tb), pad);
  __m128 far = _mm_add_ps(_mm_max_ps(ta, tb), pad);
  *t0 = _mm_max_ps(*t0, near);
  *t1 = _mm_min_ps(*t1, far);
}
#endif

/*
 * Which of w's children the ray meets within (tmin, tmax): bit c of the
 * result for child c, with the entry distance, lowered by the margin, in
 * t[c].  An unused lane's box is NaN, and the maxima and minima take the
 * NaN (it is their second operand), so the lane never passes.  This is
 * the tracer's innermost loop: with SSE (every x86-64) the four
 * children are one instruction an operation; elsewhere the same
 * operations run a lane at a time.
 */
static inline unsigned zr__slab_entries(const zr_wide_node *w, const zr_slab_ray *r,
                                    float tmin, float tmax,
                                    float t[ZR_WIDE_WIDTH]) {
#ifdef __SSE2__
  __m128 t0 = _mm_set1_ps(tmin), t1 = _mm_set1_ps(tmax);
  __m128 extent = _mm_set1_ps(w->extent);
  /* The three axes written out: GCC -O2 kept the loop over them, its
     counter and address arithmetic (2% of the sphereflake's
     instructions). */
  zr__slab_axis(w, r, 0, extent, &t0, &t1);
  zr__slab_axis(w, r, 1, extent, &t0, &t1);
  zr__slab_axis(w, r, 2, extent, &t0, &t1);
  _mm_storeu_ps(t, t0);
  return (unsigned)_mm_movemask_ps(_mm_cmple_ps(t0, t1));
#else
  float t1[ZR_WIDE_WIDTH];
  for (int c = 0; c < ZR_WIDE_WIDTH; c++) {
    t[c] = tmin;
    t1[c] = tmax;
  }
  for (int a = 0; a < 3; a++) {
    float pad = r->org_pad[a] + r->ext_pad[a] * w->extent;
    for (int c = 0; c < ZR_WIDE_WIDTH; c++) {
      float ta = (w->lo[a][c] - r->org[a]) * r->inv[a];
      float tb = (w->hi[a][c] - r->org[a]) * r->inv[a];
      float near = zr__min_lane(ta, tb) - pad;
      float far = zr__max_lane(ta, tb) + pad;
      t[c] = zr__max_lane(t[c], near);
      t1[c] = zr__min_lane(t1[c], far);
    }
  }
  unsigned mask = 0;
  for (int c = 0; c < ZR_WIDE_WIDTH; c++)
    mask |= (unsigned)(t[c] <= t1[c]) << c;
  return mask;
#endif
}

/* A child waiting on a traversal's stack: a wide node (count 0) or a
   leaf's run of primitives or faces, with the distance at which the ray
   enters its box (lowered by the slab test's margin). */
typedef struct zr_wide_entry {
  uint32_t child, count;
  float t;
} zr_wide_entry;

/* Pushes the children of w that mask names (zr__slab_entries) last to
   first, so they are popped in the tree's left-to-right order; at most
   cap entries are held.  Returns the new stack size. */
static inline int zr__wide_push_in_order(const zr_wide_node *w,
                                         unsigned mask,
                                         const float t[ZR_WIDE_WIDTH],
                                         zr_wide_entry *stack, int sp,
                                         int cap) {
  for (int c = ZR_WIDE_WIDTH - 1; c >= 0 && sp < cap; c--)
    if (mask >> c & 1)
      stack[sp++] = (zr_wide_entry){w->child[c], w->count[c], t[c]};
  return sp;
}

/* The children of w that mask names, into met[] sorted by entry
   distance, nearest first (an insertion sort: ties keep the tree's
   order); returns how many.  Both nearest-first pushes below use it. */
static inline int zr__wide_sort_met(const zr_wide_node *w, unsigned mask,
                                    const float t[ZR_WIDE_WIDTH],
                                    zr_wide_entry met[ZR_WIDE_WIDTH]) {
  int n = 0;
  for (; mask; mask &= mask - 1) {
    int c = __builtin_ctz(mask);
    zr_wide_entry x = {w->child[c], w->count[c], t[c]};
    int k = n++;
    while (k > 0 && met[k - 1].t > x.t) {
      met[k] = met[k - 1];
      k--;
    }
    met[k] = x;
  }
  return n;
}

/* Pushes the same children sorted nearest first (ties keep the tree's
   order), farthest pushed first, so the nearest is searched first and
   shrinks the interval for the others.  Returns the new stack size. */
static inline int zr__wide_push_nearest_first(const zr_wide_node *w,
                                              unsigned mask,
                                              const float t[ZR_WIDE_WIDTH],
                                              zr_wide_entry *stack, int sp,
                                              int cap) {
  zr_wide_entry met[ZR_WIDE_WIDTH];
  int n = zr__wide_sort_met(w, mask, t, met);
  for (int k = n - 1; k >= 0 && sp < cap; k--)
    stack[sp++] = met[k];
  return sp;
}

/*
 * The two pushes above without the round trip through the stack of the
 * child that would be popped at once: mask (not 0) names the children
 * met; the one the walk searches next is written to *next and the
 * others are pushed as the push above would push them, so the walk
 * visits the same children in the same order.  Most nodes a ray opens
 * have one child met, which then costs no push or pop at all.
 */
static inline int zr__wide_next_in_order(const zr_wide_node *w,
                                         unsigned mask,
                                         const float t[ZR_WIDE_WIDTH],
                                         zr_wide_entry *stack, int sp,
                                         int cap, zr_wide_entry *next) {
  int first = __builtin_ctz(mask);
  *next = (zr_wide_entry){w->child[first], w->count[first], t[first]};
  mask &= mask - 1;
  while (mask && sp < cap) {
    int c = 31 - __builtin_clz(mask);
    stack[sp++] = (zr_wide_entry){w->child[c], w->count[c], t[c]};
    mask &= ~(1u << c);
  }
  return sp;
}

static inline int zr__wide_next_nearest_first(const zr_wide_node *w,
                                              unsigned mask,
                                              const float t[ZR_WIDE_WIDTH],
                                              zr_wide_entry *stack, int sp,
                                              int cap,
                                              zr_wide_entry *next) {
  if (!(mask & (mask - 1))) { /* one child */
    int c = __builtin_ctz(mask);
    *next = (zr_wide_entry){w->child[c], w->count[c], t[c]};
    return sp;
  }
  zr_wide_entry met[ZR_WIDE_WIDTH];
  int n = zr__wide_sort_met(w, mask, t, met);
  *next = met[0];
  for (int k = n - 1; k >= 1 && sp < cap; k--)
    stack[sp++] = met[k];
  return sp;
}

#endif /* ZR_TRACE_BVH_WIDE_H */
