/*
 * test_lexer.c - the scanner and token arrays (grammar/pov.l,
 * lib/sdl/tokens.c) and the keyword tables (lib/sdl/keywords.c).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "config.h"
#include "core/budget.h"
#include "pov-parse.h"
#include "sdl/sdl.h"

typedef struct lexed {
  zr_sdl_file file;
  zr_status status;
  zr_sdl_loc err_loc;
  char err[200];
} lexed;

/* Lexes text as file "t.pov"; the caller frees with zr__sdl_file_free. */
static void lex(lexed *l, const char *text) {
  memset(l, 0, sizeof *l);
  size_t n = strlen(text);
  char *bytes = malloc(n + 1);
  char *path = strdup("t.pov");
  assert_non_null(bytes);
  assert_non_null(path);
  memcpy(bytes, text, n + 1);
  l->status = zr__sdl_file_lex(&l->file, 0, path, bytes, n, &l->err_loc,
                               l->err, sizeof l->err);
}

static void assert_token(const zr_sdl_token *t, int kind, int line,
                         int column, int length) {
  assert_int_equal(t->kind, kind);
  assert_int_equal(t->line, line);
  assert_int_equal(t->column, column);
  assert_int_equal(t->length, length);
}

static void test_lexer_tokens_and_places(void **state) {
  (void)state;
  lexed l;
  lex(&l, "sphere {\n  <1, 2.5e1, .5>, Radius\n}");
  assert_int_equal(l.status, ZR_OK);
  assert_int_equal(l.file.n_tokens, 13); /* 12 tokens and the end */
  const zr_sdl_token *t = l.file.tokens;
  assert_token(&t[0], T_SPHERE, 1, 1, 6);
  assert_token(&t[1], '{', 1, 8, 1);
  assert_token(&t[2], '<', 2, 3, 1);
  assert_token(&t[3], T_NUMBER, 2, 4, 1);
  assert_true(t[3].v.num == 1.0);
  assert_token(&t[5], T_NUMBER, 2, 7, 5);
  assert_true(t[5].v.num == 25.0);
  assert_token(&t[7], T_NUMBER, 2, 14, 2);
  assert_true(t[7].v.num == 0.5);
  assert_token(&t[10], T_IDENTIFIER, 2, 19, 6);
  assert_string_equal(t[10].v.str, "Radius");
  assert_token(&t[11], '}', 3, 1, 1);
  assert_int_equal(l.file.tokens[l.file.n_tokens - 1].kind, 0);
  size_t len;
  const char *line = zr__sdl_file_line(&l.file, 2, &len);
  assert_int_equal(len, 24);
  assert_memory_equal(line, "  <1, 2.5e1, .5>, Radius", len);
  zr__sdl_file_free(&l.file);
}

static void test_lexer_comments_nest(void **state) {
  (void)state;
  lexed l;
  lex(&l, "// line comment sphere\n/* a /* nested */ box\n*/ plane");
  assert_int_equal(l.status, ZR_OK);
  assert_int_equal(l.file.n_tokens, 2);
  assert_token(&l.file.tokens[0], T_PLANE, 3, 4, 5);
  zr__sdl_file_free(&l.file);
}

static void test_lexer_strings_unescape(void **state) {
  (void)state;
  lexed l;
  lex(&l, "#include \"a\\\"b\\\\c.inc\"");
  assert_int_equal(l.status, ZR_OK);
  assert_int_equal(l.file.tokens[0].kind, T_INCLUDE);
  assert_int_equal(l.file.tokens[1].kind, T_STRING);
  assert_string_equal(l.file.tokens[1].v.str, "a\"b\\c.inc");
  assert_int_equal(l.file.tokens[1].length, 13);
  zr__sdl_file_free(&l.file);
}

static void test_lexer_directives(void **state) {
  (void)state;
  lexed l;
  lex(&l, "#declare # local #zfor #zend #version #while");
  assert_int_equal(l.status, ZR_OK);
  assert_int_equal(l.file.tokens[0].kind, T_DECLARE);
  assert_int_equal(l.file.tokens[1].kind, T_LOCAL);
  assert_int_equal(l.file.tokens[1].length, 7);
  assert_int_equal(l.file.tokens[2].kind, T_ZFOR);
  assert_int_equal(l.file.tokens[3].kind, T_ZEND);
  assert_int_equal(l.file.tokens[4].kind, T_VERSION);
  assert_int_equal(l.file.tokens[5].kind, T_WHILE);
  assert_string_equal(l.file.tokens[5].v.str, "#while");
  zr__sdl_file_free(&l.file);
  /* A '#' that starts no directive is dropped, as povray 3.7.0 does;
     "<=", ">=" and "!=" are one token each. */
  lex(&l, "<1,2># } a <= b >= c != d");
  assert_int_equal(l.status, ZR_OK);
  assert_int_equal(l.file.tokens[5].kind, '}');
  assert_int_equal(l.file.tokens[7].kind, T_LE);
  assert_int_equal(l.file.tokens[9].kind, T_GE);
  assert_int_equal(l.file.tokens[11].kind, T_NE);
  zr__sdl_file_free(&l.file);
}

static void test_lexer_unsupported_keyword_is_a_token(void **state) {
  (void)state;
  lexed l;
  lex(&l, "iff Iff");
  assert_int_equal(l.status, ZR_OK);
  assert_int_equal(l.file.tokens[0].kind, T_UNSUPPORTED);
  assert_string_equal(l.file.tokens[0].v.str, "iff");
  /* Keywords are case sensitive: this one is an identifier. */
  assert_int_equal(l.file.tokens[1].kind, T_IDENTIFIER);
  zr__sdl_file_free(&l.file);
}

static void test_lexer_unterminated_comment(void **state) {
  (void)state;
  lexed l;
  lex(&l, "box\n  /* one /* two */\n");
  assert_int_equal(l.status, ZR_ESYNTAX);
  assert_string_equal(l.err, "unterminated comment");
  assert_int_equal(l.err_loc.line, 2);
  assert_int_equal(l.err_loc.column, 3);
  zr__sdl_file_free(&l.file);
}

static void test_lexer_unterminated_string(void **state) {
  (void)state;
  lexed l;
  /* A string may span lines, as in POV-Ray: only the end of the file
     leaves it open. */
  lex(&l, "#include \"abc\n");
  assert_int_equal(l.status, ZR_ESYNTAX);
  assert_string_equal(l.err, "unterminated string");
  assert_int_equal(l.err_loc.line, 1);
  assert_int_equal(l.err_loc.column, 10);
  zr__sdl_file_free(&l.file);
}

static void test_lexer_bad_characters(void **state) {
  (void)state;
  lexed l;
  /* A character no token begins with is a token of its own: the error
     comes when the scene reaches it (test_parser.c), as in POV-Ray,
     which passes over one in a skipped #if branch. */
  lex(&l, "sphere $\xff");
  assert_int_equal(l.status, ZR_OK);
  assert_int_equal(l.file.n_tokens, 4);
  assert_token(&l.file.tokens[1], T_BAD_CHAR, 1, 8, 1);
  assert_string_equal(l.file.tokens[1].v.str, "$");
  assert_token(&l.file.tokens[2], T_BAD_CHAR, 1, 9, 1);
  assert_string_equal(l.file.tokens[2].v.str, "\xff");
  zr__sdl_file_free(&l.file);
  /* A '#' before a word that is no directive is passed over, as povray
     3.7 renders "#global_settings" and "#box { }" (measured): the word
     is then read as it stands (the parser names it if it is unknown). */
  lex(&l, "#frobnicate");
  assert_int_equal(l.status, ZR_OK);
  zr__sdl_file_free(&l.file);
}

static void test_lexer_keyword_table(void **state) {
  (void)state;
  size_t n;
  const zr_sdl_keyword *k = zr__sdl_keywords(&n);
  /* The manual's 498 reserved words, mesh_camera and tau, without
     atand, and zRcube's six: energy and five radiosity settings (see
     keywords.c); and bmp, exr and hdr, image types the manual's list
     leaves out but its image_map syntax names and povray 3.7 reads
     (issue 12, tests/test_formats_povray.sh). */
  assert_int_equal(n, 499 + 6 + 3);
  size_t supported = 0;
  for (size_t i = 0; i < n; i++) {
    if (i > 0)
      assert_true(strcmp(k[i - 1].name, k[i].name) < 0);
    assert_ptr_equal(zr__sdl_keyword_find(k[i].name, strlen(k[i].name)),
                     &k[i]);
    supported += k[i].token != T_UNSUPPORTED;
  }
  /* srgb, srgbf, srgbt, srgbft, declare and no_bump_scale: issue 16;
     bmp, exr, hdr and tiff: issue 12; mm_per_unit and translucency:
     subsurface light transport; facets, coords and size: read and warned
     about (issue 16); image_pattern and use_alpha (session 21);
     premultiplied (session 22) */
  assert_int_equal(supported, 455);
  assert_int_equal(zr__sdl_keyword_find("color", 5)->token, T_COLOUR);
  assert_int_equal(zr__sdl_keyword_find("colour", 6)->token, T_COLOUR);
  assert_int_equal(zr__sdl_keyword_find("use_alpha", 9)->token,
                   T_USE_ALPHA);
  assert_int_equal(zr__sdl_keyword_find("premultiplied", 13)->token,
                   T_PREMULTIPLIED);
  assert_int_equal(zr__sdl_keyword_find("reflection_exponent", 19)->token,
                   T_UNSUPPORTED);
  assert_null(zr__sdl_keyword_find("Sphere", 6));
  assert_null(zr__sdl_keyword_find("sph", 3));
  /* The hashed search answers as a scan of the table for every
     keyword's prefixes, its extensions and its one-letter changes
     (identifiers that look like keywords): about 10,000 names. */
  size_t asked = 0;
  for (size_t i = 0; i < n; i++) {
    char buf[64];
    size_t len = strlen(k[i].name);
    assert_true(len + 2 < sizeof buf);
    memcpy(buf, k[i].name, len);
    for (size_t variant = 0; variant < 2 * len + 4; variant++) {
      size_t m = len;
      memcpy(buf, k[i].name, len);
      if (variant < len)
        m = variant; /* a prefix, the empty one included */
      else if (variant < 2 * len)
        buf[variant - len] ^= 0x20; /* a letter's case or '_' <-> DEL */
      else
        buf[m++] = "_x9A"[variant - 2 * len]; /* one more character */
      const zr_sdl_keyword *want = NULL;
      for (size_t j = 0; j < n && !want; j++)
        if (strlen(k[j].name) == m && memcmp(k[j].name, buf, m) == 0)
          want = &k[j];
      assert_ptr_equal(zr__sdl_keyword_find(buf, m), want);
      asked++;
    }
  }
  assert_true(asked >= 4 * n);
  assert_int_equal(zr__sdl_directive_find("include", 7)->token, T_INCLUDE);
  assert_null(zr__sdl_directive_find("includes", 8));
}

/* Lexes n_lines lines of "a b c" under budget (NULL: none) into l. */
static void lex_lines(lexed *l, size_t n_lines, zr_budget *budget) {
  memset(l, 0, sizeof *l);
  size_t n = 6 * n_lines;
  char *bytes = malloc(n + 1);
  char *path = strdup("t.pov");
  assert_non_null(bytes);
  assert_non_null(path);
  for (size_t i = 0; i < n_lines; i++)
    memcpy(bytes + 6 * i, "a b c\n", 6);
  bytes[n] = '\0';
  l->status = zr__sdl_file_lex_budget(&l->file, 0, path, bytes, n, budget,
                                      &l->err_loc, l->err, sizeof l->err);
}

/* A big file's token array is sized from its first 256 tokens (twice
   what their lines promise for the whole file); a budget that cannot
   hold that estimate but holds what doubling asks gets doubling, and
   the tokens are the same either way. */
static void test_lexer_token_array_estimate(void **state) {
  (void)state;
  enum { LINES = 60000 }; /* 180,000 tokens, ~4 MB of them */
  lexed free_run, tight;
  lex_lines(&free_run, LINES, NULL);
  assert_int_equal(free_run.status, ZR_OK);
  assert_int_equal(free_run.file.n_tokens, 3 * LINES + 1); /* + the end */
  /* The array: 256 tokens reach line 86, so 2 x 256 x (60,000 / 86)
     = 356,864 slots (8.6 MB); the budget is still charged as the array
     doubles (262,144 slots at the end, 8.4 MB with the links' words)
     and, with the names' strings, this file needs 12 MiB: a budget of
     12 MiB takes it (charged for the estimate, it did not), one of
     11 MiB does not. */
  static const size_t limits[] = {12u << 20, 11u << 20, 16u << 20};
  static const zr_status want[] = {ZR_OK, ZR_ELIMIT, ZR_OK};
  for (size_t k = 0; k < 3; k++) {
    zr_budget *b = zr__budget_new(limits[k]);
    assert_non_null(b);
    lex_lines(&tight, LINES, b);
    assert_int_equal(tight.status, want[k]);
    if (tight.status == ZR_OK) {
      assert_int_equal(tight.file.n_tokens, free_run.file.n_tokens);
      for (size_t i = 0; i < free_run.file.n_tokens; i++) {
        assert_int_equal(tight.file.tokens[i].kind,
                         free_run.file.tokens[i].kind);
        assert_int_equal(tight.file.tokens[i].line,
                         free_run.file.tokens[i].line);
      }
    }
    zr__sdl_file_free(&tight.file);
    /* every charge is given back with the file */
    assert_int_equal(atomic_load(&b->used), 0);
    zr__budget_unref(b);
  }
  zr__sdl_file_free(&free_run.file);
}

/* Whether two token arrays are the same tokens: kind, place, length
   and value (numbers bit for bit, names and strings by their text, a
   mesh2 run by its bytes and count). */
static void assert_same_tokens(const zr_sdl_file *a, const zr_sdl_file *b,
                               const char *what) {
  if (a->n_tokens != b->n_tokens)
    fail_msg("%s: %zu tokens against %zu", what, a->n_tokens, b->n_tokens);
  for (size_t i = 0; i < a->n_tokens; i++) {
    const zr_sdl_token *s = &a->tokens[i], *t = &b->tokens[i];
    if (s->kind != t->kind || s->line != t->line ||
        s->column != t->column || s->length != t->length)
      fail_msg("%s: token %zu: kind %d at %d:%d (%d) against kind %d at "
               "%d:%d (%d)", what, i, s->kind, s->line, s->column,
               s->length, t->kind, t->line, t->column, t->length);
    if (s->kind == T_NUMBER) {
      assert_memory_equal(&s->v.num, &t->v.num, sizeof s->v.num);
    } else if (s->kind == ZR_SDL_NUMBER_LIST) {
      assert_int_equal(s->v.list->begin, t->v.list->begin);
      assert_int_equal(s->v.list->end, t->v.list->end);
      assert_int_equal(s->v.list->n_items, t->v.list->n_items);
    } else if (s->kind == T_SPHERE_RUN) {
      assert_memory_equal(s->v.sphere, t->v.sphere, 4 * sizeof(double));
    } else if (s->kind == T_TRIANGLE_RUN) {
      /* Each file keeps its own copy of the corners. */
      assert_memory_equal(s->v.corners, t->v.corners, 9 * sizeof(double));
    } else if (s->kind == T_SMOOTH_TRIANGLE_RUN) {
      /* Each file keeps its own copy of the corners and normals. */
      assert_memory_equal(a->corners + s->v.smooth.corner,
                          b->corners + t->v.smooth.corner, 9 * sizeof(double));
      assert_memory_equal(a->normals + s->v.smooth.normal,
                          b->normals + t->v.smooth.normal, 9 * sizeof(double));
    } else if (!s->v.str || !t->v.str) {
      if (s->v.str != t->v.str)
        fail_msg("%s: token %zu: one value is missing", what, i);
    } else if (strcmp(s->v.str, t->v.str) != 0) {
      fail_msg("%s: token %zu: '%s' against '%s'", what, i, s->v.str,
               t->v.str);
    }
  }
}

/* Lexes size bytes both ways (the lexer's own words and braces after
   a run, and the scanner alone) and asserts the same tokens, or the
   same error at the same place. */
static void assert_lexed_alike(const char *bytes, size_t size,
                               const char *what) {
  zr_sdl_file quick, plain;
  zr_sdl_loc quick_at, plain_at;
  char quick_err[200] = "", plain_err[200] = "";
  char *b1 = malloc(size + 1), *b2 = malloc(size + 1);
  char *p1 = strdup(what), *p2 = strdup(what);
  assert_true(b1 && b2 && p1 && p2);
  memcpy(b1, bytes, size);
  memcpy(b2, bytes, size);
  b1[size] = b2[size] = '\0';
  zr_status s1 = zr__sdl_file_lex(&quick, 0, p1, b1, size, &quick_at,
                                  quick_err, sizeof quick_err);
  zr_status s2 = zr__sdl_file_lex_scanner_only(
      &plain, 0, p2, b2, size, &plain_at, plain_err, sizeof plain_err);
  if (s1 != s2)
    fail_msg("%s: status %d against %d (%s / %s)", what, s1, s2, quick_err,
             plain_err);
  if (s1 == ZR_OK) {
    assert_same_tokens(&quick, &plain, what);
  } else {
    assert_string_equal(quick_err, plain_err);
    assert_int_equal(quick_at.line, plain_at.line);
    assert_int_equal(quick_at.column, plain_at.column);
  }
  zr__sdl_file_free(&quick);
  zr__sdl_file_free(&plain);
}

/* Every .pov and .inc file of dir and the folders below it, lexed both
   ways; returns how many. */
static int lex_tree_alike(const char *dir) {
  DIR *d = opendir(dir);
  if (!d)
    return 0;
  int n = 0;
  struct dirent *e;
  while ((e = readdir(d)) != NULL) {
    if (e->d_name[0] == '.')
      continue;
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
    size_t len = strlen(e->d_name);
    bool scene = len > 4 && (strcmp(e->d_name + len - 4, ".pov") == 0 ||
                             strcmp(e->d_name + len - 4, ".inc") == 0);
    FILE *f = scene ? fopen(path, "rb") : NULL;
    if (!f) {
      n += lex_tree_alike(path); /* a folder, or nothing */
      continue;
    }
    char *bytes = NULL;
    size_t size = 0, room = 0, got;
    do {
      if (size == room) {
        room = room ? 2 * room : 65536;
        bytes = realloc(bytes, room);
        assert_non_null(bytes);
      }
      got = fread(bytes + size, 1, room - size, f);
      size += got;
    } while (got > 0);
    fclose(f);
    assert_lexed_alike(bytes, size, path);
    free(bytes);
    n++;
  }
  closedir(d);
  return n;
}

/* After a run (a sphere's, a triangle's, a mesh2 list's) the lexer
   takes plain words and braces itself while the scanner holds nothing
   read ahead: the tokens must be the scanner's, whatever follows
   (tokens.c, quick_token).  Made cases for each way out of that path,
   then every scene and include file at hand: POV-Ray's includes
   (povray-includes), this tree's scenes and, when present, the stock
   scenes. */
static void test_lexer_quick_words_same_as_scanner(void **state) {
  (void)state;
  static const char *const cases[] = {
      "sphere { <1, 2, 3>, 0.5 texture { Ball } }\n"
      "sphere { <4, 5, 6>, 1 texture { Ball } }\n",
      "sphere { <1, 2, 3>, 0.5 }sphere{<1,2,3>,1}",
      /* a comment, a directive, a string, a number, an operator */
      "sphere { <1,2,3>, 1 } // done\nsphere { <1,2,3>, 1 }/* c */ }",
      "sphere { <1,2,3>, 1 }\n#declare A = 1;\nsphere { <1,2,3>, 1 } #end",
      "sphere { <1,2,3>, 1 texture { T } } \"s\" 1.5e3 x.y <1> 2*3",
      "sphere { <1,2,3>, 1 pigment { rgb 1 } scale 2 translate -x }",
      "sphere { <1,2,3>, 1 }\r\n\tName_2 _x y9 {}}{ ",
      "sphere { <1,2,3>, 1 } word# #declare",
      "sphere { <1,2,3>, 1 } /* unterminated",
      "sphere { <1,2,3>, 1 } \"unterminated",
      "sphere { <1,2,3>, 1 } sphere { <1,2,3>, 1 } @",
      "mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } triangle { <0,0,0>, "
      "<1,0,0>, <0,1,0> } texture { T } inside_vector y }",
      "mesh2 { vertex_vectors { 2, <0,0,0>, <1,1,1> } face_indices { 1, "
      "<0,1,1> } Name }",
      "",
      "  \n ",
      "word",
      "sphere { <1,2,3>, 1 } \xc3\xa9",
  };
  for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
    char what[32];
    snprintf(what, sizeof what, "case %zu", i);
    assert_lexed_alike(cases[i], strlen(cases[i]), what);
  }
  int files = lex_tree_alike("/usr/share/povray-3.7/include");
  const char *srcdir = getenv("srcdir");
  char scenes[4096];
  snprintf(scenes, sizeof scenes, "%s/scenes", srcdir ? srcdir : ".");
  files += lex_tree_alike(scenes);
  files += lex_tree_alike("/usr/share/povray-3.7/scenes");
  print_message("%d files lexed both ways\n", files);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_lexer_tokens_and_places),
      cmocka_unit_test(test_lexer_comments_nest),
      cmocka_unit_test(test_lexer_strings_unescape),
      cmocka_unit_test(test_lexer_directives),
      cmocka_unit_test(test_lexer_unsupported_keyword_is_a_token),
      cmocka_unit_test(test_lexer_unterminated_comment),
      cmocka_unit_test(test_lexer_unterminated_string),
      cmocka_unit_test(test_lexer_bad_characters),
      cmocka_unit_test(test_lexer_keyword_table),
      cmocka_unit_test(test_lexer_token_array_estimate),
      cmocka_unit_test(test_lexer_quick_words_same_as_scanner),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
