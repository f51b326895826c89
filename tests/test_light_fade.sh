#!/bin/sh
# test_light_fade.sh - a light's fade_distance below 0
# (lib/trace/lights.c zr__light_fade).  povray 3.7 puts a negative
# fade_distance into the manual's formula 2 / (1 + (d /
# fade_distance)^fade_power) as it is: an even power fades as the
# positive distance does, an odd one lights more than the light's colour
# nearer than -fade_distance and takes light away beyond it (the sum
# with another light goes down), and a power that is no integer gives no
# real power of the negative ratio: such a light adds nothing.
# tests/light_fade.pov, povray 3.7.0.10's pixels (16x12, -A +WT1 -GA;
# each case is flat), with what the tree before this test gave (it left
# a negative fade_distance unfaded):
#   1 power 1, d 2: 235 (fade 3.33; before 137, fade 1)
#   2 power 1, d 10: 0 (fade -2; before 137)
#   3 the same beside a light of 0.5: 0 (0.5 - 0.5; before 225)
#   4 power 3, d 10, beside it: 175 (0.5 - 0.071; before 225)
#   5 power 0.5, d 2, beside it: 188 (the other light alone; before 225)
#   6 power 2, d 10: 89 (0.4, as fade_distance 5; before 137)
#   7 power 3, d 2: 193 (fade 2.14; before 137)
#   8 power 1001, d 2: 187-188 (fade 2; before 137)
#   9 fade_distance 5, power 1, d 2: 161 (fade 1.43, unchanged)
# bench/conform/light_fade_negative.sh measures these with povray.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
recorded_1="235,235,235 235,235,235 235,235,235"
recorded_2="0,0,0 0,0,0 0,0,0"
recorded_3="0,0,0 0,0,0 0,0,0"
recorded_4="175,175,175 175,175,175 175,175,175"
recorded_5="188,188,188 188,188,188 188,188,188"
recorded_6="89,89,89 89,89,89 89,89,89"
recorded_7="193,193,193 193,193,193 193,193,193"
recorded_8="188,188,188 188,188,188 188,188,188"
recorded_9="161,161,161 161,161,161 161,161,161"
pixel_cases "$srcdir/tests/light_fade.pov" Case "1 2 3 4 5 6 7 8 9" \
  "0,0 6,8 11,15"
