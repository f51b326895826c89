/*
 * test_numlist.c - runs of plain mesh2 items read from the bytes
 * (lib/sdl/numlist.c): numbers convert as strtod() does, a run stops
 * where the scanner and grammar must take over, the lexer keeps a run
 * as one token (lib/sdl/tokens.c), and the parse of a run gives the
 * same mesh and the same error places as the tokens would.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "config.h"
#include "core/strbuf.h"
#include "parse_fixture.h"
#include "pov-parse.h"
#include "sdl/sdl.h"
#include "trace/obj_mesh.h"

static zr_sdl_numreader reader(const char *s, bool uv) {
  zr_sdl_numreader r = {s, 0, strlen(s), 1, 1, uv, true};
  return r;
}

/* Reads "<x, x, x>}" and checks all three values have strtod's bits. */
static void check_number(const char *x) {
  char text[200];
  snprintf(text, sizeof text, "<%s, -%s,%s>}", x, x, x);
  zr_sdl_numreader r = reader(text, false);
  double v[3];
  int dim, line, column;
  assert_true(zr__sdl_numlist_item(&r, v, &dim, &line, &column));
  assert_int_equal(dim, 3);
  double want = strtod(x, NULL), minus = -want;
  if (memcmp(&v[0], &want, sizeof want) != 0 ||
      memcmp(&v[1], &minus, sizeof minus) != 0 ||
      memcmp(&v[2], &want, sizeof want) != 0)
    fail_msg("'%s' read as %.17g, %.17g, %.17g; strtod gives %.17g", x,
             v[0], v[1], v[2], want);
}

static void test_numlist_numbers_like_strtod(void **state) {
  (void)state;
  static const char *const numbers[] = {
      "0", "0.0", "00012", "1.", ".5", "0.1", "0.3", "3.14159", "1e22",
      "1e23", "1E5", "1e+5", "1e-5", "5e-22", "5e-23", "1.5e300",
      "1.7976931348623157e308", "1e309", "4.9e-324", "2e-400",
      "2.2250738585072014e-308", "9007199254740992", "9007199254740993",
      "123456789012345678901234", "0.000000000000000000000000000001",
      "12345678901234567890e-10", "1234567890123456789", "0.0548",
      "000.000", "1.e5", ".5e-3", "99999999999999999999"};
  for (size_t i = 0; i < sizeof numbers / sizeof *numbers; i++)
    check_number(numbers[i]);
  /* Many decimals of every length, as printf writes them. */
  unsigned long long seed = 42;
  for (int i = 0; i < 20000; i++) {
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    double x = (double)(seed >> 11) / (double)(1ULL << 53);
    double scale = (double)(1ULL << (seed >> 5) % 40) / 1048576.0;
    char text[64];
    snprintf(text, sizeof text, "%.*f", (int)(seed % 18), x * scale);
    check_number(text);
    snprintf(text, sizeof text, "%.*e", (int)(seed % 20), x * 1e10);
    check_number(text);
  }
}

/* x read as a sphere's radius at the end of the bytes, where fewer than
   16 bytes follow it (numlist.c's byte loops), and as the first number
   of the centre with many bytes after it (its eight-byte reads): both
   give strtod's bits, and the reader ends where the text does. */
static void check_both_paths(const char *x, char after) {
  double want = strtod(x, NULL);
  char text[256];
  snprintf(text, sizeof text, "<0, 0, 0>, %s%c", x, after == '>' ? '}' : after);
  zr_sdl_numreader r = reader(text, false);
  double v[4];
  if (!zr__sdl_numlist_sphere(&r, v))
    fail_msg("'%s' (at the end) not read", text);
  if (memcmp(&v[3], &want, sizeof want) != 0)
    fail_msg("'%s' read at the end as %.17g; strtod gives %.17g", x, v[3],
             want);
  assert_int_equal(r.pos, strlen(text) - 1);
  /* x before a blank or a comma: the centre's x; before '>': its z. */
  bool first = after == ' ' || after == ',';
  snprintf(text, sizeof text,
           first ? "<%s%s 0, 0>, 1                        }"
                 : "<0, 0, %s%s, 1                        }",
           x, after == ' ' ? " ," : first ? "," : ">");
  r = reader(text, false);
  if (!zr__sdl_numlist_sphere(&r, v))
    fail_msg("'%s' (followed by more) not read", text);
  if (memcmp(&v[first ? 0 : 2], &want, sizeof want) != 0)
    fail_msg("'%s' read with more after it as %.17g; strtod gives %.17g", x,
             v[first ? 0 : 2], want);
}

/* Every shape of number the eight-byte reads take or pass on: 0 to 9
   digits before the point, none or 0 to 9 after it, leading and
   trailing zeros, with and without an exponent, after each byte that
   may end a number; then bytes that a number may not end on ("1.5:",
   "12a"), which must leave the reader where it was. */
static void test_numlist_eight_byte_reads(void **state) {
  (void)state;
  static const char ends[] = {' ', ',', '>', '}'};
  unsigned long long seed = 7;
  for (int whole = 0; whole <= 9; whole++)
    for (int part = -1; part <= 9; part++)
      for (int round = 0; round < 60; round++) {
        char x[64];
        size_t n = 0;
        for (int i = 0; i < whole; i++) {
          seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
          /* round 0: all zeros; 1: all nines; then random digits */
          x[n++] = (char)('0' + (round == 0   ? 0
                                 : round == 1 ? 9
                                              : (int)((seed >> 33) % 10)));
        }
        if (part >= 0) {
          x[n++] = '.';
          for (int i = 0; i < part; i++) {
            seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
            x[n++] = (char)('0' + (round == 0   ? 0
                                   : round == 1 ? 9
                                                : (int)((seed >> 33) % 10)));
          }
        }
        if (whole == 0 && part <= 0)
          continue; /* "" and ".": no number */
        if (round % 3 == 2) {
          seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
          n += (size_t)snprintf(x + n, sizeof x - n, "e%s%d",
                                seed >> 63 ? "-" : "", (int)((seed >> 40) % 30));
        }
        x[n] = '\0';
        check_both_paths(x, ends[round % 4]);
      }
  static const char *const not_numbers[] = {
      "<1.5:, 0, 0>, 1                       }",
      "<12a, 0, 0>, 1                        }",
      "<1234567/, 0, 0>, 1                   }",
      "<0.1234567., 0, 0>, 1                 }",
      "<., 0, 0>, 1                          }",
      "<1.2.3, 0, 0>, 1                      }"};
  for (size_t i = 0; i < sizeof not_numbers / sizeof *not_numbers; i++) {
    zr_sdl_numreader r = reader(not_numbers[i], false);
    double v[4];
    if (zr__sdl_numlist_sphere(&r, v))
      fail_msg("'%s' was read", not_numbers[i]);
    assert_int_equal(r.pos, 0);
  }
}

/* Not a plain item: the reader takes nothing and stays where it was. */
static void check_not_item(const char *text, bool uv) {
  zr_sdl_numreader r = reader(text, uv);
  double v[3];
  int dim, line, column;
  if (zr__sdl_numlist_item(&r, v, &dim, &line, &column))
    fail_msg("'%s' was read as an item", text);
  assert_int_equal(r.pos, 0);
  assert_int_equal(r.line, 1);
  assert_int_equal(r.column, 1);
}

static void test_numlist_stops_where_the_grammar_starts(void **state) {
  (void)state;
  check_not_item("<1,2,3>*2, <1,2,3>}", false); /* an expression */
  check_not_item("<1,2a,3>}", false);            /* number then name */
  check_not_item("<1,2,3e>}", false);            /* "3" then "e" */
  check_not_item("<1,2.5.3,3>}", false);         /* two numbers */
  check_not_item("<1,2,3> // a comment\n}", false);
  check_not_item("<1,/* c */2,3>}", false);
  check_not_item("<1,2,3>", false); /* nothing says it is complete */
  check_not_item("<1,2>,", false);  /* 2-D outside uv_vectors */
  check_not_item("<1>,", true);
  check_not_item("<1,2,3,4>,", true);
  check_not_item("<A,2,3>,", false);
  check_not_item("<1,2,3>.x,", false);
  check_not_item(",, <1,2,3>}", false);
  check_not_item("5, <1,2,3>}", false); /* a texture index */
  /* uv_vectors takes 2-D items; signs and blanks anywhere. */
  zr_sdl_numreader r = reader(" ,\n <1 , - -2 >\n\t<+3,-4,5> }", true);
  double v[3];
  int dim, line, column;
  assert_true(zr__sdl_numlist_item(&r, v, &dim, &line, &column));
  assert_int_equal(dim, 2);
  assert_true(v[0] == 1 && v[1] == 2 && v[2] == 0);
  assert_int_equal(line, 2);
  assert_int_equal(column, 2);
  assert_true(zr__sdl_numlist_item(&r, v, &dim, &line, &column));
  assert_int_equal(dim, 3);
  assert_true(v[0] == 3 && v[1] == -4 && v[2] == 5);
  assert_int_equal(line, 3);
  assert_int_equal(column, 2);
  assert_false(zr__sdl_numlist_item(&r, v, &dim, &line, &column));
  assert_int_equal(r.bytes[r.pos], ' ');
}

/* The lexer keeps the items after a list's count as one token, and the
   tokens after it keep their places. */
static void test_numlist_lexer_keeps_one_token(void **state) {
  (void)state;
  const char *text = "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>,\n"
                     "  <0,1,0> } face_indices { 1 <0,1,2>, 4 } }\n";
  size_t n = strlen(text);
  char *bytes = malloc(n + 1);
  char *path = strdup("t.pov");
  assert_non_null(bytes);
  assert_non_null(path);
  memcpy(bytes, text, n + 1);
  zr_sdl_file file;
  zr_sdl_loc err_loc;
  char err[200];
  assert_int_equal(zr__sdl_file_lex(&file, 0, path, bytes, n, &err_loc, err,
                                    sizeof err),
                   ZR_OK);
  static const int kinds[] = {T_MESH2, '{', T_VERTEX_VECTORS, '{',
                              T_NUMBER, ZR_SDL_NUMBER_LIST, '}',
                              T_FACE_INDICES, '{', T_NUMBER,
                              ZR_SDL_NUMBER_LIST, ',', T_NUMBER, '}', '}',
                              0};
  assert_int_equal(file.n_tokens, sizeof kinds / sizeof *kinds);
  for (size_t i = 0; i < file.n_tokens; i++)
    assert_int_equal(file.tokens[i].kind, kinds[i]);
  const zr_sdl_numlist *list = file.tokens[5].v.list;
  assert_int_equal(list->n_items, 3);
  assert_int_equal(list->line, 1);
  assert_int_equal(list->column, 27);
  assert_false(list->uv);
  /* The '}' after the run, and the texture index after the face. */
  assert_int_equal(file.tokens[6].line, 2);
  assert_int_equal(file.tokens[6].column, 11);
  assert_int_equal(file.tokens[12].line, 2);
  assert_int_equal(file.tokens[12].column, 39);
  assert_int_equal(file.tokens[10].v.list->n_items, 1);
  zr__sdl_file_free(&file);
}

static const struct zr_mesh *mesh_of(const zr_scene *s, size_t i) {
  assert_true(s->n_primitives > i);
  assert_int_equal(s->primitives[i]->kind, ZR_OBJ_MESH);
  return s->primitives[i]->u.mesh.data;
}

/* A grid of side n written as the benchmark writes it, with the text
   between after some items. */
static char *grid(int n, const char *between) {
  zr_strbuf b;
  zr__strbuf_init(&b);
  zr__strbuf_printf(&b, "mesh2 { vertex_vectors { %d,\n", n * n);
  for (int j = 0; j < n; j++)
    for (int i = 0; i < n; i++)
      zr__strbuf_printf(&b, "  <%d, %.4f, %d>,%s\n", i,
                        (i * 7 % 11) * 0.0137 - j * 0.5, -10 - j,
                        (i + j) % 5 == 0 ? between : "");
  zr__strbuf_printf(&b, "} face_indices { %d,\n", 2 * (n - 1) * (n - 1));
  for (int j = 0; j < n - 1; j++)
    for (int i = 0; i < n - 1; i++) {
      int a = j * n + i;
      zr__strbuf_printf(&b, "  <%d, %d, %d>, <%d, %d, %d>,%s\n", a, a + 1,
                        a + n, a + 1, a + n + 1, a + n,
                        (i + j) % 7 == 0 ? between : "");
    }
  zr__strbuf_printf(&b, "} }\n");
  char *text = strdup(zr__strbuf_cstr(&b));
  zr__strbuf_free(&b);
  return text;
}

/* Comments and directives between items send some of them through the
   scanner and the grammar: the mesh must not change a bit. */
static void test_numlist_same_mesh_as_the_grammar(void **state) {
  fixture *f = *state;
  const int n = 30;
  char *plain = grid(n, "");
  char *spoilt = grid(n, " // a comment\n#if (1) #end");
  zr_scene *s = good(f, plain);
  const struct zr_mesh *m = mesh_of(s, 0);
  size_t nv = m->n_vertices, nf = m->n_faces;
  zr_vec3 *vertices = malloc(nv * sizeof *vertices);
  uint32_t(*faces)[3] = malloc(nf * sizeof *faces);
  assert_non_null(vertices);
  assert_non_null(faces);
  memcpy(vertices, m->vertices, nv * sizeof *vertices);
  memcpy(faces, m->faces, nf * sizeof *faces);
  s = good(f, spoilt);
  m = mesh_of(s, 0);
  assert_int_equal(m->n_vertices, nv);
  assert_int_equal(m->n_faces, nf);
  assert_memory_equal(m->vertices, vertices, nv * sizeof *vertices);
  assert_memory_equal(m->faces, faces, nf * sizeof *faces);
  free(vertices);
  free(faces);
  free(plain);
  free(spoilt);
}

/* A loop and a macro replay the token of a run: every copy reads it. */
static void test_numlist_replayed_by_loops_and_macros(void **state) {
  fixture *f = *state;
  zr_scene *s = good(
      f, "#macro M(X)\n"
         "  mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,X> }\n"
         "          face_indices { 1, <0,1,2> } }\n"
         "#end\n"
         "#declare I = 0;\n"
         "#while (I < 3)\n"
         "  mesh2 { vertex_vectors { 3, <0,0,5>, <1,0,5>, <0,1,5>, }\n"
         "          face_indices { 1, <0,1,2> } translate I*x }\n"
         "  #declare I = I + 1;\n"
         "#end\n"
         "M(7) M(8)\n");
  assert_int_equal(s->n_primitives, 5);
  for (size_t i = 0; i < 5; i++) {
    const struct zr_mesh *m = mesh_of(s, i);
    assert_int_equal(m->n_vertices, 3);
    assert_int_equal(m->n_faces, 1);
    assert_true(m->vertices[1].x == 1.0 && m->vertices[2].y == 1.0);
  }
  /* In the macro the identifier ends the run: the grammar reads the
     last item. */
  assert_true(mesh_of(s, 0)->vertices[0].z == 5.0);
  assert_true(mesh_of(s, 2)->vertices[0].x == 0.0);
  assert_true(mesh_of(s, 3)->vertices[0].z == 0.0);
  assert_true(mesh_of(s, 3)->vertices[2].z == 7.0);
  assert_true(mesh_of(s, 4)->vertices[2].z == 8.0);
}

/* Errors in and after a run point where they are, even a million lines
   into the file. */
static void test_numlist_error_places(void **state) {
  fixture *f = *state;
  bad(f, "mesh2 { vertex_vectors { 1, <0,0,0>,\n"
         "  <1,0,0> } }\n",
      ZR_ESCENE, "vertex_vectors: more items than the 1 announced",
      "t.pov:2:3: error: vertex_vectors: more items than the 1 announced\n"
      "    2 |   <1,0,0> } }\n"
      "      |   ^\n");
  bad(f, "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n"
         "  face_indices { 2, <0,1,2>,\n"
         "     <0,-1,2> } }\n",
      ZR_ESCENE, "face_indices: -1 is not an index",
      "t.pov:3:6: error: face_indices: -1 is not an index\n"
      "    3 |      <0,-1,2> } }\n"
      "      |      ^\n");
  const int lines = 1000000;
  zr_strbuf b;
  zr__strbuf_init(&b);
  zr__strbuf_printf(&b, "mesh2 { vertex_vectors { %d,\n", lines);
  for (int i = 0; i < lines; i++)
    zr__strbuf_printf(&b, "  <%d, 0.5, -1>,\n", i);
  /* Line lines + 2: the scanner goes on after the run. */
  zr__strbuf_printf(&b, "  <1, 2, 3> bogus } }\n");
  char want[300];
  snprintf(want, sizeof want,
           "t.pov:%d:13: error: undefined identifier 'bogus'\n"
           "%5d |   <1, 2, 3> bogus } }\n"
           "      |             ^~~~~\n",
           lines + 2, lines + 2);
  bad(f, zr__strbuf_cstr(&b), ZR_EUNDEFINED, "undefined identifier 'bogus'",
      want);
  zr__strbuf_free(&b);
}

/* Lexes text as "t.pov" into file, which the caller frees. */
static void lex_text(zr_sdl_file *file, const char *text) {
  size_t n = strlen(text);
  char *bytes = malloc(n + 1);
  char *path = strdup("t.pov");
  assert_non_null(bytes);
  assert_non_null(path);
  memcpy(bytes, text, n + 1);
  zr_sdl_loc err_loc;
  char err[200];
  assert_int_equal(zr__sdl_file_lex(file, 0, path, bytes, n, &err_loc, err,
                                    sizeof err),
                   ZR_OK);
}

/* "triangle { <a>, <b>, <c> }" becomes one run token, at the keyword's
   place; any other body keeps its tokens. */
static void test_numlist_triangle_run_token(void **state) {
  (void)state;
  zr_sdl_file file;
  lex_text(&file, "mesh { triangle { <0,0,0>, <1,0,0>,\n <0,1,0> }\n"
                  " triangle { <0,0,0>, <1,0,0>, <0,1,0> texture {} }\n"
                  " triangle { <0,0,0>, <1,0,0>, <0,1,0>, } }\n");
  assert_int_equal(file.tokens[0].kind, T_MESH);
  assert_int_equal(file.tokens[2].kind, T_TRIANGLE_RUN);
  assert_int_equal(file.tokens[2].line, 1);
  assert_int_equal(file.tokens[2].column, 8);
  assert_int_equal(file.tokens[2].length, 8);
  /* The scanner goes on after the '}', in its place. */
  assert_int_equal(file.tokens[3].kind, T_TRIANGLE);
  assert_int_equal(file.tokens[3].line, 3);
  assert_int_equal(file.tokens[3].column, 2);
  /* The second has a texture and the third a trailing comma: tokens. */
  assert_int_equal(file.tokens[4].kind, '{');
  assert_int_equal(file.tokens[5].kind, '<');
  for (size_t i = 6; i < file.n_tokens; i++)
    assert_int_not_equal(file.tokens[i].kind, T_TRIANGLE_RUN);
  zr__sdl_file_free(&file);
}

/* After a run the scanner starts again with small reads that grow
   (tokens.c, zr__sdl_lex_input): tokens longer than those reads, right
   after a run, come out whole and in their places - a string of every
   length from 200 to 1200 bytes (across the 256, 512 and 1024 byte
   reads), then a comment of as many bytes, then a keyword. */
static void test_numlist_tokens_across_reads_after_a_run(void **state) {
  (void)state;
  for (size_t len = 200; len <= 1200; len += 7) {
    zr_strbuf b;
    zr__strbuf_init(&b);
    zr__strbuf_printf(&b, "mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> }"
                          "\"");
    for (size_t i = 0; i < len; i++)
      zr__strbuf_printf(&b, "%c", (char)('a' + i % 26));
    zr__strbuf_printf(&b, "\" /*");
    for (size_t i = 0; i < len; i++)
      zr__strbuf_printf(&b, "%c", i % 61 == 60 ? '\n' : 'c');
    zr__strbuf_printf(&b, "*/ triangle { <0,0,0>, <1,0,0>, <0,1,0> } }");
    zr_sdl_file file;
    lex_text(&file, zr__strbuf_cstr(&b));
    zr__strbuf_free(&b);
    static const int kinds[] = {T_MESH, '{', T_TRIANGLE_RUN, T_STRING,
                                T_TRIANGLE_RUN, '}', 0};
    assert_int_equal(file.n_tokens, sizeof kinds / sizeof *kinds);
    for (size_t i = 0; i < file.n_tokens; i++)
      assert_int_equal(file.tokens[i].kind, kinds[i]);
    const char *str = file.tokens[3].v.str;
    assert_int_equal(strlen(str), len);
    for (size_t i = 0; i < len; i++)
      assert_int_equal(str[i], 'a' + i % 26);
    /* The second run sits after the comment's newlines, in its column. */
    size_t newlines = len / 61, last_line = len - newlines * 61;
    assert_int_equal(file.tokens[4].line, 1 + (int)newlines);
    assert_int_equal(file.tokens[4].column, (int)last_line + 4);
    zr__sdl_file_free(&file);
  }
}

/* Runs that follow runs are taken without the scanner (tokens.c,
   next_run): each keeps its keyword's place and length, and whatever
   is not "triangle {" or "smooth_triangle {" with a plain body (a
   longer word, a texture) goes back to the scanner. */
static void test_numlist_runs_after_runs(void **state) {
  (void)state;
  zr_sdl_file file;
  lex_text(&file,
           "mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> }\n"
           "\t  triangle{<0,0,0>,<1,0,0>,<0,1,0>}  smooth_triangle { <0,0,0>,"
           " <0,0,1>, <1,0,0>, <0,0,1>, <0,1,0>, <0,0,1> }\n"
           "triangles triangle { <1,1,1>, <2,2,2>, <3,3,3> }\n"
           " triangle { <1,1,1>, <2,2,2>, <3,3,3> texture { T } } }\n");
  static const struct {
    int kind, line, column, length;
  } want[] = {{T_MESH, 1, 1, 4},
              {'{', 1, 6, 1},
              {T_TRIANGLE_RUN, 1, 8, 8},
              {T_TRIANGLE_RUN, 2, 4, 8},
              {T_SMOOTH_TRIANGLE_RUN, 2, 39, 15},
              {T_IDENTIFIER, 3, 1, 9},
              {T_TRIANGLE_RUN, 3, 11, 8},
              {T_TRIANGLE, 4, 2, 8},
              {'{', 4, 11, 1}};
  assert_true(file.n_tokens > sizeof want / sizeof *want);
  for (size_t i = 0; i < sizeof want / sizeof *want; i++) {
    const zr_sdl_token *t = &file.tokens[i];
    if (t->kind != want[i].kind || t->line != want[i].line ||
        t->column != want[i].column || t->length != want[i].length)
      fail_msg("token %zu: kind %d at %d:%d (%d bytes), want %d at %d:%d "
               "(%d)", i, t->kind, t->line, t->column, t->length,
               want[i].kind, want[i].line, want[i].column, want[i].length);
  }
  /* A triangle's run holds its corners, one after another in the
     file's corner array; a smooth_triangle's holds its corners and
     normals in turn. */
  static const double first[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  static const double third[9] = {1, 1, 1, 2, 2, 2, 3, 3, 3};
  assert_memory_equal(file.tokens[2].v.corners, first, sizeof first);
  assert_memory_equal(file.tokens[3].v.corners, first, sizeof first);
  assert_ptr_equal(file.tokens[3].v.corners, file.tokens[2].v.corners + 9);
  assert_memory_equal(file.tokens[6].v.corners, third, sizeof third);
  /* The smooth run's corners lie between them. */
  assert_ptr_equal(file.tokens[6].v.corners, file.tokens[3].v.corners + 18);
  static const double normals[9] = {0, 0, 1, 0, 0, 1, 0, 0, 1};
  assert_int_equal(file.tokens[4].v.smooth.corner, 18);
  assert_memory_equal(file.corners + 18, first, sizeof first);
  assert_int_equal(file.tokens[4].v.smooth.normal, 0);
  assert_memory_equal(file.normals, normals, sizeof normals);
  zr__sdl_file_free(&file);
}

/* "smooth_triangle { six plain vectors }" becomes one run token, at the
   keyword's place; a texture, a seventh vector (uv_vectors), five
   vectors, a trailing comma or an expression keep the tokens. */
static void test_numlist_smooth_triangle_run_token(void **state) {
  (void)state;
  zr_sdl_file file;
  lex_text(&file,
           "mesh { smooth_triangle { <0,0,0>, <0,0,1>, <1,0,0>,\n"
           " <0,0,1>, <0,1,0>, <0,0,1> }\n"
           " smooth_triangle { <0,0,0>,<0,0,1>,<1,0,0>,<0,0,1>,<0,1,0>,"
           "<0,0,1> texture { T } }\n"
           " smooth_triangle { <0,0,0>,<0,0,1>,<1,0,0>,<0,0,1>,<0,1,0>,"
           "<0,0,1>, }\n"
           " smooth_triangle { <0,0,0>,<0,0,1>,<1,0,0>,<0,0,1>,<0,1,0> }\n"
           " smooth_triangle { <0,0,0>,<0,0,1>,<1,0,0>,<0,0,1>,<0,1,0>,"
           "<0,0,1> uv_vectors <0,0>,<1,0>,<0,1> }\n"
           " smooth_triangle { <0,0,0>,<0,0,1>,<1,0,0>,<0,0,1>,<0,1,0>,"
           "<0,0,1>*2 } }\n"
           "smooth_triangle{<0,0,0><0,0,1><1,0,0><0,0,1><0,1,0><0,0,1>}\n");
  const zr_sdl_token *t = file.tokens;
  assert_int_equal(t[0].kind, T_MESH);
  assert_int_equal(t[2].kind, T_SMOOTH_TRIANGLE_RUN);
  assert_int_equal(t[2].line, 1);
  assert_int_equal(t[2].column, 8);
  assert_int_equal(t[2].length, 15);
  /* Its corners in the file's corner array, its normals in its normal
     array. */
  static const double corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  static const double normals[9] = {0, 0, 1, 0, 0, 1, 0, 0, 1};
  assert_memory_equal(file.corners + t[2].v.smooth.corner, corners,
                      sizeof corners);
  assert_memory_equal(file.normals + t[2].v.smooth.normal, normals,
                      sizeof normals);
  /* The scanner goes on after the '}', in its place. */
  assert_int_equal(t[3].kind, T_SMOOTH_TRIANGLE);
  assert_int_equal(t[3].line, 3);
  assert_int_equal(t[3].column, 2);
  assert_int_equal(t[4].kind, '{');
  assert_int_equal(t[5].kind, '<');
  /* The five others in the mesh are whole; the last, alone, is a run. */
  size_t runs = 0, whole = 0;
  for (size_t i = 3; i < file.n_tokens; i++) {
    runs += t[i].kind == T_SMOOTH_TRIANGLE_RUN;
    whole += t[i].kind == T_SMOOTH_TRIANGLE;
  }
  assert_int_equal(runs, 1);
  assert_int_equal(whole, 5);
  assert_int_equal(t[file.n_tokens - 2].kind, T_SMOOTH_TRIANGLE_RUN);
  assert_int_equal(t[file.n_tokens - 2].line, 8);
  assert_int_equal(t[file.n_tokens - 2].column, 1);
  assert_int_equal(t[file.n_tokens - 1].kind, 0);
  zr__sdl_file_free(&file);
}

/* "sphere { <x, y, z>, r" followed by a keyword or '}' becomes one run
   token at the keyword's place; anything that an expression or a blob
   could go on with keeps the tokens. */
static void test_numlist_sphere_run_token(void **state) {
  (void)state;
  zr_sdl_file file;
  lex_text(&file, "sphere { <1, -2, 3.5>,\n 0.25 texture { T } }\n"
                  "sphere{<0,0,0>,1}\n"
                  "sphere { <0,0,0>, 1 strength 2 }\n"
                  "sphere { <0,0,0>, 1, 2 }\n"
                  "sphere { <0,0,0>, 1 * 2 }\n"
                  "sphere { <0,0,0>, 1 M }\n"
                  "sphere { <0,0,0>, 1 rgb 1 }\n"
                  "sphere { <0,0,0>, 1e999 scale 2 }\n"
                  "sphere { <0,0,0>, 1 // note\n }\n"
                  "sphere { <0,0,0> 1 }\n");
  const zr_sdl_token *t = file.tokens;
  assert_int_equal(t[0].kind, T_SPHERE_RUN);
  assert_int_equal(t[0].line, 1);
  assert_int_equal(t[0].column, 1);
  assert_int_equal(t[0].length, 6);
  assert_int_equal(t[1].kind, T_TEXTURE);
  assert_int_equal(t[1].line, 2);
  assert_int_equal(t[1].column, 7);
  assert_int_equal(t[5].kind, '}');
  assert_int_equal(t[6].kind, T_SPHERE_RUN);
  assert_int_equal(t[7].kind, '}');
  assert_int_equal(t[7].line, 3);
  assert_int_equal(t[7].column, 17);
  /* The eight others are whole: 'sphere', '{', '<' each. */
  size_t spheres = 0;
  for (size_t i = 8; i < file.n_tokens; i++) {
    assert_int_not_equal(t[i].kind, T_SPHERE_RUN);
    if (t[i].kind == T_SPHERE) {
      assert_int_equal(t[i + 1].kind, '{');
      assert_int_equal(t[i + 2].kind, '<');
      spheres++;
    }
  }
  assert_int_equal(spheres, 8);
  zr__sdl_file_free(&file);
}

/* Spheres read as runs are the same objects, bit for bit, as the
   grammar's (+0 defeats the run), in declarations ended without ';'
   (the engine counts the run's open block), in unions and blobs, and
   their warnings and errors keep their places. */
static void test_numlist_sphere_run_same_as_grammar(void **state) {
  fixture *f = *state;
  static const char *const fmt[2] = {
      "#declare S = sphere { <%d.1, -0.3e-2, 1e-3>, 0.%d }\n"
      "#declare U = union { sphere { <1, 2, 3>, %d scale 2 }\n"
      "  sphere { <-4, 5, -6>, 7 } }\n"
      "object { S }\nobject { U }\n"
      "blob { threshold 0.5 sphere { <0, 0, 0>, %d strength 1 } }\n",
      "#declare S = sphere { <%d.1, -0.3e-2, 1e-3>, 0.%d + 0 }\n"
      "#declare U = union { sphere { <1, 2, 3>, %d + 0 scale 2 }\n"
      "  sphere { <-4, 5, -6>, 7 + 0 } }\n"
      "object { S }\nobject { U }\n"
      "blob { threshold 0.5 sphere { <0, 0, 0>, %d strength 1 } }\n"};
  zr_object spheres[2][3];
  for (int k = 0; k < 2; k++) {
    char text[600];
    snprintf(text, sizeof text, fmt[k], 5, 7, 3, 2);
    zr_scene *s = good(f, text);
    assert_int_equal(s->n_primitives, 4);
    for (int i = 0; i < 3; i++) {
      assert_int_equal(s->primitives[i]->kind, ZR_OBJ_SPHERE);
      spheres[k][i] = *s->primitives[i];
      assert_int_equal(spheres[k][i].where.line, i + 1);
    }
    assert_int_equal(s->primitives[3]->kind, ZR_OBJ_BLOB);
  }
  for (int i = 0; i < 3; i++) {
    assert_memory_equal(&spheres[0][i].u.sphere.centre,
                        &spheres[1][i].u.sphere.centre, sizeof(zr_vec3));
    assert_true(spheres[0][i].u.sphere.radius ==
                spheres[1][i].u.sphere.radius);
    assert_int_equal(spheres[0][i].where.column,
                     spheres[1][i].where.column);
  }
  assert_true(spheres[0][0].u.sphere.centre.x == 5.1);
  assert_true(spheres[0][0].u.sphere.radius == 0.7);
  assert_true(spheres[0][2].u.sphere.centre.z == -6.0);
  good(f, "sphere { <0, 0, 0>, -1 pigment { rgb 1 } }\n");
  assert_int_equal(f->diag.warnings, 1);
  assert_non_null(strstr(f->diag.warning, "t.pov:1:1: warning: a sphere "
                                          "with a negative radius (-1)"));
  bad(f, "sphere { <0,0,0>, 1 texture { pigment { rgb 1 } } }\n"
         "bogus\n",
      ZR_EUNDEFINED, "undefined identifier 'bogus'",
      "t.pov:2:1: error: undefined identifier 'bogus'\n"
      "    2 | bogus\n"
      "      | ^~~~~\n");
  bad(f, "sphere { <0,0,0>, 1e400 pigment { rgb 1 } }\n", ZR_ESCENE,
      "this value is not a finite number (inf): an overflow (such as "
      "1e400) or a division such as inf/inf upstream?", NULL);
}

/* Triangles read as runs make the same mesh and the same triangle
   objects, bit for bit, as the grammar's expressions (+0 defeats the
   run), and their errors keep their places. */
static void test_numlist_triangle_run_same_as_grammar(void **state) {
  fixture *f = *state;
  static const char *const fmt[2] = {
      "mesh { triangle { <%d.1, -0.3e-2, %d>, <1.7, %d, - 2>,\n"
      " <0.1, 0.2, %d> }\n"
      "  triangle { <3,3,3>, <4,3,3>, <3,4,3> } }\n"
      "triangle { <%d, 0.1, 0.2>, <1, 2, 3>, <4, 5, 6> }\n",
      "mesh { triangle { <%d.1, -0.3e-2, %d>, <1.7, %d, - 2>,\n"
      " <0.1, 0.2, %d> + 0 }\n"
      "  triangle { <3,3,3>, <4,3,3>, <3,4,3> + 0 } }\n"
      "triangle { <%d, 0.1, 0.2>, <1, 2, 3>, <4, 5, 6> + 0 }\n"};
  zr_vec3 vertices[2][6], corners[2][3];
  for (int k = 0; k < 2; k++) {
    char text[400];
    snprintf(text, sizeof text, fmt[k], 5, 6, 7, 8, 9);
    zr_scene *s = good(f, text);
    const struct zr_mesh *m = mesh_of(s, 0);
    assert_int_equal(m->n_faces, 2);
    assert_int_equal(m->n_vertices, 6);
    memcpy(vertices[k], m->vertices, sizeof vertices[k]);
    assert_int_equal(s->primitives[1]->kind, ZR_OBJ_TRIANGLE);
    memcpy(corners[k], s->primitives[1]->u.triangle.p, sizeof corners[k]);
  }
  assert_memory_equal(vertices[0], vertices[1], sizeof vertices[0]);
  assert_memory_equal(corners[0], corners[1], sizeof corners[0]);
  assert_true(corners[0][0].x == 9.0 && corners[0][2].z == 6.0);
  bad(f, "triangle { <0,0,0>, <1,0,0>, <0,1,0> }\n"
         "bogus\n",
      ZR_EUNDEFINED, "undefined identifier 'bogus'",
      "t.pov:2:1: error: undefined identifier 'bogus'\n"
      "    2 | bogus\n"
      "      | ^~~~~\n");
}

/* A loop or a macro that replays a triangle run's token gives the same
   face each time, and a run's triangle object has the run's corners. */
static void test_numlist_triangle_run_replayed(void **state) {
  fixture *f = *state;
  zr_scene *s = good(f, "#macro T() triangle { <1.5, -2, 3e-1>, <4,5,6>,\n"
                        " <7, 8.25, -9> } #end\n"
                        "mesh { #for (i, 1, 3) triangle { <0.1,0,0>,\n"
                        " <1,0,0>, <0,1,0> } #end T() T() }\n"
                        "T()\n");
  const struct zr_mesh *m = mesh_of(s, 0);
  assert_int_equal(m->n_faces, 5);
  /* The build orders the faces: count each kind. */
  int loop = 0, macro = 0;
  for (size_t i = 0; i < m->n_faces; i++) {
    const zr_vec3 *c[3];
    for (int k = 0; k < 3; k++)
      c[k] = &m->vertices[m->faces[i][k]];
    loop += c[0]->x == 0.1 && c[1]->x == 1 && c[2]->y == 1;
    macro += c[0]->x == 1.5 && c[0]->z == 0.3 && c[2]->y == 8.25 &&
             c[2]->z == -9;
  }
  assert_int_equal(loop, 3);
  assert_int_equal(macro, 2);
  assert_int_equal(s->primitives[1]->kind, ZR_OBJ_TRIANGLE);
  const zr_vec3 *p = s->primitives[1]->u.triangle.p;
  assert_true(p[0].x == 1.5 && p[0].y == -2 && p[1].z == 6 &&
              p[2].y == 8.25);
}

/* Smooth triangles read as runs make the same mesh, corners and
   normals bit for bit, as the grammar's expressions (+0 defeats the
   run), in a mesh and alone, and their errors keep their places. */
static void test_numlist_smooth_triangle_run_same_as_grammar(void **state) {
  fixture *f = *state;
  static const char *const fmt[2] = {
      "mesh { smooth_triangle { <%d.1, -0.3e-2, %d>, <0.1, 0.2, 0.9>,\n"
      " <1.7, %d, - 2>, <-0.25, 1e-1, .5>, <0.1, 0.2, %d>, <0,0,1> }\n"
      "  triangle { <3,3,3>, <4,3,3>, <3,4,3> } }\n"
      "smooth_triangle { <%d, 0.1, 0.2>, <0,1,0>, <1, 2, 3>, <1,0,0>,\n"
      " <4, 5, 6>, <0.6, 0.8, 0> }\n",
      "mesh { smooth_triangle { <%d.1, -0.3e-2, %d>, <0.1, 0.2, 0.9>,\n"
      " <1.7, %d, - 2>, <-0.25, 1e-1, .5>, <0.1, 0.2, %d>, <0,0,1> + 0 }\n"
      "  triangle { <3,3,3>, <4,3,3>, <3,4,3> } }\n"
      "smooth_triangle { <%d, 0.1, 0.2>, <0,1,0>, <1, 2, 3>, <1,0,0>,\n"
      " <4, 5, 6>, <0.6, 0.8, 0> + 0 }\n"};
  zr_vec3 vertices[2][6], normals[2][6], corners[2][3], lone[2][3];
  for (int k = 0; k < 2; k++) {
    char text[600];
    snprintf(text, sizeof text, fmt[k], 5, 6, 7, 8, 9);
    zr_scene *s = good(f, text);
    const struct zr_mesh *m = mesh_of(s, 0);
    assert_int_equal(m->n_faces, 2);
    assert_int_equal(m->n_vertices, 6);
    assert_int_equal(m->n_normals, 6);
    memcpy(vertices[k], m->vertices, sizeof vertices[k]);
    memcpy(normals[k], m->normals, sizeof normals[k]);
    const struct zr_mesh *one = mesh_of(s, 1);
    assert_int_equal(one->n_faces, 1);
    assert_int_equal(one->n_normals, 3);
    memcpy(corners[k], one->vertices, sizeof corners[k]);
    memcpy(lone[k], one->normals, sizeof lone[k]);
  }
  assert_memory_equal(vertices[0], vertices[1], sizeof vertices[0]);
  assert_memory_equal(normals[0], normals[1], sizeof normals[0]);
  assert_memory_equal(corners[0], corners[1], sizeof corners[0]);
  assert_memory_equal(lone[0], lone[1], sizeof lone[0]);
  assert_true(vertices[0][0].x == 5.1 && vertices[0][1].y == 7.0);
  assert_true(corners[0][0].x == 9.0 && corners[0][2].z == 6.0);
  bad(f, "smooth_triangle { <0,0,0>, <0,0,1>, <1,0,0>, <0,0,1>,\n"
         " <0,1,0>, <0,0,1> }\n"
         "bogus\n",
      ZR_EUNDEFINED, "undefined identifier 'bogus'",
      "t.pov:3:1: error: undefined identifier 'bogus'\n"
      "    3 | bogus\n"
      "      | ^~~~~\n");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_numlist_numbers_like_strtod),
      cmocka_unit_test(test_numlist_eight_byte_reads),
      cmocka_unit_test(test_numlist_stops_where_the_grammar_starts),
      cmocka_unit_test(test_numlist_lexer_keeps_one_token),
      cmocka_unit_test(test_numlist_triangle_run_token),
      cmocka_unit_test(test_numlist_tokens_across_reads_after_a_run),
      cmocka_unit_test(test_numlist_runs_after_runs),
      cmocka_unit_test(test_numlist_sphere_run_token),
      cmocka_unit_test(test_numlist_smooth_triangle_run_token),
      cmocka_unit_test_setup_teardown(
          test_numlist_smooth_triangle_run_same_as_grammar, setup, teardown),
      cmocka_unit_test_setup_teardown(
          test_numlist_sphere_run_same_as_grammar, setup, teardown),
      cmocka_unit_test_setup_teardown(
          test_numlist_triangle_run_same_as_grammar, setup, teardown),
      cmocka_unit_test_setup_teardown(test_numlist_triangle_run_replayed,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_numlist_same_mesh_as_the_grammar,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(
          test_numlist_replayed_by_loops_and_macros, setup, teardown),
      cmocka_unit_test_setup_teardown(test_numlist_error_places, setup,
                                      teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
