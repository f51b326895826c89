#!/bin/sh
# test_interior_fade.sh - an interior's fade_distance below 0
# (lib/trace/shade.c fade_factor, fade_by, shadow_fades and the shading
# loop's test of what a shadow ray brings).  povray 3.7 puts a negative
# fade_distance into the formula 1 / (1 + (d / fade_distance)^power) as
# it is (and exp(-d (1 - fade_colour) / fade_distance) for powers of
# 1000 and above): odd powers leave more than all the light over short
# stretches and less than nothing over long ones, which a shadow ray
# takes from the lit point's ambient; a power that is no integer loses
# the light; shadow rays still fade for powers above 0 only.
# tests/interior_fade.pov, povray 3.7.0.10's pixels (16x12, -A +WT1
# -GA; each case is flat), with what the tree before this test gave
# (188 and 218: unfaded):
#   1 camera, power 1, 0.1 thick: 197 (a = 1.11; before 188)
#   2 camera, power 3, 0.5: 199 (a = 1.14)
#   3 camera, power 0.5: 0 (no real power)
#   4 camera, power -1, 3 thick: 225 (a = 1.5)
#   5 camera, power 1000, 0.5: 234 (e^0.5)
#   6 shadow, power 1, 3 thick: 0 (0.2 + 0.5 (-0.5); before 218)
#   7 shadow, power 3, 3 thick: 118 (0.2 - 0.019)
#   8 shadow, power 0.5: 124 (the ambient 0.2 alone)
#   9 shadow, power 2, 0.5: 203 (0.2 + 0.5 * 0.8, as fade_distance 1)
#  10 case 1 with fade_color <0.5, 0.2, 0>: 192,195,197
#  11 case 7 with that fade_color: 177,145,118
# bench/conform/interior_fade_negative.sh measures 84 cases with povray.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
recorded_1="197,197,197 197,197,197 197,197,197"
recorded_2="199,199,199 199,199,199 199,199,199"
recorded_3="0,0,0 0,0,0 0,0,0"
recorded_4="225,225,225 225,225,225 225,225,225"
recorded_5="234,234,234 234,234,234 234,234,234"
recorded_6="0,0,0 0,0,0 0,0,0"
recorded_7="118,118,118 118,118,118 118,118,118"
recorded_8="124,124,124 124,124,124 124,124,124"
recorded_9="203,203,203 203,203,203 203,203,203"
recorded_10="192,195,197 192,195,197 192,195,197"
recorded_11="177,145,118 177,145,118 177,145,118"
pixel_cases "$srcdir/tests/interior_fade.pov" Case \
  "1 2 3 4 5 6 7 8 9 10 11" "0,0 6,8 11,15"
