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
/*
 * photons { } blocks ("Photons"): the items of one block as read, for
 * an object, a light or global_settings (which keywords each may hold
 * is checked when the block is applied).
 */
typedef struct zr_sdl_photon_args {
  double v[4];
  int n;
  bool skip_first; /* "radius , 0.5": the first value left out */
} zr_sdl_photon_args;

typedef struct zr_sdl_photons {
  /* Which items were given: bit (token - base) is not used; instead
     one flag per field below. */
  bool target, refraction, reflection, collect, pass_through, area_light;
  bool has_target, has_refraction, has_reflection, has_collect,
      has_pass_through, has_area_light;
  zr_photon_object obj;
  zr_photon_settings global;
  bool has_spacing, has_count, has_media, has_load, has_save,
      has_split_union;
  zr_sdl_loc first_object_item, first_global_item, media_loc, file_loc;
  bool any_object_item, any_global_item;
  int first_object_kw, first_global_kw; /* tokens; 0 for a file item */
} zr_sdl_photons;

zr_sdl_photons *zr__sdl_photons_new(zr_sdl_parser *p);
/* One item: keyword token kw with its numbers (args may be NULL). */
bool zr__sdl_photons_item(zr_sdl_parser *p, zr_sdl_photons *ph, int kw,
                          const zr_sdl_photon_args *args,
                          const zr_sdl_loc *loc);
/* save_file / load_file "name" (save is true for save_file). */
bool zr__sdl_photons_file(zr_sdl_parser *p, zr_sdl_photons *ph, bool save,
                          const zr_sdl_loc *loc);
/* global_settings { photons { } } */
bool zr__sdl_photons_global(zr_sdl_parser *p, const zr_sdl_photons *ph,
                            const zr_sdl_loc *loc);
/* light_source { photons { } } */
bool zr__sdl_photons_light(zr_sdl_parser *p, zr_light *l,
                           const zr_sdl_photons *ph, const zr_sdl_loc *loc);
/* An object's photons { }: the block applied to o (and a CSG's parts). */
bool zr__sdl_photons_object(zr_sdl_parser *p, zr_object *o,
                            const zr_sdl_photons *ph);

#endif /* ZR_SDL_BUILD_MEDIA_H */
