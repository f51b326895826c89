#!/bin/sh
# test_fade_colour.sh - fade_color of an interior with fade_power 1000 or
# above (lib/trace/shade.c fade_factor): povray 3.7 fades each channel
# as exp(-d (1 - fade_colour) / fade_distance), in view and shadow rays;
# below 1000 fade_colour + (1 - fade_colour) / (1 + (d / fade_distance)
# ^fade_power) as before.  tests/fade_colour.pov: eight clear slabs 0.25
# to 2 thick, fade_distance 2, fade_color <0.35, 0.42, 0.85>; povray
# 3.7's pixels recorded below (16x12, row 6, one pixel in each slab):
#  1 seen through, fade_power 1001; 2 their shadows, 1001;
#  3 seen through, 1000 (exponential too); 4 seen through, 999 (the
#    1 / (1 + ...) figure: only the 2 thick slab shows); 5 shadows, 2.
# The old rule (fade_colour + (1 - fade_colour) exp(-d / fade_distance))
# is 11 levels too bright in the 2 thick slab of cases 1-3.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
recorded_1="246,247,253 237,239,251 229,232,249 221,224,247 213,217,245 206,210,243 198,204,241 191,197,239"
recorded_2="191,197,239 198,204,241 206,210,243 213,217,245 221,224,247 229,232,249 237,239,251 246,247,253"
recorded_3="246,247,253 237,239,251 229,232,249 221,224,247 213,217,245 206,210,243 198,204,241 191,197,239"
recorded_4="255,255,255 255,255,255 255,255,255 255,255,255 255,255,255 255,255,255 255,255,255 214,219,246"
recorded_5="214,219,246 220,224,248 227,230,249 233,236,250 240,242,252 246,247,253 251,251,254 254,254,255"
pixel_cases "$srcdir/tests/fade_colour.pov" Case "1 2 3 4 5" \
  "6,1 6,3 6,5 6,7 6,9 6,11 6,13 6,15"
