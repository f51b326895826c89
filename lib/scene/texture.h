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

/* Makes pg a pattern pigment of kind with POV-Ray's defaults, including
   the default colours of checker, hexagon and brick. */
void zr__pigment_set_pattern(zr_pigment *pg, zr_pattern_kind kind);

/* The colour of an image map at p in its own (pattern) space. */
zr_colour zr__image_map_eval(const zr_image_map *im, zr_vec3 p);

/* The pigment's colour at a point in world space. */
zr_colour zr__pigment_eval(const zr_pigment *pg, zr_vec3 world);

/*
 * The shading normal at a world point of a surface whose unit normal is
 * n: n tilted against the pattern's slope there (its gradient in the
 * surface's tangent plane) times the bump size, then normalised.
 */
zr_vec3 zr__normal_perturb(const zr_normal *nm, zr_vec3 world, zr_vec3 n);

#endif /* ZR_SCENE_TEXTURE_H */
