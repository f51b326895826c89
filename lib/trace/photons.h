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

/*
 * The light media photons scatter toward a media sample at p on a ray
 * going along unit dir, for the n media of list whose densities at p
 * are density[]: for each medium that scatters, its scattering times
 * its density times the sum over the media photons gathered about p of
 * their power times the medium's phase for their direction, divided by
 * the gathered sphere's volume.  Black unless one of the media collects
 * photons ("Photons and Media"), or when the scene stored none.
 */
zr_rgb zr__photons_media_light(const struct zr_photon_map *map, zr_vec3 p,
                               zr_vec3 dir, const zr_medium *const *list,
                               size_t n, const zr_rgb *density);
/* Whether the scene's map holds media photons. */
bool zr__photons_in_media(const struct zr_photon_map *map);

/* Whether a shadow ray stops at object o: with photons in the scene,
   the light through an object that refracts photons arrives as photons
   (povray 3.7 draws a target lens's shadow black where its photons do
   not land), unless the light's own photons are not refracted; and so
   does the light through a target that neither refracts nor reflects
   photons, which lets them through as they are (lib/trace/photons.c):
   povray 3.7 leaves the media and the floor in such a clear box dark
   without media photons (tests/test_media_photons.sh case 4), and a
   floor under it gets the light of the photons only (those stored on
   the box's bottom face 0.01 above it too: twice the light's). */
static inline bool zr__photons_block_shadow(const zr_scene *scene,
                                            const zr_light *light,
                                            const zr_object *o) {
  if (!scene->photons || !o->photons || o->no_image)
    return false;
  const zr_photon_object *po = o->photons;
  if (po->refraction)
    return !light || light->photon_refraction;
  return po->target && !po->reflection && light &&
         (light->photon_refraction || light->photon_reflection) &&
         !light->shadowless;
}

/* Statistics: photons stored, and the gather radius found or given. */
size_t zr__photons_stored(const struct zr_photon_map *map);
double zr__photons_radius(const struct zr_photon_map *map);

#endif /* ZR_TRACE_PHOTONS_H */
