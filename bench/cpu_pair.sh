#!/bin/sh
# bench/cpu_pair.sh - is every processor of this machine as fast as the
# others, alone and when all are busy?  (issue 13: `mpirun -n 2` keeps
# both processors busy, `-n 1` leaves one to the rest of the machine.)
#
# Renders bench/peers.sh's scene (SCENE: terrain or flake, default
# terrain) at SIZE^2 (default 2048), one thread, no antialiasing, with
# the real binary (bench/zrexe.sh), pinned by taskset: first alone on
# each processor in turn, then one copy on every processor at once.
# REPEAT rounds (default 3) of both.  Each run's render CPU seconds are
# zrcube's own ("cpu s: ... render", +V's rank line): the render's
# thread, so the launch, the parse and the PNG are left out.  Prints,
# per processor, the best and the median of its alone and paired runs,
# and the paired/alone ratio of the medians; then which other tasks sit
# on which processor and how much CPU they have taken since boot (ps),
# since a processor that hosts them lends them time while a render
# runs there.  RT=1 runs everything under chrt -r 20 (bench/timing.sh).
#   bench/cpu_pair.sh [build-dir]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$(dirname "$here")/build}" && pwd)
SCENE=${SCENE:-terrain}
SIZE=${SIZE:-2048}
REPEAT=${REPEAT:-3}
. "$here/zrexe.sh"
. "$here/timing.sh"
/usr/bin/python3 "$here/peers_gen.py" "$tmp" >/dev/null
cd "$tmp"
ncpu=$(getconf _NPROCESSORS_ONLN)
# render CPU seconds of one run: KEY CPU, appended to $tmp/r
render() {
  # shellcheck disable=SC2086
  $rt taskset -c "$2" "$zrcube" "+I$SCENE.pov" "+W$SIZE" "+H$SIZE" -A +WT1 \
    -D +V "+O$1-$2.png" >/dev/null 2>"$tmp/$1-$2.err" ||
    { cat "$tmp/$1-$2.err" >&2; exit 1; }
  sed -n 's/.*cpu s: .* render \([0-9.]*\) .*/\1/p' "$tmp/$1-$2.err" |
    awk -v k="$1 $2" '{ print k, $1 }' >>"$tmp/r"
}
echo "load before: $(cat /proc/loadavg)"
for _ in $(seq 1 "$REPEAT"); do
  c=0
  while [ "$c" -lt "$ncpu" ]; do
    render alone "$c"
    c=$((c + 1))
  done
  c=0
  while [ "$c" -lt "$ncpu" ]; do
    render paired "$c" &
    c=$((c + 1))
  done
  wait
done
echo "load after: $(cat /proc/loadavg)"
echo "$SCENE ${SIZE}^2, one thread pinned to each processor, $REPEAT rounds${rt:+ ($rt)}: render CPU s"
sort -k1,1 -k2,2n -k3,3n "$tmp/r" | awk '
  { k = $1 " " $2; n[k]++; v[k, n[k]] = $3 }
  END {
    printf "%-4s %20s %20s %8s\n", "cpu", "alone best/median", "paired best/median", "ratio"
    for (c = 0; ("alone " c) in n; c++) {
      a = "alone " c; p = "paired " c
      ma = v[a, int((n[a] + 1) / 2)]; mp = v[p, int((n[p] + 1) / 2)]
      printf "%-4d %9.3f / %8.3f %9.3f / %8.3f %8.3f\n", c, v[a, 1], ma,
        v[p, 1], mp, mp / ma
    }
  }'
echo "other tasks with CPU time since boot, by processor (ps):"
ps -e -o psr=,time=,comm= | awk '$2 != "00:00:00" && $2 != "00:00:01"' |
  sort -k1,1n -k2,2r | awk '{ printf "  cpu %s %s %s\n", $1, $2, $3 }'
