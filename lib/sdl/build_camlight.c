/*
 * build_camlight.c - building the camera, light sources and atmospheric
 * effects from the grammar's actions (reference manual r3_4: "Camera",
 * "Light Source", "Fog", "Sky Sphere", "Rainbow").
 *
 *   - The camera ("Placing the Camera"): angle sets a perspective
 *     camera's direction length to 0.5 |right| / tan(angle / 2); look_at
 *     turns direction, right and up toward the target about the sky
 *     vector, keeping their lengths and the right vector's handedness
 *     (right <-1,0,0> stays mirrored).  Both act at the end of the block,
 *     before the transforms, whatever the order of the items: that is
 *     what POV-Ray 3.7 renders show.
 *   - Other projections keep their angles (lib/trace/camera.c uses them):
 *     90 degrees unless given for fisheye, ultra_wide_angle and cylinder,
 *     360 and half of it for spherical (all measured from povray 3.7
 *     renders).  An orthographic camera without up or right in its block,
 *     or with angle, is scaled so its view is a perspective camera's at
 *     the distance from location to look_at (whose default is the point
 *     <0,0,1>: a camera at -10 z without look_at sees 11 / 10 as wide as
 *     one with look_at 0, which is what povray renders).
 *   - Lights: spotlight radius 30, falloff 45; cylinder 0.75 and 1;
 *     tightness 0; point_at the origin ("Spotlights", "Cylindrical
 *     Lights").  Transforms move the location, point_at and the area
 *     axes.  looks_like moves its object to the light's location (as
 *     povray does), gives it no_shadow and adds it to the scene.
 *   - fog: type 1, up y, octaves 6, omega 0.5, lambda 2, turb_depth 0.5;
 *     rainbow: arc and falloff angles 180, up y; sky_sphere: emission 1.
 */
#include "config.h"

#include <math.h>
#include <string.h>

#include "pov-parse.h"
#include "sdl/build_camlight.h"

static const double PI = 3.14159265358979323846;

/* ---- lights ---- */

bool zr__sdl_light(zr_sdl_parser *p, zr_light *l, const zr_sdl_loc *loc) {
  memset(l, 0, sizeof *l);
  l->kind = ZR_LIGHT_POINT;
  l->radius = 30;
  l->falloff = 45;
  l->adaptive = -1;
  l->size1 = l->size2 = 1;
  l->media_interaction = true;
  l->photon_refraction = l->photon_reflection = true;
  l->where.file = p->files[loc->file].scene_path;
  l->where.line = loc->line;
  l->where.column = loc->column;
  return true;
}

void zr__sdl_light_kind(zr_sdl_parser *p, zr_light *l, zr_light_kind kind) {
  (void)p;
  l->kind = kind;
  if (kind == ZR_LIGHT_CYLINDER) {
    l->radius = 0.75;
    l->falloff = 1;
  } else {
    l->radius = 30;
    l->falloff = 45;
  }
}

void zr__sdl_light_transform(zr_sdl_parser *p, zr_light *l,
                             const zr_transform *t) {
  l->location = zr__xform_point(t->m, l->location);
  l->point_at = zr__xform_point(t->m, l->point_at);
  l->axis1 = zr__xform_dir(t->m, l->axis1);
  l->axis2 = zr__xform_dir(t->m, l->axis2);
  if (l->looks_like) {
    zr_sdl_mod m = {ZR_SDL_MOD_TRANSFORM, t};
    zr__sdl_object_mod(p, l->looks_like, &m, NULL);
  }
  /* The object moves with the light: POV-Ray 3.7 renders the spot of a
     light projected through a sphere 1.5 units along x when the light
     is translated 1.5 along x, not the other way. */
  if (l->projected_through) {
    zr_sdl_mod m = {ZR_SDL_MOD_TRANSFORM, t};
    zr__sdl_object_mod(p, l->projected_through, &m, NULL);
  }
}

bool zr__sdl_light_int(zr_sdl_parser *p, const zr_sdl_expr *e,
                       const zr_sdl_loc *loc, int min, int *out) {
  double v;
  if (!zr__sdl_want_float(p, e, loc, &v))
    return false;
  if (!(v >= min && v <= 1e6)) {
    zr__sdl_error(p, ZR_ESCENE, loc, "expected a whole number of at least "
                                     "%d, not %g", min, v);
    return false;
  }
  *out = (int)v;
  return true;
}

bool zr__sdl_light_bool(zr_sdl_parser *p, const zr_sdl_expr *e,
                        const zr_sdl_loc *loc, bool *out) {
  double v;
  if (!zr__sdl_want_float(p, e, loc, &v))
    return false;
  *out = fabs(v) >= 1e-10; /* POV-Ray's truth ("Numeric Expressions") */
  return true;
}

bool zr__sdl_area_light(zr_sdl_parser *p, zr_light *l,
                        const zr_sdl_expr e[4], const zr_sdl_loc at[4]) {
  double n1, n2;
  if (!zr__sdl_want_vector(p, &e[0], &at[0], &l->axis1) ||
      !zr__sdl_want_vector(p, &e[1], &at[1], &l->axis2) ||
      !zr__sdl_want_float(p, &e[2], &at[2], &n1) ||
      !zr__sdl_want_float(p, &e[3], &at[3], &n2))
    return false;
  /* The manual asks sizes of at least 1 ("Area Lights"); 1024 a side
     is our own cap on a light's cost (povray accepts more). */
  if (!(n1 >= 1 && n1 <= 1024)) {
    zr__sdl_error(p, ZR_ESCENE, &at[2], "an area light has 1 to 1024 "
                                        "lights a side, not %g", n1);
    return false;
  }
  if (!(n2 >= 1 && n2 <= 1024)) {
    zr__sdl_error(p, ZR_ESCENE, &at[3], "an area light has 1 to 1024 "
                                        "lights a side, not %g", n2);
    return false;
  }
  l->area = true;
  l->size1 = (int)n1;
  l->size2 = (int)n2;
  return true;
}

bool zr__sdl_looks_like(zr_sdl_parser *p, zr_light *l, zr_object *o,
                        const zr_sdl_loc *loc) {
  zr_transform *t = zr__sdl_alloc(p, sizeof *t);
  if (!t)
    return false;
  zr__transform_identity(t);
  zr__transform_translate(t, l->location);
  zr_sdl_mod m = {ZR_SDL_MOD_TRANSFORM, t};
  if (!zr__sdl_object_mod(p, o, &m, loc))
    return false;
  zr_sdl_mod ns = {ZR_SDL_MOD_NO_SHADOW, NULL};
  if (!zr__sdl_object_mod(p, o, &ns, loc))
    return false;
  l->looks_like = o;
  return true;
}

bool zr__sdl_light_end(zr_sdl_parser *p, zr_light *l,
                       const zr_sdl_loc *loc) {
  if (l->orient && !l->circular)
    zr__sdl_warning(p, loc, "'orient' only works with 'circular' area "
                            "lights; ignored");
  if (!l->circular)
    l->orient = false;
  if (l->area_illumination)
    zr__sdl_warning(p, loc, "'area_illumination' is not rendered yet: the "
                            "area light shades from its centre");
  return true;
}

bool zr__sdl_light_add(zr_sdl_parser *p, zr_light *l,
                       const zr_sdl_loc *loc) {
  if ((l->looks_like &&
       zr__scene_add_object(p->scene, l->looks_like) != ZR_OK) ||
      zr__scene_add_light(p->scene, l) != ZR_OK) {
    zr__sdl_error(p, ZR_ENOMEM, loc, "out of memory");
    return false;
  }
  return true;
}

/* ---- camera ---- */

void zr__sdl_camera_begin(zr_sdl_parser *p, const zr_sdl_loc *loc) {
  zr_camera *c = &p->scene->camera;
  zr_camera saved = *c;
  zr__camera_init(c);
  c->given = true;
  c->confidence = 0.9;
  c->variance = 1.0 / 128.0;
  c->where.file = p->files[loc->file].scene_path;
  c->where.line = loc->line;
  c->where.column = loc->column;
  memset(&p->camera, 0, sizeof p->camera);
  p->camera.saved = saved;
  zr__transform_identity(&p->camera.transform);
}

/*
 * camera { Name ... }: the block starts from the declared camera, which
 * is finished (aimed, transformed), so what follows acts on it as on a
 * camera already placed, as in POV-Ray; its angles stay unless the
 * block sets new ones.
 */
void zr__sdl_camera_from(zr_sdl_parser *p, const zr_camera *declared) {
  zr_camera *c = &p->scene->camera;
  zr_source_loc where = c->where;
  *c = *declared;
  c->given = true;
  c->where = where;
  p->camera.from_id = true;
}

/*
 * The value of "#declare Name = camera { ... }": the camera just
 * finished, copied into the arena, while the scene gets back the camera
 * it had before the block.
 */
const zr_camera *zr__sdl_camera_value(zr_sdl_parser *p) {
  zr_camera *copy = zr__sdl_alloc(p, sizeof *copy);
  if (copy == NULL)
    return NULL;
  *copy = p->scene->camera;
  p->scene->camera = p->camera.saved;
  return copy;
}

bool zr__sdl_camera_type(zr_sdl_parser *p, zr_camera_kind kind,
                         const zr_sdl_expr *e, const zr_sdl_loc *loc) {
  zr_camera *c = &p->scene->camera;
  if (kind == ZR_CAMERA_CYLINDER) {
    double type;
    if (!zr__sdl_want_float(p, e, loc, &type))
      return false;
    if (!(type == 1 || type == 2 || type == 3 || type == 4)) {
      zr__sdl_error(p, ZR_ESCENE, loc, "a cylinder camera's type must be "
                                       "1, 2, 3 or 4, not %g", type);
      return false;
    }
    c->cylinder_type = (int)type;
  }
  c->kind = kind;
  p->camera.type_given = true;
  return true;
}

bool zr__sdl_camera_angle(zr_sdl_parser *p, double degrees,
                          const double *v, const zr_sdl_loc *loc) {
  zr_camera_kind kind = p->scene->camera.kind;
  /* "angle 0" (old scenes write it): POV-Ray 3.7 renders a perspective
     camera as if no angle were given, and sizes an orthographic one at
     the look_at distance from its direction and right vectors, as any
     angle does, without changing the direction (measured: tests/
     camera_angle0.sh). No warning. */
  if (degrees == 0 && kind == ZR_CAMERA_PERSPECTIVE)
    return true;
  if (degrees == 0 && kind == ZR_CAMERA_ORTHOGRAPHIC) {
    p->camera.angle_given = true;
    p->camera.angle = 0;
    p->camera.v_angle_given = false;
    return true;
  }
  if (kind == ZR_CAMERA_PERSPECTIVE && !(degrees > 0 && degrees < 180)) {
    zr__sdl_error(p, ZR_ESCENE, loc,
                  "a perspective camera's angle must be between 0 and 180 "
                  "degrees, not %g", degrees);
    return false;
  }
  if (kind == ZR_CAMERA_ORTHOGRAPHIC && !(degrees > 0 && degrees < 180)) {
    zr__sdl_error(p, ZR_ESCENE, loc,
                  "an orthographic camera's angle must be between 0 and "
                  "180 degrees, not %g", degrees);
    return false;
  }
  p->camera.angle_given = true;
  p->camera.angle = degrees;
  p->camera.v_angle_given = v != NULL;
  if (v)
    p->camera.v_angle = *v;
  return true;
}

bool zr__sdl_camera_blur_samples(zr_sdl_parser *p, const zr_sdl_expr *min,
                                 const zr_sdl_expr *max,
                                 const zr_sdl_loc *loc) {
  zr_camera *c = &p->scene->camera;
  int lo = 0, hi;
  if (min && !zr__sdl_light_int(p, min, loc, 1, &lo))
    return false;
  if (!zr__sdl_light_int(p, max, loc, 1, &hi))
    return false;
  /* The manual: at least 4 samples below 7, else 7, unless given. */
  c->blur_samples = hi;
  c->blur_min = min ? lo : hi < 7 ? 4 : 7;
  if (c->blur_min > hi)
    c->blur_min = hi;
  return true;
}

void zr__sdl_camera_look_at(zr_sdl_parser *p, zr_vec3 target,
                            const zr_sdl_loc *at) {
  p->camera.look_at_given = true;
  p->camera.look_at_at = *at;
  p->camera.look_at = target;
}

void zr__sdl_camera_transform(zr_sdl_parser *p, const zr_transform *t) {
  zr__transform_compose(&p->camera.transform, t);
}

/* Turns direction, right and up toward target about the sky vector. */
static void look_at(zr_camera *c, zr_vec3 target) {
  zr_vec3 d = zr_v3_sub(target, c->location);
  if (zr_v3_len(d) == 0)
    return; /* looking at itself: nothing to turn toward */
  double dl = zr_v3_len(c->direction);
  double rl = zr_v3_len(c->right);
  double ul = zr_v3_len(c->up);
  /* POV-Ray's space is left-handed: right = up x direction normally; a
     right vector pointing the other way mirrors the image and stays so.
     So does a degenerate triple, up along direction or right in their
     plane ("up z sky z" with the default direction z): POV-Ray 3.7
     renders those mirrored too (measured with up z and direction z, x,
     y and -y). */
  double handed =
      zr_v3_dot(zr_v3_cross(c->up, c->direction), c->right) > 0 ? 1 : -1;
  zr_vec3 dn = zr_v3_norm(d);
  zr_vec3 rn = zr_v3_norm(zr_v3_cross(c->sky, dn));
  /* Looking along the sky: up comes from the old right as given, then
     the mirror of a right-handed (or degenerate) triple flips right, so
     a mirrored camera looking down shows +x right and -z up where the
     plain one shows +x right and +z up (POV-Ray 3.7 renders of ten
     cameras looking along y and z, one kept as scenes/camera_sky.pov;
     POV-Ray warns of none). */
  if (zr_v3_len(rn) == 0)
    rn = zr_v3_norm(c->right);
  zr_vec3 un = zr_v3_cross(dn, rn);
  c->direction = zr_v3_scale(dn, dl);
  c->right = zr_v3_scale(rn, rl * handed);
  c->up = zr_v3_scale(un, ul);
}

/* The projections' angles: given, or each kind's default. */
static void camera_angles(zr_sdl_parser *p, zr_camera *c) {
  if (p->camera.from_id) {
    if (p->camera.angle_given && p->camera.angle > 0)
      c->h_angle = p->camera.angle;
    if (p->camera.v_angle_given)
      c->v_angle = p->camera.v_angle;
    return;
  }
  if (c->kind == ZR_CAMERA_SPHERICAL) {
    c->h_angle = p->camera.angle_given ? p->camera.angle : 360.0;
    c->v_angle = p->camera.v_angle_given ? p->camera.v_angle
                                         : 0.5 * c->h_angle;
  } else {
    c->h_angle = p->camera.angle_given && p->camera.angle > 0
                     ? p->camera.angle
                     : 90.0;
    c->v_angle = p->camera.v_angle_given ? p->camera.v_angle : c->h_angle;
  }
}

/*
 * POV-Ray 3.7 (measured with renders, see tests/test_parser.c) treats
 * location, direction, up, right, sky, angle and look_at as settings
 * whose last value counts wherever it is written, then aims the camera,
 * then applies the transforms in the order written.
 */
bool zr__sdl_camera_end(zr_sdl_parser *p) {
  zr_camera *c = &p->scene->camera;
  /* No direction to look in: POV-Ray 3.7 stops too ("Parse Error:
     Camera location and look_at point must be different.", measured). */
  if (p->camera.look_at_given &&
      zr_v3_len(zr_v3_sub(p->camera.look_at, c->location)) == 0) {
    zr__sdl_error(p, ZR_ESCENE, &p->camera.look_at_at,
                  "the camera's location and look_at point must be "
                  "different");
    return false;
  }
  bool perspective_like = c->kind == ZR_CAMERA_PERSPECTIVE ||
                          c->kind == ZR_CAMERA_ORTHOGRAPHIC;
  if (p->camera.angle_given && p->camera.angle > 0 && perspective_like) {
    double half = p->camera.angle * PI / 360.0;
    double length = 0.5 * zr_v3_len(c->right) / tan(half);
    c->direction = zr_v3_scale(zr_v3_norm(c->direction), length);
  }
  camera_angles(p, c);
  /* A camera from an identifier was sized when it was declared: sizing
     it again made templates/Basic_Scenes/Orthographic_isometric.pov's
     view seven times too wide. */
  if (c->kind == ZR_CAMERA_ORTHOGRAPHIC &&
      (p->camera.angle_given ||
       !(p->camera.from_id || p->camera.right_given ||
         p->camera.up_given))) {
    /* The view of a perspective camera at the look_at distance. */
    zr_vec3 target = p->camera.look_at_given ? p->camera.look_at
                                             : zr_v3(0, 0, 1);
    double dist = zr_v3_len(zr_v3_sub(target, c->location));
    double dl = zr_v3_len(c->direction);
    if (dist > 0.0 && dl > 0.0) {
      c->right = zr_v3_scale(c->right, dist / dl);
      c->up = zr_v3_scale(c->up, dist / dl);
    }
  }
  if (p->camera.look_at_given)
    look_at(c, p->camera.look_at);
  const zr_transform *t = &p->camera.transform;
  c->location = zr__xform_point(t->m, c->location);
  c->direction = zr__xform_dir(t->m, c->direction);
  c->up = zr__xform_dir(t->m, c->up);
  c->right = zr__xform_dir(t->m, c->right);
  c->sky = zr__xform_dir(t->m, c->sky);
  c->focal_point = zr__xform_point(t->m, c->focal_point);
  return true;
}

/* ---- atmosphere ---- */

bool zr__sdl_colour_item_to(zr_sdl_parser *p, const zr_sdl_colour_mod *m,
                            zr_colour *colour) {
  zr_sdl_expr e = zr__sdl_colour_expr(*colour);
  return zr__sdl_colour_apply(p, &e, m) &&
         zr__sdl_want_colour(p, &e, &m->loc, colour);
}

zr_fog *zr__sdl_fog_new(zr_sdl_parser *p, const zr_sdl_loc *loc) {
  (void)loc;
  zr_fog *f = zr__sdl_alloc(p, sizeof *f);
  if (!f)
    return NULL;
  memset(f, 0, sizeof *f);
  f->type = 1;
  f->octaves = 6;
  f->omega = 0.5;
  f->lambda = 2.0;
  f->turb_depth = 0.5;
  f->up = zr_v3(0, 1, 0);
  return f;
}

bool zr__sdl_fog_type(zr_sdl_parser *p, zr_fog *f, const zr_sdl_expr *e,
                      const zr_sdl_loc *loc) {
  double type;
  if (!zr__sdl_want_float(p, e, loc, &type))
    return false;
  if (type != 1 && type != 2) {
    zr__sdl_error(p, ZR_ESCENE, loc, "fog_type must be 1 (constant) or 2 "
                                     "(ground fog), not %g", type);
    return false;
  }
  f->type = (int)type;
  return true;
}

bool zr__sdl_fog_transform(zr_sdl_parser *p, zr_fog *f,
                           const zr_transform *t) {
  zr_transform *all = zr__sdl_alloc(p, sizeof *all);
  if (!all)
    return false;
  if (f->transform)
    *all = *f->transform;
  else
    zr__transform_identity(all);
  zr__transform_compose(all, t);
  f->transform = all;
  /* The manual: transformations turn the up vector, translations do
     not move it. */
  f->up = zr__xform_dir(t->m, f->up);
  return true;
}

void zr__sdl_fog_end(zr_sdl_parser *p, zr_fog *f) {
  f->up = zr_v3_len(f->up) > 0.0 ? zr_v3_norm(f->up) : zr_v3(0, 1, 0);
  f->next = NULL;
  const zr_fog **tail = &p->scene->settings.fogs;
  while (*tail)
    tail = (const zr_fog **)&(*tail)->next;
  *tail = f;
}

zr_sky_sphere *zr__sdl_sky_new(zr_sdl_parser *p,
                               const zr_sky_sphere *from) {
  zr_sky_sphere *sky = zr__sdl_alloc(p, sizeof *sky);
  if (!sky)
    return NULL;
  memset(sky, 0, sizeof *sky);
  sky->emission = zr_rgb3(1, 1, 1);
  /* The pigment list and transform are copied on change, never
     changed in place, so sharing them with the declaration is safe. */
  if (from)
    *sky = *from;
  return sky;
}

bool zr__sdl_sky_pigment(zr_sdl_parser *p, zr_sky_sphere *sky,
                         const zr_pigment *pg) {
  const zr_pigment **list =
      zr__sdl_alloc(p, (sky->n_pigments + 1) * sizeof *list);
  if (!list)
    return false;
  for (size_t i = 0; i < sky->n_pigments; i++)
    list[i] = sky->pigments[i];
  list[sky->n_pigments] = pg;
  sky->pigments = list;
  sky->n_pigments++;
  return true;
}

bool zr__sdl_sky_transform(zr_sdl_parser *p, zr_sky_sphere *sky,
                           const zr_transform *t) {
  zr_transform *all = zr__sdl_alloc(p, sizeof *all);
  if (!all)
    return false;
  if (sky->transform)
    *all = *sky->transform;
  else
    zr__transform_identity(all);
  zr__transform_compose(all, t);
  sky->transform = all;
  return true;
}

bool zr__sdl_sky_end(zr_sdl_parser *p, zr_sky_sphere *sky,
                     const zr_sdl_loc *loc) {
  if (sky->n_pigments == 0) {
    zr__sdl_error(p, ZR_ESCENE, loc, "a sky_sphere needs a pigment");
    return false;
  }
  /* The manual: only one sky sphere; the last one counts. */
  p->scene->settings.sky_sphere = sky;
  return true;
}

zr_rainbow *zr__sdl_rainbow_new(zr_sdl_parser *p) {
  zr_rainbow *rb = zr__sdl_alloc(p, sizeof *rb);
  if (!rb)
    return NULL;
  memset(rb, 0, sizeof *rb);
  rb->arc_angle = 180;
  rb->falloff_angle = 180;
  rb->up = zr_v3(0, 1, 0);
  /* "a sufficiently large value" ("Rainbow"); 1e7 is ours: any
     distance far beyond a scene's leaves 1 - exp(-d / distance) near 0
     on objects, which is what the manual asks of it. */
  rb->distance = 1e7;
  return rb;
}

bool zr__sdl_rainbow_end(zr_sdl_parser *p, zr_rainbow *rb,
                         const zr_sdl_loc *loc) {
  if (zr_v3_len(rb->direction) == 0.0) {
    zr__sdl_error(p, ZR_ESCENE, loc, "a rainbow needs a direction");
    return false;
  }
  if (!rb->colour_map) {
    zr__sdl_error(p, ZR_ESCENE, loc, "a rainbow needs a color_map");
    return false;
  }
  rb->direction = zr_v3_norm(rb->direction);
  rb->up = zr_v3_len(rb->up) > 0.0 ? zr_v3_norm(rb->up) : zr_v3(0, 1, 0);
  rb->next = NULL;
  const zr_rainbow **tail = &p->scene->settings.rainbows;
  while (*tail)
    tail = (const zr_rainbow **)&(*tail)->next;
  *tail = rb;
  return true;
}
