/*
 * io.c - saving a radiosity solution and loading it for another view of
 * the same scene, so a solution is computed once for every camera.
 *
 * The file is little-endian binary, whatever the host:
 *
 *   "ZRRADSOL"           8 bytes, the magic
 *   u32 version          3 (2 is still read: a file without light sources)
 *   u64 fingerprint      of the scene's geometry and light (below)
 *   u32 surfaces         how many exact surfaces the scene gave
 *   f64 bf_eps, area_eps; i32 visibility_rays, uniform, shooting
 *   u64 links; i32 refine_rounds, iterations; f64 residual
 *   u32 lookup           params.lookup of the solve
 *   then, per surface in scene order, its quadtree in preorder: a byte
 *   (1 when the node has four children) and the node's radiosity, six
 *   f64 (front r g b, back r g b), then (version 3) the irradiance of
 *   the light sources the node holds (direct.c), six f64 in that order;
 *   then u64 n and n links: i32 receiver, i32 source (nodes numbered in
 *   the preorder of all the trees, surface after surface), u8 receiver
 *   side, u8 source side, f64 factor, f64 visible fraction.
 *
 * The links are saved because the default lookup (a final gather at the
 * ray hit, radiosity.c) reads them: a loaded solution then renders the
 * same bytes as the solve it came from.  The vertices are smoothed again
 * after loading (the same code, so the same values).  The fingerprint is FNV-1a over every primitive's kind,
 * shape numbers, transform and the texture values radiosity reads
 * (pigment colour, diffuse, emission) and, in a scene with light
 * sources, every light's values and each finish's brilliance (lights
 * shoot into the mesh, direct.c); the camera and other finish values
 * are left out, since they do not change the solution.  A scene without
 * lights keeps the fingerprint it had in version 2.
 * Loading a file whose fingerprint differs is an error: its quadtrees
 * would belong to other surfaces.
 */
#include "radiosity/radiosity.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/iopolicy.h"

#define MAGIC "ZRRADSOL"
#define VERSION 3u

/* ---- fingerprint ---- */

static uint64_t fnv(uint64_t h, const void *data, size_t n) {
  const unsigned char *p = data;
  for (size_t i = 0; i < n; i++) {
    h ^= p[i];
    h *= 0x100000001B3ull;
  }
  return h;
}

static uint64_t fnv_d(uint64_t h, double v) {
  v = v == 0.0 ? 0.0 : v; /* -0 and 0 are the same geometry */
  return fnv(h, &v, sizeof v);
}

static uint64_t fnv_v(uint64_t h, zr_vec3 v) {
  return fnv_d(fnv_d(fnv_d(h, v.x), v.y), v.z);
}

static uint64_t hash_shape(uint64_t h, const zr_object *o) {
  switch (o->kind) {
  case ZR_OBJ_SPHERE:
    return fnv_d(fnv_v(h, o->u.sphere.centre), o->u.sphere.radius);
  case ZR_OBJ_BOX:
    return fnv_v(fnv_v(h, o->u.box.corner1), o->u.box.corner2);
  case ZR_OBJ_PLANE:
    return fnv_d(fnv_v(h, o->u.plane.normal), o->u.plane.distance);
  case ZR_OBJ_TRIANGLE:
    for (int i = 0; i < 3; i++)
      h = fnv_v(h, o->u.triangle.p[i]);
    return h;
  case ZR_OBJ_CYLINDER:
    h = fnv_v(fnv_v(h, o->u.cylinder.base), o->u.cylinder.cap);
    return fnv_d(fnv_d(h, o->u.cylinder.radius), o->u.cylinder.open);
  case ZR_OBJ_CONE:
    h = fnv_v(fnv_v(h, o->u.cone.base), o->u.cone.cap);
    h = fnv_d(fnv_d(h, o->u.cone.base_radius), o->u.cone.cap_radius);
    return fnv_d(h, o->u.cone.open);
  case ZR_OBJ_TORUS:
    return fnv_d(fnv_d(h, o->u.torus.major), o->u.torus.minor);
  case ZR_OBJ_DISC:
    h = fnv_v(fnv_v(h, o->u.disc.centre), o->u.disc.normal);
    return fnv_d(fnv_d(h, o->u.disc.radius), o->u.disc.hole_radius);
  default:
    return h;
  }
}

static uint64_t hash_light(uint64_t h, const zr_light *l) {
  h = fnv_d(h, (double)l->kind);
  h = fnv_v(fnv_v(h, l->location), l->point_at);
  h = fnv_d(fnv_d(fnv_d(h, l->colour.r), l->colour.g), l->colour.b);
  h = fnv_d(fnv_d(h, l->shadowless), l->parallel);
  h = fnv_d(fnv_d(fnv_d(h, l->radius), l->falloff), l->tightness);
  h = fnv_d(fnv_d(h, l->fade_distance), l->fade_power);
  h = fnv_d(h, l->area);
  if (l->area) {
    h = fnv_v(fnv_v(h, l->axis1), l->axis2);
    h = fnv_d(fnv_d(fnv_d(h, l->size1), l->size2), l->adaptive);
    h = fnv_d(fnv_d(fnv_d(h, l->jitter), l->circular), l->orient);
  }
  return h;
}

uint64_t zr__rad_fingerprint(const zr_scene *scene) {
  uint64_t h = 0xCBF29CE484222325ull;
  if (scene->n_lights > 0) {
    h = fnv_d(h, (double)scene->n_lights);
    for (size_t i = 0; i < scene->n_lights; i++)
      h = hash_light(h, &scene->lights[i]);
  }
  h = fnv_d(h, (double)scene->n_primitives);
  for (size_t i = 0; i < scene->n_primitives; i++) {
    const zr_object *o = scene->primitives[i];
    h = fnv_d(h, (double)o->kind);
    h = hash_shape(h, o);
    if (o->transform != NULL)
      for (int r = 0; r < 3; r++)
        for (int c = 0; c < 4; c++)
          h = fnv_d(h, o->transform->m[r][c]);
    const zr_colour pc = o->texture->pigment->colour;
    const zr_finish *f = o->texture->finish;
    h = fnv_d(fnv_d(fnv_d(h, pc.r), pc.g), pc.b);
    h = fnv_d(h, f->diffuse);
    h = fnv_d(fnv_d(fnv_d(h, f->emission.r), f->emission.g),
              f->emission.b);
    if (scene->n_lights > 0)
      h = fnv_d(h, f->brilliance);
  }
  return h;
}

/* ---- little-endian helpers ---- */

/* The writer: a save is a few million small fields (a large solution's
   3.5 MB were ~1e6 fwrite calls, 0.015 s, on the +C state path), so
   they are gathered here and reach the FILE a block at a time. */
typedef struct {
  FILE *f;
  size_t n;
  unsigned char b[1 << 16];
} writer;

static void put_bytes(writer *w, const void *p, size_t n) {
  if (w->n + n > sizeof w->b) {
    fwrite(w->b, 1, w->n, w->f);
    w->n = 0;
  }
  memcpy(w->b + w->n, p, n);
  w->n += n;
}
static void put_u8(writer *w, unsigned v) {
  unsigned char b = (unsigned char)v;
  put_bytes(w, &b, 1);
}
static void put_u64(writer *w, uint64_t v) {
  unsigned char b[8];
  for (int i = 0; i < 8; i++)
    b[i] = (unsigned char)(v >> (8 * i));
  put_bytes(w, b, 8);
}
static void put_u32(writer *w, uint32_t v) {
  unsigned char b[4];
  for (int i = 0; i < 4; i++)
    b[i] = (unsigned char)(v >> (8 * i));
  put_bytes(w, b, 4);
}
static void put_f64(writer *w, double d) {
  uint64_t v;
  memcpy(&v, &d, sizeof v);
  put_u64(w, v);
}
static void put_flush(writer *w) {
  fwrite(w->b, 1, w->n, w->f);
  w->n = 0;
}

static bool get_u64(FILE *f, uint64_t *v) {
  unsigned char b[8];
  if (fread(b, 1, 8, f) != 8)
    return false;
  *v = 0;
  for (int i = 0; i < 8; i++)
    *v |= (uint64_t)b[i] << (8 * i);
  return true;
}
static bool get_u32(FILE *f, uint32_t *v) {
  unsigned char b[4];
  if (fread(b, 1, 4, f) != 4)
    return false;
  *v = (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 |
       (uint32_t)b[3] << 24;
  return true;
}
static bool get_f64(FILE *f, double *d) {
  uint64_t v;
  if (!get_u64(f, &v))
    return false;
  memcpy(d, &v, sizeof v);
  return true;
}

/* ---- save ---- */

/* Writes node n's subtree in preorder; order[node] gets its preorder
   number, counted by *next. */
static void save_tree(writer *w, const zr_radiosity *rad, int32_t n,
                      uint32_t *order, uint32_t *next) {
  const zr__rad_node *node = &rad->nodes[n];
  order[n] = (*next)++;
  put_u8(w, node->child >= 0);
  for (int side = 0; side < 2; side++)
    for (int c = 0; c < 3; c++)
      put_f64(w, node->b[side][c]);
  for (int side = 0; side < 2; side++)
    for (int c = 0; c < 3; c++)
      put_f64(w, node->hd[side][c]);
  if (node->child >= 0)
    for (int k = 0; k < 4; k++)
      save_tree(w, rad, node->child + k, order, next);
}

static void save_links(writer *w, const zr_radiosity *rad,
                       const uint32_t *order) {
  size_t n = 0;
  for (size_t i = 0; i < rad->n_links; i++)
    n += !rad->links[i].dead;
  put_u64(w, n);
  for (size_t i = 0; i < rad->n_links; i++) {
    const zr__rad_link *l = &rad->links[i];
    if (l->dead)
      continue;
    put_u32(w, order[l->recv]);
    put_u32(w, order[l->src]);
    put_u8(w, l->rside);
    put_u8(w, l->sside);
    put_f64(w, l->ff);
    put_f64(w, l->vis);
  }
}

ZR_API zr_status zr_radiosity_save(zr_context *ctx, const zr_radiosity *rad,
                                   const char *path) {
  uint32_t *order = malloc((rad->n_nodes + 1) * sizeof *order);
  writer *w = malloc(sizeof *w);
  if (order == NULL || w == NULL) {
    free(order);
    free(w);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL,
                    "radiosity: out of memory saving '%s'", path);
  }
  /* Written beside the target and renamed over it when complete, so a
     failure leaves an older save whole; a device or directory is
     refused by name. */
  char why[512];
  char *target = NULL;
  zr_status ts = zr__io_output_target(path, &target, why, sizeof why);
  if (ts != ZR_OK) {
    free(order);
    free(w);
    return zr__diag(ctx, ZR_DIAG_ERROR, ts, NULL,
                    "radiosity: cannot write '%s': %s", path,
                    ts == ZR_ENOMEM ? zr_status_str(ts) : why);
  }
  /* With no name until complete where the system allows
     (zr__io_temp_open): a killed process leaves nothing. */
  zr_io_temp tmp;
  if (zr__io_temp_open(&tmp, target) != 0) {
    zr_status s = zr__diag(ctx, ZR_DIAG_ERROR, ZR_EIO, NULL,
                           "radiosity: cannot write '%s': %s", path,
                           strerror(errno));
    free(order);
    free(w);
    free(target);
    return s;
  }
  w->f = tmp.f;
  w->n = 0;
  put_bytes(w, MAGIC, 8);
  put_u32(w, VERSION);
  put_u64(w, rad->fingerprint);
  put_u32(w, (uint32_t)rad->n_surfs);
  put_f64(w, rad->params.bf_eps);
  put_f64(w, rad->params.area_eps);
  put_u32(w, (uint32_t)rad->params.visibility_rays);
  put_u32(w, (uint32_t)rad->params.uniform);
  put_u32(w, (uint32_t)rad->params.shooting);
  put_u64(w, rad->stats.links);
  put_u32(w, (uint32_t)rad->stats.refine_rounds);
  put_u32(w, (uint32_t)rad->stats.iterations);
  put_f64(w, rad->stats.residual);
  put_u32(w, (uint32_t)rad->params.lookup);
  uint32_t next = 0;
  for (size_t s = 0; s < rad->n_surfs; s++)
    save_tree(w, rad, rad->surfs[s].root, order, &next);
  save_links(w, rad, order);
  put_flush(w);
  free(w);
  free(order);
  bool bad = ferror(tmp.f) != 0;
  zr_status st = ZR_OK;
  if (zr__io_temp_close(&tmp, !bad) != 0 || bad)
    st = zr__diag(ctx, ZR_DIAG_ERROR, ZR_EIO, NULL,
                  "radiosity: error writing '%s'", path);
  else if (rename(tmp.name, target) != 0)
    st = zr__diag(ctx, ZR_DIAG_ERROR, ZR_EIO, NULL,
                  "radiosity: cannot rename '%s' to '%s': %s", tmp.name,
                  path, strerror(errno));
  if (st != ZR_OK && tmp.named)
    unlink(tmp.name);
  zr__io_temp_free(&tmp);
  free(target);
  return st;
}

/* ---- load ---- */

/* Reads node n's radiosity and subtree; false on a short or bad file. */
static bool load_tree(FILE *f, zr_radiosity *rad, int32_t n, int depth,
                      uint32_t version) {
  int flag = fgetc(f);
  if (flag != 0 && flag != 1)
    return false;
  for (int k = 0; k < (version >= 3 ? 2 : 1); k++)
    for (int side = 0; side < 2; side++)
      for (int c = 0; c < 3; c++) {
        double v;
        if (!get_f64(f, &v) || !isfinite(v))
          return false;
        (k ? rad->nodes[n].hd : rad->nodes[n].b)[side][c] = v;
      }
  rad->nodes[n].has_direct = 1;
  if (flag == 0)
    return true;
  if (depth >= ZR__RAD_DEPTH || !zr__rad_subdivide(rad, n))
    return false;
  for (int k = 0; k < 4; k++)
    if (!load_tree(f, rad, rad->nodes[n].child + k, depth + 1, version))
      return false;
  return true;
}

/* node[k] = the node whose preorder number (as save_tree counts) is k. */
static void number_nodes(const zr_radiosity *rad, int32_t n, int32_t *node,
                         uint32_t *next) {
  node[(*next)++] = n;
  if (rad->nodes[n].child >= 0)
    for (int k = 0; k < 4; k++)
      number_nodes(rad, rad->nodes[n].child + k, node, next);
}

/* Reads the links; false on a short file or one naming nodes or sides
   the trees do not have. */
static bool load_links(FILE *f, zr_radiosity *rad) {
  /* The links are the rest of the file, 26 bytes each: a count that
     does not match its length is corrupt (and is never allocated). */
  enum { LINK_BYTES = 4 + 4 + 1 + 1 + 8 + 8 };
  uint64_t n;
  if (!get_u64(f, &n) || n > UINT32_MAX)
    return false;
  long here = ftell(f);
  if (here < 0 || fseek(f, 0, SEEK_END) != 0)
    return false;
  long end = ftell(f);
  if (end < here || fseek(f, here, SEEK_SET) != 0 ||
      (uint64_t)(end - here) != n * LINK_BYTES)
    return false;
  int32_t *node = malloc((rad->n_nodes + 1) * sizeof *node);
  zr__rad_link *links = calloc(n + 1, sizeof *links);
  bool ok = node != NULL && links != NULL;
  uint32_t next = 0;
  for (size_t s = 0; ok && s < rad->n_surfs; s++)
    number_nodes(rad, rad->surfs[s].root, node, &next);
  for (uint64_t i = 0; ok && i < n; i++) {
    uint32_t recv, src;
    int rside, sside;
    zr__rad_link *l = &links[i];
    ok = get_u32(f, &recv) && get_u32(f, &src) &&
         (rside = fgetc(f)) >= 0 && rside <= 1 && (sside = fgetc(f)) >= 0 &&
         sside <= 1 && get_f64(f, &l->ff) && get_f64(f, &l->vis) &&
         recv < next && src < next && isfinite(l->ff) && isfinite(l->vis);
    if (ok) {
      l->recv = node[recv];
      l->src = node[src];
      l->rside = (uint8_t)rside;
      l->sside = (uint8_t)sside;
      l->final = 1;
    }
  }
  free(node);
  if (!ok) {
    free(links);
    return false;
  }
  free(rad->links);
  rad->links = links;
  rad->n_links = rad->cap_links = (size_t)n;
  return true;
}

static zr_status read_header(zr_context *ctx, FILE *f, const char *path,
                             zr_radiosity *rad, uint32_t *version_out) {
  char magic[8];
  uint32_t version, n_surfs, vis, uniform, shooting, rounds, its, lookup;
  uint64_t fp, links;
  if (fread(magic, 1, 8, f) != 8 || memcmp(magic, MAGIC, 8) != 0)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                    "radiosity: '%s' is not a zRcube radiosity file", path);
  if (!get_u32(f, &version) || version < 2 || version > VERSION)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                    "radiosity: '%s' has an unknown version", path);
  if (!get_u64(f, &fp) || !get_u32(f, &n_surfs))
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                    "radiosity: '%s' is truncated", path);
  if (fp != rad->fingerprint || n_surfs != rad->n_surfs)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EINVAL, NULL,
                    "radiosity: '%s' was solved for another scene "
                    "(fingerprint %016llx, this scene %016llx)",
                    path, (unsigned long long)fp,
                    (unsigned long long)rad->fingerprint);
  if (!get_f64(f, &rad->params.bf_eps) ||
      !get_f64(f, &rad->params.area_eps) || !get_u32(f, &vis) ||
      !get_u32(f, &uniform) || !get_u32(f, &shooting) ||
      !get_u64(f, &links) || !get_u32(f, &rounds) || !get_u32(f, &its) ||
      !get_f64(f, &rad->stats.residual) || !get_u32(f, &lookup) ||
      lookup > 1)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                    "radiosity: '%s' is truncated", path);
  rad->params.visibility_rays = (int)vis;
  rad->params.uniform = (int)uniform;
  rad->params.shooting = (int)shooting;
  rad->stats.links = (size_t)links;
  rad->params.lookup = (int)lookup;
  rad->stats.refine_rounds = (int)rounds;
  rad->stats.iterations = (int)its;
  *version_out = version;
  return ZR_OK;
}

ZR_API zr_status zr_radiosity_load(zr_context *ctx, const zr_scene *scene,
                                   const char *path, zr_radiosity **out) {
  *out = NULL;
  char why[512];
  FILE *f = NULL;
  zr_status os = zr__io_open_named(path, &f, why, sizeof why);
  if (os != ZR_OK)
    return zr__diag(ctx, ZR_DIAG_ERROR, os, NULL, "radiosity: cannot read "
                    "%s", why);
  zr_radiosity *rad;
  uint32_t version = VERSION;
  zr_status st = zr__rad_create(ctx, scene, NULL, &rad);
  if (st == ZR_OK)
    st = read_header(ctx, f, path, rad, &version);
  for (size_t s = 0; st == ZR_OK && s < rad->n_surfs; s++)
    if (!load_tree(f, rad, rad->surfs[s].root, 0, version))
      st = zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                    "radiosity: '%s' is truncated or corrupt", path);
  if (st == ZR_OK && !load_links(f, rad))
    st = zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                  "radiosity: '%s' has truncated or corrupt links", path);
  fclose(f);
  if (st != ZR_OK) {
    zr_radiosity_free(rad);
    return st;
  }
  zr__rad_smooth(rad);
  zr__rad_count(rad);
  if (rad->params.lookup == 0 && zr__rad_index_links(rad) != ZR_OK) {
    zr_radiosity_free(rad);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL,
                    "radiosity: out of memory indexing links");
  }
  *out = rad;
  return ZR_OK;
}
