/*
 * symtab.c - symbol tables: open-addressing hash tables from names to
 * values.
 *
 * POV-Ray looks identifiers up in a stack of tables (reference manual,
 * "Identifier Name Collisions"): the global table of #declare, then one
 * per include file and macro call for #local.  The global table of a
 * scene holding the stock includes has thousands of names, and a loop
 * looks its counter up on every iteration, so each table hashes (FNV-1a)
 * into a power-of-two array probed linearly, kept at most 3/4 full
 * counting the tombstones #undef leaves.  A table that was never written
 * holds no memory: macro calls that declare nothing cost no allocation.
 */
#include "config.h"

#include <stdlib.h>
#include <string.h>

#include "sdl/sdl.h"

static unsigned hash_name(const char *s) {
  unsigned h = 2166136261u;
  for (; *s; s++)
    h = (h ^ (unsigned char)*s) * 16777619u;
  return h;
}

void zr__sdl_symtab_init(zr_sdl_symtab *t) { memset(t, 0, sizeof *t); }

void zr__sdl_symtab_free(zr_sdl_symtab *t) {
  for (size_t i = 0; i < t->cap; i++)
    free(t->slots[i].name);
  free(t->slots);
  memset(t, 0, sizeof *t);
}

/* The slot holding name, or NULL. */
static zr_sdl_symbol *find(const zr_sdl_symtab *t, const char *name,
                           unsigned h) {
  if (t->cap == 0)
    return NULL;
  size_t mask = t->cap - 1;
  for (size_t i = h & mask;; i = (i + 1) & mask) {
    zr_sdl_symbol *s = &t->slots[i];
    if (!s->name)
      return NULL;
    if (!s->removed && s->hash == h && strcmp(s->name, name) == 0)
      return s;
  }
}

zr_sdl_symbol *zr__sdl_symtab_find(zr_sdl_symtab *t, const char *name) {
  return find(t, name, hash_name(name));
}

/* Rebuilds the table with cap slots, dropping tombstones. */
static zr_status rehash(zr_sdl_symtab *t, size_t cap) {
  zr_sdl_symbol *slots = calloc(cap, sizeof *slots);
  if (!slots)
    return ZR_ENOMEM;
  for (size_t i = 0; i < t->cap; i++) {
    zr_sdl_symbol *s = &t->slots[i];
    if (!s->name)
      continue;
    if (s->removed) {
      free(s->name);
      continue;
    }
    size_t j = s->hash & (cap - 1);
    while (slots[j].name)
      j = (j + 1) & (cap - 1);
    slots[j] = *s;
  }
  free(t->slots);
  t->slots = slots;
  t->cap = cap;
  t->used = t->n;
  return ZR_OK;
}

zr_status zr__sdl_symtab_set(zr_sdl_symtab *t, const char *name,
                             const zr_sdl_value *value) {
  unsigned h = hash_name(name);
  zr_sdl_symbol *s = find(t, name, h);
  if (s) {
    s->value = *value;
    return ZR_OK;
  }
  if ((t->used + 1) * 4 > t->cap * 3) {
    size_t cap = t->cap ? t->cap : 8;
    while ((t->n + 1) * 2 > cap)
      cap *= 2;
    if (rehash(t, cap) != ZR_OK)
      return ZR_ENOMEM;
  }
  char *copy = strdup(name);
  if (!copy)
    return ZR_ENOMEM;
  size_t mask = t->cap - 1;
  size_t i = h & mask;
  while (t->slots[i].name)
    i = (i + 1) & mask;
  t->slots[i].name = copy;
  t->slots[i].hash = h;
  t->slots[i].removed = false;
  t->slots[i].deprecated = false;
  t->slots[i].warned = false;
  t->slots[i].value = *value;
  t->n++;
  t->used++;
  return ZR_OK;
}

void zr__sdl_symtab_remove(zr_sdl_symtab *t, const char *name) {
  zr_sdl_symbol *s = zr__sdl_symtab_find(t, name);
  if (!s)
    return;
  /* The slot stays taken so later names in its probe run are found. */
  s->removed = true;
  t->n--;
}
