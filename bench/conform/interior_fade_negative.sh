#!/bin/sh
# interior_fade_negative.sh [ZRCUBE] - what povray 3.7 does with an
# interior's fade_distance below 0 (tests/interior_fade.pov, Case 0):
# fade_distance -1, powers 1, 2, 3, 0.5, 0, -1 and 1000, thickness 0.1,
# 0.5 and 3, camera rays (View=1) and shadow rays (View=0), without and
# with fade_color: 84 cases.  Prints the linear light at the centre
# (16-bit PNG, File_Gamma 1) from povray and, given ZRCUBE, zrcube's,
# and with ZRCUBE the count that differ.  What povray 3.7.0.10 gave
# (2026-12-03): the formula as it is, e.g. camera power 1: 0.5556 (0.1
# thick), 1.0000 (0.5), 0 (3); shadow power 3, 3 thick: 0.1808 (the
# ambient 0.2 less 0.019); power 0.5: 0 in camera rays, the ambient
# alone in shadow rays; zrcube after lib/trace/shade.c's change: 0 of
# 84 differ (before: 72).
# Usage: bench/conform/interior_fade_negative.sh [build/bin/zrcube]
# (needs povray and /usr/bin/python3 with numpy).
set -eu
scene=$(cd "$(dirname "$0")/../../tests" && pwd)/interior_fade.pov
. "$(cd "$(dirname "$0")" && pwd)/probe_value.sh"
differ=0
for fc in 0 1; do
  for v in 1 0; do
    for pa in 1 2 3 0.5 0 -1 1000; do
      for th in 0.1 0.5 3; do
        set -- FA=-1 PA=$pa TH=$th View=$v FC=$fc
        p=$(centre povray "$@")
        line="$* povray $p"
        if [ -n "$zr" ]; then
          z=$(centre "$zr" "$@")
          line="$line zrcube $z"
          [ "$p" = "$z" ] || differ=$((differ + 1))
        fi
        echo "$line"
      done
    done
  done
done
[ -z "$zr" ] || echo "$differ of 84 differ"
