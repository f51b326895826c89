#!/bin/sh
# bench/timeline.sh - where the wall time of `mpirun -n N zrcube` goes,
# rank by rank, from the moment mpirun starts (issue 13).
#
# Runs bench/peers.sh's scene (SCENE: flake or terrain, default
# terrain) at SIZE^2 (default 2048), one thread a rank, no
# antialiasing, under `mpirun --bind-to none -n N` for each N in NP
# (default "1 2"), REPEAT times each (default 3), with ZRCUBE_TIMELINE
# set: every rank then prints a line at each step (lib/par/par.c's
# zr__par_mark: main() entered, MPI joined, parse, image and writer
# ready, for each chunk of the render this rank's rows done, all ranks
# met and the rows gathered, the image written, MPI_Finalize, leaving
# main()).  A rank whose "chunk rendered" step is long waited for
# another's rows (its thread CPU stays put meanwhile).  Of each N the run with the
# best wall time is printed: per rank and step, the wall time since
# mpirun started ("at"), since the rank's previous step ("step"), and
# the CPU the rank's process and its main thread took in that step
# (their difference is the image writer's thread).  The last lines
# give mpirun's whole wall and CPU time (/usr/bin/time: the launcher
# and every rank) and what mpirun took beyond the ranks' processes.
# RT=1 (as root) runs under chrt -r 20, as bench/mpi_n2.sh does.
# LAUNCHER=zrcube-mpirun runs the README's launcher as installed (the
# build's bin/zrcube-mpirun beside the real binary) instead of mpirun.
#   bench/timeline.sh [build-dir]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$(dirname "$here")/build}" && pwd)
SCENE=${SCENE:-terrain}
SIZE=${SIZE:-2048}
NP=${NP:-1 2}
REPEAT=${REPEAT:-3}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1 ZRCUBE_TIMELINE=1
. "$here/zrexe.sh"
. "$here/timing.sh"
/usr/bin/python3 "$here/peers_gen.py" "$tmp" >/dev/null
LAUNCHER=${LAUNCHER:-mpirun}
case $LAUNCHER in
  mpirun) ;;
  zrcube-mpirun)
    mkdir "$tmp/bin"
    cp "$build/bin/zrcube-mpirun" "$tmp/bin/"
    ln -s "$zrcube" "$tmp/bin/zrcube"
    unset MPIRUN ;;
  *) echo "timeline.sh: LAUNCHER is mpirun or zrcube-mpirun" >&2; exit 2 ;;
esac
cd "$tmp"
echo "load before: $(cat /proc/loadavg)"
for n in $NP; do
  best=
  for _ in $(seq 1 "$REPEAT"); do
    start=$(date +%s.%N)
    # shellcheck disable=SC2086
    if [ "$LAUNCHER" = mpirun ]; then
      set -- mpirun --bind-to none -n "$n" "$zrcube"
    else
      set -- bin/zrcube-mpirun -n "$n"
    fi
    /usr/bin/time -f "time %e %U %S" -o time.txt $rt "$@" "+I$SCENE.pov" \
      "+W$SIZE" "+H$SIZE" -A +WT1 -D +Oout.png >/dev/null 2>err.txt ||
      { cat err.txt >&2; exit 1; }
    wall=$(awk '{ print $2 }' time.txt)
    if [ -z "$best" ] || awk -v a="$wall" -v b="$best" 'BEGIN { exit !(a < b) }'
    then
      best=$wall
      { echo "start $start"; cat time.txt; grep '^zrcube: timeline: ' err.txt; } \
        >best.txt
    fi
  done
  echo
  echo "$SCENE ${SIZE}^2, $LAUNCHER -n $n, best of $REPEAT (${rt:-no real-time policy})"
  awk '
    $1 == "start" { t0 = $2; next }
    $1 == "time" { wall = $2; cpu = $3 + $4; next }
    { r = $4; w = $6; c = $8; th = $10
      what = $11; for (i = 12; i <= NF; i++) what = what " " $i
      if (!(r in lw)) { lw[r] = t0; lc[r] = 0; lt[r] = 0 }
      line[++n] = sprintf("%4s %8.3f %8.3f %8.3f %8.3f  %s", r, w - t0,
                          w - lw[r], c - lc[r], th - lt[r], what)
      at[n] = w; lw[r] = w; lc[r] = c; lt[r] = th; total[r] = c }
    END {
      printf "%4s %8s %8s %8s %8s  %s\n", "rank", "at", "step", "cpu",
             "thread", "step ended"
      # By time, the ranks interleaved (insertion sort: a few lines).
      for (i = 1; i <= n; i++) ord[i] = i
      for (i = 2; i <= n; i++)
        for (j = i; j > 1 && at[ord[j]] < at[ord[j - 1]]; j--) {
          k = ord[j]; ord[j] = ord[j - 1]; ord[j - 1] = k }
      for (i = 1; i <= n; i++) print line[ord[i]]
      ranks = 0
      for (r in total) ranks += total[r]
      printf "whole run: wall %.3f s, CPU %.3f s (ranks %.3f, mpirun %.3f)\n",
             wall, cpu, ranks, cpu - ranks }' best.txt
done
echo "load after: $(cat /proc/loadavg)"
