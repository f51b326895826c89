/*
 * shaft.h - whether every shadow ray from a point to an area light (or
 * to a group of area lights in one plane) is sure to meet nothing, by
 * one test of the pyramid they fill against the scene's hierarchy
 * (lib/trace/shaft.c).
 */
#ifndef ZR_TRACE_SHAFT_H
#define ZR_TRACE_SHAFT_H

#include <stdbool.h>

#include "scene/scene.h"
#include "trace/shade.h"

struct zr_light_shafts;

/* Builds scene->shafts from the scene's lights (after its BVH). */
zr_status zr__shafts_build(zr_scene *scene);
void zr__shafts_free(struct zr_light_shafts *shafts);

/*
 * What the shadow rays from lit_from toward the points of light's grid
 * (jitter included) can meet (zr_shaft_plan in lib/trace/shade.h):
 * nothing (n = 0: each would find the light unblocked); only the n
 * objects listed, each of which stops any ray that crosses it (so a
 * ray is blocked, visibility 0, exactly when it crosses one of them,
 * zr__shaft_blocks); or unknown (n = -1: trace the rays as usual).  The
 * light's group (the area lights in its plane) is tried first, its
 * plan kept for the group's next light from the same point; with own
 * the light's own shaft then narrows the list (or, without a group,
 * makes it).  Unknown for lights no shaft covers (not an area light,
 * parallel, cylinder, orient, projected_through) and whenever the
 * tests cannot tell.
 */
void zr__shaft_plan(const zr_tracer *tracer, const zr_light *light,
                    zr_vec3 lit_from, bool own, zr_shaft_plan *plan);

/* Whether the shadow ray from lit_from to target crosses an object of
   plan (n > 0): the shadow walk's answer for that ray, 0 or 1. */
bool zr__shaft_blocks(const zr_tracer *tracer, const zr_shaft_plan *plan,
                      zr_vec3 lit_from, zr_vec3 target);

#endif /* ZR_TRACE_SHAFT_H */
