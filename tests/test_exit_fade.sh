#!/bin/sh
# test_exit_fade.sh - where a ray leaves a fading interior, only the light
# that comes through the surface (or, beyond the critical angle, the
# totally reflected ray that stands for it) is faded by the stretch the
# ray travelled inside; the surface's own light and its partial
# reflection are not (lib/trace/shade.c shade(), surface.leaving).  The
# tree before this test faded the whole colour of the surface, so a ray
# reflected inside was faded once per stretch and the inner face's own
# light too (tests/exit_fade.pov, fade_power 1001: 9 to 21 levels off in
# every pixel of cases 1-4, 17 in case 5; the corpus' diamond.pov, SSIM
# 0.979 -> 1.000 with it).  Measured with povray 3.7.0.10 on a slab of
# 1 unit, 16-bit linear output: at max_trace_level 4 the background
# reflected inside reaches the camera as 0.5 e^-1 of it, not 0.5 e^-2;
# in a wedge the factor is e^-(stretch after the reflection); the back
# face's emission seen through transmit 0.5 adds 0.25, unfaded.
# povray's pixels (32x24, -A +WT1 -GA), recorded below; with povray
# installed its whole picture is compared too (identical).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
scene=$srcdir/tests/exit_fade.pov
recorded_1="12,16=188,210,228 3,3=188,210,228"
recorded_2="12,16=203,222,240 20,30=203,222,240"
recorded_3="12,2=188,209,228 12,16=187,208,227 12,30=186,207,226"
recorded_4="12,2=236,236,236 12,30=236,236,236"
recorded_5="6,16=224,214,233 8,19=255,255,215 11,17=255,255,214 14,15=224,214,233 12,16=255,255,214"
pixel_w=32 pixel_h=24
pixel_cases "$scene" K "1 2 3 4 5"
