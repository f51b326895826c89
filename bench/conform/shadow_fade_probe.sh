#!/bin/sh
# shadow_fade_probe.sh [ZRCUBE] - how povray 3.7 fades light through
# clear objects whose interiors fade it (fade_distance, fade_power), in
# shadow rays (and camera rays, View=1), through unions, merges and
# nested or overlapping boxes (shadow_fade_probe.pov).  Prints for each
# case povray's light on the floor (1 = unshadowed; linear, from a
# 16-bit render with File_Gamma 1) and, given ZRCUBE, zrcube's.  What
# povray 3.7.0.10 printed (FA 0.5, FB 0.25, FC 0.5, power 1):
#   shadow: 1 0.3333  2 1.0000  3 0.5000  4 1.0000  5 1.0000  6 0.2841
#     7 0.3333  8 0.2841  9 1.0000  10 0.3333  12 1.0000  13 1.0000
#     14 0.3906  15 0.2525  16 0.2525  17 0.2404  18 1.0000  19 0.6250
#     20 1.0000  21 1.0000  22 0.3472  23 0.4040  24 0.4142  25 0.2000
#     26 0.0925  27 0.1479
#   view:   1 0.3333  2 1.0000  6 0.2841  10 0.3333  12 1.0000
#     13 1.0000  15 0.2404  19 0.6250  20 1.0000  25 1.0000  26 0.3846
#   filter 0.5, no fading: 1 0.2500  6 0.0625  7 0.2500  8 0.0625
# The rule (lib/trace/shade.c shadow_fade): the path of interiors starts
# with the camera ray's at the lit point (25, 26: 20 is empty because
# its box is no_image); going toward the light, a crossing leaves an
# interior the path holds, else enters it; a stretch is faded only where
# it leaves one, by that interior, over the distance from the surface
# before (15 against 17 gives the direction).  Every surface of a merge
# filters (6 with filter 0.5).  A merge's part without an interior has
# none (12, 13: it does not leave the other part's).  Not matched: 3
# (two faces at the same place: povray sees one of them).
# Usage: bench/conform/shadow_fade_probe.sh [build/bin/zrcube] (needs
# povray and /usr/bin/python3 with numpy).
set -eu
. "$(cd "$(dirname "$0")" && pwd)/probe_value.sh"
for c in 1 2 3 4 5 6 7 8 9 10 12 13 14 15 16 17 18 19 20 21 22 23 24 25 \
         26 27; do
  row "shadow $c" Case=$c FB=0.25 FC=0.5
done
for c in 1 2 6 10 12 13 15 19 20 25 26; do
  row "view $c" Case=$c FB=0.25 FC=0.5 View=1
done
for c in 1 6 7 8; do
  row "filter $c" Case=$c F=0.5 FA=1e9 FB=1e9
done
