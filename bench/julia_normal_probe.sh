#!/bin/sh
# julia_normal_probe.sh - black-box measurements (session 20) of the
# normal and hit that POV-Ray 3.7 gives a julia_fractal whose function
# has no distance estimate (hypercomplex exp, sin, ...), against
# zrcube's, with the SDL function trace().  Findings (povray 3.7.0.10):
#   - hypercomplex sqr and cube: POV-Ray's normals are zrcube's (the
#     gradient of |h_N|^2) to 1e-6;
#   - exp, p = 0, max_iteration 2, whose surface is the plane x = ln 4:
#     POV-Ray's normal is (a, b, b), equal y and z parts, a function of
#     y alone (not of z nor of the ray's direction), b / a = -0.707 y
#     near y = 0, largest (0.100) at |y| = 0.2, then falling about
#     e^-14 per unit; zrcube's is the gradient of |h_2|^2 (z-dependent);
#   - sin, p = <0.4,2,0.5,0.2>, max_iteration 3 (corpus epicsuper.pov):
#     the normals differ everywhere (POV-Ray's point away from the ray
#     along x), which gives POV-Ray's picture its bands;
#   - hits: POV-Ray marches from the bounding sphere's entry (or the
#     ray's origin inside it) by 1 / precision and reports the first
#     inside step, unrefined (precision 20: x = -2.0175884 where the
#     boundary is at -2.0528); some rays also stop on the sphere itself
#     (exp max_iteration 1 and 2);
#   - inside() disagrees with the escape rule (|h_i| <= 4 for
#     i < max_iteration) at 66 of 400 random points (sin, max_iteration
#     2), both ways, while trace() at precision 1000 agrees with it.
# No formula fitted these normals (tried: gradients of |h_k|^2 for
# k = 1..4, the chain rule with f' replaced by 2h, h or f(h), in
# quaternion or bicomplex products, h_N times the conjugate of the
# derivative); nothing of this changed zrcube.
#
# Usage: bench/julia_normal_probe.sh [ZRCUBE]   (default build/bin/zrcube)
set -u
here=$(cd "$(dirname "$0")" && pwd)
zr=${1:-$here/../build/bin/zrcube}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/zr_julia_normal.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
probe() {
  cat > "$tmp/pr.pov" <<EOP
#version 3.7;
#declare J = julia_fractal { $1 }
#declare N = <0, 0, 0>;
#fopen Out "out.txt" write
#declare I = 0;
#while (I < 6)
  #declare From = <-5, -0.9 + I * 0.33, 0.3 + 0.1 * I>;
  #local P = trace(J, From, x, N);
  #write(Out, "P ", vstr(3, P, ",", 0, 6), " N ", vstr(3, N, ",", 0, 6), "\n")
  #declare I = I + 1;
#end
#fclose Out
camera { location -z look_at 0 }
EOP
  echo "== $1"
  echo "   povray                                   | zrcube"
  ( cd "$tmp" && timeout 60 povray +Ipr.pov -D +W1 +H1 -F >/dev/null 2>&1 &&
    mv out.txt pov.txt &&
    timeout 60 "$zr" +Ipr.pov --parse-only -q >/dev/null 2>&1 &&
    paste -d'|' pov.txt out.txt ) || echo "failed"
}
probe "<0.4,2,0.5,0.2> hypercomplex sqr max_iteration 3 precision 1000"
probe "<0,0,0,0> hypercomplex exp max_iteration 2 precision 1000"
probe "<0.4,2,0.5,0.2> hypercomplex sin max_iteration 3 precision 1000"
probe "<0.4,2,0.5,0.2> hypercomplex sin max_iteration 3 precision 20"
