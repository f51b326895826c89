/*
 * test_team.c - teams (zr_team, lib/core/team.c): members that share a
 * computation and exchange its parts.  The members here are threads of
 * this process with an allgather over shared memory, so the library's
 * side of a team is tested without MPI (lib/par's MPI allgather is
 * tested end to end by test_rad_cli.sh, test_gi_cli.sh and
 * test_mpi_example.sh): the exchange protocol (small parts with the
 * headers, large parts after, failures agreed on every member), and a
 * radiosity solve and an irradiance cache pretrace shared by 3 members
 * giving the same bytes as one process alone.
 */
#include <math.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "core/hugepage.h"
#include "core/team.h"
#include "scene/scene.h"
#include "scene/shapes.h"
#include "trace/bvh_wide.h"
#include "zrcube.h"

#define MEMBERS 3

/* An allgather among threads: each writes its part into the shared
   buffer at its offset, all wait, each copies everything out, all wait
   again before the buffer is reused. */
typedef struct hall {
  pthread_barrier_t barrier;
  char *shared;
  size_t cap;
  pthread_mutex_t lock;
  int calls[MEMBERS];
} hall;

typedef struct member {
  hall *hall;
  int rank;
  zr_team team;
} member;

static zr_status thread_allgather(void *user, const void *mine, void *all,
                                  const size_t *counts) {
  member *m = user;
  hall *h = m->hall;
  size_t total = 0, at = 0;
  for (int r = 0; r < MEMBERS; r++) {
    if (r == m->rank)
      at = total;
    total += counts[r];
  }
  if (m->rank == 0) {
    pthread_mutex_lock(&h->lock);
    if (total > h->cap) {
      free(h->shared);
      h->shared = malloc(total);
      h->cap = total;
    }
    pthread_mutex_unlock(&h->lock);
  }
  pthread_barrier_wait(&h->barrier);
  if (counts[m->rank] > 0)
    memcpy(h->shared + at, mine, counts[m->rank]);
  pthread_barrier_wait(&h->barrier);
  if (total > 0)
    memcpy(all, h->shared, total);
  h->calls[m->rank]++;
  pthread_barrier_wait(&h->barrier);
  return ZR_OK;
}

static void hall_init(hall *h, member *ms) {
  memset(h, 0, sizeof *h);
  pthread_barrier_init(&h->barrier, NULL, MEMBERS);
  pthread_mutex_init(&h->lock, NULL);
  for (int r = 0; r < MEMBERS; r++) {
    ms[r].hall = h;
    ms[r].rank = r;
    ms[r].team.rank = r;
    ms[r].team.size = MEMBERS;
    ms[r].team.allgather = thread_allgather;
    ms[r].team.user = &ms[r];
  }
}

static void hall_free(hall *h) {
  pthread_barrier_destroy(&h->barrier);
  pthread_mutex_destroy(&h->lock);
  free(h->shared);
}

static void run_members(member *ms, void *(*fn)(void *)) {
  pthread_t tid[MEMBERS];
  for (int r = 0; r < MEMBERS; r++)
    assert_int_equal(pthread_create(&tid[r], NULL, fn, &ms[r]), 0);
  for (int r = 0; r < MEMBERS; r++)
    pthread_join(tid[r], NULL);
}

/* ---- the exchange protocol ---- */

typedef struct exchange_result {
  zr_status small, large, huge, failed, agreed;
  int small_ok, large_ok, huge_ok;
} exchange_result;

static exchange_result results[MEMBERS];

/* Member r's part of size n: bytes (r * 31 + i) mod 251. */
static char *part(int r, size_t n) {
  char *p = malloc(n ? n : 1);
  for (size_t i = 0; i < n; i++)
    p[i] = (char)((r * 31 + i) % 251);
  return p;
}

static int parts_ok(const zr__team_parts *parts, size_t (*size)(int)) {
  for (int r = 0; r < MEMBERS; r++) {
    size_t n = size(r);
    if (parts->offset[r + 1] - parts->offset[r] != n)
      return 0;
    char *want = part(r, n);
    int same = memcmp(parts->bytes + parts->offset[r], want, n) == 0;
    free(want);
    if (!same)
      return 0;
  }
  return 1;
}

/* Sizes: small parts travel with the headers; member 1 sends nothing. */
static size_t small_size(int r) { return r == 1 ? 0 : 100 + 7 * (size_t)r; }
/* One part over the inline room (4 KB) sends all by the long way. */
static size_t large_size(int r) { return r == 2 ? 100000 : 50; }
/* Parts of 1 MiB and more land in huge pages (team.c, room_alloc), a
   room of whole 2 MiB pages: 2.5 MB in all. */
static size_t huge_size(int r) { return r == 0 ? 2400000 : 50000 + (size_t)r; }

static void *exchange_member(void *p) {
  member *m = p;
  exchange_result *res = &results[m->rank];
  zr__team_parts parts;
  char *mine = part(m->rank, small_size(m->rank));
  res->small = zr__team_exchange(&m->team, ZR_OK, mine,
                                 small_size(m->rank), &parts);
  res->small_ok = res->small == ZR_OK && parts_ok(&parts, small_size);
  zr__team_parts_free(&parts);
  free(mine);
  mine = part(m->rank, large_size(m->rank));
  res->large = zr__team_exchange(&m->team, ZR_OK, mine,
                                 large_size(m->rank), &parts);
  res->large_ok = res->large == ZR_OK && parts_ok(&parts, large_size);
  zr__team_parts_free(&parts);
  free(mine);
  mine = part(m->rank, huge_size(m->rank));
  res->huge = zr__team_exchange(&m->team, ZR_OK, mine,
                                huge_size(m->rank), &parts);
  res->huge_ok = res->huge == ZR_OK && parts_ok(&parts, huge_size) &&
                 (uintptr_t)parts.bytes % ZR__HUGE_PAGE == 0;
  zr__team_parts_free(&parts);
  free(mine);
  /* Member 1 fails with ZR_EIO, member 2 with ZR_ENOMEM: every member
     gets the lowest code, ZR_EIO (-2 < -1). */
  zr_status local = m->rank == 1 ? ZR_EIO : m->rank == 2 ? ZR_ENOMEM : ZR_OK;
  res->failed = zr__team_exchange(&m->team, local, "x", 1, &parts);
  zr__team_parts_free(&parts);
  res->agreed = zr__team_agree(&m->team, m->rank == 2 ? ZR_ELIMIT : ZR_OK);
  return NULL;
}

static void test_team_exchange(void **state) {
  (void)state;
  hall h;
  member ms[MEMBERS];
  hall_init(&h, ms);
  run_members(ms, exchange_member);
  for (int r = 0; r < MEMBERS; r++) {
    assert_int_equal(results[r].small, ZR_OK);
    assert_true(results[r].small_ok);
    assert_int_equal(results[r].large, ZR_OK);
    assert_true(results[r].large_ok);
    assert_int_equal(results[r].huge, ZR_OK);
    assert_true(results[r].huge_ok);
    assert_int_equal(results[r].failed, ZR_EIO);
    assert_int_equal(results[r].agreed, ZR_ELIMIT);
  }
  /* Small parts: one allgather; large (and huge): headers, room,
     parts; a failed exchange stops after the headers; an agreement is
     one. */
  for (int r = 0; r < MEMBERS; r++)
    assert_int_equal(h.calls[r], 1 + 3 + 3 + 1 + 1);
  hall_free(&h);
}

/* Two exchanges into one kept room (zr__team_exchange_in): the same
   parts as without it, both in the room's bytes (freeing the first
   parts left the room to its owner, and the second needed no more),
   which the room still holds after the parts are freed. */
typedef struct room_result {
  int first_ok, second_ok, reused, kept;
} room_result;

static room_result room_results[MEMBERS];

static void *room_member(void *p) {
  member *m = p;
  room_result *res = &room_results[m->rank];
  zr__team_room room = {NULL, 0};
  zr__team_parts parts;
  char *mine = part(m->rank, large_size(m->rank));
  zr_status s = zr__team_exchange_in(&m->team, ZR_OK, mine,
                                     large_size(m->rank), &room, &parts);
  res->first_ok = s == ZR_OK && parts_ok(&parts, large_size) &&
                  parts.room == &room && parts.bytes == room.bytes;
  char *first = room.bytes;
  zr__team_parts_free(&parts);
  s = zr__team_exchange_in(&m->team, ZR_OK, mine, large_size(m->rank),
                           &room, &parts);
  res->second_ok = s == ZR_OK && parts_ok(&parts, large_size);
  res->reused = parts.bytes == first && room.bytes == first;
  zr__team_parts_free(&parts);
  res->kept = room.bytes == first && room.cap >= 100000 + 2 * 50;
  free(mine);
  zr__team_room_free(&room);
  return NULL;
}

static void test_team_exchange_in_room(void **state) {
  (void)state;
  hall h;
  member ms[MEMBERS];
  hall_init(&h, ms);
  run_members(ms, room_member);
  for (int r = 0; r < MEMBERS; r++) {
    assert_true(room_results[r].first_ok);
    assert_true(room_results[r].second_ok);
    assert_true(room_results[r].reused);
    assert_true(room_results[r].kept);
  }
  hall_free(&h);
}

/* A team of one (or none) copies its part. */
static void test_team_of_one(void **state) {
  (void)state;
  zr__team_parts parts;
  assert_int_equal(zr__team_exchange(NULL, ZR_OK, "abc", 3, &parts), ZR_OK);
  assert_int_equal(parts.offset[0], 0);
  assert_int_equal(parts.offset[1], 3);
  assert_memory_equal(parts.bytes, "abc", 3);
  zr__team_parts_free(&parts);
  assert_int_equal(zr__team_exchange(NULL, ZR_EIO, "abc", 3, &parts),
                   ZR_EIO);
  assert_null(parts.bytes);
  assert_int_equal(zr__team_agree(NULL, ZR_EINVAL), ZR_EINVAL);
  zr_team one = {0, 1, NULL, NULL};
  assert_int_equal(zr__team_size(&one), 1);
  assert_true(zr__team_mine(&one, 5));
}

/* A pack grows by doubling; from 1 MiB on it moves into whole huge
   pages (team.c, room_alloc) and keeps every byte put before. */
static void test_team_pack_grows_into_huge_pages(void **state) {
  (void)state;
  zr__pack pack = {0};
  unsigned char piece[1000];
  for (size_t k = 0; k < 3000; k++) {
    for (size_t i = 0; i < sizeof piece; i++)
      piece[i] = (unsigned char)((k * 7 + i) % 253);
    zr__pack_put(&pack, piece, sizeof piece);
  }
  assert_false(pack.nomem);
  assert_int_equal(pack.n, 3000 * sizeof piece);
  assert_true(pack.cap >= pack.n);
  assert_int_equal((uintptr_t)pack.bytes % ZR__HUGE_PAGE, 0);
  assert_int_equal(pack.cap % ZR__HUGE_PAGE, 0);
  size_t wrong = 0;
  for (size_t k = 0; k < 3000; k++)
    for (size_t i = 0; i < sizeof piece; i++)
      wrong += (unsigned char)pack.bytes[k * sizeof piece + i] !=
               (unsigned char)((k * 7 + i) % 253);
  assert_int_equal(wrong, 0);
  zr__pack_free(&pack);
  assert_null(pack.bytes);
}

/* ---- a radiosity solve and a cache pretrace shared by the members ---- */

/* A room lit by an emitting panel, with a box in it (planar surfaces,
   shadows: refinement, visibility and several gathering sweeps). */
static const char *const room_text =
    "#declare W = texture { pigment { rgb 0.7 } finish { diffuse 1 "
    "ambient 0 } }\n"
    "box { <-1, 0, -1>, <1, 2, 1> texture { W } }\n"
    "box { <-0.3, 1.98, -0.3>, <0.3, 1.999, 0.3> texture { pigment { "
    "rgb 1 } finish { emission 8 diffuse 0 ambient 0 } } }\n"
    "box { <-0.2, 0, -0.2>, <0.3, 0.6, 0.3> texture { pigment { rgb "
    "<0.8, 0.2, 0.1> } finish { diffuse 1 ambient 0 } } }\n"
    "camera { location <0, 1, -0.9> look_at <0, 1, 0> }\n";

/* A sphere under a sky (the irradiance cache). */
static const char *const sky_text =
    "global_settings { radiosity { } }\n"
    "camera { location <0, 1.2, -3> look_at <0, 0.4, 0> }\n"
    "sky_sphere { pigment { rgb <0.6, 0.7, 1> } }\n"
    "sphere { <0, 0.5, 0>, 0.5 pigment { rgb 0.8 } finish { diffuse 0.8 "
    "} }\n"
    "plane { y, 0 pigment { rgb 0.6 } }\n";

static const zr_scene *shared_scene;
static char saved[MEMBERS + 1][64];
static zr_status solved[MEMBERS + 1];

static void solve_and_save(const zr_team *team, int slot) {
  zr_context *ctx = NULL;
  zr_radiosity *rad = NULL;
  zr_status s = zr_context_new(&ctx);
  zr_radiosity_params p;
  zr_radiosity_params_init(&p, shared_scene);
  p.bf_eps = 1e-3;
  p.threads = slot == 1 ? 2 : 1; /* threads inside a member too */
  p.team = team;
  if (s == ZR_OK)
    s = zr_radiosity_solve(ctx, shared_scene, &p, &rad);
  if (s == ZR_OK)
    s = zr_radiosity_save(ctx, rad, saved[slot]);
  solved[slot] = s;
  zr_radiosity_free(rad);
  zr_context_free(ctx);
}

static void *solve_member(void *p) {
  member *m = p;
  solve_and_save(&m->team, m->rank);
  return NULL;
}

static void assert_same_file(const char *a, const char *b) {
  FILE *fa = fopen(a, "rb"), *fb = fopen(b, "rb");
  assert_non_null(fa);
  assert_non_null(fb);
  size_t n = 0;
  int ca, cb;
  do {
    ca = fgetc(fa);
    cb = fgetc(fb);
    assert_int_equal(ca, cb);
    n++;
  } while (ca != EOF);
  assert_true(n > 100);
  fclose(fa);
  fclose(fb);
}

static void test_team_radiosity(void **state) {
  (void)state;
  zr_context *ctx = NULL;
  zr_scene *scene = NULL;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  assert_int_equal(zr_scene_parse_string(ctx, "<room>", room_text,
                                         strlen(room_text), &scene),
                   ZR_OK);
  shared_scene = scene;
  for (int r = 0; r <= MEMBERS; r++)
    snprintf(saved[r], sizeof saved[r], "test_team_%d_%ld.zrrad", r,
             (long)getpid());
  solve_and_save(NULL, MEMBERS); /* alone */
  assert_int_equal(solved[MEMBERS], ZR_OK);
  hall h;
  member ms[MEMBERS];
  hall_init(&h, ms);
  run_members(ms, solve_member);
  for (int r = 0; r < MEMBERS; r++) {
    assert_int_equal(solved[r], ZR_OK);
    assert_same_file(saved[MEMBERS], saved[r]);
    assert_true(h.calls[r] > 3); /* they did exchange */
  }
  for (int r = 0; r <= MEMBERS; r++)
    remove(saved[r]);
  hall_free(&h);
  zr_scene_free(scene);
  zr_context_free(ctx);
}

static float *pictures[MEMBERS + 1];

static void pretrace_and_render(const zr_team *team, int slot) {
  zr_context *ctx = NULL;
  zr_gi_cache *cache = NULL;
  zr_status s = zr_context_new(&ctx);
  zr_gi_params gp;
  zr_gi_params_init(&gp, shared_scene);
  gp.threads = 1;
  gp.team = team;
  zr_render_params rp;
  zr_render_params_init(&rp);
  rp.width = 40;
  rp.height = 30;
  if (s == ZR_OK)
    s = zr_gi_cache_new(ctx, shared_scene, &gp, &cache);
  if (s == ZR_OK)
    s = zr_gi_cache_pretrace(cache, &rp);
  rp.gi_cache = cache;
  pictures[slot] = calloc((size_t)rp.width * rp.height * 3, sizeof(float));
  if (s == ZR_OK)
    s = zr_render_image(shared_scene, &rp, pictures[slot], NULL);
  solved[slot] = s;
  zr_gi_cache_free(cache);
  zr_context_free(ctx);
}

static void *pretrace_member(void *p) {
  member *m = p;
  pretrace_and_render(&m->team, m->rank);
  return NULL;
}

static void test_team_cache(void **state) {
  (void)state;
  zr_context *ctx = NULL;
  zr_scene *scene = NULL;
  assert_int_equal(zr_context_new(&ctx), ZR_OK);
  assert_int_equal(zr_scene_parse_string(ctx, "<sky>", sky_text,
                                         strlen(sky_text), &scene),
                   ZR_OK);
  shared_scene = scene;
  pretrace_and_render(NULL, MEMBERS);
  assert_int_equal(solved[MEMBERS], ZR_OK);
  hall h;
  member ms[MEMBERS];
  hall_init(&h, ms);
  run_members(ms, pretrace_member);
  for (int r = 0; r < MEMBERS; r++) {
    assert_int_equal(solved[r], ZR_OK);
    assert_memory_equal(pictures[r], pictures[MEMBERS],
                        40 * 30 * 3 * sizeof(float));
    assert_true(h.calls[r] > 3);
  }
  for (int r = 0; r <= MEMBERS; r++)
    free(pictures[r]);
  hall_free(&h);
  zr_scene_free(scene);
  zr_context_free(ctx);
}

/* ---- a parse shared by the members (zr_context_set_team) ---- */

/* A mesh2 of an n x n grid of vertices rippled by amp, two triangles a
   cell (n = 100: 19,602 faces, above the size a team shares), after
   head (text that comes first). */
static char *grid_text(const char *head, int n, double amp, int meshes) {
  size_t cap = strlen(head) + (size_t)meshes * (size_t)n * (size_t)n * 80 +
               100;
  char *b = malloc(cap);
  size_t at = (size_t)snprintf(b, cap, "%s", head);
  for (int m = 0; m < meshes; m++) {
    at += (size_t)snprintf(b + at, cap - at,
                           "mesh2 { vertex_vectors { %d", n * n);
    for (int j = 0; j < n; j++)
      for (int i = 0; i < n; i++)
        at += (size_t)snprintf(b + at, cap - at, ", <%d, %.6f, %d>", i,
                               amp * (m + 1) * sin(i * 0.37) *
                                   cos(j * 0.21),
                               j);
    at += (size_t)snprintf(b + at, cap - at, " } face_indices { %d",
                           2 * (n - 1) * (n - 1));
    for (int j = 0; j < n - 1; j++)
      for (int i = 0; i < n - 1; i++) {
        int a = j * n + i;
        at += (size_t)snprintf(b + at, cap - at,
                               ", <%d,%d,%d>, <%d,%d,%d>", a, a + 1, a + n,
                               a + 1, a + n + 1, a + n);
      }
    at += (size_t)snprintf(b + at, cap - at, " } }\n");
  }
  return b;
}

/* What each member parses, what it got and the scene it parsed. */
static char *parse_texts[MEMBERS];
static zr_status parsed[MEMBERS];
static zr_scene *parsed_scene[MEMBERS];

static zr_status parse_text(const zr_team *team, int threads,
                            const char *text, zr_scene **out) {
  zr_context *ctx = NULL;
  zr_status s = zr_context_new(&ctx);
  if (s != ZR_OK)
    return s;
  zr_context_set_diag(ctx, NULL, NULL);
  zr_context_set_threads(ctx, threads);
  zr_context_set_team(ctx, team);
  s = zr_scene_parse_string(ctx, "<grid>", text, strlen(text), out);
  zr_context_free(ctx);
  return s;
}

static void *parse_member(void *p) {
  member *m = p;
  /* Member 1 builds its share with two threads. */
  parsed[m->rank] = parse_text(&m->team, m->rank == 1 ? 2 : 1,
                               parse_texts[m->rank],
                               &parsed_scene[m->rank]);
  return NULL;
}

/* Every mesh of a's the same bytes as b's (the same tree, the faces in
   the same order). */
static void assert_same_meshes(const zr_scene *a, const zr_scene *b) {
  assert_int_equal(a->n_primitives, b->n_primitives);
  for (size_t i = 0; i < a->n_primitives; i++) {
    assert_int_equal(a->primitives[i]->kind, ZR_OBJ_MESH);
    const struct zr_mesh *x = a->primitives[i]->u.mesh.data;
    const struct zr_mesh *y = b->primitives[i]->u.mesh.data;
    assert_int_equal(x->n_faces, y->n_faces);
    assert_int_equal(x->n_nodes, y->n_nodes);
    assert_memory_equal(x->nodes, y->nodes,
                        x->n_nodes * sizeof(zr_wide_node));
    assert_memory_equal(x->faces, y->faces, x->n_faces * sizeof *x->faces);
    assert_memory_equal(x->face_row, y->face_row,
                        x->n_faces * sizeof *x->face_row);
  }
}

/* The members parse texts[r]; each must end as a parse alone of its
   text ends (failed: that status), and each member must have made
   calls allgathers. */
static void run_parse(const char *const texts[MEMBERS], int calls) {
  hall h;
  member ms[MEMBERS];
  hall_init(&h, ms);
  for (int r = 0; r < MEMBERS; r++)
    parse_texts[r] = (char *)texts[r];
  run_members(ms, parse_member);
  for (int r = 0; r < MEMBERS; r++) {
    zr_scene *alone = NULL;
    zr_status s = parse_text(NULL, 1, texts[r], &alone);
    assert_int_equal(parsed[r], s);
    if (s == ZR_OK)
      assert_same_meshes(parsed_scene[r], alone);
    zr_scene_free(alone);
    zr_scene_free(parsed_scene[r]);
    parsed_scene[r] = NULL;
    assert_int_equal(h.calls[r], calls);
  }
  hall_free(&h);
}

/* Three members parse two large meshes together: each mesh costs a
   comparison of keys and an exchange of large parts (3 allgathers), the
   parse's end one more, and every member holds the meshes one process
   builds alone. */
static void test_team_parse_meshes(void **state) {
  (void)state;
  char *text = grid_text("", 100, 0.8, 2);
  const char *const texts[MEMBERS] = {text, text, text};
  run_parse(texts, 2 * (1 + 3) + 1);
  free(text);
}

/* A member that read other bytes (its first mesh differs) parts from
   the others at that mesh's comparison: one call each, then every
   member builds alone and none waits. */
static void test_team_parse_other_bytes(void **state) {
  (void)state;
  char *same = grid_text("", 100, 0.8, 2);
  char *other = grid_text("", 100, 0.5, 2);
  const char *const texts[MEMBERS] = {same, same, other};
  run_parse(texts, 1);
  free(same);
  free(other);
}

/* A member whose parse fails before the mesh (a syntax error) still
   makes the parse's last call, which meets the others' comparison for
   their first mesh: they part there and go on alone. */
static void test_team_parse_failed_member(void **state) {
  (void)state;
  char *good = grid_text("", 100, 0.8, 2);
  char *bad = grid_text("sphere { <0, 0, 0> 1 \n", 100, 0.8, 2);
  const char *const texts[MEMBERS] = {good, bad, good};
  run_parse(texts, 1);
  free(good);
  free(bad);
}

/* A member with a mesh fewer: the first mesh is shared (4 calls), then
   its end meets the others' second mesh (1 call) and they finish
   alone. */
static void test_team_parse_fewer_meshes(void **state) {
  (void)state;
  char *two = grid_text("", 100, 0.8, 2);
  char *one = grid_text("", 100, 0.8, 1);
  const char *const texts[MEMBERS] = {two, two, one};
  run_parse(texts, 1 + 3 + 1);
  free(two);
  free(one);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_team_exchange),
      cmocka_unit_test(test_team_exchange_in_room),
      cmocka_unit_test(test_team_of_one),
      cmocka_unit_test(test_team_pack_grows_into_huge_pages),
      cmocka_unit_test(test_team_radiosity),
      cmocka_unit_test(test_team_cache),
      cmocka_unit_test(test_team_parse_meshes),
      cmocka_unit_test(test_team_parse_other_bytes),
      cmocka_unit_test(test_team_parse_failed_member),
      cmocka_unit_test(test_team_parse_fewer_meshes),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
