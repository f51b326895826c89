/*
 * bitmap.h - where a point falls on an image_map, bump_map or
 * material_map picture (the map types of "Bitmap Modifiers"), and what
 * bump maps and material maps make of it.
 */
#ifndef ZR_SCENE_BITMAP_H
#define ZR_SCENE_BITMAP_H

#include <stdbool.h>

#include "core/vec.h"
#include "scene/scene.h"

/* The point p of the map's own space in picture coordinates: *px from
   0 at the left edge to width at the right, *py from 0 at the top row
   to height at the bottom, each wrapped into the picture when the map
   repeats that way.  *repeat_x and *repeat_y say which ways it does.
   False when "once" leaves p off the picture. */
bool zr__bitmap_where(const zr_image_map *im, zr_vec3 p, double *px,
                      double *py, bool *repeat_x, bool *repeat_y);

/* The per-pixel number (im->values) at picture coordinates px, py: the
   pixel's own without interpolation, else bilinear between pixel
   centres; wrapped or clamped at the edges as the flags say. */
double zr__bitmap_value(const zr_image_map *im, double px, double py,
                        bool repeat_x, bool repeat_y);

/* The shading normal a bump_map gives at a world point of a surface
   whose unit normal is n (nm->bump_map not NULL). */
zr_vec3 zr__bump_map_perturb(const zr_normal *nm, zr_vec3 world, zr_vec3 n);

/* The entry of a material_map's texture list (n entries, n >= 1) that
   the picture picks at p, the map's own space: its index modulo n, the
   first entry off a "once" picture. */
size_t zr__material_map_entry(const zr_image_map *im, zr_vec3 p, size_t n);

#endif /* ZR_SCENE_BITMAP_H */
