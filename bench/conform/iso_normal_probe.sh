#!/bin/sh
# iso_normal_probe.sh - how povray 3.7 takes an isosurface's normal.
# trace() onto y + C x^2 + 2 C z^2 (C = 1000) from above at x = z = 0,
# and onto y + C y^2 + x, for accuracy 0.01, 0.001 and 0.0001, and print
# the hit and the normal.  Central differences would give a normal of
# <0, 1, 0> on the first; povray's is <C h, 1, 2 C h> normalised with h
# the accuracy, (0.408248, 0.408248, 0.816497) at 0.001: forward
# differences of step accuracy (the second: <1, 1 + C (2 y + h), 0>).
# lib/trace/obj_isosurface.c follows; tests/test_isosurface.c checks the
# first case against the numbers printed here (2026-12-02).
set -eu
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/n.pov" <<'POV'
#version 3.7;
#declare C = 1000;
#declare N = <0, 0, 0>;
#declare Iso = isosurface { function { y + C*x*x + 2*C*z*z } threshold 0
  max_gradient 100000 contained_by { box { -1, 1 } } accuracy ACC }
#declare P = trace(Iso, <0, 0.5, 0>, -y, N);
#debug concat("quadratic accuracy ", str(ACC, 0, 4), " normal ",
  vstr(3, N, ",", 0, 9), "\n")
#declare Iso2 = isosurface { function { y + C*y*y + x } threshold 0
  max_gradient 100000 contained_by { box { -1, 1 } } accuracy ACC }
#declare P = trace(Iso2, <0, 0.5, 0>, -y, N);
#debug concat("y + C y^2 + x accuracy ", str(ACC, 0, 4), " hit y ",
  str(P.y, 0, 9), " normal ", vstr(3, N, ",", 0, 6), "\n")
POV
for acc in 0.01 0.001 0.0001; do
  povray +I"$tmp/n.pov" -D +W1 +H1 Declare=ACC=$acc 2>&1 |
    grep -E '^(quadratic|y \+)'
done
