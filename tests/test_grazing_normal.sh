#!/bin/sh
# test_grazing_normal.sh - a reflection whose tilted normal (normal { })
# mirrors a grazing ray into the surface is turned back out of it
# (lib/trace/shade.c), so a bumpy chrome plane shows the sky where
# povray 3.7 does (tests/grazing_normal.pov).  Before, such rays met the
# plane from below and came back black: SSIM 0.73 against povray's
# picture, worst 8x8 block 0.21 off; now 0.998 and 0.009.  Needs povray
# (skipped without it).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
ZR_NEEDS_POVRAY=1
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
cp "$srcdir/tests/grazing_normal.pov" . || exit 99
timeout 120 povray +Igrazing_normal.pov +Opov.png +W160 +H120 -D -A +WT1 \
  -GA </dev/null >pov.log 2>&1 || { tail -3 pov.log >&2; exit 99; }
timeout 120 "$zrcube" +Igrazing_normal.pov +Ozr.png +W160 +H120 -D +WT1 \
  >zr.log 2>&1 || { cat zr.log >&2; exit 1; }
if out=$("$imgcmp" zr.png pov.png --ssim-min 0.97 --delta-max 0.05); then
  echo "ok: against povray's picture: $out"
else
  echo "FAIL: against povray's picture: $out"
  exit 1
fi
