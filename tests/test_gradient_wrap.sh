#!/bin/sh
# test_gradient_wrap.sh - the gradient pattern's wrap (lib/scene/pattern.c
# zr__pattern_wave): povray 3.7 keeps a value above 1's fraction, then
# wraps v frequency + phase as fmod(t, 1.00001), plus 1 while negative,
# so negative coordinates drift by 1e-5 a unit (-7.3 gives 0.70007,
# -1e9 - 0.5 gives 0.4 where an exact wrap gives 0.5) and a frequency
# moves positive ones (frequency 3 at x = 1: 0.99998).  The table below
# is povray 3.7.0.10's output of bench/conform/gradient_wrap_probe.pov
# (x, value, value with frequency 3; povray's colours are floats, so
# each value within 1e-7).  Before: an exact wrap (-1e9 - 0.5 gave 0.5,
# -1.000005 gave 0, x = 1 with frequency 3 gave 0).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
cat >want.txt <<'TABLE'
-0.250000 0.750000000000 0.250000000000
-0.500000 0.500000000000 0.500010013580
-0.999990 0.000010000000 0.000049999999
-1.000005 0.999994993210 0.000005000000
-1.000010 0.000000000000 0.000000000000
-1.500000 0.500010013580 0.500039994717
-2.000030 0.999989986420 0.999970018864
-7.300000 0.700070023537 0.100210003555
-123.456000 0.545229971409 0.635699987411
-100000.300000 0.699989974499 0.099969998002
-1000000000.500000 0.400000065565 0.200010195374
0.250000 0.250000000000 0.750000000000
1.500000 0.500000000000 0.499989986420
123.456000 0.456000000238 0.367989987135
1.000000 1.000000000000 0.999979972839
0.000000 0.000000000000 0.000000000000
TABLE
"$srcdir/bench/conform/gradient_wrap_probe.sh" "$zrcube" >got.txt ||
  { echo "FAIL: the probe did not run"; exit 1; }
[ "$(wc -l <got.txt)" = "$(wc -l <want.txt)" ] ||
  { echo "FAIL: got"; cat got.txt; exit 1; }
paste want.txt got.txt | awk '
  function abs(v) { return v < 0 ? -v : v }
  { if (abs($2 - $5) > 1e-7 || abs($3 - $6) > 1e-7) {
      print "FAIL: x " $1 ": povray " $2 " " $3 ", zrcube " $5 " " $6; bad = 1
    } else print "ok: x " $1 " " $5 " " $6 }
  END { exit bad }'
