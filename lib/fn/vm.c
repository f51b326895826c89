/*
 * vm.c - the machine that runs compiled user functions.
 *
 * A body is compiled once, when it is declared (lib/sdl/function.c),
 * into bytecode for a small stack machine over doubles
 * (lib/fn/code.h), and evaluated many times: by patterns and
 * isosurfaces per sample, by the parser for `#declare V = F(3);`.
 * Each function records how many doubles an evaluation needs, callees
 * included; the machine takes them from one array on its own C stack,
 * so evaluating never allocates and threads share nothing.  Chains of
 * calls are limited to ZR_FN_MAX_DEPTH by the compiler, as POV-Ray
 * documents, so runaway input cannot blow the C stack.
 *
 * The machine dispatches by direct threading where the compiler allows
 * it.  It calls nothing above lib/core: pigments and splines are
 * reached through the callbacks the compiler stored (zr_fn_extern),
 * the internal functions are lib/fn/internal.c.
 */
#include "config.h"

#include <math.h>
#include <string.h>

#include "fn/code.h"

static double truth(bool b) { return b ? 1.0 : 0.0; }

/* POV-Ray's select(): the sign of a picks the value (Float Functions). */
static double select3(double a, double b, double c) { return a < 0 ? b : c; }
static double select4(double a, double b, double c, double d) {
  return a < 0 ? b : a == 0 ? c : d;
}

/*
 * Runs f with its parameters at base[0 .. n_params); its counters follow
 * and its operand stack is above them.  A call runs the callee with its
 * arguments, already on the stack, as the callee's parameters: no copy,
 * and f->need says the array is big enough.
 */
/*
 * Dispatch.  With GCC and Clang each instruction jumps straight to the
 * code of the next ("labels as values", a GNU C extension both share):
 * no loop, no range check, and one indirect jump per instruction that
 * the processor predicts from its own history.  Other compilers get the
 * plain switch (as does -DZR_FN_SWITCH, to test it).  NEXT() and JUMP()
 * end a case.
 */
#if defined(__GNUC__) && !defined(ZR_FN_SWITCH)
#define VM_THREADED 1
#define CASE(o) L_##o:
#define NEXT() goto *dispatch[(++i)->op]
#define JUMP(k) i = code + (k); goto *dispatch[i->op]
#else
#define CASE(o) case o:
#define NEXT() i++; break
#define JUMP(k) i = code + (k); break
#endif

static double run(const zr_fn *f, double *base) {
  double *sp = base + f->n_slots;
  const insn *code = f->code, *i = code;
  /* No bound on i: the program ends with OP_RETURN (the compiler adds
     it). */
#ifdef VM_THREADED
#define AS_LABEL(o) [o] = &&L_##o,
  static const void *const dispatch[] = {OPS(AS_LABEL)};
#undef AS_LABEL
  goto *dispatch[i->op];
#else
  for (;;) {
    switch ((op)i->op) {
#endif
    CASE(OP_CONST) *sp++ = f->consts[i->arg]; NEXT();
    CASE(OP_LOAD) *sp++ = base[i->arg]; NEXT();
    CASE(OP_STORE) base[i->arg] = *--sp; NEXT();
    CASE(OP_INC) base[i->arg] += 1; NEXT();
    CASE(OP_JGT)
      if (base[i->arg] > base[i->arg + 1]) {
        JUMP(i->n);
      }
      NEXT();
    CASE(OP_JUMP) JUMP(i->n);
    CASE(OP_ADD) sp--; sp[-1] += sp[0]; NEXT();
    CASE(OP_SUB) sp--; sp[-1] -= sp[0]; NEXT();
    CASE(OP_MUL) sp--; sp[-1] *= sp[0]; NEXT();
    CASE(OP_DIV) sp--; sp[-1] /= sp[0]; NEXT();
    CASE(OP_ADD_S) sp[-1] += base[i->arg]; NEXT();
    CASE(OP_SUB_S) sp[-1] -= base[i->arg]; NEXT();
    CASE(OP_MUL_S) sp[-1] *= base[i->arg]; NEXT();
    CASE(OP_DIV_S) sp[-1] /= base[i->arg]; NEXT();
    CASE(OP_ADD_K) sp[-1] += f->consts[i->arg]; NEXT();
    CASE(OP_SUB_K) sp[-1] -= f->consts[i->arg]; NEXT();
    CASE(OP_MUL_K) sp[-1] *= f->consts[i->arg]; NEXT();
    CASE(OP_DIV_K) sp[-1] /= f->consts[i->arg]; NEXT();
    CASE(OP_LT) sp--; sp[-1] = truth(sp[-1] < sp[0]); NEXT();
    CASE(OP_LE) sp--; sp[-1] = truth(sp[-1] <= sp[0]); NEXT();
    CASE(OP_EQ) sp--; sp[-1] = truth(sp[-1] == sp[0]); NEXT();
    CASE(OP_NE) sp--; sp[-1] = truth(sp[-1] != sp[0]); NEXT();
    CASE(OP_GE) sp--; sp[-1] = truth(sp[-1] >= sp[0]); NEXT();
    CASE(OP_GT) sp--; sp[-1] = truth(sp[-1] > sp[0]); NEXT();
    /* povray 3.7 treats any non-zero value, however small, as true in
       functions (1e-11 & 1 is 1), unlike #if's 1e-10 tolerance. */
    CASE(OP_AND) sp--; sp[-1] = truth(sp[-1] != 0 && sp[0] != 0); NEXT();
    CASE(OP_OR) sp--; sp[-1] = truth(sp[-1] != 0 || sp[0] != 0); NEXT();
    CASE(OP_NEG) sp[-1] = -sp[-1]; NEXT();
    CASE(OP_NOT) sp[-1] = truth(sp[-1] == 0); NEXT();
    CASE(OP_SIN) sp[-1] = sin(sp[-1]); NEXT();
    CASE(OP_COS) sp[-1] = cos(sp[-1]); NEXT();
    CASE(OP_TAN) sp[-1] = tan(sp[-1]); NEXT();
    CASE(OP_ASIN) sp[-1] = asin(sp[-1]); NEXT();
    CASE(OP_ACOS) sp[-1] = acos(sp[-1]); NEXT();
    CASE(OP_ATAN) sp[-1] = atan(sp[-1]); NEXT();
    CASE(OP_SINH) sp[-1] = sinh(sp[-1]); NEXT();
    CASE(OP_COSH) sp[-1] = cosh(sp[-1]); NEXT();
    CASE(OP_TANH) sp[-1] = tanh(sp[-1]); NEXT();
    CASE(OP_ASINH) sp[-1] = asinh(sp[-1]); NEXT();
    CASE(OP_ACOSH) sp[-1] = acosh(sp[-1]); NEXT();
    CASE(OP_ATANH) sp[-1] = atanh(sp[-1]); NEXT();
    CASE(OP_EXP) sp[-1] = exp(sp[-1]); NEXT();
    CASE(OP_LN) sp[-1] = log(sp[-1]); NEXT();
    CASE(OP_LOG) sp[-1] = log10(sp[-1]); NEXT();
    CASE(OP_SQRT) sp[-1] = sqrt(sp[-1]); NEXT();
    CASE(OP_ABS) sp[-1] = fabs(sp[-1]); NEXT();
    CASE(OP_FLOOR) sp[-1] = floor(sp[-1]); NEXT();
    CASE(OP_CEIL) sp[-1] = ceil(sp[-1]); NEXT();
    CASE(OP_INT) sp[-1] = trunc(sp[-1]); NEXT();
    CASE(OP_DEGREES) sp[-1] *= 180.0 / M_PI; NEXT();
    CASE(OP_RADIANS) sp[-1] *= M_PI / 180.0; NEXT();
    CASE(OP_ATAN2) sp--; sp[-1] = atan2(sp[-1], sp[0]); NEXT();
    CASE(OP_POW) sp--; sp[-1] = pow(sp[-1], sp[0]); NEXT();
    CASE(OP_MOD) sp--; sp[-1] = fmod(sp[-1], sp[0]); NEXT();
    CASE(OP_MIN) sp--; sp[-1] = sp[0] < sp[-1] ? sp[0] : sp[-1]; NEXT();
    CASE(OP_MAX) sp--; sp[-1] = sp[0] > sp[-1] ? sp[0] : sp[-1]; NEXT();
    CASE(OP_SELECT3)
      sp -= 2;
      sp[-1] = select3(sp[-1], sp[0], sp[1]);
      NEXT();
    CASE(OP_SELECT4)
      sp -= 3;
      sp[-1] = select4(sp[-1], sp[0], sp[1], sp[2]);
      NEXT();
    CASE(OP_CALL)
      sp -= i->n;
      *sp = run(f->callees[i->arg], sp);
      sp++;
      NEXT();
    CASE(OP_INTERNAL)
      sp -= i->n;
      *sp = zr__fn_internal_eval(i->arg, sp);
      sp++;
      NEXT();
    CASE(OP_TEXTURE) {
      const zr_fn_extern *e = &f->externs[i->arg];
      sp -= 3;
      *sp = e->eval(e->what, i->n, sp);
      sp++;
      NEXT();
    }
    CASE(OP_SPLINE) {
      /* Component n of the spline externs[arg] at the top value. */
      const zr_fn_extern *e = &f->externs[i->arg];
      sp[-1] = e->eval(e->what, i->n, sp - 1);
      NEXT();
    }
    CASE(OP_XFORM) {
      /* Component n of the top three values as a point moved by
         transforms[arg]. */
      zr_vec3 q = zr__xform_point(f->transforms[i->arg]->m,
                                  zr_v3(sp[-3], sp[-2], sp[-1]));
      sp -= 2;
      sp[-1] = i->n == 0 ? q.x : i->n == 1 ? q.y : q.z;
      NEXT();
    }
    CASE(OP_RETURN) return sp[-1];
#ifndef VM_THREADED
    default: return NAN; /* never: every opcode has its case */
    }
  }
#endif
}

double zr__fn_run(const zr_fn *f, double *base) { return run(f, base); }

double zr__fn_eval(const zr_fn *fn, const double *args) {
  double mem[ZR_FN_MAX_STACK];
  memcpy(mem, args, (size_t)fn->n_params * sizeof *args);
  return run(fn, mem);
}

int zr__fn_params(const zr_fn *fn) { return fn->n_params; }

const char *zr__fn_unsupported(const zr_fn *fn) { return fn->unsupported; }
