#!/bin/sh
# test_shadow_fade.sh - the light a shadow ray brings through clear
# objects whose interiors fade it, and through merges of several parts
# (lib/trace/shade.c shadow_fade, lib/trace/bvh.c visit_leaf).  povray
# 3.7 fades a shadow ray as it fades a camera ray: its path of
# interiors starts with the interiors of the ray that met the lit point,
# and a stretch between two surfaces is faded only where the ray leaves
# an interior the path holds, by that one; and it filters the light at
# every surface of a merge, not the first two; fade_power 0 halves the
# camera's rays (1 / (1 + (d / fade_distance)^0)) and leaves shadow
# rays alone.  tests/shadow_fade.pov,
# povray 3.7.0.10's pixels (16x12, -A +WT1 -GA; each case is flat),
# with what the tree before this test gave:
#   1 stacked merge, own interiors: 188 (1.00 of the light)
#   2 merge of two filter 0.5 blocks apart: 49 (0.0625; before 99)
#   3 the same clear and fading: 105 (0.2841; before 188, unfaded)
#   4 overlapping blocks: 100 (0.2525; before 66)
#   5 a clear block inside a fading one: 152 (0.625; before 113)
#   6 the floor inside a fading block: 89 (0.2)
#   7 as 6 with a fading block inside: 61 (0.0925; before 32)
#   8 a merge whose parts take its interior: 113 (0.3333)
#   9 a block of fade_power 0 (fade_distance 1) seen through: 137 (the
#     camera's ray halved, the shadow ray not faded; before 188)
#  10 the same with fade_power 1: 99 (both halved)
#  11 two blocks stacked in a merge, one with no interior: 188 (1.00;
#     before 113: the part took the other's interior)
#  12 the same seen through: 113 (0.3333; before 67)
# bench/conform/shadow_fade_probe.sh and fade_power_probe.sh measure
# these and more.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
recorded_1="188,188,188 188,188,188 188,188,188"
recorded_2="49,49,49 49,49,49 49,49,49"
recorded_3="105,105,105 105,105,105 105,105,105"
recorded_4="100,100,100 100,100,100 100,100,100"
recorded_5="152,152,152 152,152,152 152,152,152"
recorded_6="89,89,89 89,89,89 89,89,89"
recorded_7="61,61,61 61,61,61 61,61,61"
recorded_8="113,113,113 113,113,113 113,113,113"
recorded_9="137,137,137 137,137,137 137,137,137"
recorded_10="99,99,99 99,99,99 99,99,99"
recorded_11="188,188,188 188,188,188 188,188,188"
recorded_12="113,113,113 113,113,113 113,113,113"
pixel_cases "$srcdir/tests/shadow_fade.pov" Case "1 2 3 4 5 6 7 8 9 10 11 12" \
  "0,0 6,8 11,15"
