/*
 * warp.h - pattern warps ("Warps"): repeat, black_hole, turbulence and
 * the planar, cylindrical, spherical, toroidal and cubic mappings.
 */
#ifndef ZR_SCENE_WARP_H
#define ZR_SCENE_WARP_H

#include "scene/scene.h"

/* The manual's defaults for a warp of this kind, identity frame. */
void zr__warp_init(zr_warp *w, zr_warp_kind kind);
/* One warp's move of p, in the warp's own frame. */
zr_vec3 zr__warp_apply(const zr_warp *w, zr_vec3 p);
/* Every warp of a pattern, last written first, each in its frame: p is
   in the pattern's space (after all its transforms). */
zr_vec3 zr__warp_point(const zr_warp *warps, int n, zr_vec3 p);
/* p with each coordinate cut to the largest a pattern is given (+-1e17,
   measured: lib/scene/warp.c); zr__warp_point ends with it. */
zr_vec3 zr__warp_cut(zr_vec3 p);

#endif /* ZR_SCENE_WARP_H */
