/*
 * obj_mesh.h - triangle meshes (mesh, mesh2, smooth_triangle): building
 * a mesh's own bounding volume hierarchy, and the ray and inside tests
 * the tracer dispatches to (lib/trace/intersect.c).  The mesh's data is
 * the scene model's (lib/scene/shapes.h).
 */
#ifndef ZR_TRACE_OBJ_MESH_H
#define ZR_TRACE_OBJ_MESH_H

#include <stdbool.h>
#include <stdint.h>

#include "scene/scene.h"
#include "scene/shapes.h"

/* One crossing of a ray with a mesh, in the mesh's own coordinates. */
typedef struct zr_mesh_crossing {
  double t;
  zr_vec3 normal;  /* any length, smooth when the face has normals */
  int32_t texture; /* index into the texture list, -1 for none */
  double u, v;     /* surface coordinates ("UV Mapping"); meshes only */
  size_t face;     /* which face (radiosity looks its cell up by it) */
} zr_mesh_crossing;

/* A crossing with one face before its normal is made: t and the
   barycentric u, v of Moller and Trumbore's test. */
typedef struct zr_mesh_raw_hit {
  double t, u, v;
  size_t face;
} zr_mesh_raw_hit;

/* That test in double precision: true with t, u, v when the line org +
   t dir crosses face f (a row of the faces as the BVH ordered them). */
bool zr__mesh_face_hit(const struct zr_mesh *mesh, size_t f, zr_vec3 org,
                       zr_vec3 dir, double *t, double *u, double *v);

/* The barycentric u, v and the t at which the line crosses the plane of
   face f, computed as that test computes them, whether or not they lie
   in the triangle; false when the line is parallel to it. */
bool zr__mesh_face_plane(const struct zr_mesh *mesh, size_t f, zr_vec3 org,
                         zr_vec3 dir, double *t, double *u, double *v);

/* Builds the BVH (reordering the faces) and checks the indices; the
   first bad index is reported in *bad_face (status ZR_ESCENE).  Up to
   threads threads build it; the tree is the same for any number. */
zr_status zr__mesh_build(struct zr_mesh *mesh, zr_arena *arena,
                         int threads, size_t *bad_face);
/* The same with the members of a team (zr_context_set_team) while
   *team_on: each builds its share of a large mesh's subtrees and they
   exchange them, every member ending with the tree one process builds
   alone.  *team_on becomes false when the members parted (their meshes
   differ, or one failed): every member learns it in the same call, and
   none calls the team again in that parse (lib/sdl/directive.c). */
struct zr_team;
zr_status zr__mesh_build_team(struct zr_mesh *mesh, zr_arena *arena,
                              int threads, const struct zr_team *team,
                              bool *team_on, size_t *bad_face);

/* The nearest two crossings with tmin < t < tmax, nearest first. */
int zr__mesh_crossings(const struct zr_mesh *mesh, zr_vec3 org, zr_vec3 dir,
                       double tmin, double tmax, zr_mesh_crossing out[2]);
/* The first of those two alone (0 or 1 of them), found faster. */
int zr__mesh_nearest(const struct zr_mesh *mesh, zr_vec3 org, zr_vec3 dir,
                     double tmin, double tmax, zr_mesh_crossing *out);
/* The same for a mesh object without clipped_by, as zr__intersect_t's
   first hit (trace/intersect.h's zr_ray and zr_hit), and the crossing's
   normal in the mesh's own space, of any length, in *normal (not NULL):
   the search for the nearest surface makes the winner's world normal
   from it (zr__mesh_world_normal) rather than search the mesh again. */
struct zr_ray;
struct zr_hit;
int zr__mesh_nearest_t(const zr_object *o, const struct zr_ray *ray,
                       double tmin, double tmax, struct zr_hit *hit,
                       zr_vec3 *normal);

/* The world normal zr__intersect gives a crossing of mesh object o
   whose normal in the mesh's space is n: through o's transform,
   normalized, turned for inverse. */
zr_vec3 zr__mesh_world_normal(const zr_object *o, zr_vec3 n);

/* Any one crossing of a mesh object without clipped_by with
   tmin < t < tmax, the first its hierarchy meets (not the nearest), as
   zr__mesh_nearest_t reports one; 0 when there is none. */
int zr__mesh_any_t(const zr_object *o, const struct zr_ray *ray,
                   double tmin, double tmax, struct zr_hit *hit);

/* Whether p (mesh coordinates) is inside: an odd number of crossings
   along the inside vector.  False when the mesh has no inside_vector. */
bool zr__mesh_inside(const struct zr_mesh *mesh, zr_vec3 p);

/* The object a crossing with texture index k reports. */
static inline const zr_object *zr__mesh_hit_object(const zr_object *o,
                                                   int32_t k) {
  if (k < 0 || !o->u.mesh.textured)
    return o;
  return &o->u.mesh.textured[k];
}

#endif /* ZR_TRACE_OBJ_MESH_H */
