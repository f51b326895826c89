/*
 * test_par.c - lib/par without an MPI launcher: interleaved rows, the file
 * bundle and its readers, the thread pool, and the one-rank world.
 *
 * The multi-rank paths (broadcast, Allgatherv, Gatherv) run under mpirun
 * in tests/test_cli.sh, which compares images made with 1, 2 and 3 ranks.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "par/bundle.h"
#include "par/par.h"
#include "par/pool.h"
#include "par/rows.h"
#include "par/writer.h"
#include "zrcube.h"

/* ---- rows ---------------------------------------------------------- */

static void test_par_rows_cover_each_row_once(void **state) {
  (void)state;
  for (int height = 0; height <= 17; height++) {
    for (int nranks = 1; nranks <= 6; nranks++) {
      int owner[17];
      memset(owner, -1, sizeof owner);
      int total = 0;
      for (int rank = 0; rank < nranks; rank++) {
        int count = zr__rows_count(height, rank, nranks);
        total += count;
        for (int i = 0; i < count; i++) {
          int y = zr__rows_row(i, rank, nranks);
          assert_in_range(y, 0, height - 1);
          assert_int_equal(owner[y], -1);
          owner[y] = rank;
        }
      }
      assert_int_equal(total, height);
    }
  }
  /* More ranks than rows: the extra ranks get nothing. */
  assert_int_equal(zr__rows_count(2, 5, 8), 0);
  assert_int_equal(zr__rows_count(10, 0, 0), 0);
}

/* Threads taking rows of bands from one counter (zr__rows_claim): the
   bands of a pass in increasing order, one of them empty and a gap
   between two (bands done already, as when a render continues). */
enum { CLAIM_THREADS = 4, CLAIM_HEIGHT = 400 };
static const int claim_bands[][2] = {{0, 150}, {150, 150}, {150, 230},
                                     {260, 400}};

typedef struct claim_run {
  atomic_int next;
  atomic_int band;       /* the band every thread is on */
  atomic_int arrived;    /* threads done with the band */
  atomic_int taken[CLAIM_HEIGHT];
  atomic_int misplaced;  /* a row outside its band */
} claim_run;

static void *claim_thread(void *arg) {
  claim_run *c = arg;
  int nbands = (int)(sizeof claim_bands / sizeof *claim_bands);
  for (int b = 0; b < nbands; b++) {
    /* Every thread starts band b only when all have finished b - 1, as
       the ranks meet between chunks. */
    while (atomic_load(&c->band) < b)
      sched_yield();
    int y0 = claim_bands[b][0], y1 = claim_bands[b][1], y;
    while ((y = zr__rows_claim(&c->next, y0, y1)) >= 0) {
      if (y < y0 || y >= y1)
        atomic_store(&c->misplaced, 1);
      else
        atomic_fetch_add(&c->taken[y], 1);
    }
    if (atomic_fetch_add(&c->arrived, 1) == CLAIM_THREADS * (b + 1) - 1)
      atomic_store(&c->band, b + 1);
  }
  return NULL;
}

static void test_par_rows_claim_each_row_once(void **state) {
  (void)state;
  for (int round = 0; round < 20; round++) {
    claim_run *c = calloc(1, sizeof *c);
    assert_non_null(c);
    pthread_t t[CLAIM_THREADS];
    for (int i = 0; i < CLAIM_THREADS; i++)
      assert_int_equal(pthread_create(&t[i], NULL, claim_thread, c), 0);
    for (int i = 0; i < CLAIM_THREADS; i++)
      pthread_join(t[i], NULL);
    assert_int_equal(atomic_load(&c->misplaced), 0);
    for (int y = 0; y < CLAIM_HEIGHT; y++)
      assert_int_equal(atomic_load(&c->taken[y]),
                       (y >= 230 && y < 260) ? 0 : 1);
    free(c);
  }
  /* A band behind the counter has nothing left. */
  atomic_int next;
  atomic_init(&next, 50);
  assert_int_equal(zr__rows_claim(&next, 10, 40), -1);
  assert_int_equal(zr__rows_claim(&next, 10, 60), 50);
  assert_int_equal(zr__rows_claim(&next, 70, 80), 70);
  assert_int_equal(atomic_load(&next), 71);
}

static void test_par_rows_uninterleave_restores_order(void **state) {
  (void)state;
  enum { HEIGHT = 11, NRANKS = 3, ROW = 6 };
  float rank_major[HEIGHT * ROW], image[HEIGHT * ROW];
  float *p = rank_major;
  for (int rank = 0; rank < NRANKS; rank++)
    for (int i = 0; i < zr__rows_count(HEIGHT, rank, NRANKS); i++)
      for (int k = 0; k < ROW; k++)
        *p++ = (float)(100 * zr__rows_row(i, rank, NRANKS) + k);
  assert_ptr_equal(p, rank_major + HEIGHT * ROW);
  zr__rows_uninterleave(rank_major, image, HEIGHT, NRANKS, ROW);
  for (int y = 0; y < HEIGHT; y++)
    for (int k = 0; k < ROW; k++)
      assert_true(image[y * ROW + k] == (float)(100 * y + k));
}

/* ---- bundle -------------------------------------------------------- */

static void fill_bundle(zr_bundle *b) {
  static const char binary[] = {'a', '\0', 'b', '\xff', '\n'};
  zr__bundle_init(b);
  assert_int_equal(zr__bundle_add(b, "scene.pov", "sphere {}", 9), ZR_OK);
  assert_int_equal(zr__bundle_add(b, "empty.inc", "", 0), ZR_OK);
  assert_int_equal(zr__bundle_add(b, "/abs/bin.dat", binary, sizeof binary),
                   ZR_OK);
}

static void test_par_bundle_roundtrip(void **state) {
  (void)state;
  zr_bundle b, copy;
  fill_bundle(&b);
  char *blob;
  size_t size;
  assert_int_equal(zr__bundle_serialise(&b, &blob, &size), ZR_OK);
  /* magic + count + per file (2 lengths + path + bytes) */
  assert_int_equal(size, 12 + (16 + 9 + 9) + (16 + 9 + 0) + (16 + 12 + 5));
  zr__bundle_init(&copy);
  assert_int_equal(zr__bundle_deserialise(&copy, blob, size), ZR_OK);
  assert_int_equal(copy.count, b.count);
  for (size_t i = 0; i < b.count; i++) {
    assert_string_equal(copy.files[i].path, b.files[i].path);
    assert_int_equal(copy.files[i].size, b.files[i].size);
    assert_memory_equal(copy.files[i].bytes, b.files[i].bytes,
                        b.files[i].size ? b.files[i].size : 1);
  }
  assert_non_null(zr__bundle_find(&copy, "empty.inc"));
  assert_null(zr__bundle_find(&copy, "missing.inc"));
  free(blob);
  zr__bundle_free(&b);
  zr__bundle_free(&copy);
  zr__bundle_free(NULL);
}

static void test_par_bundle_rejects_malformed(void **state) {
  (void)state;
  zr_bundle b, copy;
  fill_bundle(&b);
  char *blob;
  size_t size;
  assert_int_equal(zr__bundle_serialise(&b, &blob, &size), ZR_OK);
  zr__bundle_init(&copy);
  /* Every truncation is caught, and leaves the target untouched. */
  for (size_t n = 0; n < size; n++) {
    assert_int_equal(zr__bundle_deserialise(&copy, blob, n), ZR_EFORMAT);
    assert_int_equal(copy.count, 0);
  }
  char *longer = malloc(size + 1);
  memcpy(longer, blob, size);
  longer[size] = 'x';
  assert_int_equal(zr__bundle_deserialise(&copy, longer, size + 1),
                   ZR_EFORMAT);
  /* A length larger than the blob. */
  memcpy(longer, blob, size);
  longer[12 + 7] = '\x7f';
  assert_int_equal(zr__bundle_deserialise(&copy, longer, size), ZR_EFORMAT);
  /* A NUL inside a path. */
  memcpy(longer, blob, size);
  longer[12 + 8 + 2] = '\0';
  assert_int_equal(zr__bundle_deserialise(&copy, longer, size), ZR_EFORMAT);
  /* Another magic. */
  memcpy(longer, blob, size);
  longer[3] = '2';
  assert_int_equal(zr__bundle_deserialise(&copy, longer, size), ZR_EFORMAT);
  assert_int_equal(copy.count, 0);
  free(longer);
  free(blob);
  zr__bundle_free(&b);
}

static void write_file(const char *path, const char *text) {
  FILE *f = fopen(path, "wb");
  assert_non_null(f);
  fputs(text, f);
  fclose(f);
}

static void test_par_bundle_records_and_serves(void **state) {
  (void)state;
  char dir[] = "/tmp/zr_test_par_XXXXXX";
  assert_non_null(mkdtemp(dir));
  char scene[64], missing[64];
  snprintf(scene, sizeof scene, "%s/a.pov", dir);
  snprintf(missing, sizeof missing, "%s/none.inc", dir);
  write_file(scene, "#include \"none.inc\"\n");

  zr_bundle recorded;
  zr__bundle_init(&recorded);
  char *bytes;
  size_t size;
  assert_int_equal(zr__bundle_record_reader(scene, &bytes, &size, &recorded),
                   ZR_OK);
  assert_int_equal(size, 20);
  /* 21 bytes: the text and the NUL a scanner may rely on. */
  assert_memory_equal(bytes, "#include \"none.inc\"\n", 21);
  free(bytes);
  assert_int_equal(
      zr__bundle_record_reader(missing, &bytes, &size, &recorded),
      ZR_ENOTFOUND);
  assert_int_equal(zr__bundle_record_reader(dir, &bytes, &size, &recorded),
                   ZR_EIO);
  assert_int_equal(recorded.count, 1);

  /* A second read of a path gives what the first one recorded. */
  write_file(scene, "changed");
  assert_int_equal(zr__bundle_record_reader(scene, &bytes, &size, &recorded),
                   ZR_OK);
  assert_int_equal(size, 20);
  free(bytes);

  /* The other side: what was recorded is served, the rest is missing. */
  char *blob;
  size_t blob_size;
  assert_int_equal(zr__bundle_serialise(&recorded, &blob, &blob_size),
                   ZR_OK);
  zr_bundle received;
  zr__bundle_init(&received);
  assert_int_equal(zr__bundle_deserialise(&received, blob, blob_size), ZR_OK);
  unlink(scene);
  rmdir(dir);
  assert_int_equal(zr__bundle_serve_reader(scene, &bytes, &size, &received),
                   ZR_OK);
  assert_int_equal(size, 20);
  assert_memory_equal(bytes, "#include \"none.inc\"\n", 21);
  free(bytes);
  assert_int_equal(zr__bundle_serve_reader(missing, &bytes, &size, &received),
                   ZR_ENOTFOUND);
  free(blob);
  zr__bundle_free(&recorded);
  zr__bundle_free(&received);
}

/* fill's check in the test: accepts bytes that begin with "big". */
static zr_status starts_big(const char *path, const char *bytes, size_t size,
                            void *user) {
  (void)path;
  ++*(int *)user;
  return size >= 3 && memcmp(bytes, "big", 3) == 0 ? ZR_OK : ZR_EIO;
}

/* A file of defer_from bytes or more is recorded as its path and size
   only; it cannot travel (serialise, serve) until zr__bundle_fill has
   read it again, and fill keeps it only if the check accepts it. */
static void test_par_bundle_defers_big_files(void **state) {
  (void)state;
  char dir[] = "/tmp/zr_test_par_XXXXXX";
  assert_non_null(mkdtemp(dir));
  char big[64], small[64];
  snprintf(big, sizeof big, "%s/big.inc", dir);
  snprintf(small, sizeof small, "%s/small.inc", dir);
  zr_bundle b;
  zr__bundle_init(&b);
  b.defer_from = 8;
  assert_int_equal(zr__bundle_record_observer(small, "tiny", 4, &b), ZR_OK);
  assert_int_equal(zr__bundle_record_observer(big, "big bytes", 9, &b),
                   ZR_OK);
  assert_int_equal(b.count, 2);
  assert_non_null(b.files[0].bytes);
  assert_null(b.files[1].bytes);
  assert_int_equal(b.files[1].size, 9);
  /* A second read must have the same size (its bytes are the caller's
     to compare). */
  assert_int_equal(zr__bundle_record_observer(big, "big other", 9, &b),
                   ZR_OK);
  assert_int_equal(zr__bundle_record_observer(big, "big longer", 10, &b),
                   ZR_EIO);
  char *blob = NULL, *bytes = NULL;
  size_t size = 0;
  assert_int_equal(zr__bundle_serialise(&b, &blob, &size), ZR_EINVAL);
  assert_int_equal(zr__bundle_serve_reader(big, &bytes, &size, &b), ZR_EIO);

  /* Gone from disk, changed, another size: refused, still deferred. */
  int checks = 0;
  const char *failed = NULL;
  assert_int_equal(zr__bundle_fill(&b, starts_big, &checks, &failed),
                   ZR_ENOTFOUND);
  assert_string_equal(failed, big);
  write_file(big, "BIG BYTES");
  assert_int_equal(zr__bundle_fill(&b, starts_big, &checks, &failed), ZR_EIO);
  assert_int_equal(checks, 1);
  write_file(big, "big bytes!");
  assert_int_equal(zr__bundle_fill(&b, starts_big, &checks, &failed), ZR_EIO);
  assert_int_equal(checks, 1); /* refused by its size, before the check */
  assert_null(b.files[1].bytes);

  /* The same bytes: kept, and the bundle travels whole. */
  write_file(big, "big bytes");
  assert_int_equal(zr__bundle_fill(&b, starts_big, &checks, &failed), ZR_OK);
  assert_null(failed);
  assert_int_equal(checks, 2);
  assert_int_equal(zr__bundle_serialise(&b, &blob, &size), ZR_OK);
  zr_bundle received;
  zr__bundle_init(&received);
  assert_int_equal(zr__bundle_deserialise(&received, blob, size), ZR_OK);
  assert_int_equal(zr__bundle_serve_reader(big, &bytes, &size, &received),
                   ZR_OK);
  assert_int_equal(size, 9);
  assert_memory_equal(bytes, "big bytes", 10);
  free(bytes);
  free(blob);
  unlink(big);
  rmdir(dir);
  zr__bundle_free(&b);
  zr__bundle_free(&received);
}

/* ---- rendering ----------------------------------------------------- */

/* Small, but with an edge for antialiasing, a reflection and a shadow. */
static const char scene_text[] =
    "camera { location <0, 1, -4> look_at <0, 0.5, 0> }\n"
    "light_source { <3, 5, -4>, color rgb 1 }\n"
    "plane { y, 0 pigment { color rgb <0.8, 0.8, 0.6> } }\n"
    "box { <-2, 0, 1>, <-1, 1.5, 2> pigment { color rgb <0.2, 0.4, 1> } }\n"
    "sphere { <0, 0.7, 0>, 0.7 pigment { color rgb <1, 0.3, 0.2> }\n"
    "  finish { reflection 0.3 } }\n";

typedef struct render_fixture {
  zr_context *ctx;
  zr_scene *scene;
  zr_render_params params;
} render_fixture;

static int setup_render(void **state) {
  render_fixture *f = calloc(1, sizeof *f);
  if (!f || zr_context_new(&f->ctx) != ZR_OK)
    return -1;
  if (zr_scene_parse_string(f->ctx, "<test>", scene_text,
                            sizeof scene_text - 1, &f->scene) != ZR_OK) {
    print_error("%s", zr_context_last_error(f->ctx));
    return -1;
  }
  zr_render_params_init(&f->params);
  f->params.width = 37; /* odd sizes: rows do not split evenly */
  f->params.height = 23;
  *state = f;
  return 0;
}

static int teardown_render(void **state) {
  render_fixture *f = *state;
  zr_scene_free(f->scene);
  zr_context_free(f->ctx);
  free(f);
  return 0;
}

static float *reference(render_fixture *f) {
  size_t n = (size_t)f->params.width * f->params.height * 3;
  float *rgb = malloc(n * sizeof *rgb);
  assert_int_equal(zr_render_image(f->scene, &f->params, rgb, NULL), ZR_OK);
  return rgb;
}

/* Renders with the pool as nranks ranks of threads threads would, one
   rank after another, and puts the rows back in order. */
static float *pooled(render_fixture *f, int nranks, int threads,
                     zr_render_stats *stats) {
  int w = f->params.width, h = f->params.height;
  size_t row = (size_t)w * 3;
  float *centres = malloc((size_t)h * row * sizeof(float));
  float *rank_major = malloc((size_t)h * row * sizeof(float));
  for (int pass = 0; pass < (f->params.antialias ? 2 : 1); pass++) {
    float *p = rank_major;
    for (int rank = 0; rank < nranks; rank++) {
      zr_pool_job job = {.scene = f->scene,
                         .params = &f->params,
                         .rank = rank,
                         .nranks = nranks,
                         .centres = pass ? centres : NULL,
                         .rows_rgb = p,
                         .threads = threads,
                         .stats = stats};
      assert_int_equal(zr__pool_render(&job), ZR_OK);
      p += (size_t)zr__rows_count(h, rank, nranks) * row;
    }
    zr__rows_uninterleave(rank_major, centres, h, nranks, row);
  }
  free(rank_major);
  return centres;
}

static void check_pool_matches_reference(render_fixture *f) {
  float *want = reference(f);
  size_t bytes = (size_t)f->params.width * f->params.height * 3 *
                 sizeof(float);
  static const int layouts[][2] = {{1, 1}, {1, 3}, {2, 2}, {3, 1}, {5, 4}};
  zr_render_stats first = {0};
  for (size_t i = 0; i < sizeof layouts / sizeof *layouts; i++) {
    zr_render_stats stats = {0};
    float *got = pooled(f, layouts[i][0], layouts[i][1], &stats);
    /* Same bytes: the library traces each pixel the same way wherever. */
    assert_memory_equal(got, want, bytes);
    if (i == 0)
      first = stats;
    assert_memory_equal(&stats, &first, sizeof stats);
    free(got);
  }
  assert_int_equal(first.camera_rays,
                   (uint64_t)f->params.width * f->params.height);
  free(want);
}

static void test_par_pool_matches_serial_render(void **state) {
  check_pool_matches_reference(*state);
}

static void test_par_pool_matches_serial_render_antialiased(void **state) {
  render_fixture *f = *state;
  f->params.antialias = 1;
  f->params.aa_threshold = 0.1;
  check_pool_matches_reference(f);
  f->params.antialias = 0;
}

/* Two "ranks" (pools run at once on threads of this process) taking
   the rows of bands from one counter, each into its own buffer at the
   rows' places, as ranks on one host do (lib/par/par.c shared_rows):
   put together by owner, the same bytes as one render. */
typedef struct claim_rank {
  zr_pool_job job;
  zr_status status;
} claim_rank;

static void *claim_rank_main(void *arg) {
  claim_rank *r = arg;
  r->status = zr__pool_render(&r->job);
  return NULL;
}

static void test_par_pool_claims_shared_rows(void **state) {
  render_fixture *f = *state;
  int w = f->params.width, h = f->params.height;
  size_t row = (size_t)w * 3;
  float *want = reference(f);
  float *got = malloc((size_t)h * row * sizeof(float));
  float *buf[2] = {malloc((size_t)h * row * sizeof(float)),
                   malloc((size_t)h * row * sizeof(float))};
  int *owner = malloc((size_t)h * sizeof *owner);
  zr_render_stats stats[2] = {{0}, {0}};
  atomic_int next;
  atomic_init(&next, 0);
  for (int y = 0; y < h; y++)
    owner[y] = -1;
  /* Two bands, as two chunks: rows 0 .. 9 and 10 .. h - 1. */
  int bands[2][2] = {{0, 10}, {10, h}};
  for (int b = 0; b < 2; b++) {
    claim_rank ranks[2];
    pthread_t t[2];
    for (int r = 0; r < 2; r++) {
      memset(&ranks[r], 0, sizeof ranks[r]);
      ranks[r].job = (zr_pool_job){
          .scene = f->scene,
          .params = &f->params,
          .rows_rgb = buf[r] + (size_t)bands[b][0] * row,
          .row_stride = row,
          .threads = 2,
          .stats = &stats[r],
          .first_row = bands[b][0],
          .end_row = bands[b][1],
          .first_col = 0,
          .end_col = w,
          .claim = &next,
          .owner = owner,
          .owner_rank = r};
      assert_int_equal(
          pthread_create(&t[r], NULL, claim_rank_main, &ranks[r]), 0);
    }
    for (int r = 0; r < 2; r++) {
      pthread_join(t[r], NULL);
      assert_int_equal(ranks[r].status, ZR_OK);
    }
  }
  for (int y = 0; y < h; y++) {
    assert_in_range(owner[y], 0, 1);
    memcpy(got + (size_t)y * row, buf[owner[y]] + (size_t)y * row,
           row * sizeof(float));
  }
  assert_memory_equal(got, want, (size_t)h * row * sizeof(float));
  assert_int_equal(stats[0].camera_rays + stats[1].camera_rays,
                   (uint64_t)w * h);
  /* A claim needs the band's end and the owners, and follows no
     writer. */
  zr_pool_job bad = {.scene = f->scene, .params = &f->params,
                     .rows_rgb = got, .threads = 1, .claim = &next,
                     .owner = owner};
  assert_int_equal(zr__pool_render(&bad), ZR_EINVAL);
  free(want);
  free(got);
  free(buf[0]);
  free(buf[1]);
  free(owner);
}

typedef struct progress_log {
  size_t calls;
  size_t last_done;
  size_t total;
  int out_of_order;
} progress_log;

/* Runs on worker threads, where cmocka cannot fail a test: it notes. */
static void log_progress(size_t done, size_t total, void *user) {
  progress_log *log = user;
  /* Calls are serialised and counted in order. */
  if (done != log->last_done + 1)
    log->out_of_order = 1;
  log->calls++;
  log->last_done = done;
  log->total = total;
}

static void test_par_pool_reports_progress(void **state) {
  render_fixture *f = *state;
  size_t row = (size_t)f->params.width * 3;
  float *rgb = malloc((size_t)f->params.height * row * sizeof(float));
  progress_log log = {0, 4, 0, 0};
  zr_pool_job job = {.scene = f->scene,
                     .params = &f->params,
                     .rank = 1,
                     .nranks = 2,
                     .rows_rgb = rgb,
                     .threads = 3,
                     .progress = log_progress,
                     .progress_user = &log,
                     .progress_base = 4,
                     .progress_total = 99};
  assert_int_equal(zr__pool_render(&job), ZR_OK);
  assert_int_equal(log.calls, 11); /* rows 1, 3, ..., 21 of 23 */
  assert_false(log.out_of_order);
  assert_int_equal(log.last_done, 15);
  assert_int_equal(log.total, 99);
  free(rgb);
}

static void test_par_pool_returns_failure(void **state) {
  render_fixture *f = *state;
  /* zr_render_pixels refuses an antialiasing depth of 0 on every row; the
     pool must hand that status back whichever thread met it first. */
  f->params.antialias = 1;
  f->params.aa_depth = 0;
  size_t row = (size_t)f->params.width * 3;
  float *rgb = malloc((size_t)f->params.height * row * sizeof(float));
  zr_pool_job job = {.scene = f->scene,
                     .params = &f->params,
                     .rank = 0,
                     .nranks = 1,
                     .rows_rgb = rgb,
                     .threads = 4};
  assert_int_equal(zr__pool_render(&job), ZR_EINVAL);
  zr_par *par;
  assert_int_equal(zr__par_init(NULL, NULL, &par), ZR_OK);
  zr_image *image;
  assert_int_equal(zr_image_new(f->params.width, f->params.height, &image),
                   ZR_OK);
  zr_par_render render = {.scene = f->scene,
                          .params = &f->params,
                          .threads = 2,
                          .image = image};
  assert_int_equal(zr__par_render(par, &render), ZR_EINVAL);
  zr_image_free(image);
  zr__par_finalize(par);
  free(rgb);
}

static void test_par_world_of_one_renders_image(void **state) {
  render_fixture *f = *state;
  /* make check runs without mpirun: a world of one, MPI untouched. */
  zr_par *par;
  assert_int_equal(zr__par_init(NULL, NULL, &par), ZR_OK);
  assert_int_equal(zr__par_rank(par), 0);
  assert_int_equal(zr__par_size(par), 1);
  assert_int_equal(zr__par_uses_mpi(par), 0);
  assert_true(zr__par_default_threads(par) >= 1);
  assert_true(zr__par_default_threads(par) <= zr__par_cpus_allowed());
  assert_int_equal(zr__par_threads(par, 3), 3);
  assert_int_equal(zr__par_threads(par, 0), zr__par_default_threads(par));
  assert_int_equal(zr__par_agree(par, ZR_ESYNTAX), ZR_ESYNTAX);
  zr_status root = ZR_EUNDEFINED;
  zr_bundle b;
  zr__bundle_init(&b);
  assert_int_equal(zr__par_share_bundle(par, &b, &root), ZR_OK);
  assert_int_equal(root, ZR_EUNDEFINED);

  f->params.antialias = 1;
  f->params.aa_threshold = 0.1;
  float *want = reference(f);
  zr_image *image;
  assert_int_equal(zr_image_new(f->params.width, f->params.height, &image),
                   ZR_OK);
  zr_par_render job = {.scene = f->scene,
                       .params = &f->params,
                       .threads = 2,
                       .image = image};
  assert_int_equal(zr__par_render(par, &job), ZR_OK);
  assert_memory_equal(zr_image_pixels(image), want,
                      (size_t)f->params.width * f->params.height * 3 *
                          sizeof(float));
  assert_int_equal(job.stats.camera_rays,
                   (uint64_t)f->params.width * f->params.height);
  assert_true(job.render_seconds >= 0);

  /* An image of the wrong size is refused before any work. */
  f->params.width++;
  assert_int_equal(zr__par_render(par, &job), ZR_EINVAL);
  f->params.width--;
  f->params.antialias = 0;
  zr_image_free(image);
  free(want);
  zr__par_finalize(par);
  zr__par_finalize(NULL);
}

/*
 * Renders the window win (rows win[0] .. win[1] - 1, columns win[2] ..
 * win[3] - 1) of f's image in the world par, with 2 threads, and
 * returns how many of the image's floats are not want's inside the
 * window (the full render's: a window's pixels are the same bytes) or
 * not black outside it.  0 when the window is right.
 */
static size_t window_mismatches(render_fixture *f, zr_par *par,
                                const int win[4], const float *want) {
  int w = f->params.width, h = f->params.height;
  zr_image *image;
  assert_int_equal(zr_image_new(w, h, &image), ZR_OK);
  zr_par_render job = {.scene = f->scene,
                       .params = &f->params,
                       .threads = 2,
                       .image = image,
                       .row0 = win[0],
                       .row1 = win[1],
                       .col0 = win[2],
                       .col1 = win[3]};
  assert_int_equal(zr__par_render(par, &job), ZR_OK);
  const float *got = zr_image_pixels(image);
  size_t wrong = 0;
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      int in = y >= win[0] && y < win[1] && x >= win[2] && x < win[3];
      for (int c = 0; c < 3; c++) {
        size_t i = ((size_t)y * (size_t)w + (size_t)x) * 3 + (size_t)c;
        wrong += got[i] != (in ? want[i] : 0.0f);
      }
    }
  zr_image_free(image);
  return wrong;
}

/* A window of rows (whole rows: rendered in place in the image) and one
   of columns (part rows: gathered and copied) give the full render's
   pixels inside and leave the rest black, with and without
   antialiasing. */
static void test_par_world_of_one_renders_window(void **state) {
  render_fixture *f = *state;
  zr_par *par;
  assert_int_equal(zr__par_init(NULL, NULL, &par), ZR_OK);
  int w = f->params.width, h = f->params.height;
  assert_true(w >= 8 && h >= 8);
  const int windows[2][4] = {{2, h - 3, 0, w}, {0, h, 1, w - 2}};
  for (int aa = 0; aa < 2; aa++) {
    f->params.antialias = aa;
    f->params.aa_threshold = 0.1;
    float *want = reference(f);
    for (int k = 0; k < 2; k++)
      assert_int_equal(window_mismatches(f, par, windows[k], want), 0);
    free(want);
  }
  f->params.antialias = 0;
  zr__par_finalize(par);
}

/* An image of 2 MiB of floats or more: the render's buffers are
   aligned on and advised to huge pages, their sizes rounded up
   (par.c, float_alloc).  The whole image and a window of part rows
   (which goes through every buffer: the rank's rows, the band and the
   rank-major copy) give the serial render's pixels, antialiased, and
   black outside the window. */
static void test_par_world_of_one_renders_large_image(void **state) {
  render_fixture *f = *state;
  zr_par *par;
  assert_int_equal(zr__par_init(NULL, NULL, &par), ZR_OK);
  f->params.width = 448;
  f->params.height = 400;
  int w = f->params.width, h = f->params.height;
  assert_true((size_t)w * (size_t)h * 3 * sizeof(float) >= (size_t)2 << 20);
  f->params.antialias = 1;
  f->params.aa_threshold = 0.1;
  float *want = reference(f);
  const int windows[2][4] = {{0, h, 0, w}, {0, h, 1, w - 2}};
  for (int k = 0; k < 2; k++)
    assert_int_equal(window_mismatches(f, par, windows[k], want), 0);
  free(want);
  f->params.antialias = 0;
  f->params.width = 37;
  f->params.height = 23;
  zr__par_finalize(par);
}

/* ---- the writer (par/writer.h) ------------------------------------ */

typedef struct encoded {
  unsigned char *bytes;
  size_t size;
} encoded;

static zr_status encode_png(zr_image *image, void *user) {
  encoded *e = user;
  zr_image_encoding enc;
  zr_image_encoding_init(&enc, ZR_FORMAT_PNG8);
  return zr_image_encode(NULL, image, &enc, &e->bytes, &e->size);
}

/* The image encoded now gives got's bytes; frees them. */
static void assert_encodes_as(zr_image *image, encoded *got) {
  encoded want = {NULL, 0};
  assert_int_equal(encode_png(image, &want), ZR_OK);
  assert_int_equal(got->size, want.size);
  assert_memory_equal(got->bytes, want.bytes, want.size);
  free(got->bytes);
  free(want.bytes);
}

/* A gradient's row y, the value it gets once "rendered". */
static void fill_row(zr_image *image, int y) {
  int w = zr_image_width(image);
  float *row = zr_image_pixels(image) + (size_t)y * (size_t)w * 3;
  for (int i = 0; i < w * 3; i++)
    row[i] = (float)((y * 7 + i) % 97) / 96.0f;
}

/* The encoder waits for each row: rows filled only after the writer
   started, each told final after it is filled, give the bytes of the
   whole image encoded afterwards; an abandoned write fails. */
static void test_par_writer_waits_for_rows(void **state) {
  (void)state;
  int w = 37, h = 29;
  zr_image *image;
  assert_int_equal(zr_image_new(w, h, &image), ZR_OK);
  encoded got = {NULL, 0};
  zr_par_writer *writer;
  assert_int_equal(zr__par_writer_start(image, encode_png, &got, &writer),
                   ZR_OK);
  for (int y = 0; y < h; y++) {
    if (y % 5 == 0)
      usleep(2000); /* an encoder that did not wait would be ahead */
    fill_row(image, y);
    zr__par_writer_rows(writer, y + 1);
    assert_int_equal(zr__par_writer_rows_done(writer), y + 1);
  }
  assert_int_equal(zr__par_writer_finish(writer, 0), ZR_OK);
  assert_encodes_as(image, &got);

  /* Abandoned with rows still missing: the write fails, the image is
     ungated (a later write does not wait). */
  encoded none = {NULL, 0};
  assert_int_equal(zr__par_writer_start(image, encode_png, &none, &writer),
                   ZR_OK);
  zr__par_writer_rows(writer, h / 2);
  assert_int_equal(zr__par_writer_finish(writer, 1), ZR_ECANCELLED);
  assert_null(none.bytes);
  encoded again = {NULL, 0};
  assert_int_equal(encode_png(image, &again), ZR_OK);
  assert_encodes_as(image, &again);
  zr_image_free(image);
}

/* zr__par_writer_wait_idle: 0 while the encoder works, 1 once it waits
   for rows not yet told, 1 once the write has returned. */
typedef struct held_encode {
  atomic_int go;
  encoded out;
} held_encode;

static zr_status encode_when_told(zr_image *image, void *user) {
  held_encode *held = user;
  while (!atomic_load(&held->go))
    usleep(500);
  return encode_png(image, &held->out);
}

static void test_par_writer_idle(void **state) {
  (void)state;
  int w = 37, h = 29;
  zr_image *image;
  assert_int_equal(zr_image_new(w, h, &image), ZR_OK);
  held_encode held = {.out = {NULL, 0}};
  atomic_init(&held.go, 0);
  zr_par_writer *writer;
  assert_int_equal(
      zr__par_writer_start(image, encode_when_told, &held, &writer), ZR_OK);
  assert_int_equal(zr__par_writer_wait_idle(writer, 0.02), 0); /* busy */
  for (int y = 0; y < h / 2; y++)
    fill_row(image, y);
  zr__par_writer_rows(writer, h / 2);
  atomic_store(&held.go, 1);
  /* It encodes the rows told, then waits for row h / 2. */
  assert_int_equal(zr__par_writer_wait_idle(writer, 10.0), 1);
  for (int y = h / 2; y < h; y++)
    fill_row(image, y);
  zr__par_writer_rows(writer, h - 1);
  /* Told more: idle again once it has encoded them. */
  assert_int_equal(zr__par_writer_wait_idle(writer, 10.0), 1);
  zr__par_writer_rows(writer, h);
  assert_int_equal(zr__par_writer_wait_idle(writer, 10.0), 1); /* done */
  assert_int_equal(zr__par_writer_finish(writer, 0), ZR_OK);
  assert_encodes_as(image, &held.out);
  zr_image_free(image);
}

/* A render with a writer in a world of one: the writer is told the rows
   as they are final and writes the render's picture. */
static void test_par_world_of_one_feeds_writer(void **state) {
  render_fixture *f = *state;
  zr_par *par;
  assert_int_equal(zr__par_init(NULL, NULL, &par), ZR_OK);
  for (int aa = 0; aa < 2; aa++) {
    f->params.antialias = aa;
    f->params.aa_threshold = 0.1;
    zr_image *image;
    assert_int_equal(zr_image_new(f->params.width, f->params.height, &image),
                     ZR_OK);
    encoded got = {NULL, 0};
    zr_par_writer *writer;
    assert_int_equal(
        zr__par_writer_start(image, encode_png, &got, &writer), ZR_OK);
    zr_par_render job = {.scene = f->scene,
                         .params = &f->params,
                         .threads = 2,
                         .image = image,
                         .writer = writer,
                         .write_row_seconds = 1.0};
    assert_int_equal(zr__par_render(par, &job), ZR_OK);
    assert_int_equal(zr__par_writer_rows_done(writer), f->params.height);
    assert_int_equal(job.tail_bands, 0); /* one rank: no tail */
    assert_int_equal(zr__par_writer_finish(writer, 0), ZR_OK);
    assert_encodes_as(image, &got);
    zr_image_free(image);
  }
  f->params.antialias = 0;
  zr__par_finalize(par);
}

int main(void) {
  /* The world-of-one test must not think mpirun started it. */
  unsetenv("OMPI_COMM_WORLD_SIZE");
  unsetenv("PMIX_RANK");
  unsetenv("PMI_RANK");
  unsetenv("PMI_SIZE");
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_par_rows_cover_each_row_once),
      cmocka_unit_test(test_par_rows_uninterleave_restores_order),
      cmocka_unit_test(test_par_rows_claim_each_row_once),
      cmocka_unit_test(test_par_bundle_roundtrip),
      cmocka_unit_test(test_par_bundle_rejects_malformed),
      cmocka_unit_test(test_par_bundle_records_and_serves),
      cmocka_unit_test(test_par_bundle_defers_big_files),
      cmocka_unit_test_setup_teardown(test_par_pool_matches_serial_render,
                                      setup_render, teardown_render),
      cmocka_unit_test_setup_teardown(
          test_par_pool_matches_serial_render_antialiased, setup_render,
          teardown_render),
      cmocka_unit_test_setup_teardown(test_par_pool_claims_shared_rows,
                                      setup_render, teardown_render),
      cmocka_unit_test_setup_teardown(test_par_pool_reports_progress,
                                      setup_render, teardown_render),
      cmocka_unit_test_setup_teardown(test_par_pool_returns_failure,
                                      setup_render, teardown_render),
      cmocka_unit_test_setup_teardown(test_par_world_of_one_renders_image,
                                      setup_render, teardown_render),
      cmocka_unit_test_setup_teardown(test_par_world_of_one_renders_window,
                                      setup_render, teardown_render),
      cmocka_unit_test_setup_teardown(
          test_par_world_of_one_renders_large_image, setup_render,
          teardown_render),
      cmocka_unit_test(test_par_writer_waits_for_rows),
      cmocka_unit_test(test_par_writer_idle),
      cmocka_unit_test_setup_teardown(test_par_world_of_one_feeds_writer,
                                      setup_render, teardown_render),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
