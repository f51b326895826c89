/*
 * build_media.h - what the grammar's media, density, interior_texture
 * and photons actions call (lib/sdl/build_media.c).
 */
#ifndef ZR_SDL_BUILD_MEDIA_H
#define ZR_SDL_BUILD_MEDIA_H

#include "sdl/sdl.h"

/* media { [MEDIA_IDENTIFIER] ...: POV-Ray's defaults, or a copy. */
zr_medium *zr__sdl_media_new(zr_sdl_parser *p, const zr_medium *from,
                             const zr_sdl_loc *loc);
/* method, intervals, samples (one value), confidence, variance, ratio,
   jitter, aa_level, aa_threshold, absorption, emission. */
bool zr__sdl_media_item(zr_sdl_parser *p, zr_medium *m, int token,
                        const zr_sdl_expr *e, const zr_sdl_loc *loc);
/* samples Min, Max */
bool zr__sdl_media_samples(zr_sdl_parser *p, zr_medium *m,
                           const zr_sdl_expr *lo, const zr_sdl_loc *lo_loc,
                           const zr_sdl_expr *hi, const zr_sdl_loc *hi_loc);
/* scattering { Type, COLOR ... }: the type and colour. */
bool zr__sdl_media_scattering(zr_sdl_parser *p, zr_medium *m,
                              const zr_sdl_expr *type,
                              const zr_sdl_loc *type_loc,
                              const zr_sdl_expr *colour,
                              const zr_sdl_loc *colour_loc);
/* eccentricity Value: Henyey-Greenstein scattering only. */
bool zr__sdl_media_eccentricity(zr_sdl_parser *p, zr_medium *m,
                                const zr_sdl_expr *e,
                                const zr_sdl_loc *loc);
bool zr__sdl_media_density(zr_sdl_parser *p, zr_medium *m,
                           const zr_pigment *density);
/* Moves the densities given so far ("Media": later ones stay). */
bool zr__sdl_media_transform(zr_sdl_parser *p, zr_medium *m,
                             const zr_transform *t);
/* interior { media { } }: appended to the interior's list. */
bool zr__sdl_interior_media(zr_sdl_parser *p, zr_interior *in,
                            const zr_medium *m);
/* A scene-level media { }: atmospheric media. */
bool zr__sdl_atmosphere_media(zr_sdl_parser *p, const zr_medium *m);
/* The interior moved with its object: a copy whose media densities are
   transformed, or in itself when nothing in it depends on place. */
const zr_interior *zr__sdl_interior_transform(zr_sdl_parser *p,
                                              const zr_interior *in,
                                              const zr_transform *t);
/* interior_texture { } on o and on its CSG children without one. */
void zr__sdl_interior_texture(zr_object *o, const zr_texture *tx);
/* density_file df3 "name" and its interpolate: the density's pattern
   becomes the file's voxels (lib/scene/df3.c). */
bool zr__sdl_density_file(zr_sdl_parser *p, zr_pigment *pg,
                          const char *name, const zr_sdl_loc *loc);
bool zr__sdl_normal_density_file(zr_sdl_parser *p, zr_normal *nm,
                                 const char *name, const zr_sdl_expr *amount,
                                 const zr_sdl_loc *loc);
bool zr__sdl_density_interpolate(zr_sdl_parser *p, zr_pattern *pt,
                                 const zr_sdl_expr *e,
                                 const zr_sdl_loc *loc);
/* global_settings { photons { } } was read at loc: warns. */
void zr__sdl_photons_global(zr_sdl_parser *p, const zr_sdl_loc *loc);

#endif /* ZR_SDL_BUILD_MEDIA_H */
