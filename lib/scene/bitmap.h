/*
 * bitmap.h - where a point falls on an image_map, bump_map or
 * material_map picture (the map types of "Bitmap Modifiers"), and what
 * bump maps and material maps make of it.
 */
#ifndef ZR_SCENE_BITMAP_H
#define ZR_SCENE_BITMAP_H

#include <stdbool.h>

#include "core/vec.h"
#include "image/image.h"
#include "scene/scene.h"

/* How a bump_map's or material_map's per-pixel number is found
   (zr_image_map.value_kind). */
enum {
  ZR_BITMAP_VALUE_ARRAY = 0, /* values[] (float pictures) */
  ZR_BITMAP_VALUE_INDEX,     /* the palette index */
  ZR_BITMAP_VALUE_GREY,      /* 0.297 r + 0.589 g + 0.114 b, by code_value */
  ZR_BITMAP_VALUE_RED,       /* the red sample on a 0 .. 255 scale */
  ZR_BITMAP_VALUE_CLEAR      /* 1 - alpha (image_pattern's use_alpha) */
};

/* The code of channel c (0 red, 1 green, 2 blue) of pixel i of a map
   whose picture is not floats. */
static inline unsigned zr__bitmap_code(const zr_image_map *im, size_t i,
                                       int c) {
  size_t k = 3 * i + (size_t)c;
  if (im->layout == ZR_LAYOUT_INDEX)
    return im->palette[3 * (size_t)im->indices[i] + (size_t)c];
  if (im->layout == ZR_LAYOUT_GREY)
    k = i;
  return im->maxval > 255 ? ((const unsigned short *)im->codes)[k]
                          : ((const unsigned char *)im->codes)[k];
}

/* The colour of pixel i of an image map (working space). */
static inline void zr__bitmap_rgb(const zr_image_map *im, size_t i,
                                  float rgb[3]) {
  if (im->pixels) {
    for (int c = 0; c < 3; c++)
      rgb[c] = im->pixels[3 * i + (size_t)c];
  } else if (im->layout == ZR_LAYOUT_GREY) {
    rgb[0] = rgb[1] = rgb[2] = im->table[zr__bitmap_code(im, i, 0)];
  } else {
    for (int c = 0; c < 3; c++)
      rgb[c] = im->table[zr__bitmap_code(im, i, c)];
  }
}

/* The point p of the map's own space in picture coordinates: *px from
   0 at the left edge to width at the right, *py from 0 at the top row
   to height at the bottom, each wrapped into the picture when the map
   repeats that way.  *repeat_x and *repeat_y say which ways it does.
   False when "once" leaves p off the picture. */
bool zr__bitmap_where(const zr_image_map *im, zr_vec3 p, double *px,
                      double *py, bool *repeat_x, bool *repeat_y);

/* The per-pixel number (value_kind) at picture coordinates px, py: the
   pixel's own without interpolation, else bilinear between pixel
   centres; wrapped or clamped at the edges as the flags say. */
double zr__bitmap_value(const zr_image_map *im, double px, double py,
                        bool repeat_x, bool repeat_y);

/* The shading normal a bump_map gives at a world point of a surface
   whose unit normal is n (nm->bump_map not NULL). */
zr_vec3 zr__bump_map_perturb(const zr_normal *nm, zr_vec3 world, zr_vec3 n);

/* image_pattern's value at p, the map's own space: the picture's grey
   there as a bump_map reads it (the file's numbers, decoded only when a
   gamma is given), 0 off a "once" picture. */
double zr__bitmap_pattern(const zr_image_map *im, zr_vec3 p);

/* The entry of a material_map's texture list (n entries, n >= 1) that
   the picture picks at p, the map's own space: its index modulo n, the
   first entry off a "once" picture. */
size_t zr__material_map_entry(const zr_image_map *im, zr_vec3 p, size_t n);

#endif /* ZR_SCENE_BITMAP_H */
