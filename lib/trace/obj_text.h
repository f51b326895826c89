/*
 * obj_text.h - POV-Ray's text object: TrueType glyph outlines extruded
 * from z = 0 to z = thickness, traced exactly (lib/trace/obj_text.c).
 */
#ifndef ZR_TRACE_OBJ_TEXT_H
#define ZR_TRACE_OBJ_TEXT_H

#include <stdbool.h>

#include "scene/scene.h"
#include "trace/obj_mesh.h"

/* One piece of an outline in text coordinates: a quadratic Bezier curve
   p0 p1 p2, or the line p0 p2 when line is set. */
typedef struct zr_text_segment {
  double p0[2], p1[2], p2[2];
  bool line;
} zr_text_segment;

/* A placed glyph: segments[first .. first + n) and their 2D box. */
typedef struct zr_text_glyph {
  size_t first, n;
  double lo[2], hi[2];
} zr_text_glyph;

struct zr_text {
  zr_text_segment *segments;
  size_t n_segments;
  zr_text_glyph *glyphs;
  size_t n_glyphs;
  double thickness;
  zr_vec3 lo, hi; /* the box of every glyph, empty when none */
};

/* The nearest two crossings with tmin < t < tmax, nearest first, in the
   text's own coordinates (texture always -1). */
int zr__text_crossings(const struct zr_text *text, zr_vec3 org,
                       zr_vec3 dir, double tmin, double tmax,
                       zr_mesh_crossing out[2]);

/* Whether p lies inside a glyph's extrusion (non-zero winding, the
   TrueType fill rule). */
bool zr__text_inside(const struct zr_text *text, zr_vec3 p);

#endif /* ZR_TRACE_OBJ_TEXT_H */
