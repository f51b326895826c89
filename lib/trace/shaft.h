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
 * True when no shadow ray from lit_from toward any point of light's
 * grid (jitter included) can cross a surface that casts shadows, so
 * each would find the light unblocked: the light's group (the area
 * lights in its plane) is tried first, its answer kept for the next
 * light from the same point, then, when own is set, the light alone.
 * False for lights no shaft covers (not an area light, parallel,
 * cylinder, orient, projected_through) and whenever the test cannot
 * tell.
 */
bool zr__shaft_clear(const zr_tracer *tracer, const zr_light *light,
                     zr_vec3 lit_from, bool own);

#endif /* ZR_TRACE_SHAFT_H */
