/*
 * values.c - numeric expressions and symbol tables.
 *
 * POV-Ray has one expression language for floats, vectors and colours
 * (reference manual, "Float Expressions", "Vector Expressions", "Color
 * Expressions"): operators work component by component, and the smaller
 * operand is promoted, a float to every component ("scale 2" means
 * "scale <2,2,2>", and a float where a colour is wanted fills all five
 * components, as the "Reflection" section notes).  An expression here is
 * up to five doubles with a dimension; the grammar checks what each place
 * wants through the zr__sdl_want_*() calls, which name the mismatch.
 * Symbol tables are in symtab.c, the functions and strings in
 * builtins.c.
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "pov-parse.h"
#include "sdl/sdl.h"

zr_sdl_expr zr__sdl_float(double f) {
  zr_sdl_expr e;
  memset(&e, 0, sizeof e);
  e.dim = 1;
  e.v[0] = f;
  return e;
}

zr_sdl_expr zr__sdl_vec(double x, double y, double z) {
  zr_sdl_expr e;
  memset(&e, 0, sizeof e);
  e.dim = 3;
  e.v[0] = x;
  e.v[1] = y;
  e.v[2] = z;
  return e;
}

zr_sdl_expr zr__sdl_colour_expr(zr_colour c) {
  zr_sdl_expr e;
  e.dim = 5;
  e.v[0] = c.r;
  e.v[1] = c.g;
  e.v[2] = c.b;
  e.v[3] = c.f;
  e.v[4] = c.t;
  return e;
}

/* What an expression of dimension dim is called in messages. */
static const char *dim_name(int dim) {
  switch (dim) {
  case 1:
    return "a float";
  case 2:
    return "a 2-D vector";
  case 4:
    return "a 4-D vector";
  case 5:
    return "a colour";
  default:
    return "a vector";
  }
}

/* Widens e to dim components: a float fills them all, a shorter vector
   is padded with zeros. */
static zr_sdl_expr promote(const zr_sdl_expr *e, int dim) {
  zr_sdl_expr r = *e;
  for (int i = e->dim; i < dim; i++)
    r.v[i] = e->dim == 1 ? e->v[0] : 0.0;
  if (dim > r.dim)
    r.dim = dim;
  return r;
}

bool zr__sdl_binop(zr_sdl_parser *p, int op, const zr_sdl_expr *a,
                   const zr_sdl_expr *b, const zr_sdl_loc *loc,
                   zr_sdl_expr *out) {
  int dim = a->dim > b->dim ? a->dim : b->dim;
  zr_sdl_expr x = promote(a, dim), y = promote(b, dim);
  for (int i = 0; i < dim; i++) {
    switch (op) {
    case '+':
      x.v[i] += y.v[i];
      break;
    case '-':
      x.v[i] -= y.v[i];
      break;
    case '*':
      x.v[i] *= y.v[i];
      break;
    default:
      if (y.v[i] == 0.0) {
        /* POV-Ray warns once a component and goes on with +inf whatever
           the sign of the dividend, 0/0 included (measured with povray
           3.7: 5/0, -5/0 and 0/0 all print "inf", -5/0 < 0 is false;
           tests/sdl_divzero.sh). */
        zr__sdl_warning(p, loc, "Divide by zero.");
        x.v[i] = HUGE_VAL;
        break;
      }
      x.v[i] /= y.v[i];
      break;
    }
  }
  *out = x;
  return true;
}

void zr__sdl_negate(zr_sdl_expr *e) {
  for (int i = 0; i < e->dim; i++)
    e->v[i] = -e->v[i];
}

zr_sdl_list *zr__sdl_list_new(zr_sdl_parser *p) {
  zr_sdl_list *l = p->free_lists;
  if (l)
    p->free_lists = l->next_free;
  else if (!(l = zr__sdl_alloc(p, sizeof *l)))
    return NULL;
  l->n = 0;
  l->next_free = NULL;
  return l;
}

/* A list the grammar dropped after an error is not given back: the
   arena frees it with the scene. */
void zr__sdl_list_release(zr_sdl_parser *p, zr_sdl_list *l) {
  l->next_free = p->free_lists;
  p->free_lists = l;
}

bool zr__sdl_list_add(zr_sdl_parser *p, zr_sdl_list *l, const zr_sdl_expr *e,
                      const zr_sdl_loc *loc) {
  if (e->dim != 1) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "expected a float here, got %s",
                  dim_name(e->dim));
    return false;
  }
  if (l->n >= ZR_SDL_LIST_MAX) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "too many values (more than %d)",
                  ZR_SDL_LIST_MAX);
    return false;
  }
  l->v[l->n++] = e->v[0];
  return true;
}

bool zr__sdl_from_list(zr_sdl_parser *p, const zr_sdl_list *l,
                       const zr_sdl_loc *loc, zr_sdl_expr *out) {
  if (l->n < 2 || l->n > 5) {
    zr__sdl_error(p, ZR_ESYNTAX, loc,
                  "a vector has 2 to 5 components, not %d", l->n);
    return false;
  }
  memset(out, 0, sizeof *out);
  out->dim = l->n;
  memcpy(out->v, l->v, (size_t)l->n * sizeof l->v[0]);
  return true;
}

bool zr__sdl_dot(zr_sdl_parser *p, const zr_sdl_expr *e, int item,
                 const zr_sdl_loc *loc, zr_sdl_expr *out) {
  int index;
  const char *name;
  switch (item) {
  case T_X: index = 0; name = "x"; break;
  case T_U: index = 0; name = "u"; break;
  case T_RED: index = 0; name = "red"; break;
  case T_Y: index = 1; name = "y"; break;
  case T_V: index = 1; name = "v"; break;
  case T_GREEN: index = 1; name = "green"; break;
  case T_Z: index = 2; name = "z"; break;
  case T_BLUE: index = 2; name = "blue"; break;
  case T_T: index = 3; name = "t"; break;
  case T_FILTER: index = 3; name = "filter"; break;
  case T_TRANSMIT: index = 4; name = "transmit"; break;
  default: index = -1; name = "gray"; break;
  }
  if (e->dim == 1 || (index < 0 && e->dim < 3) || index >= e->dim) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "%s has no component '.%s'",
                  dim_name(e->dim), name);
    return false;
  }
  /* .gray weighs red, green and blue as the manual's grey: "gray value
     = Red*29.7% + Green*58.9% + Blue*11.4%" (2.3.3.3.7, "Noise and
     pigment functions"). */
  *out = zr__sdl_float(index < 0 ? 0.297 * e->v[0] + 0.589 * e->v[1] +
                                       0.114 * e->v[2]
                                 : e->v[index]);
  return true;
}

typedef struct func_info {
  int token;
  const char *name;
  int arity; /* -1: one or more; -2: two or more; -3: three or four */
} func_info;

static const func_info funcs[] = {
    {T_SIN, "sin", 1},         {T_COS, "cos", 1},
    {T_TAN, "tan", 1},         {T_ASIN, "asin", 1},
    {T_ACOS, "acos", 1},       {T_ATAN, "atan", 1},
    {T_ATAN2, "atan2", 2},     {T_SINH, "sinh", 1},
    {T_COSH, "cosh", 1},       {T_TANH, "tanh", 1},
    {T_SQRT, "sqrt", 1},       {T_POW, "pow", 2},
    {T_ABS, "abs", 1},         {T_MIN, "min", -1},
    {T_MAX, "max", -1},        {T_EXP, "exp", 1},
    {T_LOG, "log", 1},         {T_LN, "ln", 1},
    {T_FLOOR, "floor", 1},     {T_CEIL, "ceil", 1},
    {T_INT, "int", 1},         {T_MOD, "mod", 2},
    {T_DIV, "div", 2},         {T_DEGREES, "degrees", 1},
    {T_RADIANS, "radians", 1},   {T_ACOSH, "acosh", 1},
    {T_ASINH, "asinh", 1},       {T_ATANH, "atanh", 1},
    {T_SELECT, "select", -3},    {T_BITWISE_AND, "bitwise_and", -2},
    {T_BITWISE_OR, "bitwise_or", -2},
    {T_BITWISE_XOR, "bitwise_xor", -2},
};

static double evaluate(int token, const double *a, int n) {
  double r;
  switch (token) {
  case T_SIN: return sin(a[0]);
  case T_COS: return cos(a[0]);
  case T_TAN: return tan(a[0]);
  case T_ASIN: return asin(a[0]);
  case T_ACOS: return acos(a[0]);
  case T_ATAN: return atan(a[0]);
  case T_ATAN2: return atan2(a[0], a[1]);
  case T_SINH: return sinh(a[0]);
  case T_COSH: return cosh(a[0]);
  case T_TANH: return tanh(a[0]);
  case T_SQRT: return sqrt(a[0]);
  case T_POW: return pow(a[0], a[1]);
  case T_ABS: return fabs(a[0]);
  case T_EXP: return exp(a[0]);
  case T_LOG: return log10(a[0]); /* POV-Ray's log is base 10 */
  case T_LN: return log(a[0]);
  case T_FLOOR: return floor(a[0]);
  case T_CEIL: return ceil(a[0]);
  case T_INT: return trunc(a[0]);
  case T_MOD: return a[1] == 0.0 ? NAN : fmod(a[0], a[1]);
  case T_DIV: return a[1] == 0.0 ? NAN : trunc(a[0] / a[1]);
  case T_DEGREES: return a[0] * 180.0 / 3.14159265358979323846;
  case T_RADIANS: return a[0] * 3.14159265358979323846 / 180.0;
  case T_ACOSH: return acosh(a[0]);
  case T_ASINH: return asinh(a[0]);
  case T_ATANH: return atanh(a[0]);
  case T_SELECT:
    /* select(A, B, C [, D]): B when A < 0, else C; with D, C only when
       A = 0 and D when A > 0 ("Float Functions"). */
    if (a[0] < 0)
      return a[1];
    return n == 3 || a[0] == 0 ? a[2] : a[3];
  case T_BITWISE_AND:
  case T_BITWISE_OR:
  case T_BITWISE_XOR: {
    /* Each argument is first made an integer (the manual's note). */
    long long b = (long long)a[0];
    for (int i = 1; i < n; i++) {
      long long c = (long long)a[i];
      b = token == T_BITWISE_AND ? (b & c)
          : token == T_BITWISE_OR ? (b | c) : (b ^ c);
    }
    return (double)b;
  }
  case T_MIN:
  case T_MAX:
    r = a[0];
    for (int i = 1; i < n; i++)
      r = token == T_MIN ? fmin(r, a[i]) : fmax(r, a[i]);
    return r;
  default:
    return NAN;
  }
}

bool zr__sdl_call(zr_sdl_parser *p, int func, const zr_sdl_list *args,
                  const zr_sdl_loc *loc, zr_sdl_expr *out) {
  const func_info *f = NULL;
  for (size_t i = 0; i < sizeof funcs / sizeof funcs[0]; i++)
    if (funcs[i].token == func)
      f = &funcs[i];
  if (!f)
    return zr__sdl_error(p, ZR_ESYNTAX, loc, "unknown function"), false;
  if ((f->arity == -2 && args->n < 2) ||
      (f->arity == -3 && (args->n < 3 || args->n > 4))) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "'%s' takes %s arguments, not %d",
                  f->name, f->arity == -2 ? "two or more" : "3 or 4",
                  args->n);
    return false;
  }
  if (f->arity >= 0 && args->n != f->arity) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "'%s' takes %d argument%s, not %d",
                  f->name, f->arity, f->arity == 1 ? "" : "s", args->n);
    return false;
  }
  double r = evaluate(func, args->v, args->n);
  if (!isfinite(r)) {
    zr__sdl_error(p, ZR_ESCENE, loc,
                  "'%s' has no finite value for these arguments", f->name);
    return false;
  }
  *out = zr__sdl_float(r);
  return true;
}

bool zr__sdl_vcall(zr_sdl_parser *p, int func, const zr_sdl_expr *a,
                   const zr_sdl_expr *b, const zr_sdl_loc *loc,
                   zr_sdl_expr *out) {
  zr_vec3 u, v = {0, 0, 0};
  if (!zr__sdl_want_vector(p, a, loc, &u) ||
      (b && !zr__sdl_want_vector(p, b, loc, &v)))
    return false;
  switch (func) {
  case T_VLENGTH:
    *out = zr__sdl_float(zr_v3_len(u));
    break;
  case T_VNORMALIZE:
    u = zr_v3_norm(u);
    *out = zr__sdl_vec(u.x, u.y, u.z);
    break;
  case T_VDOT:
    *out = zr__sdl_float(zr_v3_dot(u, v));
    break;
  default:
    u = zr_v3_cross(u, v);
    *out = zr__sdl_vec(u.x, u.y, u.z);
    break;
  }
  return true;
}

static bool mismatch(zr_sdl_parser *p, const zr_sdl_loc *loc,
                     const char *want, int dim) {
  zr__sdl_error(p, ZR_ESYNTAX, loc, "expected %s, got %s", want,
                dim_name(dim));
  return false;
}

/*
 * A value that reaches the scene (a radius, a point, a colour, a
 * transform's numbers, a loop count, an index) must be a finite number:
 * an infinity or a NaN (1e400, inf/inf) would pass silently into
 * bounds, intersections and pixels.  POV-Ray 3.7 takes them without a
 * word (measured: "sphere { 0, 1e400 }" renders); here they stop the
 * parse where they enter, with the place.  Only the first dim items
 * are looked at.
 */
static bool finite_value(zr_sdl_parser *p, const zr_sdl_loc *loc,
                         const zr_sdl_expr *e, int dim) {
  for (int i = 0; i < dim && i < 5; i++) {
    if (!isfinite(e->v[i])) {
      zr__sdl_error(p, ZR_ESCENE, loc, "this value is not a finite "
                    "number (%s%s): an overflow (such as 1e400) or a "
                    "division such as inf/inf upstream?",
                    isnan(e->v[i]) ? "nan" : e->v[i] > 0 ? "inf" : "-inf",
                    dim > 1 ? " in one of its components" : "");
      return false;
    }
  }
  return true;
}

bool zr__sdl_want_float(zr_sdl_parser *p, const zr_sdl_expr *e,
                        const zr_sdl_loc *loc, double *out) {
  if (e->dim != 1)
    return mismatch(p, loc, "a float", e->dim);
  if (!finite_value(p, loc, e, 1))
    return false;
  *out = e->v[0];
  return true;
}

bool zr__sdl_want_any_float(zr_sdl_parser *p, const zr_sdl_expr *e,
                            const zr_sdl_loc *loc, double *out) {
  if (e->dim != 1)
    return mismatch(p, loc, "a float", e->dim);
  *out = e->v[0];
  return true;
}

bool zr__sdl_want_extent(zr_sdl_parser *p, const zr_sdl_expr *e,
                         const zr_sdl_loc *loc, zr_vec3 *out) {
  if (e->dim > 3)
    return mismatch(p, loc, "a vector", e->dim);
  zr_sdl_expr v = promote(e, 3);
  for (int i = 0; i < 3; i++) {
    if (isinf(v.v[i]))
      v.v[i] = 0.0; /* only to pass the NaN test below */
  }
  if (!finite_value(p, loc, &v, 3))
    return false;
  v = promote(e, 3);
  *out = zr_v3(v.v[0], v.v[1], v.v[2]);
  return true;
}

bool zr__sdl_want_vector(zr_sdl_parser *p, const zr_sdl_expr *e,
                         const zr_sdl_loc *loc, zr_vec3 *out) {
  if (e->dim > 3)
    return mismatch(p, loc, "a vector", e->dim);
  zr_sdl_expr v = promote(e, 3);
  if (!finite_value(p, loc, &v, 3))
    return false;
  *out = zr_v3(v.v[0], v.v[1], v.v[2]);
  return true;
}

bool zr__sdl_want_colour(zr_sdl_parser *p, const zr_sdl_expr *e,
                         const zr_sdl_loc *loc, zr_colour *out) {
  if (e->dim == 2)
    return mismatch(p, loc, "a colour", e->dim);
  zr_sdl_expr c = promote(e, 5);
  if (!finite_value(p, loc, &c, 5))
    return false;
  *out = zr_colour5(c.v[0], c.v[1], c.v[2], c.v[3], c.v[4]);
  return true;
}

bool zr__sdl_want_rgb(zr_sdl_parser *p, const zr_sdl_expr *e,
                      const zr_sdl_loc *loc, zr_rgb *out) {
  zr_colour c;
  if (!zr__sdl_want_colour(p, e, loc, &c))
    return false;
  *out = zr_rgb3(c.r, c.g, c.b);
  return true;
}

/* Reads a colour item's value as n components into v: a float fills
   them all, a shorter vector gets zeros ("rgbt <1, 0.5, 0.25>" has
   transmit 0 and "rgb <0.2, 0.3>" blue 0 in POV-Ray 3.7, measured:
   tests/refused/colour_short_vector.pov). */
static bool item_components(zr_sdl_parser *p, const zr_sdl_colour_mod *m,
                            int n, double *v) {
  (void)p;
  const zr_sdl_expr *e = &m->value;
  zr_sdl_expr x = promote(e, n);
  for (int i = 0; i < n; i++)
    v[i] = x.v[i];
  return true;
}

/* An sRGB-encoded component (the manual's "sRGB Colors": srgb, srgbf,
   srgbt, srgbft) in the working space: the sRGB standard's decoding to
   linear light, then the working space's exponent 1/assumed_gamma.
   Negative values decode as the mirror image of positive ones. */
static double srgb_to_working(double s, double assumed_gamma) {
  double a = fabs(s);
  double linear = a <= 0.04045 ? a / 12.92 : pow((a + 0.055) / 1.055, 2.4);
  if (assumed_gamma > 0 && assumed_gamma != 1.0)
    linear = pow(linear, 1.0 / assumed_gamma);
  return s < 0 ? -linear : linear;
}

bool zr__sdl_colour_apply(zr_sdl_parser *p, zr_sdl_expr *colour,
                          const zr_sdl_colour_mod *mod) {
  if (colour->dim != 5) {
    zr_colour c;
    if (!zr__sdl_want_colour(p, colour, &mod->loc, &c))
      return false;
    *colour = zr__sdl_colour_expr(c);
  }
  double v[5];
  double *c = colour->v;
  switch (mod->token) {
  case 0:
    return true;
  case T_SRGB:
  case T_SRGBF:
  case T_SRGBT:
  case T_SRGBFT: {
    int n = mod->token == T_SRGB ? 3 : mod->token == T_SRGBFT ? 5 : 4;
    if (!item_components(p, mod, n, v))
      return false;
    for (int i = 0; i < 3; i++)
      c[i] = srgb_to_working(v[i], p->scene->settings.assumed_gamma);
    if (mod->token == T_SRGBF || mod->token == T_SRGBFT)
      c[3] = v[3];
    if (mod->token == T_SRGBT)
      c[4] = v[3];
    if (mod->token == T_SRGBFT)
      c[4] = v[4];
    return true;
  }
  case T_RGB:
    if (!item_components(p, mod, 3, v))
      return false;
    memcpy(c, v, 3 * sizeof v[0]);
    return true;
  case T_RGBF:
    if (!item_components(p, mod, 4, v))
      return false;
    memcpy(c, v, 4 * sizeof v[0]);
    return true;
  case T_RGBT:
    if (!item_components(p, mod, 4, v))
      return false;
    memcpy(c, v, 3 * sizeof v[0]);
    c[4] = v[3];
    return true;
  case T_RGBFT:
    if (!item_components(p, mod, 5, v))
      return false;
    memcpy(c, v, 5 * sizeof v[0]);
    return true;
  default:
    break;
  }
  if (mod->value.dim != 1)
    return mismatch(p, &mod->loc, "a float", mod->value.dim);
  int index = mod->token == T_RED     ? 0
              : mod->token == T_GREEN ? 1
              : mod->token == T_BLUE  ? 2
              : mod->token == T_FILTER ? 3 : 4;
  c[index] = mod->value.v[0];
  return true;
}
