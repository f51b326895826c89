/*
 * nurbs.c - rational B-splines for exact conic surfaces.
 *
 * Radiosity on the true surfaces of a scene needs a parameterisation
 * S(u,v) of every curved object, with its normal and area element, that
 * is exact rather than tessellated.  Quadrics of revolution are rational
 * quadratic: a circle is a degree-2 NURBS curve with weights 1 and
 * sqrt(2)/2, and turning a profile curve about an axis multiplies the
 * circle by the profile (Piegl & Tiller, "The NURBS Book", 2nd ed.:
 * basis functions and their derivatives, chapter 2; rational curves and
 * the nine-point circle, section 7.5; surfaces of revolution, section
 * 8.5).  The code below follows those definitions:
 *  - find_span is a binary search of the clamped knot vector;
 *  - the basis functions come from the triangular Cox-de Boor scheme,
 *    and their derivatives from N'_{i,p} = p N_{i,p-1} / (u_{i+p} - u_i)
 *    - p N_{i+1,p-1} / (u_{i+p+1} - u_{i+1});
 *  - a rational surface is evaluated in homogeneous space, A(u,v) =
 *    sum N_i M_j w_ij P_ij and W(u,v) = sum N_i M_j w_ij, and S = A / W
 *    with the quotient rule for S_u, S_v and S_uv.
 * An affine transform maps a NURBS onto the NURBS with the transformed
 * control points and the same weights (affine invariance), so objects
 * under POV-Ray transforms stay exact.
 */
#include "radiosity/nurbs.h"

#include <math.h>
#include <string.h>

int zr__nurbs_find_span(int n_cp, int degree, const double *knots, double t) {
  int last = n_cp - 1;
  if (t >= knots[last + 1])
    return last;
  if (t <= knots[degree])
    return degree;
  int lo = degree, hi = last + 1;
  /* Invariant: knots[lo] <= t < knots[hi]. */
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    if (t < knots[mid])
      hi = mid;
    else
      lo = mid;
  }
  return lo;
}

void zr__nurbs_basis(int k, double t, int degree, const double *knots,
                     double *n, double *dn) {
  /* ndu[j] holds the degree-d functions N_{k-d+j, d}; lower keeps the
     degree - 1 row, from which the derivatives are formed. */
  double ndu[ZR__NURBS_MAX_DEGREE + 1] = {1.0};
  double lower[ZR__NURBS_MAX_DEGREE + 1] = {1.0};
  for (int d = 1; d <= degree; d++) {
    memcpy(lower, ndu, sizeof ndu);
    double next[ZR__NURBS_MAX_DEGREE + 1] = {0.0};
    for (int j = 0; j < d; j++) {
      /* N_{i,d-1} with i = k - d + 1 + j feeds N_{i-1,d} and N_{i,d}. */
      int i = k - d + 1 + j;
      double span = knots[i + d] - knots[i];
      double a = span > 0.0 ? lower[j] / span : 0.0;
      next[j] += (knots[i + d] - t) * a;
      next[j + 1] += (t - knots[i]) * a;
    }
    memcpy(ndu, next, sizeof ndu);
  }
  memcpy(n, ndu, sizeof(double) * (size_t)(degree + 1));
  if (degree == 0) {
    dn[0] = 0.0;
    return;
  }
  /* lower[j] = N_{k-degree+1+j, degree-1}, j = 0..degree-1. */
  for (int j = 0; j <= degree; j++) {
    int i = k - degree + j;
    double left = 0.0, right = 0.0;
    if (j >= 1) {
      double span = knots[i + degree] - knots[i];
      left = span > 0.0 ? lower[j - 1] / span : 0.0;
    }
    if (j < degree) {
      double span = knots[i + degree + 1] - knots[i + 1];
      right = span > 0.0 ? lower[j] / span : 0.0;
    }
    dn[j] = degree * (left - right);
  }
}

/* Homogeneous sums: A, A_u, A_v, A_uv in xyz and W alike in [3]. */
typedef struct homogeneous {
  double a[4], au[4], av[4], auv[4];
} homogeneous;

static void accumulate(const zr__nurbs *s, double u, double v,
                       homogeneous *h) {
  double nu[ZR__NURBS_MAX_DEGREE + 1], dnu[ZR__NURBS_MAX_DEGREE + 1];
  double nv[ZR__NURBS_MAX_DEGREE + 1], dnv[ZR__NURBS_MAX_DEGREE + 1];
  int ku = zr__nurbs_find_span(s->nu, s->p, s->ku, u);
  int kv = zr__nurbs_find_span(s->nv, s->q, s->kv, v);
  zr__nurbs_basis(ku, u, s->p, s->ku, nu, dnu);
  zr__nurbs_basis(kv, v, s->q, s->kv, nv, dnv);
  memset(h, 0, sizeof *h);
  for (int a = 0; a <= s->p; a++) {
    for (int b = 0; b <= s->q; b++) {
      const double *cw = s->cw[ku - s->p + a][kv - s->q + b];
      for (int c = 0; c < 4; c++) {
        h->a[c] += nu[a] * nv[b] * cw[c];
        h->au[c] += dnu[a] * nv[b] * cw[c];
        h->av[c] += nu[a] * dnv[b] * cw[c];
        h->auv[c] += dnu[a] * dnv[b] * cw[c];
      }
    }
  }
}

static zr_vec3 xyz(const double *h) { return zr_v3(h[0], h[1], h[2]); }

void zr__nurbs_eval(const zr__nurbs *s, double u, double v,
                    zr__nurbs_derivs *out) {
  homogeneous h;
  accumulate(s, u, v, &h);
  double w = h.a[3], wu = h.au[3], wv = h.av[3], wuv = h.auv[3];
  /* Quotient rule ("The NURBS Book" eq. 4.20) for S = A / W. */
  zr_vec3 pt = zr_v3_scale(xyz(h.a), 1.0 / w);
  zr_vec3 su = zr_v3_scale(zr_v3_madd(xyz(h.au), pt, -wu), 1.0 / w);
  zr_vec3 sv = zr_v3_scale(zr_v3_madd(xyz(h.av), pt, -wv), 1.0 / w);
  zr_vec3 suv = xyz(h.auv);
  suv = zr_v3_madd(suv, pt, -wuv);
  suv = zr_v3_madd(suv, sv, -wu);
  suv = zr_v3_madd(suv, su, -wv);
  out->s = pt;
  out->su = su;
  out->sv = sv;
  out->suv = zr_v3_scale(suv, 1.0 / w);
}

void zr__nurbs_transform(zr__nurbs *s, const double m[4][4]) {
  for (int i = 0; i < s->nu; i++) {
    for (int j = 0; j < s->nv; j++) {
      double *cw = s->cw[i][j];
      double r[3];
      /* M (w P) + w t: the affine map applied to the weighted point. */
      for (int k = 0; k < 3; k++)
        r[k] = m[k][0] * cw[0] + m[k][1] * cw[1] + m[k][2] * cw[2] +
               m[k][3] * cw[3];
      memcpy(cw, r, sizeof r);
    }
  }
}

/* The clamped knot vector 0,0,0, 1/2,1/2, 1,1,1 of two quadratic arcs,
   or with four arcs the nine-point circle's quarters. */
static void arc_knots(double *knots, int arcs) {
  int k = 0;
  for (int i = 0; i < 3; i++)
    knots[k++] = 0.0;
  for (int a = 1; a < arcs; a++) {
    knots[k++] = (double)a / arcs;
    knots[k++] = (double)a / arcs;
  }
  for (int i = 0; i < 3; i++)
    knots[k++] = 1.0;
}

void zr__nurbs_profile_line(zr__nurbs_profile *c, double r0, double h0,
                            double r1, double h1) {
  memset(c, 0, sizeof *c);
  c->degree = 1;
  c->n_cp = 2;
  c->knots[0] = c->knots[1] = 0.0;
  c->knots[2] = c->knots[3] = 1.0;
  c->r[0] = r0;
  c->h[0] = h0;
  c->r[1] = r1;
  c->h[1] = h1;
  c->w[0] = c->w[1] = 1.0;
}

void zr__nurbs_profile_half_circle(zr__nurbs_profile *c, double rad) {
  /* Two quarter arcs: corner control points carry weight cos(45 deg). */
  static const double r[5] = {0, 1, 1, 1, 0};
  static const double h[5] = {-1, -1, 0, 1, 1};
  memset(c, 0, sizeof *c);
  c->degree = 2;
  c->n_cp = 5;
  arc_knots(c->knots, 2);
  for (int i = 0; i < 5; i++) {
    c->r[i] = rad * r[i];
    c->h[i] = rad * h[i];
    c->w[i] = (i % 2) ? M_SQRT1_2 : 1.0;
  }
}

void zr__nurbs_profile_circle(zr__nurbs_profile *c, double centre,
                              double rad) {
  /* Four quarter arcs, corners on the circumscribed square. */
  static const double r[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  static const double h[9] = {-1, -1, 0, 1, 1, 1, 0, -1, -1};
  memset(c, 0, sizeof *c);
  c->degree = 2;
  c->n_cp = 9;
  arc_knots(c->knots, 4);
  for (int i = 0; i < 9; i++) {
    c->r[i] = centre + rad * r[i];
    c->h[i] = rad * h[i];
    c->w[i] = (i % 2) ? M_SQRT1_2 : 1.0;
  }
}

void zr__nurbs_revolve(zr__nurbs *s, const zr__nurbs_profile *c) {
  /* The nine-point circle from +x towards -z: its corner points lie on
     the circumscribed square and carry weight sqrt(2)/2. */
  static const double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1};
  static const double cz[9] = {0, -1, -1, -1, 0, 1, 1, 1, 0};
  memset(s, 0, sizeof *s);
  s->p = 2;
  s->q = c->degree;
  s->nu = 9;
  s->nv = c->n_cp;
  arc_knots(s->ku, 4);
  memcpy(s->kv, c->knots, sizeof s->kv);
  for (int i = 0; i < 9; i++) {
    double wi = (i % 2) ? M_SQRT1_2 : 1.0;
    for (int j = 0; j < c->n_cp; j++) {
      double w = wi * c->w[j];
      s->cw[i][j][0] = w * c->r[j] * cx[i];
      s->cw[i][j][1] = w * c->h[j];
      s->cw[i][j][2] = w * c->r[j] * cz[i];
      s->cw[i][j][3] = w;
    }
  }
}
