/*
 * obj_text.h - POV-Ray's text object: TrueType glyph outlines extruded
 * from z = 0 to z = thickness, traced exactly (lib/trace/obj_text.c).
 */
#ifndef ZR_TRACE_OBJ_TEXT_H
#define ZR_TRACE_OBJ_TEXT_H

#include <stdbool.h>

#include "scene/scene.h"
#include "scene/shapes.h"
#include "trace/obj_mesh.h"

/* The nearest two crossings with tmin < t < tmax, nearest first, in the
   text's own coordinates (texture always -1). */
int zr__text_crossings(const struct zr_text *text, zr_vec3 org,
                       zr_vec3 dir, double tmin, double tmax,
                       zr_mesh_crossing out[2]);

/* Whether p lies inside a glyph's extrusion (non-zero winding, the
   TrueType fill rule). */
bool zr__text_inside(const struct zr_text *text, zr_vec3 p);

#endif /* ZR_TRACE_OBJ_TEXT_H */
