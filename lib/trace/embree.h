/*
 * embree.h - the optional Embree 3 backend for triangle meshes
 * (configure --with-embree; lib/trace/embree.c says how it works).
 * Without it these calls are inline no-ops and every mesh keeps its
 * own hierarchy (lib/trace/obj_mesh.c).
 */
#ifndef ZR_TRACE_EMBREE_H
#define ZR_TRACE_EMBREE_H

#include "config.h"

#include "core/context.h"
#include "scene/scene.h"
#include "scene/shapes.h"
#include "trace/obj_mesh.h"

#ifdef ZR_HAVE_EMBREE

/*
 * Gives every mesh among scene's primitives (CSG parts included) an
 * Embree scene (mesh->accel) when ctx asks for that backend
 * (zr_context_set_accel), owned by scene->embree.  A mesh whose
 * vertices do not fit in single precision keeps its own hierarchy.
 * Errors from Embree are reported through ctx as a warning, and the
 * meshes then keep their own hierarchy too.
 */
zr_status zr__embree_attach(zr_scene *scene, zr_context *ctx);

/*
 * The nearest crossing of mesh m with org + t dir, tmin < t <
 * tmax, as zr__mesh_nearest finds it (least t, then least face), among
 * the triangles Embree names: 1 with *out, 0 for none, -1 for a ray
 * Embree cannot take (a negative tmin, coordinates beyond single
 * precision), which the caller searches with the mesh's hierarchy.
 */
int zr__embree_nearest(const struct zr_mesh *m, zr_vec3 org, zr_vec3 dir,
                       double tmin, double tmax, zr_mesh_raw_hit *out);

/* The nearest two crossings in (tmin, tmax), nearest first, as
   zr__mesh_crossings finds them, among the triangles Embree names: how
   many, or -1 as above. */
int zr__embree_crossings(const struct zr_mesh *m, zr_vec3 org, zr_vec3 dir,
                         double tmin, double tmax, zr_mesh_raw_hit out[2]);

#else

static inline zr_status zr__embree_attach(zr_scene *scene, zr_context *ctx) {
  (void)scene;
  (void)ctx;
  return ZR_OK;
}

static inline int zr__embree_nearest(const struct zr_mesh *m, zr_vec3 org,
                                     zr_vec3 dir, double tmin, double tmax,
                                     zr_mesh_raw_hit *out) {
  (void)m, (void)org, (void)dir, (void)tmin, (void)tmax, (void)out;
  return -1;
}

static inline int zr__embree_crossings(const struct zr_mesh *m,
                                       zr_vec3 org, zr_vec3 dir,
                                       double tmin, double tmax,
                                       zr_mesh_raw_hit out[2]) {
  (void)m, (void)org, (void)dir, (void)tmin, (void)tmax, (void)out;
  return -1;
}

#endif /* ZR_HAVE_EMBREE */

#endif /* ZR_TRACE_EMBREE_H */
