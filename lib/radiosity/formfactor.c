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
 * straight angles.  An edge on a line through p has r x dr = 0 all along
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
 *
 * The oracle.  Hanrahan et al. decide where to refine from a cheap upper
 * estimate.  A differential area facing a coaxial disc of area A at
 * distance r has F = A / (pi r^2 + A) exactly; tilting the disc and the
 * receiver multiplies by the two cosines.  Unlike A cos cos / (pi r^2),
 * the point-source factor, this never exceeds 1 and has no pole at r = 0,
 * so touching patches (a box on a floor, a lamp against a wall) give a
 * bounded estimate and refinement ends at the minimum area as it should.
 */
#include "radiosity/formfactor.h"

#include <math.h>

/* ---- point to polygon ---- */

/*
 * The contour sum over the vertices of the clipped polygon, fed one
 * vertex at a time in order and closed at the end.
 */
typedef struct contour {
  zr_vec3 p, n;        /* the receiving point and its normal */
  zr_vec3 first, prev; /* first and previous vertices, relative to p */
  int count;
  double sum;
} contour;

static void contour_edge(contour *c, zr_vec3 ra, zr_vec3 rb) {
  zr_vec3 cr = zr_v3_cross(ra, rb);
  double s = zr_v3_len(cr);
  /* A zero cross product means the edge lies on a line through p (or has
     no length): r x dr vanishes along it and it adds nothing. */
  if (!(s > 0.0))
    return;
  double theta = atan2(s, zr_v3_dot(ra, rb));
  c->sum += theta * zr_v3_dot(c->n, cr) / s;
}

static void contour_vertex(contour *c, zr_vec3 v) {
  zr_vec3 r = zr_v3_sub(v, c->p);
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
  return fabs(c->sum) / (2.0 * M_PI);
}

/*
 * Whether p lies in the polygon's plane, judged against the polygon's
 * size so the test is the same at any scene scale.  Newell's method gives
 * the plane normal of any simple polygon, convex or not.
 */
static bool in_polygon_plane(zr_vec3 p, const zr_vec3 *v, size_t nv) {
  zr_vec3 m = zr_v3(0, 0, 0);
  double size = 0.0;
  for (size_t i = 0; i < nv; i++) {
    zr_vec3 a = v[i], b = v[(i + 1) % nv];
    m.x += (a.y - b.y) * (a.z + b.z);
    m.y += (a.z - b.z) * (a.x + b.x);
    m.z += (a.x - b.x) * (a.y + b.y);
    size = fmax(size, zr_v3_len(zr_v3_sub(a, v[0])));
  }
  double ml = zr_v3_len(m);
  if (!(ml > 0.0))
    return true; /* a degenerate polygon has no area to see */
  double dist = zr_v3_dot(m, zr_v3_sub(p, v[0])) / ml;
  return fabs(dist) <= 1e-12 * size;
}

double zr__ff_point_polygon(zr_vec3 p, zr_vec3 n, const zr_vec3 *verts,
                            size_t nv) {
  if (nv < 3 || in_polygon_plane(p, verts, nv))
    return 0.0;
  contour c = {p, n, zr_v3(0, 0, 0), zr_v3(0, 0, 0), 0, 0.0};
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

/* ---- quadrature over patches ---- */

double zr__ff_point_patch_quadrature(zr_vec3 p, zr_vec3 n,
                                     const zr__surface *src, double u0,
                                     double u1, double v0, double v1,
                                     const zr__gauss_rule *rule) {
  double sum = 0.0;
  for (int i = 0; i < rule->n; i++) {
    for (int j = 0; j < rule->n; j++) {
      zr__surface_point q;
      zr__surface_eval(src, u0 + (u1 - u0) * rule->x[i],
                       v0 + (v1 - v0) * rule->x[j], &q);
      zr_vec3 d = zr_v3_sub(q.p, p);
      double r2 = zr_v3_dot(d, d);
      if (!(r2 > 0.0))
        continue; /* a Gauss point on p itself: the kernel's pole */
      double cos_p = zr_v3_dot(n, d);
      if (cos_p <= 0.0)
        continue;
      /* cos_p cos_q / r^2 with both cosines unnormalised: / r^4. */
      double cos_q = fabs(zr_v3_dot(q.n, d));
      sum += rule->w[i] * rule->w[j] * q.da * cos_p * cos_q / (r2 * r2);
    }
  }
  return sum * (u1 - u0) * (v1 - v0) / M_PI;
}

double zr__ff_patch_polygon(const zr__surface *recv, double u0, double u1,
                            double v0, double v1, const zr_vec3 *verts,
                            size_t nv, int cells,
                            const zr__gauss_rule *rule) {
  double du = (u1 - u0) / cells, dv = (v1 - v0) / cells;
  double flux = 0.0, area = 0.0;
  for (int a = 0; a < cells; a++) {
    for (int b = 0; b < cells; b++) {
      for (int i = 0; i < rule->n; i++) {
        for (int j = 0; j < rule->n; j++) {
          zr__surface_point pt;
          zr__surface_eval(recv, u0 + (a + rule->x[i]) * du,
                           v0 + (b + rule->x[j]) * dv, &pt);
          double w = rule->w[i] * rule->w[j] * pt.da;
          area += w;
          flux += w * zr__ff_point_polygon(pt.p, pt.n, verts, nv);
        }
      }
    }
  }
  return area > 0.0 ? flux / area : 0.0;
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
