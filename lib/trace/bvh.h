/*
 * bvh.h - the tracer's bounding volume hierarchy over a scene's
 * primitives (surface area heuristic), with unbounded primitives such as
 * planes kept in a separate list tested on every ray.
 */
#ifndef ZR_TRACE_BVH_H
#define ZR_TRACE_BVH_H

#include <stdbool.h>
#include <stdint.h>

#include "scene/scene.h"
#include "trace/intersect.h"

struct zr_bvh;

/* Builds scene->bvh from scene->primitives. */
zr_status zr__bvh_build(zr_scene *scene, zr_context *ctx);
/* The same, taking the path the build takes when a box or centre
   holds a NaN (bvh.c, pick_min) whatever the boxes hold: for the test
   that both paths build the same tree. */
zr_status zr__bvh_build_nan_path(zr_scene *scene, zr_context *ctx);
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

/*
 * zr__bvh_all for a walk that stops at the first crossing of some
 * objects, those for which blocks(object, user) is true: a mesh such as
 * that reports one crossing, the first its hierarchy meets rather than
 * its nearest two, found without searching the rest of its triangles
 * (an any-hit test; shadow rays through an opaque mesh).  visit must
 * return false for that crossing, as it would for any other.
 */
typedef bool (*zr_blocks_fn)(const zr_object *object, void *user);
bool zr__bvh_all_blocked(const struct zr_bvh *bvh, const zr_ray *ray,
                         double tmin, double tmax, zr_crossing_fn visit,
                         zr_blocks_fn blocks, void *user);

/*
 * The crossings of one primitive o in (tmin, tmax), without normals, as
 * zr__intersect_t gives them (the same t, bit for bit, in the same
 * order), by the walks' own code: a plain sphere or plane without the
 * table call.  The shadow cache's retry of its last blocker uses it.
 */
int zr__bvh_crossings_t(const zr_object *o, const zr_ray *ray, double tmin,
                        double tmax, zr_hit hits[ZR_MAX_CROSSINGS]);

/*
 * The positions in scene->primitives of the primitives whose box holds
 * p, and of every unbounded one, ascending: the only ones that can hold
 * p inside (zr__inside), found in O(log n) rather than by asking all n.
 * Writes at most cap of them to out and returns how many there are
 * (more than cap: the caller asks again with room for them).
 */
size_t zr__bvh_point_candidates(const struct zr_bvh *bvh, zr_vec3 p,
                                uint32_t *out, size_t cap);

/*
 * Whether a region of space is clear of every primitive, as far as the
 * two tests tell: the walk opens each box of the hierarchy (a node's or
 * a leaf's, single precision rounded outward, so holding its
 * primitives' boxes) for which meets(lo, hi, user) is true, and asks
 * clear(object, user) of every primitive in the leaves opened and of
 * every unbounded one.  Returns false at the first primitive that clear
 * does not clear.  meets may say true of a box the region misses, never
 * false of one it meets (the area light shafts of lib/trace/shaft.c).
 */
typedef bool (*zr_region_box_fn)(const double lo[3], const double hi[3],
                                 void *user);
typedef bool (*zr_region_prim_fn)(const zr_object *object, void *user);
bool zr__bvh_region_clear(const struct zr_bvh *bvh, zr_region_box_fn meets,
                          zr_region_prim_fn clear, void *user);

/*
 * The sweep of the binned surface area heuristic (Wald 2007), shared by
 * this hierarchy and each mesh's (obj_mesh.c).  A node's primitives are
 * put in ZR_SAH_BINS bins along one axis by their centres; a bin holds
 * their count and the box of their boxes.  Returns the k, 1 to
 * ZR_SAH_BINS - 1, for which bins [0, k) going left and the rest right
 * costs least, A_left N_left + A_right N_right (areas of the two sides'
 * boxes, the expected number of intersection tests for a ray that
 * meets the node), with that cost in *cost; -1 when every split leaves
 * a side empty.  n is the node's number of primitives.
 */
enum { ZR_SAH_BINS = 16 };
typedef struct zr_sah_bin {
  double lo[3], hi[3];
  size_t count;
} zr_sah_bin;
int zr__sah_sweep(const zr_sah_bin bins[ZR_SAH_BINS], size_t n,
                  double *cost);

/* Statistics for tests and the benchmark note. */
typedef struct zr_bvh_info {
  size_t nodes;
  size_t leaves;
  size_t bounded;
  size_t unbounded;
  int depth;
  /* A digest of the primitives' order in the leaves, the node and leaf
     counts and the depth: the same tree, the same digest (tests). */
  uint64_t order_digest;
  /* A digest of the wide nodes' bytes: the same boxes bit for bit. */
  uint64_t node_digest;
} zr_bvh_info;
void zr__bvh_get_info(const struct zr_bvh *bvh, zr_bvh_info *info);

/*
 * Whether any primitive crosses the segment ray->origin + t ray->dir,
 * tmin < t < tmax: the answer of a zr__bvh_all walk whose visit stops
 * at the first crossing (the same boxes opened, the same crossings
 * found, bit for bit), without making the crossings.  Triangles,
 * polygons, boxes, planes and spheres without clipped_by are asked
 * whether a crossing lies in the interval by their own arithmetic
 * (transformed or not); every other primitive through zr__intersect_t.
 * Radiosity's visibility rays ask it (lib/radiosity).
 *
 * hint (NULL: none) remembers where the last blocker was found: its
 * leaf is searched first, so a run of rays that one surface blocks
 * (the rays of one point to one source) finds it at once.  A leaf is
 * searched only when the walk would open it too (its box and hence
 * every box above it met), so the answer does not depend on the hint.
 * Start a hint zeroed (zr_bvh_hint h = {0}); one hint serves one
 * thread, and any number of walks of the same hierarchy.
 */
typedef struct zr_bvh_hint {
  uint64_t where; /* 0: none; else 1 + the leaf's code (bvh.c) */
} zr_bvh_hint;
bool zr__bvh_occluded(const struct zr_bvh *bvh, const zr_ray *ray,
                      double tmin, double tmax, zr_bvh_hint *hint);

#endif /* ZR_TRACE_BVH_H */
