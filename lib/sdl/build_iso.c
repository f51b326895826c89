/*
 * build_iso.c - the grammar's actions for the isosurface (POV-Ray 3.7
 * reference, "Isosurface"); the tracer's side is
 * lib/trace/obj_isosurface.c.
 *
 * The defaults are the manual's: contained_by box { -1, 1 }, threshold
 * 0, accuracy 0.001, max_gradient 1.1, and only the first crossing of a
 * ray reported (max_trace 1).  The function is compiled by
 * lib/sdl/function.c; one that uses what the evaluator does not have
 * yet (most of functions.inc's internal functions, pattern functions)
 * is refused here, by name, since it could not be traced.
 *
 * evaluate P0, P1, P2 asks POV-Ray to adapt max_gradient while it
 * renders, from the gradients earlier rays met.  zRcube's rays share no
 * state (an image must not depend on the order pixels are traced in),
 * so it traces with the fixed gradient POV-Ray would reach at most,
 * P0 * P1, and says so.
 */
#include "sdl/build_iso.h"

#include <math.h>

#include "pov-parse.h"

zr_object *zr__sdl_isosurface_new(zr_sdl_parser *p, const zr_sdl_loc *loc,
                                  const zr_fn *fn,
                                  const zr_sdl_loc *fn_loc) {
  const char *missing = zr__fn_unsupported(fn);
  if (missing) {
    zr__sdl_error(p, ZR_EUNSUPPORTED, fn_loc,
                  "the isosurface's function uses %s, which is not "
                  "supported yet", missing);
    return NULL;
  }
  if (zr__fn_params(fn) > 3) {
    zr__sdl_error(p, ZR_ESCENE, fn_loc,
                  "an isosurface's function takes x, y and z, not %d "
                  "parameters", zr__fn_params(fn));
    return NULL;
  }
  zr_object *o = zr__sdl_object_new(p, ZR_OBJ_ISOSURFACE, loc);
  if (!o)
    return NULL;
  o->u.isosurface.fn = fn;
  o->u.isosurface.lo = zr_v3(-1, -1, -1);
  o->u.isosurface.hi = zr_v3(1, 1, 1);
  o->u.isosurface.threshold = 0.0;
  o->u.isosurface.accuracy = 0.001;
  o->u.isosurface.max_gradient = 1.1;
  o->u.isosurface.max_trace = 1;
  return o;
}

/* contained_by { sphere | box }, for the isosurface and the
   parametric. */
static bool container(zr_sdl_parser *p, const zr_object *c,
                      const zr_sdl_loc *loc, bool *sphere, zr_vec3 *lo,
                      zr_vec3 *hi, zr_vec3 *centre, double *radius) {
  if ((c->kind != ZR_OBJ_SPHERE && c->kind != ZR_OBJ_BOX) || c->transform ||
      c->inverse || c->clip) {
    zr__sdl_error(p, ZR_ESCENE, loc,
                  "contained_by takes a plain sphere or box");
    return false;
  }
  if (c->kind == ZR_OBJ_SPHERE) {
    if (!(c->u.sphere.radius > 0.0)) {
      zr__sdl_error(p, ZR_ESCENE, loc,
                    "the container's radius must be positive");
      return false;
    }
    *sphere = true;
    *centre = c->u.sphere.centre;
    *radius = c->u.sphere.radius;
    return true;
  }
  *sphere = false;
  *lo = zr_v3_min(c->u.box.corner1, c->u.box.corner2);
  *hi = zr_v3_max(c->u.box.corner1, c->u.box.corner2);
  return true;
}

bool zr__sdl_isosurface_container(zr_sdl_parser *p, zr_object *o,
                                  const zr_object *c,
                                  const zr_sdl_loc *loc) {
  return container(p, c, loc, &o->u.isosurface.sphere, &o->u.isosurface.lo,
                   &o->u.isosurface.hi, &o->u.isosurface.centre,
                   &o->u.isosurface.radius);
}

/* evaluate P0, P1, P2 (see the top of the file). */
static bool evaluate(zr_sdl_parser *p, zr_object *o, const zr_sdl_expr *e,
                     const zr_sdl_loc *at) {
  double v[3];
  for (int i = 0; i < 3; i++)
    if (!zr__sdl_want_float(p, &e[i], &at[i], &v[i]))
      return false;
  double g = v[0] * fmax(v[1], 1.0);
  if (!(g > 0.0) || !(v[2] > 0.0)) {
    zr__sdl_error(p, ZR_ESCENE, &at[0],
                  "evaluate's values must be positive");
    return false;
  }
  zr__sdl_warning(p, &at[0],
                  "evaluate: zRcube keeps no state between rays and "
                  "traces with max_gradient %g (P0 * P1)", g);
  o->u.isosurface.max_gradient = g;
  return true;
}

bool zr__sdl_isosurface_item(zr_sdl_parser *p, zr_object *o, int token,
                             const zr_sdl_expr *e, const zr_sdl_loc *at) {
  if (token == T_ALL_INTERSECTIONS) {
    o->u.isosurface.max_trace = 0;
    return true;
  }
  if (token == T_EVALUATE)
    return evaluate(p, o, e, at);
  double v;
  if (!zr__sdl_want_float(p, e, at, &v))
    return false;
  switch (token) {
  case T_THRESHOLD:
    o->u.isosurface.threshold = v;
    return true;
  case T_ACCURACY:
    if (!(v > 0.0)) {
      zr__sdl_error(p, ZR_ESCENE, at, "accuracy must be positive");
      return false;
    }
    o->u.isosurface.accuracy = v;
    return true;
  case T_MAX_GRADIENT:
    if (!(v > 0.0)) {
      zr__sdl_error(p, ZR_ESCENE, at, "max_gradient must be positive");
      return false;
    }
    o->u.isosurface.max_gradient = v;
    return true;
  default: /* T_MAX_TRACE */
    if (!(v >= 1.0) || v > 1e9) {
      zr__sdl_error(p, ZR_ESCENE, at, "max_trace must be at least 1");
      return false;
    }
    o->u.isosurface.max_trace = (int)v;
    return true;
  }
}

/* ---- ovus ---- */

/*
 * The lemon between the spheres ("Ovus"): the manual only says it is
 * "automatically computed so as to provide the needed continuity".
 * POV-Ray 3.7's, measured with trace() on ovus objects of several
 * radius ratios, is the circle of radius R = 2 max(a, b) tangent inside
 * to both spheres' circles, the bottom's (radius a about the origin) and
 * the top's (radius b about (0, a)): its centre (-c, h) is R - a from
 * the first and R - b from the second (bench/provenance/probe.py
 * ovus_lemon: of R = 1.5 ... 3 max(a, b), only 2 fits povray's traces,
 * to 5e-6).  When b >= 2 a the top sphere
 * holds the bottom one and the ovus is the top sphere, as the manual
 * says.
 */
zr_object *zr__sdl_ovus(zr_sdl_parser *p, const zr_sdl_loc *loc,
                        const zr_sdl_expr *bottom,
                        const zr_sdl_loc *bottom_loc,
                        const zr_sdl_expr *top, const zr_sdl_loc *top_loc) {
  double a, b;
  if (!zr__sdl_want_float(p, bottom, bottom_loc, &a) ||
      !zr__sdl_want_float(p, top, top_loc, &b))
    return NULL;
  if (!(a > 0.0) || !(b > 0.0)) {
    zr__sdl_error(p, ZR_ESCENE, !(a > 0.0) ? bottom_loc : top_loc,
                  "an ovus's radii must be positive");
    return NULL;
  }
  zr_object *o = zr__sdl_object_new(p, ZR_OBJ_OVUS, loc);
  if (!o)
    return NULL;
  o->u.ovus.bottom = a;
  o->u.ovus.top = b;
  if (b >= 2.0 * a) {
    /* lemon_r 0: the top sphere alone; POV-Ray warns likewise. */
    zr__sdl_warning(p, top_loc, "the ovus's top radius is at least twice "
                    "its bottom radius: it is a sphere");
    return o;
  }
  double r = 2.0 * fmax(a, b);
  double h = ((r - a) * (r - a) - (r - b) * (r - b) + a * a) / (2.0 * a);
  o->u.ovus.lemon_r = r;
  o->u.ovus.lemon_h = h;
  o->u.ovus.lemon_c = sqrt(fmax(0.0, (r - a) * (r - a) - h * h));
  /* The tangent points: on the line from the lemon's centre through
     each sphere's centre, R from the former. */
  o->u.ovus.y0 = -h * a / (r - a);
  o->u.ovus.y1 = h + r * (a - h) / (r - b);
  return o;
}

/* ---- parametric ---- */

/*
 * The defaults: contained_by box { -1, 1 } and accuracy 0.001, as the
 * manual gives them.  It gives no max_gradient default; zRcube takes 1
 * (scenes should give their own, as the manual's example does).  The
 * functions take u and v (function.c's synonyms of x and y); a function
 * of more is refused.
 */
zr_object *zr__sdl_parametric_new(zr_sdl_parser *p, const zr_sdl_loc *loc,
                                  const zr_fn *const fn[3],
                                  const zr_sdl_loc fn_loc[3],
                                  const zr_sdl_expr uv[2],
                                  const zr_sdl_loc uv_loc[2]) {
  for (int k = 0; k < 3; k++) {
    const char *missing = zr__fn_unsupported(fn[k]);
    if (missing) {
      zr__sdl_error(p, ZR_EUNSUPPORTED, &fn_loc[k],
                    "the parametric's function uses %s, which is not "
                    "supported yet", missing);
      return NULL;
    }
    if (zr__fn_params(fn[k]) > 3) {
      zr__sdl_error(p, ZR_ESCENE, &fn_loc[k],
                    "a parametric's function takes u and v, not %d "
                    "parameters", zr__fn_params(fn[k]));
      return NULL;
    }
  }
  zr_vec3 a, b;
  if (!zr__sdl_want_vector(p, &uv[0], &uv_loc[0], &a) ||
      !zr__sdl_want_vector(p, &uv[1], &uv_loc[1], &b))
    return NULL;
  if (!(a.x <= b.x) || !(a.y <= b.y)) {
    zr__sdl_error(p, ZR_ESCENE, &uv_loc[1],
                  "the parametric's <u2, v2> must exceed <u1, v1>");
    return NULL;
  }
  /* POV-Ray 3.7 takes an empty range without a word and draws nothing
     (measured: <0,0>, <2*pi,0>); so does the tracer here, with a
     warning. */
  if (a.x == b.x || a.y == b.y)
    zr__sdl_warning(p, &uv_loc[1], "the parametric's u or v range is "
                    "empty: it has no points and is not drawn");
  zr_object *o = zr__sdl_object_new(p, ZR_OBJ_PARAMETRIC, loc);
  if (!o)
    return NULL;
  for (int k = 0; k < 3; k++)
    o->u.parametric.fn[k] = fn[k];
  o->u.parametric.u0 = a.x;
  o->u.parametric.v0 = a.y;
  o->u.parametric.u1 = b.x;
  o->u.parametric.v1 = b.y;
  o->u.parametric.lo = zr_v3(-1, -1, -1);
  o->u.parametric.hi = zr_v3(1, 1, 1);
  o->u.parametric.accuracy = 0.001;
  o->u.parametric.max_gradient = 1.0;
  return o;
}

/*
 * POV-Ray 3.7 draws a parametric whose max_gradient (default 1) is far
 * below its real partial derivatives whole: the corpus' GSprites_Terrain_
 * demo.pov's water, a sheet <64 u - 32, 0.25 (sin 8 pi u + sin 8 pi v),
 * 64 v - 32> with no max_gradient, is there in povray's picture (with
 * max_gradient 0.1 too, bar 2% of its pixels; tests/test_parametric_
 * gradient.sh).  zRcube's search (lib/trace/obj_parametric.c) trusts G
 * to bound its boxes, and with G 64 times too small found only the
 * crossings Newton's method happened to reach from neighbouring boxes:
 * the sheet was gone, or holed where a second search starts near the
 * first crossing.  So the functions' difference quotients over a grid of
 * PARAM_GRID x PARAM_GRID cells of the (u, v) rectangle are measured
 * here; each is a partial derivative somewhere in its cell (mean value
 * theorem), so their largest is a lower bound of the true maximum, and
 * when it exceeds G the search uses it times PARAM_SLACK instead, with a
 * warning.  A sine sampled n times a period reaches sin(pi/n)/(pi/n) of
 * its largest slope: 0.90 at n = 4, and 1.25 covers that with room.  A
 * G that is large enough is kept as given: such scenes trace as before.
 */
enum { PARAM_GRID = 64 };
#define PARAM_SLACK 1.25

static void parametric_point(const zr_object *o, double u, double v,
                             double out[3]) {
  double args[3] = {u, v, 0.0};
  for (int k = 0; k < 3; k++)
    out[k] = zr__fn_eval(o->u.parametric.fn[k], args);
}

bool zr__sdl_parametric_done(zr_sdl_parser *p, zr_object *o,
                             const zr_sdl_loc *loc) {
  double u0 = o->u.parametric.u0, u1 = o->u.parametric.u1;
  double v0 = o->u.parametric.v0, v1 = o->u.parametric.v1;
  if (!(u0 < u1) || !(v0 < v1))
    return true; /* an empty range: nothing is drawn */
  double du = (u1 - u0) / PARAM_GRID, dv = (v1 - v0) / PARAM_GRID;
  double row[PARAM_GRID + 1][3], found = 0.0;
  for (int j = 0; j <= PARAM_GRID; j++) {
    double v = j < PARAM_GRID ? v0 + j * dv : v1;
    double prev[3];
    for (int i = 0; i <= PARAM_GRID; i++) {
      double u = i < PARAM_GRID ? u0 + i * du : u1, q[3];
      parametric_point(o, u, v, q);
      for (int k = 0; k < 3; k++) {
        double a = i > 0 ? fabs(q[k] - prev[k]) / du : 0.0;
        double b = j > 0 ? fabs(q[k] - row[i][k]) / dv : 0.0;
        /* A pole or a gap in the functions (NaN, inf) says nothing
           about the slope elsewhere. */
        if (isfinite(a) && a > found)
          found = a;
        if (isfinite(b) && b > found)
          found = b;
        prev[k] = q[k];
        row[i][k] = q[k];
      }
    }
  }
  double g = o->u.parametric.max_gradient;
  if (found > g) {
    o->u.parametric.max_gradient = found * PARAM_SLACK;
    zr__sdl_warning(p, loc, "the parametric's partial derivatives reach "
                    "%g, above its max_gradient %g: traced with "
                    "max_gradient %g", found, g,
                    o->u.parametric.max_gradient);
  }
  return true;
}

bool zr__sdl_parametric_container(zr_sdl_parser *p, zr_object *o,
                                  const zr_object *c,
                                  const zr_sdl_loc *loc) {
  return container(p, c, loc, &o->u.parametric.sphere, &o->u.parametric.lo,
                   &o->u.parametric.hi, &o->u.parametric.centre,
                   &o->u.parametric.radius);
}

bool zr__sdl_parametric_item(zr_sdl_parser *p, zr_object *o, int token,
                             const zr_sdl_expr *e, const zr_sdl_loc *at) {
  double v;
  if (!zr__sdl_want_float(p, e, at, &v))
    return false;
  switch (token) {
  case T_ACCURACY:
    if (!(v > 0.0)) {
      zr__sdl_error(p, ZR_ESCENE, at, "accuracy must be positive");
      return false;
    }
    o->u.parametric.accuracy = v;
    return true;
  case T_MAX_GRADIENT:
    if (!(v > 0.0)) {
      zr__sdl_error(p, ZR_ESCENE, at, "max_gradient must be positive");
      return false;
    }
    o->u.parametric.max_gradient = v;
    return true;
  default: /* T_PRECOMPUTE: the depth, at most 20 ("Parametric") */
    if (!(v >= 0.0 && v <= 20.0)) {
      zr__sdl_error(p, ZR_ESCENE, at, "precompute's depth must be 0 to 20");
      return false;
    }
    return true;
  }
}
