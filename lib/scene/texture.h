/*
 * texture.h - pigments and normals evaluated at a surface point: colour
 * maps, colour lists, image maps and pattern normals.
 */
#ifndef ZR_SCENE_TEXTURE_H
#define ZR_SCENE_TEXTURE_H

#include "core/vec.h"
#include "scene/scene.h"

/* The colour of map at value v (entries ascending, n >= 1). */
zr_colour zr__colour_map_eval(const zr_colour_map *map, double v);

/* The map a pattern without color_map uses: black at 0 to white at 1,
   which is what POV-Ray renders for gradient (measured). */
const zr_colour_map *zr__default_colour_map(void);

/* Makes pg a pattern pigment of kind with POV-Ray's defaults for the
   kind's parameters, including the default colours of checker, hexagon
   and brick; pg's pattern modifiers stay (zr__pattern_set_kind). */
void zr__pigment_set_pattern(zr_pigment *pg, zr_pattern_kind kind);

/* The colour of an image map at p in its own (pattern) space. */
zr_colour zr__image_map_eval(const zr_image_map *im, zr_vec3 p);

/* The pigment's colour at a point in world space. */
zr_colour zr__pigment_eval(const zr_pigment *pg, zr_vec3 world);
/* The same at a surface point with unit normal n (world space), which
   the slope pattern needs; zr__pigment_eval passes a zero normal. */
zr_colour zr__pigment_eval_n(const zr_pigment *pg, zr_vec3 world,
                             zr_vec3 n);

/*
 * The shading normal at a world point of a surface whose unit normal is
 * n: n tilted against the pattern's slope there (its gradient in the
 * surface's tangent plane) times the bump size, then normalised.
 */
zr_vec3 zr__normal_perturb(const zr_normal *nm, zr_vec3 world, zr_vec3 n);

/* Where value v falls in map m (n >= 1): entry *i with weight 1 - *t and
   entry *i + 1 with weight *t (*t is 0 at or beyond either end, and for
   block patterns, whose value is the entry's index). */
void zr__map_find(const zr_map *m, double v, bool block, size_t *i,
                  double *t);

/* A slope_map's height at pattern value v. */
double zr__slope_map_eval(const zr_map *m, double v);

/* For a patterned texture, the texture its pattern picks at a world
   point and, when the point lies between two entries, the second one in
   *second with weight *t (else NULL and 0); a plain texture itself. */
const zr_texture *zr__texture_pick(const zr_texture *tx, zr_vec3 world,
                                   const zr_texture **second, double *t);
/* The same at a surface point with unit normal n (world space). */
const zr_texture *zr__texture_pick_n(const zr_texture *tx, zr_vec3 world,
                                     zr_vec3 n, const zr_texture **second,
                                     double *t);

/* The light a texture, all its layers together, lets through at a
   world point: the product of each layer's f * C + t. */
zr_rgb zr__texture_see_through(const zr_texture *tx, zr_vec3 world);
/* The same for one layer alone (a patterned layer blends its map's). */
zr_rgb zr__texture_see_through_layer(const zr_texture *layer,
                                     zr_vec3 world);

#endif /* ZR_SCENE_TEXTURE_H */
