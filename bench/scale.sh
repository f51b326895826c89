#!/bin/sh
# bench/scale.sh - how zrcube scales over ranks and threads (issue 15).
#
# Runs two scenes, a ray-traced one and a radiosity one, as 1 rank x 1
# thread, 2 ranks x 1 thread, 1 rank x 2 threads and 4 ranks x 1 thread
# (all under mpirun, so each pays the same launch), REPEAT times in turn
# so that the machine's load falls on each alike, and keeps each
# configuration's fastest run.  zrcube -v prints, per rank, the wall and
# CPU seconds of each phase (parse, global illumination, render, the
# final gather of pixels) and the bytes the rank sent (scene files,
# solution exchanges, pixels); bench/scale_model.py turns those into
# parallel efficiency per phase, fits the model and draws the charts.
#
# Wall time on a shared machine says little: Linux's autogroup
# scheduler gives each session one fair share, so the ranks of one
# mpirun share one share, and under other sessions' load 2 ranks get no
# more processor than 1.  CPU seconds are the work each rank did whatever
# the load, so efficiency is also reported from them: the 1-rank CPU
# over N times the busiest rank's CPU, what an idle machine with N cores
# shows; the 4-rank run (oversubscribed on 2 cores) is used for its CPU
# only, to fit the model, which then predicts the 2-rank run.
# The images of every configuration are compared byte for byte.
#
#   bench/scale.sh [build-dir]        (REPEAT=3 by default; RT=1 below)
#
# Output: bench/scale/runs.tsv (every run), bench/scale/summary.md and
# the charts bench/scale/efficiency.png and bench/scale/model.png.
# The program timed is the build's real bin/.libs/zrcube, not libtool's
# wrapper script (bench/zrexe.sh), and each rank's -v line also gives
# its whole process's CPU, so the summary has a whole-process row:
# mpirun's launch plus the busiest rank's process CPU.
# CHECK_RANKS="3 8" adds oversubscribed runs that check bytes only.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
top=$(dirname "$here")
build=${1:-$top/build}
# The ranks run from scenes/: a relative build folder would name no
# program there.
build=$(cd "$build" && pwd) ||
  { echo "scale.sh: no build folder ${1:-$top/build}" >&2; exit 1; }
. "$here/zrexe.sh" # the real program, not libtool's wrapper
out=$here/scale
REPEAT=${REPEAT:-3}
CHECK_RANKS=${CHECK_RANKS:-}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# Waiting ranks give the processor away instead of spinning: on a shared
# machine a spinning rank steals time from the one it waits for.
export OMPI_MCA_mpi_yield_when_idle=1
MPIRUN="mpirun --bind-to none"
# RT=1 (as root): run every mpirun under the round-robin real-time policy
# (chrt -r), which the scheduler serves before every ordinary process:
# on a machine shared with other sessions' work this gives the ranks the
# cores as an idle machine would (the kernel still keeps 5% for the
# rest).  Round-robin, not FIFO, so that oversubscribed ranks take turns.
if [ "${RT:-0}" = 1 ]; then
  MPIRUN="chrt -r 20 $MPIRUN"
fi
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# scene name, arguments (run from scenes/).  --state-interval=600: the
# +C state file is written every 10 s of wall time by default, and under
# this machine's load the renders take 10 times the wall time they take
# on an idle machine with a core a rank (2 to 4 s, no state file at
# all), so rank 0 wrote 75 MB files the measure stands for none of.
ray_args="default.pov +W2048 +H1536 +A0.3 --state-interval=600"
rad_args="cornell.pov --gi=hierarchical +W64 +H64 -D --state-interval=600"

# The runs are collected aside and replace bench/scale/runs.tsv only
# when every one has run: a failed or interrupted run leaves the last
# complete measurement in place.
runs=$tmp/runs.tsv
printf 'scene\tranks\tthreads\trep\twall\tload1\trank\tphase_wall\tphase_cpu\tsent\n' >"$runs"

# one SCENE RANKS THREADS REP ARGS...: a run, its -v lines into runs.tsv.
one() {
  o_scene=$1 o_ranks=$2 o_threads=$3 o_rep=$4
  shift 4
  o_img=$tmp/${o_scene}_${o_ranks}x${o_threads}.png
  o_load=$(cut -d' ' -f1 /proc/loadavg)
  # RT=1, one rank of one thread: the run on processor 0 and a
  # real-time spinner on processor 1, so that the second core runs no
  # other session's work beside it (which shares the caches and the
  # memory bus: 1-rank runs took more CPU than 2 ranks together,
  # efficiencies of 101 to 110%); a 2-rank or 2-thread run fills both.
  o_pin= o_spin=
  if [ "${RT:-0}" = 1 ] && [ "$o_ranks" = 1 ] && [ "$o_threads" = 1 ]; then
    chrt -r 20 taskset -c 1 sh -c 'while :; do :; done' &
    o_spin=$!
    o_pin="taskset -c 0"
  fi
  o_t0=$(date +%s.%N)
  (cd "$top/scenes" && timeout 600 $o_pin $MPIRUN -n "$o_ranks" "$zrcube" \
     "$@" +WT"$o_threads" -v +O"$o_img" 2>"$tmp/err") ||
    { [ -n "$o_spin" ] && kill "$o_spin";
      echo "scale.sh: $o_scene ${o_ranks}x$o_threads failed:" >&2;
      cat "$tmp/err" >&2; exit 1; }
  o_t1=$(date +%s.%N)
  [ -z "$o_spin" ] || { kill "$o_spin"; wait "$o_spin" 2>/dev/null || :; }
  o_wall=$(echo "$o_t1 - $o_t0" | bc -l)
  # zrcube: rank R: wall s: parse P gi G radiosity R render X gather Y
  #   exchange E; cpu s: ...; sent B: scene S solution L pixels X; ...
  sed -n 's/^zrcube: rank \([0-9]*\): wall s: \(.*\); cpu s: \(.*\); sent B: \(.*\); exchanges \([0-9]*\).*/\1	\2	\3	\4 exchanges \5/p' \
    "$tmp/err" | while IFS='	' read -r rk pw pc sb; do
      printf '%s\t%s\t%s\t%s\t%.4f\t%s\t%s\t%s\t%s\t%s\n' "$o_scene" \
        "$o_ranks" "$o_threads" "$o_rep" "$o_wall" "$o_load" "$rk" \
        "$pw" "$pc" "$sb" >>"$runs"
    done
  if [ "$o_rep" = 1 ]; then
    ref=$tmp/${o_scene}_1x1.png
    if [ -f "$ref" ] && ! cmp -s "$ref" "$o_img"; then
      echo "scale.sh: $o_scene ${o_ranks}x$o_threads: other bytes than 1x1" >&2
      exit 1
    fi
  fi
}

echo "load before: $(cat /proc/loadavg)"
# mpirun's own launch, without zrcube: best of 3 per rank count.
for n in 1 2 4; do
  best=
  for k in 1 2 3; do
    t0=$(date +%s.%N)
    $MPIRUN -n $n true
    t1=$(date +%s.%N)
    t=$(echo "$t1 - $t0" | bc -l)
    if [ -z "$best" ] || [ "$(echo "$t < $best" | bc -l)" = 1 ]; then
      best=$t
    fi
  done
  printf 'launch\t%s\t1\t1\t%.4f\t%s\t0\t-\t-\t-\n' "$n" "$best" \
    "$(cut -d' ' -f1 /proc/loadavg)" >>"$runs"
done
for rep in $(seq 1 "$REPEAT"); do
  for cfg in "1 1" "2 1" "1 2" "4 1"; do
    # shellcheck disable=SC2086
    one ray $cfg "$rep" $ray_args
    # shellcheck disable=SC2086
    one rad $cfg "$rep" $rad_args
  done
done
for n in $CHECK_RANKS; do
  # shellcheck disable=SC2086
  one ray "$n" 1 1 $ray_args
  # shellcheck disable=SC2086
  one rad "$n" 1 1 $rad_args
  echo "$n ranks (oversubscribed): same bytes as 1 rank"
done
echo "load after: $(cat /proc/loadavg)"
cp "$runs" "$out/runs.tsv"
/usr/bin/python3 "$here/scale_model.py" "$out/runs.tsv" "$out"
