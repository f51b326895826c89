/*
 * fileio.c - the file directives #fopen, #fclose, #read and #write
 * (reference manual, "File I/O Directives").
 *
 * A file opened for reading is read through the context's reader and
 * lexed by the scene scanner, like an include file, so #read takes its
 * string, float and vector literals (with unary signs) from a token
 * array, and a malformed datum is reported with the data file's line
 * under a caret.  Reading the last datum closes the file and undefines
 * its handle (as povray 3.7.0 does), so defined(F) tells the end.  #write
 * prints floats as "%g", vectors as "<x,y,z> " (the format povray 3.7.0
 * writes) and strings as they are.
 *
 * A file is read where #include looks (next to the including file, in
 * the include paths, in POV-Ray's include directory) and written where
 * it is named, both under the context's I/O restrictions
 * (lib/core/iopolicy.c): by default reads below the scene's folder, the
 * working directory and the include paths, writes below the working
 * directory, judged after symbolic links are resolved.  The binary word
 * types of #write (uint8 ...) are not supported yet.
 */
#include "config.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/iopolicy.h"
#include "pov-parse.h"
#include "sdl/sdl.h"

void zr__sdl_close_files(zr_sdl_parser *p) {
  while (p->handles) {
    zr_sdl_fhandle *h = p->handles;
    p->handles = h->next;
    if (h->out)
      fclose(h->out);
    free(h);
  }
}

static void forget(zr_sdl_parser *p, zr_sdl_fhandle *h) {
  for (zr_sdl_fhandle **k = &p->handles; *k; k = &(*k)->next) {
    if (*k == h) {
      *k = h->next;
      break;
    }
  }
  if (h->out)
    fclose(h->out);
  free(h);
}

/* The open file called name, or NULL after reporting. */
static zr_sdl_fhandle *handle(zr_sdl_parser *p, const char *name,
                              const zr_sdl_loc *at) {
  const zr_sdl_symbol *s = zr__sdl_lookup(p, name, NULL);
  if (!s || s->value.kind != ZR_SDL_FILE) {
    zr__sdl_error(p, ZR_ESYNTAX, at, "'%s' is not an open file", name);
    return NULL;
  }
  return (zr_sdl_fhandle *)s->value.ptr;
}

static bool do_fopen(zr_sdl_parser *p, const zr_sdl_loc *at) {
  zr_sdl_loc nl = zr__sdl_peek_loc(p, 0);
  const char *name = zr__sdl_read_name(p, "'#fopen'");
  if (!name)
    return false;
  zr_sdl_loc fl = zr__sdl_peek_loc(p, 0);
  if (zr__sdl_parse_nested(p, T_START_STRING) != ZR_OK)
    return false;
  const char *path = p->nested_rvalue.ptr;
  const zr_sdl_token *mode = zr__sdl_peek(p, 0);
  const char *m = mode->kind == T_UNSUPPORTED || mode->kind == T_IDENTIFIER
                      ? mode->v.str : "";
  bool reading = strcmp(m, "read") == 0;
  if (!reading && strcmp(m, "write") != 0 && strcmp(m, "append") != 0) {
    zr_sdl_loc ml = zr__sdl_peek_loc(p, 0);
    zr__sdl_error(p, ZR_ESYNTAX, &ml,
                  "expected 'read', 'write' or 'append' after the file name");
    return false;
  }
  zr__sdl_top(p)->pos++;
  zr_sdl_fhandle *h = calloc(1, sizeof *h);
  if (!h) {
    zr__sdl_error(p, ZR_ENOMEM, at, "out of memory");
    return false;
  }
  h->file = -1;
  if (reading) {
    /* Searched like #include, under the I/O restrictions. */
    h->file = zr__sdl_open_data(p, path, &fl);
    if (h->file < 0) {
      free(h);
      return false;
    }
  } else if (p->ctx && p->ctx->no_scene_writes) {
    /* Another process writes this file (zr_context_set_scene_writes):
       the handle takes the #write directives and discards them. */
    h->writing = true;
  } else {
    char why[1024];
    FILE *out = NULL;
    h->writing = true;
    zr_status s = zr__io_open_scene_write(
        p->ctx, path, m[0] == 'w' ? ZR_IO_ACCESS_WRITE : ZR_IO_ACCESS_APPEND,
        &out, why, sizeof why);
    h->out = out;
    if (s != ZR_OK) {
      free(h);
      zr__sdl_error(p, s, &fl, "'#fopen' cannot open a file for %s: %s",
                    m[0] == 'w' ? "writing" : "appending", why);
      return false;
    }
  }
  h->next = p->handles;
  p->handles = h;
  zr_sdl_value v;
  memset(&v, 0, sizeof v);
  v.kind = ZR_SDL_FILE;
  v.ptr = h;
  /* File handles are always global ("The fopen Directive"). */
  if (zr__sdl_symtab_set(&p->globals, name, &v) != ZR_OK) {
    zr__sdl_error(p, ZR_ENOMEM, &nl, "out of memory");
    return false;
  }
  return true;
}

static bool do_fclose(zr_sdl_parser *p) {
  zr_sdl_loc nl = zr__sdl_peek_loc(p, 0);
  const char *name = zr__sdl_read_name(p, "'#fclose'");
  if (!name)
    return false;
  /* A file that #read closed at its end may be closed again (the stock
     fileio.pov does so). */
  if (!zr__sdl_lookup(p, name, NULL))
    return true;
  zr_sdl_fhandle *h = handle(p, name, &nl);
  if (!h)
    return false;
  forget(p, h);
  zr__sdl_symtab_remove(&p->globals, name);
  return true;
}

/* A signed number in a data file at tokens[*i]. */
static bool datum_number(const zr_sdl_token *t, size_t *i, double *out) {
  double sign = 1;
  while (t[*i].kind == '-' || t[*i].kind == '+') {
    if (t[*i].kind == '-')
      sign = -sign;
    (*i)++;
  }
  if (t[*i].kind != T_NUMBER)
    return false;
  *out = sign * t[(*i)++].v.num;
  return true;
}

/* Reads the next datum of h into *v: 1, 0 at the end of the file, -1
   after reporting a malformed one. */
static int datum(zr_sdl_parser *p, zr_sdl_fhandle *h, zr_sdl_value *v) {
  const zr_sdl_file *f = &p->files[h->file];
  const zr_sdl_token *t = f->tokens;
  size_t i = h->pos;
  while (t[i].kind == ',')
    i++;
  if (t[i].kind == 0)
    return 0;
  size_t start = i;
  memset(v, 0, sizeof *v);
  if (t[i].kind == T_STRING) {
    v->kind = ZR_SDL_STRING;
    v->ptr = zr__sdl_strdup(p, t[i].v.str, strlen(t[i].v.str));
    if (!v->ptr)
      return -1;
    i++;
  } else if (t[i].kind == '<') {
    i++;
    v->num.dim = 0;
    for (;;) {
      if (v->num.dim == 5 || !datum_number(t, &i, &v->num.v[v->num.dim]))
        goto malformed;
      v->num.dim++;
      if (t[i].kind != ',')
        break;
      i++;
    }
    if (t[i].kind != '>' || v->num.dim < 2)
      goto malformed;
    i++;
    v->kind = v->num.dim == 5 ? ZR_SDL_COLOUR : ZR_SDL_VECTOR;
  } else {
    double x;
    if (!datum_number(t, &i, &x))
      goto malformed;
    v->kind = ZR_SDL_FLOAT;
    v->num = zr__sdl_float(x);
  }
  h->pos = i;
  return 1;
malformed:;
  zr_sdl_loc at = zr__sdl_token_loc(h->file, &t[i > start ? i : start]);
  zr__sdl_error(p, ZR_ESYNTAX, &at,
                "expected a float, vector or string literal");
  return -1;
}

static bool do_read(zr_sdl_parser *p) {
  if (!zr__sdl_expect(p, '(', "'(' after '#read'"))
    return false;
  zr_sdl_loc nl = zr__sdl_peek_loc(p, 0);
  const char *name = zr__sdl_read_name(p, "'#read ('");
  zr_sdl_fhandle *h = name ? handle(p, name, &nl) : NULL;
  if (!h)
    return false;
  if (h->file < 0) {
    zr__sdl_error(p, ZR_ESYNTAX, &nl, "'%s' is open for writing", name);
    return false;
  }
  bool open = true;
  while (zr__sdl_peek(p, 0)->kind == ',') {
    zr__sdl_top(p)->pos++;
    zr_sdl_loc vl = zr__sdl_peek_loc(p, 0);
    const char *var = zr__sdl_read_name(p, "','");
    if (!var)
      return false;
    if (!open)
      continue;
    zr_sdl_value v;
    int r = datum(p, h, &v);
    if (r < 0)
      return false;
    if (r == 0) {
      /* Past the end: the file closes and its handle goes. */
      forget(p, h);
      zr__sdl_symtab_remove(&p->globals, name);
      open = false;
      continue;
    }
    zr_sdl_decl_name decl;
    memset(&decl, 0, sizeof decl);
    decl.name = var;
    decl.frame = (int)(p->n_frames - 1);
    if (!zr__sdl_define(p, &decl, false, &v, &vl))
      return false;
  }
  if (open) {
    /* Like povray 3.7.0, the file closes as soon as its last datum was
       read, so "#while (defined(F)) #read (F, V) ... #end" stops right. */
    const zr_sdl_token *t = p->files[h->file].tokens;
    size_t i = h->pos;
    while (t[i].kind == ',')
      i++;
    if (t[i].kind == 0) {
      forget(p, h);
      zr__sdl_symtab_remove(&p->globals, name);
    }
  }
  return zr__sdl_expect(p, ')', "',' or ')' in '#read'");
}

static bool do_write(zr_sdl_parser *p) {
  if (!zr__sdl_expect(p, '(', "'(' after '#write'"))
    return false;
  zr_sdl_loc nl = zr__sdl_peek_loc(p, 0);
  const char *name = zr__sdl_read_name(p, "'#write ('");
  zr_sdl_fhandle *h = name ? handle(p, name, &nl) : NULL;
  if (!h)
    return false;
  if (!h->writing) {
    zr__sdl_error(p, ZR_ESYNTAX, &nl, "'%s' is open for reading", name);
    return false;
  }
  /* povray 3.7.0 reads "#write (F Text)" without the comma too (the
     stock portfolio scene writes so). */
  if (zr__sdl_peek(p, 0)->kind == ',')
    zr__sdl_top(p)->pos++;
  for (;;) {
    zr_sdl_loc il = zr__sdl_peek_loc(p, 0);
    if (zr__sdl_parse_nested(p, T_START_ARG) != ZR_OK)
      return false;
    const zr_sdl_value *v = &p->nested_rvalue;
    FILE *out = h->out;
    switch (v->kind) {
    case ZR_SDL_STRING:
      if (out)
        fputs(v->ptr, out);
      break;
    case ZR_SDL_FLOAT:
      if (out)
        fprintf(out, "%g", v->num.v[0]);
      break;
    case ZR_SDL_VECTOR:
    case ZR_SDL_COLOUR:
      for (int i = 0; out && i < v->num.dim; i++)
        fprintf(out, i ? ",%g" : "<%g", v->num.v[i]);
      if (out)
        fputs("> ", out);
      break;
    default:
      zr__sdl_error(p, ZR_ESYNTAX, &il,
                    "'#write' writes floats, vectors and strings only");
      return false;
    }
    if (p->nested_end == ')')
      return true;
  }
}

bool zr__sdl_run_file_directive(zr_sdl_parser *p, int kind,
                                const zr_sdl_loc *at) {
  switch (kind) {
  case T_FOPEN:
    return do_fopen(p, at);
  case T_FCLOSE:
    return do_fclose(p);
  case T_READ:
    return do_read(p);
  default:
    return do_write(p);
  }
}
