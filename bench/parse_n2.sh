#!/bin/sh
# bench/parse_n2.sh - the terrain's parse under `mpirun -n 2`, rank by
# rank, for builds A and B in turn (issue 13: the parse every rank
# repeated is what kept the terrain's -n 2 efficiency under 90%).
#
# bench/peers.sh's terrain (130,050 triangles in a 15 MB mesh), rendered
# at SIZE (default 512) with one thread a rank, runs REPEAT times
# (default 5) for each build, A then B then A ..., under the round-robin
# real-time policy with RT=1 (as bench/mpi_n2.sh); -v makes every rank
# print its phases (bin/zrcube.c, print_rank_times).  Printed: for each
# build and rank the best (least) parse wall and CPU seconds and the
# best whole-run wall, and the bytes and exchanges of the team calls
# (the mesh's subtrees, when the build shares them).
#   bench/parse_n2.sh build-A build-B
set -eu
here=$(cd "$(dirname "$0")" && pwd)
SIZE=${SIZE:-512}
REPEAT=${REPEAT:-5}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
. "$here/timing.sh"
/usr/bin/python3 "$here/peers_gen.py" "$tmp" >/dev/null
a=$(cd "$1" && pwd)
b=$(cd "$2" && pwd)
cd "$tmp"
echo "load before: $(cat /proc/loadavg)"
for rep in $(seq 1 "$REPEAT"); do
  for tag in A B; do
    if [ "$tag" = A ]; then build=$a; else build=$b; fi
    . "$here/zrexe.sh"
    start=$(date +%s.%N)
    $rt mpirun --bind-to none -n 2 "$zrcube" +Iterrain.pov +W"$SIZE" \
      +H"$SIZE" -A +WT1 -D -v +O"$tag.png" 2>"$tmp/err" >/dev/null ||
      { cat "$tmp/err" >&2; exit 1; }
    end=$(date +%s.%N)
    echo "$tag whole $(echo "$end - $start" | bc)" >>"$tmp/r"
    sed -n 's/^zrcube: rank \([0-9]*\): wall s: parse \([0-9.]*\) .*cpu s: parse \([0-9.]*\) .*solution \([0-9]*\) pixels .*exchanges \([0-9]*\);.*/\1 \2 \3 \4 \5/p' \
      "$tmp/err" | sed "s/^/$tag rank /" >>"$tmp/r"
  done
  cmp -s A.png B.png || { echo "parse_n2.sh: other bytes" >&2; exit 1; }
done
echo "load after: $(cat /proc/loadavg)"
echo "A: $a"
echo "B: $b"
echo "terrain ${SIZE}^2, mpirun -n 2, +WT1, best of $REPEAT, ${rt:-no real-time policy}"
awk '$2 == "whole" { k = $1; if (!(k in w) || $3 < w[k]) w[k] = $3; next }
     { k = $1 " " $3
       if (!(k in pw) || $4 < pw[k]) pw[k] = $4
       if (!(k in pc) || $5 < pc[k]) pc[k] = $5
       by[k] = $6; calls[k] = $7 }
     END {
       printf "%-5s %5s %11s %11s %12s %10s\n", "build", "rank",
         "parse wall", "parse CPU", "team bytes", "team calls"
       n = split("A B", t, " ")
       for (i = 1; i <= n; i++) {
         for (r = 0; r < 2; r++) {
           k = t[i] " " r
           printf "%-5s %5d %11.4f %11.4f %12d %10d\n", t[i], r, pw[k],
             pc[k], by[k], calls[k]
         }
         printf "%-5s whole run wall %.3f s\n", t[i], w[t[i]]
       } }' "$tmp/r"
