/*
 * team.c - exchanging the parts of a shared computation among the
 * members of a team (see team.h).  Every exchange starts with the
 * members' statuses and sizes, so a member that failed (out of memory)
 * makes the others fail with it instead of leaving them waiting in an
 * allgather it never enters, and the parts' sizes need not be known in
 * advance.
 */
#include "core/team.h"

#include <stdlib.h>
#include <string.h>

void zr__team_parts_free(zr__team_parts *parts) {
  if (parts == NULL)
    return;
  free(parts->bytes);
  free(parts->offset);
  parts->bytes = NULL;
  parts->offset = NULL;
}

/* The header each member sends first. */
typedef struct header {
  int64_t status;
  uint64_t bytes;
} header;

zr_status zr__team_exchange(const zr_team *t, zr_status local,
                            const void *mine, size_t bytes,
                            zr__team_parts *out) {
  out->bytes = NULL;
  out->offset = NULL;
  int n = zr__team_size(t);
  out->offset = malloc(((size_t)n + 1) * sizeof *out->offset);
  header *heads = malloc((size_t)n * sizeof *heads);
  size_t *counts = malloc((size_t)n * sizeof *counts);
  if (n == 1) {
    zr_status s = local;
    if (s == ZR_OK && (!out->offset || !heads || !counts))
      s = ZR_ENOMEM;
    if (s == ZR_OK) {
      out->bytes = malloc(bytes ? bytes : 1);
      if (!out->bytes)
        s = ZR_ENOMEM;
      else if (bytes)
        memcpy(out->bytes, mine, bytes);
      out->offset[0] = 0;
      out->offset[1] = bytes;
    }
    free(heads);
    free(counts);
    if (s != ZR_OK)
      zr__team_parts_free(out);
    return s;
  }
  /* A member without room for the headers cannot take part at all;
     that is a failure every member must see, yet the allgather needs
     the room.  The three arrays are n small words each: with those
     out of reach the team's transport has failed anyway. */
  if (!out->offset || !heads || !counts) {
    free(heads);
    free(counts);
    zr__team_parts_free(out);
    return ZR_ENOMEM;
  }
  header me = {local, bytes};
  for (int r = 0; r < n; r++)
    counts[r] = sizeof(header);
  zr_status s = t->allgather(t->user, &me, heads, counts);
  if (s == ZR_OK) {
    for (int r = 0; r < n; r++)
      if (heads[r].status < s)
        s = (zr_status)heads[r].status;
  }
  size_t total = 0;
  if (s == ZR_OK) {
    for (int r = 0; r < n; r++) {
      out->offset[r] = total;
      counts[r] = (size_t)heads[r].bytes;
      total += counts[r];
    }
    out->offset[n] = total;
    out->bytes = malloc(total ? total : 1);
    /* Every member learns whether every other found the room. */
    zr_status room = out->bytes ? ZR_OK : ZR_ENOMEM;
    header ok = {room, 0};
    size_t *c16 = malloc((size_t)n * sizeof *c16);
    if (c16 == NULL) {
      s = ZR_ENOMEM; /* see above: a transport that cannot hold n words */
    } else {
      for (int r = 0; r < n; r++)
        c16[r] = sizeof(header);
      s = t->allgather(t->user, &ok, heads, c16);
      free(c16);
      for (int r = 0; s == ZR_OK && r < n; r++)
        if (heads[r].status < s)
          s = (zr_status)heads[r].status;
    }
  }
  if (s == ZR_OK)
    s = t->allgather(t->user, mine, out->bytes, counts);
  free(heads);
  free(counts);
  if (s != ZR_OK)
    zr__team_parts_free(out);
  return s;
}

zr_status zr__team_agree(const zr_team *t, zr_status local) {
  int n = zr__team_size(t);
  if (n == 1)
    return local;
  /* One allgather of the headers alone. */
  header *heads = malloc((size_t)n * sizeof *heads);
  size_t *counts = malloc((size_t)n * sizeof *counts);
  zr_status s = ZR_ENOMEM;
  if (heads && counts) {
    header me = {local, 0};
    for (int r = 0; r < n; r++)
      counts[r] = sizeof(header);
    s = t->allgather(t->user, &me, heads, counts);
    for (int r = 0; s == ZR_OK && r < n; r++)
      if (heads[r].status < s)
        s = (zr_status)heads[r].status;
  }
  free(heads);
  free(counts);
  return s;
}

void zr__pack_put(zr__pack *p, const void *bytes, size_t n) {
  if (p->nomem)
    return;
  if (p->cap - p->n < n) {
    size_t cap = p->cap ? p->cap : 256;
    while (cap - p->n < n)
      cap *= 2;
    char *b = realloc(p->bytes, cap);
    if (b == NULL) {
      p->nomem = 1;
      return;
    }
    p->bytes = b;
    p->cap = cap;
  }
  memcpy(p->bytes + p->n, bytes, n);
  p->n += n;
}

void zr__pack_free(zr__pack *p) {
  free(p->bytes);
  p->bytes = NULL;
  p->n = p->cap = 0;
}
