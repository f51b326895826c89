#!/bin/sh
# bench/rank_waits.sh - how long ranks wait for each other at the ends
# of a render's chunks under `mpirun -n 2`, with rows taken from the
# shared counter (one host's default) and with the static deal
# (ZRCUBE_ROWS=static), runs alternated.
#
# For each run, each chunk's "rows of this rank done" marks
# (ZRCUBE_TIMELINE) give the two ranks' finishing times; the wait is
# the later minus the earlier, summed over the chunks (the tail chunk,
# which rank 0 leaves to the others while it writes the image, is not
# counted).  Prints each run's summed wait and wall time, then the
# median and the largest of each mode.  The image bytes must be the
# same in both modes.
#   bench/rank_waits.sh [build-dir]   (SCENE flake|terrain, SIZE, RUNS, RT=1)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$(dirname "$here")/build}" && pwd)
SCENE=${SCENE:-terrain}
SIZE=${SIZE:-2048}
RUNS=${RUNS:-5}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
. "$here/zrexe.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 "$here/peers_gen.py" "$tmp" >/dev/null
cd "$tmp"
rt=
[ "${RT:-0}" = 1 ] && rt="chrt -r 20"
echo "load before: $(cat /proc/loadavg)"
for _ in $(seq 1 "$RUNS"); do
  for mode in shared static; do
    start=$(date +%s.%N)
    # shellcheck disable=SC2086
    env ZRCUBE_TIMELINE=1 ZRCUBE_ROWS="$mode" $rt mpirun --bind-to none \
      -n 2 $zrcube +I$SCENE.pov +W$SIZE +H$SIZE -A +WT1 -D \
      +O$mode.png 2>"$mode.err"
    end=$(date +%s.%N)
    awk -v mode="$mode" -v wall="$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')" '
      / render: rows of this rank done$/ {
        r = $4; n[r]++; t[r, n[r]] = $6 }
      END {
        w = 0
        for (i = 1; i <= n[0] && i <= n[1]; i++) {
          d = t[0, i] - t[1, i]; w += d < 0 ? -d : d }
        printf "%s %.3f %.3f %d\n", mode, w, wall, n[0] }' \
      "$mode.err" >>waits.txt
  done
  cmp -s shared.png static.png ||
    { echo "rank_waits.sh: the modes made other bytes" >&2; exit 1; }
done
echo "load after: $(cat /proc/loadavg)"
echo "$SCENE ${SIZE}^2, mpirun -n 2, $RUNS runs a mode${rt:+, $rt}"
echo "mode    wait s (summed over chunks) each run      wall s each run"
for mode in shared static; do
  awk -v m="$mode" '$1 == m { w = w sprintf(" %.3f", $2)
                              s = s sprintf(" %.2f", $3) }
       END { printf "%-7s%s   |%s\n", m, w, s }' waits.txt
done
