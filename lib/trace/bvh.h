/*
 * bvh.h - the tracer's bounding volume hierarchy over a scene's
 * primitives (surface area heuristic), with unbounded primitives such as
 * planes kept in a separate list tested on every ray.
 */
#ifndef ZR_TRACE_BVH_H
#define ZR_TRACE_BVH_H

#include "scene/scene.h"

struct zr_bvh;

/* Builds scene->bvh from scene->primitives. */
zr_status zr__bvh_build(zr_scene *scene, zr_context *ctx);
void zr__bvh_free(struct zr_bvh *bvh);

#endif /* ZR_TRACE_BVH_H */
