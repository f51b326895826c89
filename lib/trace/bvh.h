/*
 * bvh.h - the tracer's bounding volume hierarchy over a scene's
 * primitives (surface area heuristic), with unbounded primitives such as
 * planes kept in a separate list tested on every ray.
 */
#ifndef ZR_TRACE_BVH_H
#define ZR_TRACE_BVH_H

#include <stdbool.h>

#include "scene/scene.h"
#include "trace/intersect.h"

struct zr_bvh;

/* Builds scene->bvh from scene->primitives. */
zr_status zr__bvh_build(zr_scene *scene, zr_context *ctx);
void zr__bvh_free(struct zr_bvh *bvh);

/*
 * The nearest crossing of ray with any primitive for tmin < t < tmax.
 * Returns false when there is none.  A NULL bvh (an empty scene) has no
 * crossings.
 */
bool zr__bvh_nearest(const struct zr_bvh *bvh, const zr_ray *ray,
                     double tmin, double tmax, zr_hit *hit);

/*
 * Calls visit for every crossing with tmin < t < tmax, in no particular
 * order, until visit returns false (then this returns false too).  The
 * crossings carry t and the object but no normal (it is left zero).  Used
 * by shadow rays, which must see every surface between a point and a
 * light to attenuate through transparent ones.
 */
typedef bool (*zr_crossing_fn)(const zr_hit *hit, void *user);
bool zr__bvh_all(const struct zr_bvh *bvh, const zr_ray *ray, double tmin,
                 double tmax, zr_crossing_fn visit, void *user);

/* Statistics for tests and the benchmark note. */
typedef struct zr_bvh_info {
  size_t nodes;
  size_t leaves;
  size_t bounded;
  size_t unbounded;
  int depth;
} zr_bvh_info;
void zr__bvh_get_info(const struct zr_bvh *bvh, zr_bvh_info *info);

#endif /* ZR_TRACE_BVH_H */
