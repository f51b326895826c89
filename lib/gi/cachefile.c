/*
 * cachefile.c - the irradiance cache on disk: POV-Ray 3.6's save_file
 * and load_file in the radiosity block (3.7 moved them to the command
 * line as +RFO and +RFI; zrcube takes --gi-save and --gi-load).
 *
 * The file is zRcube's own: a text header line
 *   "zRcube irradiance cache 1 <records>\n"
 * then each record as 29 little-endian IEEE doubles (point, normal,
 * three values, two gradients per channel, radius, and its depth as a
 * whole number), in the order the records joined the cache, so a loaded cache
 * is the same records in the same order and renders the same bytes.
 */
#include "gi/gi.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/context.h"

#define MAGIC "zRcube irradiance cache 1"
#define FIELDS 29

static void pack(const zr__gi_record *r, double *v) {
  int k = 0;
  v[k++] = r->p.x, v[k++] = r->p.y, v[k++] = r->p.z;
  v[k++] = r->n.x, v[k++] = r->n.y, v[k++] = r->n.z;
  for (int c = 0; c < 3; c++)
    v[k++] = r->e[c];
  for (int c = 0; c < 3; c++) {
    v[k++] = r->grad_r[c].x, v[k++] = r->grad_r[c].y;
    v[k++] = r->grad_r[c].z;
  }
  for (int c = 0; c < 3; c++) {
    v[k++] = r->grad_t[c].x, v[k++] = r->grad_t[c].y;
    v[k++] = r->grad_t[c].z;
  }
  v[k++] = r->r;
  v[k++] = (double)r->depth;
}

static bool unpack(const double *v, zr__gi_record *r) {
  int k = 0;
  for (int i = 0; i < FIELDS; i++)
    if (!isfinite(v[i]))
      return false;
  r->p = zr_v3(v[0], v[1], v[2]);
  r->n = zr_v3(v[3], v[4], v[5]);
  k = 6;
  for (int c = 0; c < 3; c++)
    r->e[c] = v[k++];
  for (int c = 0; c < 3; c++, k += 3)
    r->grad_r[c] = zr_v3(v[k], v[k + 1], v[k + 2]);
  for (int c = 0; c < 3; c++, k += 3)
    r->grad_t[c] = zr_v3(v[k], v[k + 1], v[k + 2]);
  r->r = v[k++];
  double d = v[k];
  if (!(r->r > 0.0) || !(d >= 0.0 && d < 20.0) || d != (int)d)
    return false;
  r->depth = (int32_t)d;
  return true;
}

/* Doubles as 8 little-endian bytes whatever the host's order. */
static void put_double(unsigned char *b, double x) {
  uint64_t u;
  memcpy(&u, &x, sizeof u);
  for (int i = 0; i < 8; i++)
    b[i] = (unsigned char)(u >> (8 * i));
}

static double get_double(const unsigned char *b) {
  uint64_t u = 0;
  for (int i = 0; i < 8; i++)
    u |= (uint64_t)b[i] << (8 * i);
  double x;
  memcpy(&x, &u, sizeof x);
  return x;
}

ZR_API zr_status zr_gi_cache_save(zr_context *ctx, const zr_gi_cache *c,
                                  const char *path) {
  if (!c || !path)
    return ZR_EINVAL;
  FILE *f = fopen(path, "wb");
  if (!f)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EIO, NULL,
                    "cannot write the irradiance cache '%s': %s", path,
                    strerror(errno));
  bool ok = fprintf(f, "%s %zu\n", MAGIC, c->records.n) > 0;
  for (size_t i = 0; ok && i < c->records.n; i++) {
    double v[FIELDS];
    unsigned char b[FIELDS * 8];
    pack(&c->records.v[i], v);
    for (int k = 0; k < FIELDS; k++)
      put_double(b + 8 * k, v[k]);
    ok = fwrite(b, 1, sizeof b, f) == sizeof b;
  }
  if (fclose(f) != 0)
    ok = false;
  if (!ok)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_EIO, NULL,
                    "cannot write the irradiance cache '%s'", path);
  return ZR_OK;
}

ZR_API zr_status zr_gi_cache_load(zr_context *ctx, const zr_scene *scene,
                                  const zr_gi_params *params,
                                  const char *path, zr_gi_cache **out) {
  if (!scene || !path || !out)
    return ZR_EINVAL;
  *out = NULL;
  FILE *f = fopen(path, "rb");
  if (!f)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOTFOUND, NULL,
                    "cannot read the irradiance cache '%s': %s", path,
                    strerror(errno));
  char line[128];
  size_t n = 0;
  char tail = 0;
  bool ok = fgets(line, sizeof line, f) != NULL &&
            strncmp(line, MAGIC " ", sizeof MAGIC) == 0 &&
            sscanf(line + sizeof MAGIC, "%zu%c", &n, &tail) == 2 &&
            tail == '\n';
  zr_gi_cache *c = NULL;
  zr_status s = ok ? zr_gi_cache_new(ctx, scene, params, &c) : ZR_EFORMAT;
  for (size_t i = 0; s == ZR_OK && i < n; i++) {
    unsigned char b[FIELDS * 8];
    double v[FIELDS];
    zr__gi_record r;
    if (fread(b, 1, sizeof b, f) != sizeof b) {
      s = ZR_EFORMAT;
      break;
    }
    for (int k = 0; k < FIELDS; k++)
      v[k] = get_double(b + 8 * k);
    if (!unpack(v, &r))
      s = ZR_EFORMAT;
    else if (!zr__gi_cache_add(c, &r))
      s = ZR_ENOMEM;
  }
  if (s == ZR_OK && fgetc(f) != EOF)
    s = ZR_EFORMAT; /* more bytes than the header announced */
  fclose(f);
  if (s != ZR_OK) {
    zr_gi_cache_free(c);
    if (s == ZR_EFORMAT)
      return zr__diag(ctx, ZR_DIAG_ERROR, s, NULL,
                      "'%s' is not an irradiance cache zRcube wrote, or "
                      "it is cut short", path);
    return s;
  }
  *out = c;
  return ZR_OK;
}
