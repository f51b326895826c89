/*
 * formfactor.h - form factors for hierarchical radiosity, without
 * visibility (the solver multiplies by its visibility estimate).
 *
 * Sources are two-sided here: a polygon or patch transfers to a point
 * whichever way it faces, and the solver decides whether a one-sided
 * surface emits towards the receiver.  The receiver is one-sided: only
 * the half-space in front of its normal is seen.
 */
#ifndef ZR_RADIOSITY_FORMFACTOR_H
#define ZR_RADIOSITY_FORMFACTOR_H

#include <stddef.h>

#include "core/vec.h"
#include "radiosity/quadrature.h"
#include "radiosity/surface.h"

/*
 * The exact form factor from a differential area at p with unit normal n
 * to the planar polygon verts[0..nv-1] (any orientation, convex or not,
 * but simple), by Lambert's contour integral.  The part of the polygon
 * behind the tangent plane at p is clipped away first; a point in the
 * polygon's own plane gives 0.  Result in [0, 1]; 0 for nv < 3.
 */
double zr__ff_point_polygon(zr_vec3 p, zr_vec3 n, const zr_vec3 *verts,
                            size_t nv);

/* atan2(y, x) for y > 0 as the contour sum computes it (a reduction to
   |u| <= 1/16 and a series; within a few ulps of libm's). */
double zr__ff_edge_angle(double y, double x);

/*
 * A polygon's plane, found once (Newell's normal, on coordinates
 * relative to verts[0] over the polygon's size) for a polygon that many
 * points look at: zr__ff_point_polygon_pre(p, n, pl) is
 * zr__ff_point_polygon(p, n, verts, nv) bit for bit without finding it
 * again.  pl keeps the pointer verts, which must outlive it.
 */
typedef struct zr__ff_polygon {
  const zr_vec3 *verts;
  size_t nv;
  zr_vec3 normal; /* unit; zero for a degenerate polygon */
  double size;    /* largest distance from verts[0] to another vertex */
  double inv_size; /* 1 / size, as every point's in-plane test takes it */
} zr__ff_polygon;

void zr__ff_polygon_init(zr__ff_polygon *pl, const zr_vec3 *verts,
                         size_t nv);
double zr__ff_point_polygon_pre(zr_vec3 p, zr_vec3 n,
                                const zr__ff_polygon *pl);

/*
 * count factors at once: out[i] is the factor from p[i], n[i] to pl[i],
 * with the sign of zr__ff_point_polygon_sided, bit for bit as one at a
 * time gives it, and, with AVX, four at a time in less than twice the
 * time of one (formfactor.c, "many points and polygons at once").
 */
#define ZR__FF_LANES 4
void zr__ff_point_polygons(size_t count, const zr_vec3 *p, const zr_vec3 *n,
                           const zr__ff_polygon *const *pl, double sign,
                           double *out);

/* One factor, the sum's sign as zr__ff_point_polygons takes it: 0 both
   sides of the polygon count (|sum|), +-1 only the side whose contour
   sum has that sign (sign * sum, clamped at 0). */
double zr__ff_point_polygon_sided(zr_vec3 p, zr_vec3 n,
                                  const zr__ff_polygon *pl, double sign);

/*
 * The form factor from a differential area at p, n to the parameter
 * rectangle [u0,u1] x [v0,v1] of src by the product Gauss rule of the
 * kernel cos_p cos_q / (pi r^2) dA_q (split at knot lines, see
 * zr__surface_quadrature): for curved patches, and valid when the patch
 * is small against its distance (it is not an exact factor for near or
 * touching patches, where the kernel is singular).
 */
double zr__ff_point_patch_quadrature(zr_vec3 p, zr_vec3 n,
                                     const zr__surface *src, double u0,
                                     double u1, double v0, double v1,
                                     const zr__gauss_rule *rule);

/*
 * The form factor from the receiver patch [u0,u1] x [v0,v1] of recv to
 * the polygon: the area average of the exact point-to-polygon factor,
 * sampled at the product Gauss points of rule (n x n points) on cells x
 * cells sub-rectangles of every knot span (zr__surface_quadrature).
 * F_recv->poly = (1/A) int F(dA -> poly) dA.
 */
double zr__ff_patch_polygon(const zr__surface *recv, double u0, double u1,
                            double v0, double v1, const zr_vec3 *verts,
                            size_t nv, int cells,
                            const zr__gauss_rule *rule);

/* The most points zr__ff_patch_patch takes on one curved edge. */
#define ZR__FF_MAX_SEGS 64

/*
 * The form factor from the cell [ru0,ru1] x [rv0,rv1] of recv to the cell
 * [su0,su1] x [sv0,sv1] of src, for a link.  The receiver's normals are
 * flipped when side < 0 (the inside of a closed surface).  The receiver
 * is integrated by zr__surface_quadrature (cells, rule); at each point
 * the source cell's boundary (zr__surface_patch_polygon, segs points per
 * curved edge, at most ZR__FF_MAX_SEGS) goes into the contour formula.
 * That is exact for straight-edged planar cells and, by Stokes' theorem,
 * exact up to the chords' O(segs^-2) for a curved cell that the receiver
 * points see one-to-one (no silhouette inside the cell).
 */
double zr__ff_patch_patch(const zr__surface *recv, const double rcell[4],
                          double side, const zr__surface *src,
                          const double scell[4], int segs, int cells,
                          const zr__gauss_rule *rule);

/*
 * zr__ff_patch_patch with only one side of the source counted: side
 * sside (+1 the outward side, -1 the inward one) where it faces a
 * receiver point, nothing where the other side does.  By Stokes'
 * theorem the signed contour sum is the projected solid angle of the
 * parts turned that way less that of the parts turned away, so a curved
 * cell that a receiver point sees from behind (the far side of a ball,
 * through the ball) gives 0, not its projected size, and one that the
 * ball's rim crosses is short by the sliver folded behind the rim.
 */
double zr__ff_patch_patch_sided(const zr__surface *recv,
                                const double rcell[4], double side,
                                const zr__surface *src, const double scell[4],
                                double sside, int segs, int cells,
                                const zr__gauss_rule *rule);

/*
 * Hanrahan, Salzman and Aupperle's cheap estimate of the form factor from
 * a receiver point x (normal nx) to a source of area area_y centred at y
 * (normal ny): the factor of a coaxial disc of that area, tilted by the
 * two cosines,
 *   F ~ area_y cos_x cos_y / (pi r^2 + area_y).
 * It never exceeds 1 and stays finite as r -> 0.  Cosines behind either
 * surface count as 0; the source is one-sided here, since the estimate
 * decides where links go.
 */
double zr__ff_oracle(zr_vec3 x, zr_vec3 nx, zr_vec3 y, zr_vec3 ny,
                     double area_y);

#endif /* ZR_RADIOSITY_FORMFACTOR_H */
