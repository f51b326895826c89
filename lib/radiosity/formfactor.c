/*
 * formfactor.c - exact and estimated form factors for radiosity.
 *
 * Point to polygon.  The form factor from a differential area dA at p,
 * normal n, to a polygon is its projected solid angle over pi.  By
 * Stokes' theorem the area integral becomes a contour integral over the
 * edges (Lambert 1760; in the form used by Baum, Rushmeier and Winget,
 * "Improving radiosity solutions through the use of analytically
 * determined form-factors", SIGGRAPH 1989):
 *   F = (1 / 2 pi) | sum_e theta_e (n . g_e) |,
 * where for the edge from a to b, with r_a = a - p and r_b = b - p,
 * theta_e is the angle between r_a and r_b and g_e the unit vector along
 * r_a x r_b.  Each term is computed as atan2(|c|, r_a . r_b) (n . c) / |c|
 * with c = r_a x r_b, which stays accurate for tiny and for nearly
 * straight angles (the atan2 is edge_angle below, a table of atan(k/8)
 * and a short series, a few ulps from libm's at 60% of its time).  An edge on a line through p has r x dr = 0 all along
 * it, so its term is exactly 0 and is skipped: a point on an edge's line
 * gives a finite factor, never NaN.
 *
 * The formula integrates over the whole sphere of directions, so a
 * polygon that reaches behind the tangent plane at p must first be
 * clipped to the front half-space n . (x - p) >= 0 (Sutherland-Hodgman,
 * streamed: vertices go straight into the sum, so any number of vertices
 * needs no buffer).  The clipped boundary runs along the tangent plane,
 * where its terms count the polygon's extent on the horizon.  A point in
 * the polygon's own plane sees it edge-on, so the factor is 0 (the
 * contour formula would wrongly give 1 for a point inside the polygon).
 *
 * Patch to polygon.  A link's factor F_ij = (1/A_i) int_Ai F(dA_i -> j)
 * is integrated with a product Gauss-Legendre rule over the receiver's
 * parameter rectangle, weighting by the area element (Hanrahan,
 * Salzman and Aupperle, "A rapid hierarchical radiosity algorithm",
 * SIGGRAPH 1991, use this inner exact factor with outer quadrature).
 * The contour integral depends only on the boundary, so by Stokes'
 * theorem it also gives the factor of a curved source cell from its
 * boundary curve, provided the cell is seen one-to-one from the point
 * (true inside a sphere, for instance); zr__ff_patch_patch samples that
 * boundary with chords, losing O(segs^-2).  Clipping stays exact for
 * curved cells too: the part of the boundary that the clip replaces lies
 * in the tangent plane, where only the angle it subtends counts.
 *
 * The oracle.  Hanrahan et al. decide where to refine from a cheap upper
 * estimate.  A differential area facing a coaxial disc of area A at
 * distance r has F = A / (pi r^2 + A) exactly; for tilted patches the
 * estimate multiplies by the two cosines at the centres, which is the
 * far-field limit.  Unlike A cos cos / (pi r^2),
 * the point-source factor, this never exceeds 1 and has no pole at r = 0,
 * so touching patches (a box on a floor, a lamp against a wall) give a
 * bounded estimate and refinement ends at the minimum area as it should.
 */
#include "radiosity/formfactor.h"

#include <math.h>
#include <stdint.h>

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#include <immintrin.h>
#define LANES_AVX 1
#endif

/* ---- point to polygon ---- */

/*
 * The contour sum over the vertices of the clipped polygon, fed one
 * vertex at a time in order and closed at the end.
 */
typedef struct contour {
  zr_vec3 p, n;        /* the receiving point and its normal */
  zr_vec3 first, prev; /* unit directions to the first and last vertex */
  int count;
  double sum;
  /* 0: the factor is |sum| (the polygon seen from either side); +-1:
     sign * sum, clamped at 0 (only one side of the polygon counts). */
  double sign;
} contour;

/* atan(k / 8), k = 0 .. 8. */
static const double atan_eighths[9] = {
    0.0,
    0.12435499454676144,
    0.24497866312686414,
    0.35877067027057225,
    0.4636476090008061,
    0.5585993153435624,
    0.6435011087932844,
    0.7188299996216245,
    0.7853981633974483,
};

/*
 * atan2(y, x) for y > 0, in (0, pi): the angle of an edge, within a few
 * units in the last place of libm's (tests/test_radiosity ff_angle), at
 * a fraction of its cost.  The ratio t = min / max of y and |x| is in
 * [0, 1]; with c the nearest multiple of 1/8, atan t = atan c +
 * atan u, u = (t - c) / (1 + t c), |u| <= 1/16, whose odd series to u^13
 * leaves less than u^15 / 15 < 1e-19.
 */
static double edge_angle(double y, double x) {
  double ax = fabs(x);
  bool swap = y > ax;
  double t = swap ? ax / y : y / ax;
  /* Not a number (never from finite unit vectors): libm's answer, and
     no conversion of it to int. */
  if (!(t <= 1.0))
    return atan2(y, x);
  int k = (int)(t * 8.0 + 0.5);
  double c = k * 0.125;
  double u = (t - c) / (1.0 + t * c), u2 = u * u;
  double a =
      atan_eighths[k] +
      (u + u * u2 *
               (-1.0 / 3.0 +
                u2 * (1.0 / 5.0 +
                      u2 * (-1.0 / 7.0 +
                            u2 * (1.0 / 9.0 +
                                  u2 * (-1.0 / 11.0 + u2 * (1.0 / 13.0)))))));
  if (swap)
    a = M_PI_2 - a;
  return x < 0.0 ? M_PI - a : a;
}

double zr__ff_edge_angle(double y, double x) { return edge_angle(y, x); }

static void contour_edge(contour *c, zr_vec3 ra, zr_vec3 rb) {
  zr_vec3 cr = zr_v3_cross(ra, rb);
  double s = zr_v3_len(cr);
  /* A zero cross product means the edge lies on a line through p (or has
     no length): r x dr vanishes along it and it adds nothing. */
  if (!(s > 0.0))
    return;
  double theta = edge_angle(s, zr_v3_dot(ra, rb));
  c->sum += theta * zr_v3_dot(c->n, cr) / s;
}

static void contour_vertex(contour *c, zr_vec3 v) {
  /* Unit directions: the terms depend only on directions, and products
     of raw differences would overflow or underflow in scenes scaled by
     1e+-100 long before the directions lose precision. */
  zr_vec3 r = zr_v3_norm(zr_v3_sub(v, c->p));
  if (c->count == 0)
    c->first = r;
  else
    contour_edge(c, c->prev, r);
  c->prev = r;
  c->count++;
}

static double contour_close(contour *c) {
  if (c->count >= 2)
    contour_edge(c, c->prev, c->first);
  double sum = c->sign == 0.0 ? fabs(c->sum) : fmax(0.0, c->sign * c->sum);
  return sum / (2.0 * M_PI);
}

/*
 * A polygon's plane, found once per polygon and reused for every point
 * that looks at it.  Newell's method gives the plane normal of any
 * simple polygon, convex or not (for the curved boundary of a NURBS
 * cell, its mean plane); it runs on coordinates relative to v[0] and
 * divided by the polygon's size, so products of coordinates neither
 * overflow nor underflow.
 */
typedef zr__ff_polygon polygon_plane;

static void polygon_plane_init(polygon_plane *pl, const zr_vec3 *v,
                               size_t nv) {
  pl->verts = v;
  pl->nv = nv;
  pl->normal = zr_v3(0, 0, 0);
  pl->size = 0.0;
  pl->inv_size = 0.0;
  if (nv < 3)
    return;
  for (size_t i = 1; i < nv; i++)
    pl->size = fmax(pl->size, zr_v3_len(zr_v3_sub(v[i], v[0])));
  if (!(pl->size > 0.0))
    return;
  pl->inv_size = 1.0 / pl->size;
  zr_vec3 m = zr_v3(0, 0, 0);
  for (size_t i = 0; i < nv; i++) {
    zr_vec3 a = zr_v3_scale(zr_v3_sub(v[i], v[0]), 1.0 / pl->size);
    zr_vec3 b =
        zr_v3_scale(zr_v3_sub(v[(i + 1) % nv], v[0]), 1.0 / pl->size);
    m.x += (a.y - b.y) * (a.z + b.z);
    m.y += (a.z - b.z) * (a.x + b.x);
    m.z += (a.x - b.x) * (a.y + b.y);
  }
  pl->normal = zr_v3_norm(m);
}

/*
 * Whether p lies in the polygon's plane, judged against the polygon's
 * size so the test is the same at any scene scale.  A polygon without
 * area counts as seen edge-on.
 */
static bool in_plane(const polygon_plane *pl, zr_vec3 p) {
  if (zr_v3_dot(pl->normal, pl->normal) == 0.0)
    return true;
  zr_vec3 d = zr_v3_scale(zr_v3_sub(p, pl->verts[0]), pl->inv_size);
  return fabs(zr_v3_dot(pl->normal, d)) <= 1e-12;
}

static double point_polygon_signed(zr_vec3 p, zr_vec3 n,
                                   const polygon_plane *pl, double sign) {
  if (in_plane(pl, p))
    return 0.0;
  const zr_vec3 *verts = pl->verts;
  size_t nv = pl->nv;
  contour c = {p, n, zr_v3(0, 0, 0), zr_v3(0, 0, 0), 0, 0.0, sign};
  /* Sutherland-Hodgman against the half-space h(x) = n . (x - p) >= 0:
     for each edge a -> b emit the crossing point, then b if in front. */
  zr_vec3 a = verts[nv - 1];
  double ha = zr_v3_dot(n, zr_v3_sub(a, p));
  for (size_t i = 0; i < nv; i++) {
    zr_vec3 b = verts[i];
    double hb = zr_v3_dot(n, zr_v3_sub(b, p));
    bool a_in = ha >= 0.0, b_in = hb >= 0.0;
    if (a_in != b_in)
      contour_vertex(&c, zr_v3_madd(a, zr_v3_sub(b, a), ha / (ha - hb)));
    if (b_in)
      contour_vertex(&c, b);
    a = b;
    ha = hb;
  }
  return fmin(1.0, contour_close(&c));
}

static double point_polygon(zr_vec3 p, zr_vec3 n, const polygon_plane *pl) {
  return point_polygon_signed(p, n, pl, 0.0);
}

double zr__ff_point_polygon(zr_vec3 p, zr_vec3 n, const zr_vec3 *verts,
                            size_t nv) {
  polygon_plane pl;
  polygon_plane_init(&pl, verts, nv);
  return point_polygon(p, n, &pl);
}

double zr__ff_point_polygon_sided(zr_vec3 p, zr_vec3 n,
                                  const zr__ff_polygon *pl, double sign) {
  return point_polygon_signed(p, n, pl, sign);
}

void zr__ff_polygon_init(zr__ff_polygon *pl, const zr_vec3 *verts,
                         size_t nv) {
  polygon_plane_init(pl, verts, nv);
}

double zr__ff_point_polygon_pre(zr_vec3 p, zr_vec3 n,
                                const zr__ff_polygon *pl) {
  return point_polygon(p, n, pl);
}

/* ---- many points and polygons at once ----
 *
 * One contour sum is a chain of dependent square roots and divisions
 * (a unit direction, then the edge's sine, its angle's two quotients
 * and the term's), whose latency the processor cannot hide behind the
 * sum's few other operations: a quadrilateral took some 300 cycles, most
 * of them waiting.  zr__ff_point_polygons takes four (point, polygon)
 * pairs in the four lanes of AVX registers: each lane clips its own
 * polygon (scalar, as point_polygon_signed does) into slots, then slot
 * k of every lane is made unit at once and edge k of every lane summed
 * at once.  Each lane does the scalar code's operations in its order on
 * the same values (no FMA, IEEE square roots and quotients), and adds
 * its edges in edge order to its own sum, so every lane gives the
 * scalar bits.  A lane past its last edge, or whose edge is skipped
 * (zero cross product), adds +0, which changes no sum (a sum that
 * starts at +0 is never -0).  Polygons of more than LANE_VERTS vertices,
 * and every pair without AVX, go through the scalar code. */

enum { LANE_VERTS = 8, LANE_SLOTS = 2 * LANE_VERTS + 2 };

/* The finished factor from a lane's contour sum (contour_close's). */
static double lane_factor(double sum, double sign) {
  double s = sign == 0.0 ? fabs(sum) : fmax(0.0, sign * sum);
  return fmin(1.0, s / (2.0 * M_PI));
}

#ifdef LANES_AVX
#define AVX_FN __attribute__((target("avx")))

/* The clipped polygons of four lanes, vertex k of lane l less its point
   at [k][l]; slot count[l] repeats slot 0 (the closing edge's end). */
typedef struct lane_slots {
  _Alignas(32) double x[LANE_SLOTS][4];
  _Alignas(32) double y[LANE_SLOTS][4];
  _Alignas(32) double z[LANE_SLOTS][4];
  int count[4];
} lane_slots;

/* point_polygon_signed's clipping for lane l into its slots. */
static void lane_clip(lane_slots *ls, int l, zr_vec3 p, zr_vec3 n,
                      const polygon_plane *pl) {
  const zr_vec3 *verts = pl->verts;
  size_t nv = pl->nv;
  int m = 0;
  zr_vec3 a = verts[nv - 1];
  double ha = zr_v3_dot(n, zr_v3_sub(a, p));
  for (size_t i = 0; i < nv; i++) {
    zr_vec3 b = verts[i];
    double hb = zr_v3_dot(n, zr_v3_sub(b, p));
    bool a_in = ha >= 0.0, b_in = hb >= 0.0;
    if (a_in != b_in) {
      zr_vec3 d = zr_v3_sub(zr_v3_madd(a, zr_v3_sub(b, a), ha / (ha - hb)), p);
      ls->x[m][l] = d.x;
      ls->y[m][l] = d.y;
      ls->z[m][l] = d.z;
      m++;
    }
    if (b_in) {
      zr_vec3 d = zr_v3_sub(b, p);
      ls->x[m][l] = d.x;
      ls->y[m][l] = d.y;
      ls->z[m][l] = d.z;
      m++;
    }
    a = b;
    ha = hb;
  }
  /* Fewer than two vertices close no edge (contour_close). */
  if (m < 2)
    m = 0;
  ls->x[m][l] = ls->x[0][l];
  ls->y[m][l] = ls->y[0][l];
  ls->z[m][l] = ls->z[0][l];
  ls->count[l] = m;
}

AVX_FN static inline __m256d lanes_select(__m256d mask, __m256d a,
                                         __m256d b) {
  return _mm256_or_pd(_mm256_and_pd(mask, a), _mm256_andnot_pd(mask, b));
}

/* edge_angle(y, x) a lane, by its operations in its order; *fine gets
   the lanes whose reduced ratio is a number (t <= 1), the others being
   edge_angle's case for libm. */
AVX_FN static inline __m256d lanes_edge_angle(__m256d y, __m256d x,
                                              int *fine) {
  __m256d ax = _mm256_andnot_pd(_mm256_set1_pd(-0.0), x);
  __m256d swap = _mm256_cmp_pd(y, ax, _CMP_GT_OQ);
  __m256d t = _mm256_div_pd(lanes_select(swap, ax, y),
                            lanes_select(swap, y, ax));
  __m256d ok = _mm256_cmp_pd(t, _mm256_set1_pd(1.0), _CMP_LE_OQ);
  *fine = _mm256_movemask_pd(ok);
  /* 0 in the other lanes, so the table index stays in 0 .. 8. */
  t = _mm256_and_pd(ok, t);
  __m128i k = _mm256_cvttpd_epi32(_mm256_add_pd(
      _mm256_mul_pd(t, _mm256_set1_pd(8.0)), _mm256_set1_pd(0.5)));
  __m256d c = _mm256_mul_pd(_mm256_cvtepi32_pd(k), _mm256_set1_pd(0.125));
  __m256d u = _mm256_div_pd(
      _mm256_sub_pd(t, c),
      _mm256_add_pd(_mm256_set1_pd(1.0), _mm256_mul_pd(t, c)));
  __m256d u2 = _mm256_mul_pd(u, u);
  __m256d q = _mm256_mul_pd(u2, _mm256_set1_pd(1.0 / 13.0));
  q = _mm256_mul_pd(u2, _mm256_add_pd(_mm256_set1_pd(-1.0 / 11.0), q));
  q = _mm256_mul_pd(u2, _mm256_add_pd(_mm256_set1_pd(1.0 / 9.0), q));
  q = _mm256_mul_pd(u2, _mm256_add_pd(_mm256_set1_pd(-1.0 / 7.0), q));
  q = _mm256_mul_pd(u2, _mm256_add_pd(_mm256_set1_pd(1.0 / 5.0), q));
  q = _mm256_add_pd(_mm256_set1_pd(-1.0 / 3.0), q);
  __m256d series = _mm256_add_pd(u, _mm256_mul_pd(_mm256_mul_pd(u, u2), q));
  int ks[4];
  _mm_storeu_si128((__m128i *)ks, k);
  __m256d a = _mm256_add_pd(
      _mm256_set_pd(atan_eighths[ks[3]], atan_eighths[ks[2]],
                    atan_eighths[ks[1]], atan_eighths[ks[0]]),
      series);
  a = lanes_select(swap, _mm256_sub_pd(_mm256_set1_pd(M_PI_2), a), a);
  return lanes_select(_mm256_cmp_pd(x, _mm256_setzero_pd(), _CMP_LT_OQ),
                      _mm256_sub_pd(_mm256_set1_pd(M_PI), a), a);
}

/* The contour sums of four lanes (zeros in slots, count 0, for unused
   lanes), normals in nx, ny, nz. */
AVX_FN static void lanes_sums(lane_slots *ls, const double nx[4],
                              const double ny[4], const double nz[4],
                              double sums[4]) {
  int top = 0;
  for (int l = 0; l < 4; l++)
    top = ls->count[l] > top ? ls->count[l] : top;
  /* Slots past a lane's own read as zero vectors. */
  for (int l = 0; l < 4; l++)
    for (int k = ls->count[l] + 1; k <= top; k++)
      ls->x[k][l] = ls->y[k][l] = ls->z[k][l] = 0.0;
  /* Unit directions, as zr_v3_norm makes them. */
  for (int k = 0; k <= top; k++) {
    __m256d dx = _mm256_load_pd(ls->x[k]), dy = _mm256_load_pd(ls->y[k]);
    __m256d dz = _mm256_load_pd(ls->z[k]);
    __m256d len = _mm256_sqrt_pd(_mm256_add_pd(
        _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)),
        _mm256_mul_pd(dz, dz)));
    __m256d pos = _mm256_cmp_pd(len, _mm256_setzero_pd(), _CMP_GT_OQ);
    __m256d inv = _mm256_div_pd(_mm256_set1_pd(1.0), len);
    _mm256_store_pd(ls->x[k], lanes_select(pos, _mm256_mul_pd(dx, inv), dx));
    _mm256_store_pd(ls->y[k], lanes_select(pos, _mm256_mul_pd(dy, inv), dy));
    _mm256_store_pd(ls->z[k], lanes_select(pos, _mm256_mul_pd(dz, inv), dz));
  }
  __m256d vnx = _mm256_loadu_pd(nx), vny = _mm256_loadu_pd(ny);
  __m256d vnz = _mm256_loadu_pd(nz);
  __m256d count = _mm256_set_pd(ls->count[3], ls->count[2], ls->count[1],
                                ls->count[0]);
  __m256d sum = _mm256_setzero_pd();
  /* Edge k, slot k to k + 1, in every lane at once: contour_edge's. */
  for (int k = 0; k < top; k++) {
    __m256d ax = _mm256_load_pd(ls->x[k]), ay = _mm256_load_pd(ls->y[k]);
    __m256d az = _mm256_load_pd(ls->z[k]);
    __m256d bx = _mm256_load_pd(ls->x[k + 1]);
    __m256d by = _mm256_load_pd(ls->y[k + 1]);
    __m256d bz = _mm256_load_pd(ls->z[k + 1]);
    __m256d cx = _mm256_sub_pd(_mm256_mul_pd(ay, bz), _mm256_mul_pd(az, by));
    __m256d cy = _mm256_sub_pd(_mm256_mul_pd(az, bx), _mm256_mul_pd(ax, bz));
    __m256d cz = _mm256_sub_pd(_mm256_mul_pd(ax, by), _mm256_mul_pd(ay, bx));
    __m256d sn = _mm256_sqrt_pd(_mm256_add_pd(
        _mm256_add_pd(_mm256_mul_pd(cx, cx), _mm256_mul_pd(cy, cy)),
        _mm256_mul_pd(cz, cz)));
    __m256d live = _mm256_and_pd(
        _mm256_cmp_pd(sn, _mm256_setzero_pd(), _CMP_GT_OQ),
        _mm256_cmp_pd(_mm256_set1_pd(k), count, _CMP_LT_OQ));
    int live_bits = _mm256_movemask_pd(live);
    if (live_bits == 0)
      continue;
    __m256d d = _mm256_add_pd(
        _mm256_add_pd(_mm256_mul_pd(ax, bx), _mm256_mul_pd(ay, by)),
        _mm256_mul_pd(az, bz));
    __m256d nd = _mm256_add_pd(
        _mm256_add_pd(_mm256_mul_pd(vnx, cx), _mm256_mul_pd(vny, cy)),
        _mm256_mul_pd(vnz, cz));
    int fine;
    __m256d theta = lanes_edge_angle(sn, d, &fine);
    __m256d term = _mm256_and_pd(
        live, _mm256_div_pd(_mm256_mul_pd(theta, nd), sn));
    if ((fine & live_bits) != live_bits) {
      /* A lane outside the table's range: edge_angle's own answer. */
      double tv[4], sv[4], dv[4], nv[4];
      _mm256_storeu_pd(tv, term);
      _mm256_storeu_pd(sv, sn);
      _mm256_storeu_pd(dv, d);
      _mm256_storeu_pd(nv, nd);
      for (int l = 0; l < 4; l++)
        if ((live_bits >> l & 1) && !(fine >> l & 1))
          tv[l] = edge_angle(sv[l], dv[l]) * nv[l] / sv[l];
      term = _mm256_loadu_pd(tv);
    }
    sum = _mm256_add_pd(sum, term);
  }
  _mm256_storeu_pd(sums, sum);
}

/* Up to four pairs, lanes 0 .. count - 1. */
AVX_FN static void lanes_four(size_t count, const zr_vec3 *p,
                              const zr_vec3 *n,
                              const zr__ff_polygon *const *pl, double sign,
                              double *out) {
  lane_slots ls;
  double nx[4] = {0}, ny[4] = {0}, nz[4] = {0}, sums[4];
  int summed = 0; /* lanes whose factor is their contour sum's */
  for (int l = 0; l < 4; l++) {
    ls.count[l] = 0;
    ls.x[0][l] = ls.y[0][l] = ls.z[0][l] = 0.0;
    if ((size_t)l >= count)
      continue;
    if (pl[l]->nv > LANE_VERTS) {
      out[l] = point_polygon_signed(p[l], n[l], pl[l], sign);
      continue;
    }
    if (in_plane(pl[l], p[l])) {
      out[l] = 0.0;
      continue;
    }
    nx[l] = n[l].x;
    ny[l] = n[l].y;
    nz[l] = n[l].z;
    lane_clip(&ls, l, p[l], n[l], pl[l]);
    summed |= 1 << l;
  }
  if (summed == 0)
    return;
  lanes_sums(&ls, nx, ny, nz, sums);
  for (int l = 0; l < 4; l++)
    if (summed >> l & 1)
      out[l] = lane_factor(sums[l], sign);
}
#endif

void zr__ff_point_polygons(size_t count, const zr_vec3 *p, const zr_vec3 *n,
                           const zr__ff_polygon *const *pl, double sign,
                           double *out) {
#ifdef LANES_AVX
  if (__builtin_cpu_supports("avx")) {
    for (size_t i = 0; i < count; i += 4)
      lanes_four(count - i < 4 ? count - i : 4, p + i, n + i, pl + i, sign,
                 out + i);
    return;
  }
#endif
  for (size_t i = 0; i < count; i++)
    out[i] = point_polygon_signed(p[i], n[i], pl[i], sign);
}

/* ---- quadrature over patches ---- */

/* The kernel cos_p cos_q / (pi r^2) summed over quadrature points. */
typedef struct kernel_sum {
  zr_vec3 p, n;
  double sum;
} kernel_sum;

static void add_kernel(const zr__surface_point *q, double weight,
                       void *user) {
  kernel_sum *k = user;
  zr_vec3 d = zr_v3_sub(q->p, k->p);
  double r2 = zr_v3_dot(d, d);
  double cos_p = zr_v3_dot(k->n, d);
  /* A Gauss point on p itself is the kernel's pole; behind p, nothing. */
  if (!(r2 > 0.0) || cos_p <= 0.0)
    return;
  /* cos_p cos_q / r^2 with both cosines unnormalised: / r^4. */
  double cos_q = fabs(zr_v3_dot(q->n, d));
  k->sum += weight * cos_p * cos_q / (M_PI * r2 * r2);
}

double zr__ff_point_patch_quadrature(zr_vec3 p, zr_vec3 n,
                                     const zr__surface *src, double u0,
                                     double u1, double v0, double v1,
                                     const zr__gauss_rule *rule) {
  kernel_sum k = {p, n, 0.0};
  zr__surface_quadrature(src, u0, u1, v0, v1, 1, rule, add_kernel, &k);
  return k.sum;
}

/* The area-weighted point-to-polygon factor over a receiver.  Points
   wait in fours (zr__ff_point_polygons) and their factors are added in
   the order the points came, so the sum is the one-at-a-time sum. */
typedef struct polygon_flux {
  polygon_plane plane;
  double side, sign; /* the receiver's normals times side; the sum's sign */
  double flux, area;
  int waiting;
  zr_vec3 p[ZR__FF_LANES], n[ZR__FF_LANES];
  double weight[ZR__FF_LANES];
} polygon_flux;

static void flux_flush(polygon_flux *f) {
  const zr__ff_polygon *pl[ZR__FF_LANES] = {&f->plane, &f->plane, &f->plane,
                                           &f->plane};
  double ff[ZR__FF_LANES];
  zr__ff_point_polygons((size_t)f->waiting, f->p, f->n, pl, f->sign, ff);
  for (int i = 0; i < f->waiting; i++)
    f->flux += f->weight[i] * ff[i];
  f->waiting = 0;
}

static void add_polygon_flux(const zr__surface_point *pt, double weight,
                             void *user) {
  polygon_flux *f = user;
  f->area += weight;
  f->p[f->waiting] = pt->p;
  f->n[f->waiting] = zr_v3_scale(pt->n, f->side);
  f->weight[f->waiting] = weight;
  if (++f->waiting == ZR__FF_LANES)
    flux_flush(f);
}

/* The mean factor from the receiver cell to the polygon (its plane
   made), its normals turned to side and the sum taken with sign. */
static double polygon_flux_mean(polygon_flux *f, const zr__surface *recv,
                                double u0, double u1, double v0, double v1,
                                int cells, const zr__gauss_rule *rule) {
  f->flux = f->area = 0.0;
  f->waiting = 0;
  zr__surface_quadrature(recv, u0, u1, v0, v1, cells, rule,
                         add_polygon_flux, f);
  flux_flush(f);
  return f->area > 0.0 ? f->flux / f->area : 0.0;
}

double zr__ff_patch_polygon(const zr__surface *recv, double u0, double u1,
                            double v0, double v1, const zr_vec3 *verts,
                            size_t nv, int cells,
                            const zr__gauss_rule *rule) {
  polygon_flux f;
  polygon_plane_init(&f.plane, verts, nv);
  f.side = 1.0;
  f.sign = 0.0;
  return polygon_flux_mean(&f, recv, u0, u1, v0, v1, cells, rule);
}

/* The factor of zr__ff_patch_patch, the source counted from both sides
   (sign 0) or from one (+-1: the sign that its contour sum has where
   that side faces the receiver point). */
static double patch_patch(const zr__surface *recv, const double rcell[4],
                          double side, const zr__surface *src,
                          const double scell[4], double sign, int segs,
                          int cells, const zr__gauss_rule *rule) {
  zr_vec3 poly[4 * ZR__FF_MAX_SEGS];
  segs = segs < 1 ? 1 : segs > ZR__FF_MAX_SEGS ? ZR__FF_MAX_SEGS : segs;
  size_t nv = zr__surface_patch_polygon(src, scell[0], scell[1], scell[2],
                                        scell[3], segs, poly,
                                        4 * ZR__FF_MAX_SEGS);
  polygon_flux f;
  polygon_plane_init(&f.plane, poly, nv);
  f.side = side < 0.0 ? -1.0 : 1.0;
  f.sign = sign;
  return polygon_flux_mean(&f, recv, rcell[0], rcell[1], rcell[2], rcell[3],
                           cells, rule);
}

double zr__ff_patch_patch(const zr__surface *recv, const double rcell[4],
                          double side, const zr__surface *src,
                          const double scell[4], int segs, int cells,
                          const zr__gauss_rule *rule) {
  return patch_patch(recv, rcell, side, src, scell, 0.0, segs, cells, rule);
}

double zr__ff_patch_patch_sided(const zr__surface *recv,
                                const double rcell[4], double side,
                                const zr__surface *src, const double scell[4],
                                double sside, int segs, int cells,
                                const zr__gauss_rule *rule) {
  /* The boundary runs (u0,v0), (u1,v0), (u1,v1), (u0,v1), anticlockwise
     about S_u x S_v, which is orient times the outward normal; seen from
     the side S_u x S_v points to, the contour sum is negative. */
  double sign = (sside < 0.0 ? 1.0 : -1.0) * (src->orient < 0.0 ? -1.0 : 1.0);
  return patch_patch(recv, rcell, side, src, scell, sign, segs, cells, rule);
}

/* ---- the refinement oracle ---- */

double zr__ff_oracle(zr_vec3 x, zr_vec3 nx, zr_vec3 y, zr_vec3 ny,
                     double area_y) {
  zr_vec3 d = zr_v3_sub(y, x);
  double r2 = zr_v3_dot(d, d);
  /* Coincident centres: the factor is unknown but at most 1, and an
     upper estimate is what refinement needs. */
  if (!(r2 > 0.0))
    return area_y > 0.0 ? 1.0 : 0.0;
  double r = sqrt(r2);
  /* Clamped to [0, 1]: for denormal distances r = sqrt(r2) is inexact
     and a cosine could exceed 1 by rounding. */
  double cos_x = fmin(1.0, fmax(0.0, zr_v3_dot(nx, d) / r));
  double cos_y = fmin(1.0, fmax(0.0, -zr_v3_dot(ny, d) / r));
  return area_y * cos_x * cos_y / (M_PI * r2 + area_y);
}
