/*
 * photons.h - caustics by photon mapping ("Photons" in the reference):
 * light sources shoot photons at target objects, the photons that
 * objects reflected or refracted are stored where they land, and the
 * shader gathers them as diffuse light (lib/trace/photons.c).
 */
#ifndef ZR_TRACE_PHOTONS_H
#define ZR_TRACE_PHOTONS_H

#include "scene/scene.h"

struct zr_photon_map;

/* Shoots the photons of a scene whose global_settings hold a photons
   block and stores them in scene->photons (left NULL when none is
   stored).  Called by zr__scene_finish() once the BVH is built. */
zr_status zr__photons_build(zr_scene *scene, zr_context *ctx);
void zr__photons_free(struct zr_photon_map *map);

/*
 * The photons' light at surface point p whose unit normal n faces the
 * viewer: the sum over the photons gathered about p, each weighed by
 * cos^(brilliance - 1) of its angle with n, divided by the gathered
 * disc's area.  Times diffuse and the pigment it is the diffuse light
 * the photons bring, as a light source's is.  Black where none lands.
 */
zr_rgb zr__photons_gather(const struct zr_photon_map *map, zr_vec3 p,
                          zr_vec3 n, double brilliance);

/* Whether a shadow ray stops at object o: with photons in the scene,
   the light through an object that refracts photons arrives as photons
   (povray 3.7 draws a target lens's shadow black where its photons do
   not land), unless the light's own photons are not refracted. */
static inline bool zr__photons_block_shadow(const zr_scene *scene,
                                            const zr_light *light,
                                            const zr_object *o) {
  return scene->photons && o->photons && o->photons->refraction &&
         !o->no_image && (!light || light->photon_refraction);
}

/* Statistics: photons stored, and the gather radius found or given. */
size_t zr__photons_stored(const struct zr_photon_map *map);
double zr__photons_radius(const struct zr_photon_map *map);

#endif /* ZR_TRACE_PHOTONS_H */
