/*
 * test_lexer.c - the scanner and token arrays (grammar/pov.l,
 * lib/sdl/tokens.c) and the keyword tables (lib/sdl/keywords.c).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

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
  lex(&l, "sphere $");
  assert_int_equal(l.status, ZR_ESYNTAX);
  assert_string_equal(l.err, "unexpected character '$'");
  assert_int_equal(l.err_loc.column, 8);
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
     about (issue 16) */
  assert_int_equal(supported, 452);
  assert_int_equal(zr__sdl_keyword_find("color", 5)->token, T_COLOUR);
  assert_int_equal(zr__sdl_keyword_find("colour", 6)->token, T_COLOUR);
  assert_int_equal(zr__sdl_keyword_find("use_alpha", 9)->token,
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
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
