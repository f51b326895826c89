#!/bin/sh
# bench/mpi_n2.sh - issue 13's MPI target: the whole-process time of
# `mpirun -n 2` against one rank, on bench/peers.sh's scenes.
#
# For each scene (flake: 7,381 spheres; terrain: 130,050 triangles in a
# 15 MB mesh) and size (SIZES, default "512 2048"), no antialiasing, one
# thread a rank, runs in turn REPEAT times (default 3): zrcube alone (no
# mpirun), mpirun -n 1 and mpirun -n 2 (--bind-to none), and keeps each
# one's best wall time and best CPU seconds (user + system of the
# launcher and every rank, /usr/bin/time).  The images must be the same
# bytes.  RT=1 (as root) runs everything under the round-robin real-time
# policy (chrt -r 20): on this machine, shared with other sessions,
# that serves the runs before the others' processes, as an idle 2-core
# machine would, so the wall times mean something.  The efficiency
# printed is wall(-n 1) / (2 wall(-n 2)); the ratio "n2/n1" must stay
# at or under 1 (issue 13), "n2/plain" compares with no launcher at all.
# The "2 threads" column is one process of two threads (+WT2, no
# mpirun), "t-eff" its efficiency against one (wall(plain) / (2
# wall(2 threads))): issue 13 asks the same 90% of both.  The
# "zrcube-mpirun" columns run the README's launcher as installed (the
# build's bin/zrcube-mpirun beside the real binary, no libtool wrapper),
# which also cuts mpirun's own start-up on one host
# (bin/zrcube-mpirun.in), -n 1 and -n 2, "w-eff" their efficiency.
#   bench/mpi_n2.sh [build-dir]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$(dirname "$here")/build}" && pwd)
SIZES=${SIZES:-512 2048}
REPEAT=${REPEAT:-3}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
. "$here/zrexe.sh"
. "$here/timing.sh"
/usr/bin/python3 "$here/peers_gen.py" "$tmp" >/dev/null
# The launcher as `make install` lays it out: zrcube beside it.
mkdir "$tmp/bin"
cp "$build/bin/zrcube-mpirun" "$tmp/bin/"
ln -s "$zrcube" "$tmp/bin/zrcube"
cd "$tmp"
echo "load before: $(cat /proc/loadavg)"
for scene in flake terrain; do
  for size in $SIZES; do
    args="+I$scene.pov +W$size +H$size -A +WT1 -D"
    for rep in $(seq 1 "$REPEAT"); do
      # shellcheck disable=SC2086
      one "$scene-$size-plain" $zrcube $args +Oplain.png
      # shellcheck disable=SC2086
      one "$scene-$size-n1" mpirun --bind-to none -n 1 $zrcube $args +On1.png
      # shellcheck disable=SC2086
      one "$scene-$size-n2" mpirun --bind-to none -n 2 $zrcube $args +On2.png
      # shellcheck disable=SC2086
      one "$scene-$size-t2" $zrcube $args +WT2 +Ot2.png
      # shellcheck disable=SC2086
      one "$scene-$size-w1" env -u MPIRUN bin/zrcube-mpirun -n 1 $args +Ow1.png
      # shellcheck disable=SC2086
      one "$scene-$size-w2" env -u MPIRUN bin/zrcube-mpirun -n 2 $args +Ow2.png
      cmp -s plain.png n1.png && cmp -s plain.png n2.png &&
        cmp -s plain.png t2.png && cmp -s plain.png w1.png &&
        cmp -s plain.png w2.png ||
        { echo "mpi_n2.sh: $scene $size: other bytes" >&2; exit 1; }
    done
  done
done
echo "load after: $(cat /proc/loadavg)"
echo "best of $REPEAT, ${rt:-no real-time policy}; seconds (wall / CPU)"
awk '{ c = $3 + $4
       if (!($1 in w) || $2 < w[$1]) { w[$1] = $2; o[$1] = $5 }
       if (!($1 in u) || c < u[$1]) u[$1] = c }
     END {
       printf "%-14s %13s %13s %13s %7s %8s %6s %13s %6s %13s %13s %6s\n",
         "scene", "plain", "mpirun -n 1", "mpirun -n 2", "n2/n1", "n2/plain",
         "eff", "2 threads", "t-eff", "z-mpirun -n 1", "z-mpirun -n 2",
         "w-eff"
       n = split("flake terrain", sc, " ")
       m = split(sizes, sz, " ")
       for (i = 1; i <= n; i++) for (j = 1; j <= m; j++) {
         k = sc[i] "-" sz[j]
         if (!((k "-n2") in w)) continue
         printf "%-14s %6.2f/%6.2f %6.2f/%6.2f %6.2f/%6.2f %7.2f %8.2f %5.1f%% %6.2f/%6.2f %5.1f%% %6.2f/%6.2f %6.2f/%6.2f %5.1f%%\n",
           sc[i] " " sz[j], w[k "-plain"], u[k "-plain"], w[k "-n1"],
           u[k "-n1"], w[k "-n2"], u[k "-n2"], w[k "-n2"] / w[k "-n1"],
           w[k "-n2"] / w[k "-plain"], 100 * w[k "-n1"] / (2 * w[k "-n2"]),
           w[k "-t2"], u[k "-t2"], 100 * w[k "-plain"] / (2 * w[k "-t2"]),
           w[k "-w1"], u[k "-w1"], w[k "-w2"], u[k "-w2"],
           100 * w[k "-w1"] / (2 * w[k "-w2"])
       }
       printf "other processes'"'"' CPU s during the best runs (timing.sh), n1 / n2:"
       for (i = 1; i <= n; i++) for (j = 1; j <= m; j++) {
         k = sc[i] "-" sz[j]
         if ((k "-n2") in w)
           printf "  %s %s %.2f / %.2f", sc[i], sz[j], o[k "-n1"], o[k "-n2"]
       }
       printf "\n" }' sizes="$SIZES" "$tmp/t"
