#!/bin/sh
# test_media_povray.sh - zRcube's media against POV-Ray 3.7's, picture to
# picture: tests/media_check.pov (a beam through haze, emission with a
# density, absorption, Henyey-Greenstein and Rayleigh scattering) is
# rendered by povray with its media samples as written (20) and with 80
# (Declare=Samples=80).  The two must agree (SSIM >= 0.99), or POV-Ray's
# own picture is not converged and says nothing; then zRcube's render
# must score SSIM >= 0.95 against the 80-sample one, and no 8x8 block
# may differ by more than 0.04 on average (SSIM forgives twice the haze
# density: 0.97, but its delta is 0.10) (160x120, no
# antialiasing, one thread, 2x2 box filter: tests/imgcmp).
# Skips (77) when povray is not installed.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
ZR_NEEDS_POVRAY=1
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
scene=$srcdir/tests/media_check.pov
inc=/usr/share/povray-3.7/include
timeout 300 povray +I"$scene" +Opov20.png +W160 +H120 -D -A +WT1 -GA \
  +L"$inc" </dev/null >pov20.log 2>&1 &&
timeout 300 povray +I"$scene" +Opov80.png +W160 +H120 -D -A +WT1 -GA \
  +L"$inc" Declare=Samples=80 </dev/null >pov80.log 2>&1 || {
  echo "test_media_povray.sh: povray failed:" >&2
  tail -3 pov20.log pov80.log >&2
  exit 99
}
if ! converged=$("$imgcmp" pov20.png pov80.png --ssim-min 0.99); then
  echo "POV-Ray at 20 and 80 samples: $converged: not converged" >&2
  exit 99
fi
echo "POV-Ray at 20 and 80 samples: $converged"
timeout 300 "$zrcube" +I"$scene" +Ozr.png +W160 +H120 -D +WT1 \
  </dev/null >zr.log 2>&1 || {
  echo "test_media_povray.sh: zrcube failed:" >&2
  tail -3 zr.log >&2
  exit 1
}
if result=$("$imgcmp" zr.png pov80.png --ssim-min 0.95 --delta-max 0.04); then
  echo "zRcube against POV-Ray (80 samples): $result ok"
  echo "1 passed, 0 failed"
  exit 0
fi
echo "zRcube against POV-Ray (80 samples): $result FAIL (need ssim >= 0.95, delta <= 0.04)"
echo "0 passed, 1 failed"
exit 1
