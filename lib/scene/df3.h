/*
 * df3.h - POV-Ray's df3 voxel files for the density_file pattern
 * (lib/scene/df3.c).
 */
#ifndef ZR_SCENE_DF3_H
#define ZR_SCENE_DF3_H

#include <stddef.h>

#include "core/arena.h"
#include "scene/scene.h"

/* Decodes a df3 file's bytes into *out (values in arena); ZR_EFORMAT
   when the sizes and the length disagree. */
zr_status zr__df3_decode(const unsigned char *bytes, size_t size,
                         zr_arena *arena, zr_density_file *out);

/* The pattern's value at p in pattern space. */
double zr__df3_value(const zr_density_file *d, zr_vec3 p);

#endif /* ZR_SCENE_DF3_H */
