#!/bin/sh
# parse_vs_tachyon.sh - the sphere-heavy parse of two zRcube builds and
# Tachyon's, interleaved (issue 13: "sphere-heavy scenes parse within
# 1.5x of Tachyon's .dat reader for the same data").
#
#   bench/parse_vs_tachyon.sh OLD_BUILD NEW_BUILD [ROUNDS]
#
# bench/peers_gen.py writes the sphereflake (7,381 spheres) in both
# formats into a temporary folder.  Each round runs OLD, NEW (their real
# bin/.libs/zrcube, `+V -A +WT1 +W512 +H512`) and `tachyon -numthreads 1
# -res 512 512` once each, under `chrt -r 20` when run as root; zRcube's
# figure is its "cpu s: parse" (+V: read, lex, parse and BVH build, CPU
# seconds), Tachyon's its "Scene Parsing Time" + "Preprocessing Time"
# (a wall clock).  Prints one line per run, then the best, median and
# mean of each with the load.  Timings are printed, never asserted.
set -eu
[ $# -ge 2 ] || { echo "usage: bench/parse_vs_tachyon.sh OLD NEW [ROUNDS]" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
old=$(cd "$1" && pwd)
new=$(cd "$2" && pwd)
rounds=${3:-15}
rt=""
[ "$(id -u)" = 0 ] && command -v chrt >/dev/null 2>&1 && rt="chrt -r 20"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
python3 "$here/peers_gen.py" "$dir"
echo "load at start: $(cat /proc/loadavg)"
for i in $(seq "$rounds"); do
  for b in "$old" "$new"; do
    v=$(LD_LIBRARY_PATH=$b/lib/.libs $rt "$b/bin/.libs/zrcube" +V -A +WT1 \
        +W512 +H512 "-O$dir/o.png" "$dir/flake.pov" 2>&1 |
        sed -n 's/.*cpu s: parse \([0-9.]*\).*/\1/p')
    echo "$b $v"
  done
  t=$($rt tachyon -numthreads 1 -res 512 512 "$dir/flake.dat" \
      -o "$dir/t.tga" 2>&1 |
      awk '/Scene Parsing Time/{a=$4} /Preprocessing Time/{b=$3}
           END {printf "%.4f", a + b}')
  echo "tachyon $t"
done | tee "$dir/runs.txt"
echo "load at end: $(cat /proc/loadavg)"
python3 - "$dir/runs.txt" <<'PY'
import collections, statistics, sys
d = collections.OrderedDict()
for line in open(sys.argv[1]):
    k, v = line.split()
    d.setdefault(k, []).append(float(v))
for k, v in d.items():
    v.sort()
    print("%-40s best %.4f median %.4f mean %.4f n %d"
          % (k, v[0], statistics.median(v), statistics.mean(v), len(v)))
PY
