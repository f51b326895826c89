/*
 * team.h - the library's side of a team (zr_team in zrcube.h): members
 * that share one computation and exchange their parts of it.
 *
 * Work is dealt to members by a rule every member evaluates alike (a
 * fixed order of items, member r taking the chunks r, r + n, ...), so no
 * member has to be told what to do; after the work, one exchange gives
 * every member every part, and each member combines them in the same
 * order.  Nothing here talks to a network: the caller's allgather does.
 */
#ifndef ZR_CORE_TEAM_H
#define ZR_CORE_TEAM_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "zrcube.h"

/*
 * Room kept from one exchange to the next by a caller that exchanges
 * many times (a radiosity solve: a dozen exchanges of up to megabytes,
 * and a hundred sweeps).  Fresh room each time costs a page fault for
 * every page first touched (14 us a 4 KiB page, or a 2 MiB page zeroed,
 * on this project's virtual machine), and a member sending a large part
 * waits, spinning in MPI, while the other copies it into fresh pages:
 * see zr__team_exchange_in.  It only grows; zr__team_room_free.
 */
typedef struct zr__team_room {
  char *bytes;
  size_t cap;
} zr__team_room;

/* The members' parts after an exchange: member r's part is
   bytes[offset[r] .. offset[r + 1]). */
typedef struct zr__team_parts {
  char *bytes;
  size_t *offset; /* size + 1 entries */
  /* Non-NULL: bytes are this room's, which zr__team_parts_free leaves
     to its owner. */
  zr__team_room *room;
} zr__team_parts;

/* Members and this member's rank; NULL is a team of one. */
static inline int zr__team_size(const zr_team *t) {
  return t != NULL && t->size > 1 ? t->size : 1;
}
static inline int zr__team_rank(const zr_team *t) {
  return zr__team_size(t) > 1 ? t->rank : 0;
}

/* Whether chunk (of a fixed sequence of chunks) is this member's: the
   chunks are dealt round robin. */
static inline int zr__team_mine(const zr_team *t, size_t chunk) {
  return (int)(chunk % (size_t)zr__team_size(t)) == zr__team_rank(t);
}

/*
 * Collective.  Every member passes its status and its part (bytes long);
 * every member gets the same answer: ZR_OK with every part in *out (free
 * with zr__team_parts_free) when all succeeded, else the lowest failure
 * code among the members, so all take the same branch.  Two calls of
 * allgather: the members' statuses and sizes (16 bytes each), then the
 * parts.  A team of one copies its part.
 */
zr_status zr__team_exchange(const zr_team *t, zr_status local,
                            const void *mine, size_t bytes,
                            zr__team_parts *out);
void zr__team_parts_free(zr__team_parts *parts);

/* zr__team_exchange with the parts, when they do not travel with the
   headers, in room (grown when too small) instead of fresh memory;
   room NULL is zr__team_exchange.  The parts hold the room until
   zr__team_parts_free. */
zr_status zr__team_exchange_in(const zr_team *t, zr_status local,
                               const void *mine, size_t bytes,
                               zr__team_room *room, zr__team_parts *out);

/* room's bytes, at least size of them (grown, the contents lost, when
   it holds fewer); NULL when out of memory, the room then unchanged. */
char *zr__team_room_get(zr__team_room *room, size_t size);
void zr__team_room_free(zr__team_room *room);

/* The status all members agree on (a status-only exchange:
   zr__team_same_key with key 0). */
zr_status zr__team_agree(const zr_team *t, zr_status local);

/*
 * Collective: the status all members agree on, as zr__team_agree, and
 * whether they all passed the same key (ZR_EINVAL when every member
 * succeeded but the keys differ).  A computation whose members may have
 * taken different paths (each member parses the scene files it read
 * itself: another host's copy may differ) calls it before every
 * exchange with a key naming the step and its input, and goes on
 * together only on ZR_OK: every call is an allgather of the same size,
 * so members that reached different steps still meet in it, learn it
 * and stop together instead of waiting in exchanges the others never
 * enter (lib/sdl's parse with a team, zr_context_set_team).
 */
zr_status zr__team_same_key(const zr_team *t, zr_status local,
                            uint64_t key);
/* The key of a parse's last call (lib/sdl/directive.c); the keys of
   the steps before it are never 0. */
#define ZR__TEAM_KEY_DONE ((uint64_t)0)

/* A growable byte buffer for packing a part. */
typedef struct zr__pack {
  char *bytes;
  size_t n, cap;
  int nomem;
} zr__pack;

void zr__pack_put(zr__pack *p, const void *bytes, size_t n);
/* Room for n more bytes at once, where the caller knows the size: the
   pack is then made once instead of grown by doubling. */
void zr__pack_reserve(zr__pack *p, size_t n);
void zr__pack_free(zr__pack *p);
/* Empties p for the next part, keeping its room (see zr__team_room). */
static inline void zr__pack_reset(zr__pack *p) {
  p->n = 0;
  p->nomem = 0;
}

/* Reads n bytes at *at from a part ending at end; 0 when it runs out. */
static inline int zr__unpack(const char **at, const char *end, void *dst,
                             size_t n) {
  if ((size_t)(end - *at) < n)
    return 0;
  memcpy(dst, *at, n);
  *at += n;
  return 1;
}

#endif /* ZR_CORE_TEAM_H */
