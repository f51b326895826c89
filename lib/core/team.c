/*
 * team.c - exchanging the parts of a shared computation among the
 * members of a team (see team.h).  Every exchange starts with the
 * members' statuses and sizes, so a member that failed (out of memory)
 * makes the others fail with it instead of leaving them waiting in an
 * allgather it never enters, and the parts' sizes need not be known in
 * advance.
 */
#include "core/team.h"

#include "core/hugepage.h"

#include <assert.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

void zr__team_parts_free(zr__team_parts *parts) {
  if (parts == NULL)
    return;
  if (parts->room == NULL)
    free(parts->bytes);
  free(parts->offset);
  parts->bytes = NULL;
  parts->offset = NULL;
  parts->room = NULL;
}

/*
 * Room for the parts of an exchange, or for packing a part, freed with
 * free.  Both are fresh memory each time (the caller unpacks the parts
 * and frees them; a pack grows by doubling), and on this project's
 * virtual machine first touching a 4 KiB page costs about 14 us: a
 * 2-rank hierarchical solve of scenes/cornell.pov received 14.9 MB in
 * 12 such exchanges (44 KB to 2.4 MB) and packed as much, and its
 * ranks took 8,300 page faults each where a 1-rank run took 4,770
 * (perf -e page-faults: the growing packs and the parts' room).  From
 * ROOM_HUGE bytes on the room is whole 2 MiB pages advised to huge
 * pages (core/hugepage.h), one fault each; *size is rounded up to the
 * room made.
 */
#define ROOM_HUGE (ZR__HUGE_PAGE / 2)

static char *room_alloc(size_t *size) {
  if (*size < ROOM_HUGE || *size > SIZE_MAX - ZR__HUGE_PAGE)
    return malloc(*size ? *size : 1);
  size_t room = (*size + ZR__HUGE_PAGE - 1) & ~(ZR__HUGE_PAGE - 1);
  void *p = NULL;
  if (posix_memalign(&p, ZR__HUGE_PAGE, room) != 0)
    return NULL;
  zr__mem_advise_huge(p, room);
  *size = room;
  return p;
}

char *zr__team_room_get(zr__team_room *room, size_t size) {
  if (room->bytes != NULL && room->cap >= size)
    return room->bytes;
  /* Half as much again as asked, so that parts growing a little from
     one exchange to the next (a solve's later rounds) fit. */
  size_t want = size > SIZE_MAX / 3 ? size : size + size / 2;
  char *b = room_alloc(&want);
  if (b == NULL)
    return NULL;
  free(room->bytes);
  room->bytes = b;
  room->cap = want;
  return b;
}

void zr__team_room_free(zr__team_room *room) {
  free(room->bytes);
  room->bytes = NULL;
  room->cap = 0;
}

/* The header each member sends first. */
typedef struct header {
  int64_t status;
  uint64_t bytes;
} header;

/* Parts up to this size travel with the headers, in one allgather of
   SLOT bytes a member, for teams of up to INLINE_MEMBERS (the room for
   them is on the stack, so taking part cannot fail for memory). */
#define SLOT 4096
#define INLINE_MEMBERS 16
/* Larger teams send headers alone first, from the stack up to this. */
#define STACK_HEADERS 4096

zr_status zr__team_exchange(const zr_team *t, zr_status local,
                            const void *mine, size_t bytes,
                            zr__team_parts *out) {
  return zr__team_exchange_in(t, local, mine, bytes, NULL, out);
}

zr_status zr__team_exchange_in(const zr_team *t, zr_status local,
                               const void *mine, size_t bytes,
                               zr__team_room *room, zr__team_parts *out) {
  out->bytes = NULL;
  out->offset = NULL;
  out->room = NULL;
  int n = zr__team_size(t);
  size_t inline_cap = n <= INLINE_MEMBERS ? SLOT - sizeof(header) : 0;
  size_t slot = sizeof(header) + inline_cap;
  /* Room made before the first allgather: a member without it says so
     in its header, and every member fails alike. */
  out->offset = malloc(((size_t)n + 1) * sizeof *out->offset);
  size_t reserve = (size_t)n * inline_cap;
  out->bytes = malloc(reserve ? reserve : 1);
  if (n == 1) {
    zr_status s = local;
    free(out->bytes);
    out->bytes = NULL;
    if (s == ZR_OK && out->offset)
      out->bytes = malloc(bytes ? bytes : 1);
    if (s == ZR_OK && (!out->offset || !out->bytes))
      s = ZR_ENOMEM;
    if (s == ZR_OK) {
      if (bytes)
        memcpy(out->bytes, mine, bytes);
      out->offset[0] = 0;
      out->offset[1] = bytes;
    } else {
      zr__team_parts_free(out);
    }
    return s;
  }
  static_assert(INLINE_MEMBERS * SLOT <= 65536, "stack room");
  static_assert(STACK_HEADERS * sizeof(header) <= 65536, "stack room");
  char stack[65536];
  char *recv = (size_t)n * slot <= sizeof stack ? stack
                                                : malloc((size_t)n * slot);
  size_t *counts = malloc((size_t)n * sizeof *counts);
  header me = {local, bytes};
  if (me.status == ZR_OK && (!out->offset || !out->bytes || !counts))
    me.status = ZR_ENOMEM;
  if (recv == NULL || counts == NULL) {
    /* Only a team of more than STACK_HEADERS members gets here without
       room to take part; its transport holds as much per member. */
    if (recv != stack)
      free(recv);
    free(counts);
    zr__team_parts_free(out);
    return ZR_ENOMEM;
  }
  char send[SLOT];
  memcpy(send, &me, sizeof me);
  if (bytes <= inline_cap && bytes > 0)
    memcpy(send + sizeof me, mine, bytes);
  for (int r = 0; r < n; r++)
    counts[r] = slot;
  zr_status s = t->allgather(t->user, send, recv, counts);
  bool all_inline = true;
  size_t total = 0;
  for (int r = 0; s == ZR_OK && r < n; r++) {
    header h;
    memcpy(&h, recv + (size_t)r * slot, sizeof h);
    if (h.status < s)
      s = (zr_status)h.status;
    out->offset[r] = total;
    counts[r] = (size_t)h.bytes;
    total += counts[r];
    all_inline = all_inline && counts[r] <= inline_cap;
  }
  if (s == ZR_OK) {
    out->offset[n] = total;
    if (all_inline) {
      for (int r = 0; r < n; r++)
        if (counts[r] > 0)
          memcpy(out->bytes + out->offset[r],
                 recv + (size_t)r * slot + sizeof(header), counts[r]);
    } else {
      /* Larger parts: room for all of them, agreed, then the parts. */
      free(out->bytes);
      if (room != NULL) {
        out->bytes = zr__team_room_get(room, total);
        out->room = out->bytes ? room : NULL;
      } else {
        size_t made = total;
        out->bytes = room_alloc(&made);
      }
      s = zr__team_agree(t, out->bytes ? ZR_OK : ZR_ENOMEM);
      if (s == ZR_OK)
        s = t->allgather(t->user, mine, out->bytes, counts);
    }
  }
  if (recv != stack)
    free(recv);
  free(counts);
  if (s != ZR_OK)
    zr__team_parts_free(out);
  return s;
}

zr_status zr__team_same_key(const zr_team *t, zr_status local,
                            uint64_t key) {
  int n = zr__team_size(t);
  if (n == 1)
    return local;
  /* One allgather of the headers, the key where the size goes. */
  header *heads = malloc((size_t)n * sizeof *heads);
  size_t *counts = malloc((size_t)n * sizeof *counts);
  zr_status s = ZR_ENOMEM;
  if (heads && counts) {
    header me = {local, key};
    for (int r = 0; r < n; r++)
      counts[r] = sizeof(header);
    s = t->allgather(t->user, &me, heads, counts);
    bool same = true;
    for (int r = 0; s == ZR_OK && r < n; r++) {
      if (heads[r].status < s)
        s = (zr_status)heads[r].status;
      same = same && heads[r].bytes == key;
    }
    if (s == ZR_OK && !same)
      s = ZR_EINVAL;
  }
  free(heads);
  free(counts);
  return s;
}

/* A status-only exchange is zr__team_same_key's allgather with the key
   every member passes alike: the same one call, the same bits.  A
   member in zr__team_agree that meets another's keyed step (a bug) now
   fails with it, ZR_EINVAL on both, instead of one side going on. */
zr_status zr__team_agree(const zr_team *t, zr_status local) {
  return zr__team_same_key(t, local, 0);
}

/* Room for n more bytes: the capacity doubled from 256 until it holds
   them (exact, with exact set, from 256 bytes on). */
static void pack_room(zr__pack *p, size_t n, bool exact) {
  if (p->nomem || p->cap - p->n >= n)
    return;
  if (n > SIZE_MAX / 2 - p->n) {
    p->nomem = 1;
    return;
  }
  size_t cap = p->cap ? p->cap : 256;
  if (exact && p->n + n > cap)
    cap = p->n + n;
  while (cap - p->n < n)
    cap *= 2;
  /* Big packs move into huge pages (room_alloc); below, realloc. */
  char *b = cap < ROOM_HUGE ? realloc(p->bytes, cap) : room_alloc(&cap);
  if (b == NULL) {
    p->nomem = 1;
    return;
  }
  if (cap >= ROOM_HUGE) {
    if (p->n > 0)
      memcpy(b, p->bytes, p->n);
    free(p->bytes);
  }
  p->bytes = b;
  p->cap = cap;
}

void zr__pack_reserve(zr__pack *p, size_t n) { pack_room(p, n, true); }

void zr__pack_put(zr__pack *p, const void *bytes, size_t n) {
  pack_room(p, n, false);
  if (p->nomem)
    return;
  memcpy(p->bytes + p->n, bytes, n);
  p->n += n;
}

void zr__pack_free(zr__pack *p) {
  free(p->bytes);
  p->bytes = NULL;
  p->n = p->cap = 0;
}
