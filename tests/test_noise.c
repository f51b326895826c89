/*
 * test_noise.c - rand() and the noise functions against values recorded
 * from POV-Ray 3.7 by the probe scripts in bench/noise/ (the data files
 * in tests/noise/ are their output; rerunning a script rewrites its file
 * byte for byte).  Every line of a data file is one probe: its inputs and
 * the value POV-Ray printed with str(v, 0, 20).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sdl/sdl.h"
#include "test_util.h"

/* Opens tests/noise/name in the source tree (ZR_SRCDIR, set by make
   check, or the current folder). */
static FILE *open_data(const char *name) {
  const char *dir = getenv("ZR_SRCDIR");
  char path[4096];
  snprintf(path, sizeof path, "%s/tests/noise/%s", dir ? dir : ".", name);
  FILE *f = fopen(path, "r");
  if (!f)
    fail_msg("cannot open %s", path);
  return f;
}

/* Every value of 16 streams, 40 steps each.  The values are k / (2^32 -
   1) printed with 20 decimals, so 1e-15 allows only printing rounding. */
static void test_noise_rand_streams(void **state) {
  (void)state;
  FILE *f = open_data("rand.txt");
  char line[256];
  unsigned long long s = 0;
  double last_seed = NAN;
  int n = 0;
  while (fgets(line, sizeof line, f)) {
    double seed, value;
    int step;
    if (line[0] == '#' || sscanf(line, "%lf %d %lf", &seed, &step,
                                 &value) != 3)
      continue;
    if (step == 0 || seed != last_seed)
      s = zr__sdl_seed_state(seed);
    last_seed = seed;
    assert_near(zr__sdl_rand_step(&s), value, 1e-15);
    n++;
  }
  fclose(f);
  assert_int_equal(n, 640);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_noise_rand_streams),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
