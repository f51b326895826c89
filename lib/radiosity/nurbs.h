/*
 * nurbs.h - small rational B-spline (NURBS) curves and surfaces, enough
 * for exact conics: the circle, and surfaces of revolution built from it
 * (sphere, cylinder and cone sides, discs and annuli).
 *
 * Sizes are fixed so a surface is plain data without allocation: the
 * nine-point circle (Piegl & Tiller, "The NURBS Book", 2nd ed., section
 * 7.5) is the widest net we build, and degree 2 is all a conic needs.
 */
#ifndef ZR_RADIOSITY_NURBS_H
#define ZR_RADIOSITY_NURBS_H

#include "core/vec.h"

#define ZR__NURBS_MAX_DEGREE 3
#define ZR__NURBS_MAX_CP 9
#define ZR__NURBS_MAX_KNOTS (ZR__NURBS_MAX_CP + ZR__NURBS_MAX_DEGREE + 1)

/*
 * A planar NURBS curve in the (r, h) half-plane: the profile that a
 * surface of revolution turns about the h axis.
 */
typedef struct zr__nurbs_profile {
  int degree;
  int n_cp;
  double knots[ZR__NURBS_MAX_KNOTS]; /* n_cp + degree + 1 of them */
  double r[ZR__NURBS_MAX_CP];        /* distance from the axis */
  double h[ZR__NURBS_MAX_CP];        /* height along the axis */
  double w[ZR__NURBS_MAX_CP];        /* weights, positive */
} zr__nurbs_profile;

/*
 * A tensor-product NURBS surface over [0,1]^2.  Control points are kept
 * homogeneous, (w x, w y, w z, w), so an affine map is applied to them
 * linearly and evaluation needs no division until the end.
 */
typedef struct zr__nurbs {
  int p, q;   /* degrees in u and in v */
  int nu, nv; /* control points along u and along v */
  double ku[ZR__NURBS_MAX_KNOTS];
  double kv[ZR__NURBS_MAX_KNOTS];
  double cw[ZR__NURBS_MAX_CP][ZR__NURBS_MAX_CP][4]; /* [i in u][j in v] */
} zr__nurbs;

/* A point of a surface with its first and mixed derivatives. */
typedef struct zr__nurbs_derivs {
  zr_vec3 s;       /* S(u,v) */
  zr_vec3 su, sv;  /* dS/du, dS/dv */
  zr_vec3 suv;     /* d2S/dudv, which gives the normal where S_u vanishes */
} zr__nurbs_derivs;

/*
 * The index k of the knot span [knots[k], knots[k+1]) that holds t, for a
 * curve of n_cp control points and the given degree; t == 1 (the end of
 * the clamped knot vector) belongs to the last non-empty span.
 */
int zr__nurbs_find_span(int n_cp, int degree, const double *knots, double t);

/*
 * The degree + 1 B-spline basis functions that are non-zero on span k at
 * t, in n[0..degree], and their first derivatives in dn[0..degree]
 * (Cox-de Boor recurrence, "The NURBS Book" eq. 2.5 and 2.9).
 */
void zr__nurbs_basis(int k, double t, int degree, const double *knots,
                     double *n, double *dn);

/* Evaluates the surface at (u,v) in [0,1]^2. */
void zr__nurbs_eval(const zr__nurbs *s, double u, double v,
                    zr__nurbs_derivs *out);

/* Applies the affine map m (object to world, row-major 4x4) to s. */
void zr__nurbs_transform(zr__nurbs *s, const double m[4][4]);

/* Profiles in the (r, h) half-plane. */
void zr__nurbs_profile_line(zr__nurbs_profile *c, double r0, double h0,
                            double r1, double h1);
/* The half circle of radius rad from (0, -rad) through (rad, 0) to
   (0, rad): two rational quarter arcs. */
void zr__nurbs_profile_half_circle(zr__nurbs_profile *c, double rad);
/* The whole circle of radius rad about (r, h) = (centre, 0), from its
   lowest point counter-clockwise (outwards first): a torus's tube. */
void zr__nurbs_profile_circle(zr__nurbs_profile *c, double centre,
                              double rad);

/*
 * The surface swept by turning profile c once about the y axis (section
 * 8.5 of "The NURBS Book"): u goes round the nine-point circle, starting
 * on +x and turning towards -z, v runs along the profile.  With a profile
 * that climbs in h at positive r, S_u x S_v points away from the axis.
 */
void zr__nurbs_revolve(zr__nurbs *s, const zr__nurbs_profile *c);

#endif /* ZR_RADIOSITY_NURBS_H */
