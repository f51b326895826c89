#!/bin/sh
# mesh_parse.sh - the parse of big meshes by two zRcube builds and by
# Tachyon, interleaved (issue 13: "mesh, mesh2, triangle-heavy ... scenes
# parse within 1.5x of Tachyon's .dat reader for the same data").
#
#   bench/mesh_parse.sh OLD_BUILD NEW_BUILD [ROUNDS]
#
# bench/peers_gen.py writes the terrain (130,050 flat triangles: POV
# `triangle`s, Tachyon `TRI`s) and, with --smooth, the same grid as
# smooth triangles with the surface's normals (`smooth_triangle`s,
# Tachyon `STRI`s).  Each round runs, for each scene, OLD and NEW (their
# real bin/.libs/zrcube --parse-only +WT1: read, lex, parse and the
# mesh's hierarchy; CPU seconds of the whole process from perf stat's
# task-clock) and `tachyon -numthreads 1 -res 64 64` (its "Scene Parsing
# Time" + "Preprocessing Time", wall), under `chrt -r 20` when run as
# root.  Prints the best and median of each with the load.  Timings are
# printed, never asserted.
set -eu
[ $# -ge 2 ] || { echo "usage: bench/mesh_parse.sh OLD NEW [ROUNDS]" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
old=$(cd "$1" && pwd)
new=$(cd "$2" && pwd)
rounds=${3:-9}
rt=""
[ "$(id -u)" = 0 ] && command -v chrt >/dev/null 2>&1 && rt="chrt -r 20"
command -v perf >/dev/null 2>&1 || { echo "mesh_parse.sh: needs perf" >&2; exit 2; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
/usr/bin/python3 "$here/peers_gen.py" "$dir" >/dev/null
/usr/bin/python3 "$here/peers_gen.py" --smooth "$dir" >/dev/null
echo "load at start: $(cat /proc/loadavg)"
for i in $(seq "$rounds"); do
  for scene in terrain sterrain; do
    for b in "$old" "$new"; do
      LD_LIBRARY_PATH=$b/lib/.libs perf stat -x, -e task-clock \
        -o "$dir/stat" $rt "$b/bin/.libs/zrcube" --parse-only +WT1 \
        "$dir/$scene.pov" >/dev/null 2>&1
      echo "$scene $b $(awk -F, '/task-clock/ { printf "%.4f", $1 / 1000 }' "$dir/stat")"
    done
    t=$($rt tachyon -numthreads 1 -res 64 64 "$dir/$scene.dat" \
        -o "$dir/t.tga" 2>&1 |
        awk '/Scene Parsing Time/{a=$4} /Preprocessing Time/{b=$3}
             END {printf "%.4f", a + b}')
    echo "$scene tachyon $t"
  done
done >"$dir/runs.txt"
echo "load at end: $(cat /proc/loadavg)"
echo "CPU seconds (zRcube) and parse + preprocessing seconds (Tachyon), $rounds rounds"
for scene in terrain sterrain; do
  for who in "$old" "$new" tachyon; do
    awk -v s="$scene" -v w="$who" '$1 == s && $2 == w { print $3 }' \
      "$dir/runs.txt" | sort -g |
      awk -v s="$scene" -v w="$who" '{ v[NR] = $1 }
        END { printf "%-9s %-40s best %.4f median %.4f\n", s, w, v[1],
              v[int((NR + 1) / 2)] }'
  done
done
