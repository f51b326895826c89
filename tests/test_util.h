/*
 * test_util.h - numeric assertions the cmocka test programs share.
 * Include it after <cmocka.h> (which needs <setjmp.h>, <stdarg.h>,
 * <stddef.h> and <stdint.h> before it).  Each takes its tolerance from
 * the caller, who says why it is what it is.
 */
#ifndef ZR_TESTS_TEST_UTIL_H
#define ZR_TESTS_TEST_UTIL_H

#include <math.h>

#include "core/vec.h"

/* Fails unless |a - b| <= tol (a NaN on either side fails). */
static inline void assert_near(double a, double b, double tol) {
  if (!(fabs(a - b) <= tol))
    fail_msg("%.17g differs from %.17g by more than %g", a, b, tol);
}

/* Fails unless each component of v is within tol of (x, y, z). */
static inline void assert_vec(zr_vec3 v, double x, double y, double z,
                              double tol) {
  if (!(fabs(v.x - x) <= tol && fabs(v.y - y) <= tol &&
        fabs(v.z - z) <= tol))
    fail_msg("<%.17g, %.17g, %.17g> differs from <%.17g, %.17g, %.17g> "
             "by more than %g",
             v.x, v.y, v.z, x, y, z, tol);
}

#endif /* ZR_TESTS_TEST_UTIL_H */
