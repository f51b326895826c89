/*
 * surface.h - exact parametric surfaces S(u,v), (u,v) in [0,1]^2, for
 * hierarchical radiosity: a point, the unit outward normal and the area
 * element |S_u x S_v| of every object that has area, in world space.
 *
 * Planar faces are planar patches (parallelograms for box faces, a
 * collapsed square for triangles); discs and annuli, spheres, open
 * cylinder and cone sides are rational quadratic NURBS (see nurbs.h).
 * An object's transform is applied when the surface is built, so
 * evaluation never transforms.  A surface is plain data (no allocation)
 * and read-only once built: threads may share it.
 */
#ifndef ZR_RADIOSITY_SURFACE_H
#define ZR_RADIOSITY_SURFACE_H

#include <stdbool.h>
#include <stddef.h>

#include "core/context.h"
#include "core/transform.h"
#include "core/vec.h"
#include "radiosity/nurbs.h"
#include "radiosity/quadrature.h"

typedef enum zr__surface_kind {
  ZR__SURFACE_PARALLELOGRAM = 0, /* origin + u e1 + v e2 */
  ZR__SURFACE_TRIANGLE,          /* (1-u) p0 + u ((1-v) p1 + v p2) */
  ZR__SURFACE_DISC,              /* NURBS, planar; v = 0 on the rim */
  ZR__SURFACE_SPHERE,            /* NURBS; v = 0 at the -y pole */
  ZR__SURFACE_CYLINDER,          /* NURBS; v = 0 at the base */
  ZR__SURFACE_CONE,              /* NURBS; v = 0 at the base */
  ZR__SURFACE_TORUS,             /* NURBS; v = 0 under the tube */
  ZR__SURFACE_MESH               /* triangles in quadtree slots, below */
} zr__surface_kind;

struct zr_mesh; /* lib/trace/obj_mesh.h */

typedef struct zr__surface {
  zr__surface_kind kind;
  bool planar;
  /* +1 when S_u x S_v points outwards, -1 when a mirroring transform
     turned it inwards. */
  double orient;
  zr_vec3 plane_normal; /* planar kinds: the unit outward normal */
  zr_vec3 p[3];         /* parallelogram: origin, e1, e2; triangle: p0..p2 */
  zr__nurbs nurbs;      /* curved kinds and discs */
  /* Surfaces of revolution, for zr__surface_locate: world to the model
     frame (axis +y, the centre or base at the origin) and the profile's
     radius at v = 0 (r0) and v = 1 (r1) and height at v = 1 (the
     sphere's radius is r0; a torus keeps its major and minor radii
     in r0 and r1). */
  double to_model[4][4];
  double r0, r1, height;
  /* A mesh (mesh, mesh2, smooth_triangle, height_field): its faces, in
     the order of the mesh's own BVH, fill the 4^slot_depth cells of
     the quadtree's level slot_depth one each, in quadtree order (child
     k of a cell holds the k-th quarter of its faces), so every cell
     above that level is a cluster of faces that lie close together and
     every cell at or below it is part of one triangle, parametrised as
     a triangle surface in its slot.  Points and normals are the flat
     triangles' (smooth normals are the tracer's), mapped by xf. */
  const struct zr_mesh *mesh;
  const zr_transform *mesh_xf;
  size_t n_faces;
  int slot_depth;
  /* The faces in world space and the aggregates of every cluster,
     made once by zr__surface_mesh_cache (NULL: computed when asked);
     owned by whoever made it, zr__surface_mesh_cache_free frees it. */
  struct zr__mesh_cache *cache;
} zr__surface;

/* One evaluated point. */
typedef struct zr__surface_point {
  zr_vec3 p;  /* world position */
  zr_vec3 n;  /* unit outward normal (the limit where S_u x S_v is 0) */
  double da;  /* area element |S_u x S_v| */
} zr__surface_point;

/*
 * Constructors.  xf is the object's transform (NULL for none); ctx and
 * where (both may be NULL) receive the message of a ZR_EINVAL for
 * degenerate input: a zero radius or edge, coincident points, a singular
 * transform.  Radii and points follow POV-Ray's object syntax.
 */
zr_status zr__surface_parallelogram(zr__surface *s, zr_vec3 origin,
                                    zr_vec3 e1, zr_vec3 e2,
                                    const zr_transform *xf, zr_context *ctx,
                                    const zr_diag_place *where);
zr_status zr__surface_triangle(zr__surface *s, zr_vec3 p0, zr_vec3 p1,
                               zr_vec3 p2, const zr_transform *xf,
                               zr_context *ctx, const zr_diag_place *where);
/* The six faces -x, +x, -y, +y, -z, +z of a box, normals outwards. */
zr_status zr__surface_box_faces(zr__surface faces[6], zr_vec3 corner1,
                                zr_vec3 corner2, const zr_transform *xf,
                                zr_context *ctx, const zr_diag_place *where);
/*
 * An infinite plane (POV-Ray's normal and distance, then the object's
 * transform) clipped to the world box [lo, hi], the scene's bounds, as a
 * parallelogram facing along the plane's normal.  It is exactly the
 * plane's section of the box when the plane is perpendicular to an axis,
 * the usual floor or wall; otherwise it is a rectangle in the plane
 * that covers the section, and *covers_more (may be NULL) is set so
 * the caller trims what lies outside the bounds.
 */
zr_status zr__surface_plane_in_box(zr__surface *s, zr_vec3 normal,
                                   double distance, zr_vec3 lo, zr_vec3 hi,
                                   const zr_transform *xf, bool *covers_more,
                                   zr_context *ctx,
                                   const zr_diag_place *where);
/*
 * The same plane's exact section of [lo, hi]: the parallelogram above
 * when the plane is perpendicular to an axis, else the convex polygon
 * where it crosses the box as a fan of (at most four) triangles facing
 * along the plane's normal.  Returns how many surfaces it wrote to out,
 * -1 (with a message) when the plane misses the box.
 */
int zr__surface_plane_section(zr__surface out[4], zr_vec3 normal,
                              double distance, zr_vec3 lo, zr_vec3 hi,
                              const zr_transform *xf, zr_context *ctx,
                              const zr_diag_place *where);
/* A disc (hole_radius 0) or annulus facing along normal. */
zr_status zr__surface_disc(zr__surface *s, zr_vec3 centre, zr_vec3 normal,
                           double radius, double hole_radius,
                           const zr_transform *xf, zr_context *ctx,
                           const zr_diag_place *where);
zr_status zr__surface_sphere(zr__surface *s, zr_vec3 centre, double radius,
                             const zr_transform *xf, zr_context *ctx,
                             const zr_diag_place *where);
/* POV-Ray's torus about the y axis: the tube's circle (radius minor, its
   centre major from the axis) turned about y. */
zr_status zr__surface_torus(zr__surface *s, double major, double minor,
                            const zr_transform *xf, zr_context *ctx,
                            const zr_diag_place *where);
/* The open side of a cylinder (caps are discs of their own). */
zr_status zr__surface_cylinder(zr__surface *s, zr_vec3 base, zr_vec3 cap,
                               double radius, const zr_transform *xf,
                               zr_context *ctx, const zr_diag_place *where);
/* The open side of a cone; either radius may be 0 (an apex). */
zr_status zr__surface_cone(zr__surface *s, zr_vec3 base, double base_radius,
                           zr_vec3 cap, double cap_radius,
                           const zr_transform *xf, zr_context *ctx,
                           const zr_diag_place *where);

/* The faces of mesh (in its own coordinates, then xf) as one surface;
   ZR_EINVAL for a mesh with no faces or more than 4^12. */
zr_status zr__surface_mesh(zr__surface *s, const struct zr_mesh *mesh,
                           const zr_transform *xf, zr_context *ctx,
                           const zr_diag_place *where);
/* Whether the parameter rectangle cell of a mesh surface is a cluster
   (it spans more than one face's slot); [*f0, *f1) are the faces in
   it either way.  False for every other kind. */
bool zr__surface_mesh_cluster(const zr__surface *s, const double cell[4],
                              size_t *f0, size_t *f1);
/* Face f of a mesh surface as a triangle surface (its plane_normal is
   0 when the face has no area); false for a face with no area.  Only
   the fields a triangle uses are set. */
bool zr__surface_mesh_face(const zr__surface *s, size_t f, zr__surface *tri);
/* A face in world space, for loops over many faces. */
typedef struct zr__mesh_face {
  zr_vec3 p[3];
  zr_vec3 n; /* unit outward normal */
  double area;
} zr__mesh_face;
/* Face f of a mesh surface; false for a face with no area. */
bool zr__surface_mesh_tri(const zr__surface *s, size_t f, zr__mesh_face *out);
/*
 * Makes s's cache: the world-space faces and, for each level of the
 * quadtree above the faces', the aggregate of each cluster, the same
 * values zr__surface_mesh_tri and zr__surface_mesh_aggregate compute
 * without it (so a solution is the same bytes with or without), but
 * each read once instead of at every node, link and sample (with 100k
 * faces the aggregates of large clusters were most of a solve).  *bytes
 * is its size.  ZR_ENOMEM on failure (s keeps no cache); a no-op for
 * other kinds.
 */
zr_status zr__surface_mesh_cache(zr__surface *s, size_t *bytes);
void zr__surface_mesh_cache_free(zr__surface *s);
/* The (u,v) of point p on face f of a mesh surface. */
void zr__surface_mesh_locate_face(const zr__surface *s, size_t f, zr_vec3 p,
                                  double *u, double *v);
/* A cluster's aggregate: area, area-weighted centroid and mean normal,
   and the largest angle between that normal and its faces' (pi when
   the normals cancel out). */
void zr__surface_mesh_aggregate(const zr__surface *s, size_t f0, size_t f1,
                                double *area, zr_vec3 *centre,
                                zr_vec3 *normal, double *spread);

/* S(u,v), the normal and the area element at (u,v) in [0,1]^2. */
void zr__surface_eval(const zr__surface *s, double u, double v,
                      zr__surface_point *out);

/* Receives one quadrature point and its weight (area it stands for). */
typedef void (*zr__surface_visit_fn)(const zr__surface_point *pt,
                                     double weight, void *user);

/*
 * Visits the Gauss points of the parameter rectangle [u0,u1] x [v0,v1]:
 * split first at the knot lines of a NURBS (where the area element has a
 * kink), then each piece into cells x cells sub-rectangles, each with
 * the product rule.  The weights sum to the rectangle's area.
 */
void zr__surface_quadrature(const zr__surface *s, double u0, double u1,
                            double v0, double v1, int cells,
                            const zr__gauss_rule *rule,
                            zr__surface_visit_fn visit, void *user);

/* The area of the parameter rectangle by zr__surface_quadrature. */
double zr__surface_area(const zr__surface *s, double u0, double u1,
                        double v0, double v1, int cells,
                        const zr__gauss_rule *rule);

/*
 * The (u,v) of a world point p of the surface, as a ray hit reports it,
 * so radiosity can be looked up in the quadtree cell that holds it.  For
 * a point off the surface it is the parameter of a nearby surface point
 * (the projection along the model's own coordinates); results lie in
 * [0,1].  Where u is not defined (poles, apex, a disc's centre) u = 0.
 */
void zr__surface_locate(const zr__surface *s, zr_vec3 p, double *u,
                        double *v);

/*
 * Whether p lies inside the solid that s bounds on its own: 1 inside,
 * 0 outside, -1 when s is not a closed surface (only a sphere and a
 * torus are).  A point outside a closed surface sees only its outward
 * side, a point inside only its inward side: a segment from a point of
 * s that leaves it on the other side crosses s again.
 */
int zr__surface_encloses(const zr__surface *s, zr_vec3 p);

/*
 * The boundary of the parameter rectangle as a world-space polygon, in
 * the order (u0,v0), (u1,v0), (u1,v1), (u0,v1).  Edges that are straight
 * on the surface give their two corners; curved edges are split into
 * segs equal parameter steps.  Points repeated where an edge collapses
 * (a triangle's apex, a pole) are dropped.  Returns the number of points
 * written, at most max; it is exact for the planar straight-edged kinds
 * and an inscribed polygon otherwise.
 */
size_t zr__surface_patch_polygon(const zr__surface *s, double u0, double u1,
                                 double v0, double v1, int segs,
                                 zr_vec3 *out, size_t max);

#endif /* ZR_RADIOSITY_SURFACE_H */
