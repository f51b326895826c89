#!/bin/sh
# bench/mpi_yield.sh - whether a rank that waits in a blocking MPI call
# should give its processor away (Open MPI's mpi_yield_when_idle, which
# lib/par/par.c sets to 1 for a one-host job unless the environment
# names it): mpirun -n 2 with the variable 0 and 1, and one rank, runs
# alternated RUNS times (default 4), under whatever load the machine
# has - the case this serves is a busy one (other work on the host).
# Prints each run's wall, user and system seconds (/usr/bin/time, the
# launcher and every rank), -v's gather (each rank's wall time in the
# rows' exchange after the chunks) and each rank's process CPU.  The
# image bytes must be the same in every mode.
#   bench/mpi_yield.sh [build-dir]   (SCENE flake|terrain, SIZE, RUNS)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$(dirname "$here")/build}" && pwd)
SCENE=${SCENE:-flake}
SIZE=${SIZE:-2048}
RUNS=${RUNS:-4}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
. "$here/zrexe.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 "$here/peers_gen.py" "$tmp" >/dev/null
cd "$tmp"
echo "$SCENE ${SIZE}^2; mode: yield 0 / 1 under -n 2, n1 = one rank"
echo "mode  wall   user   sys  | gather s and process CPU s, rank by rank | load"
for _ in $(seq 1 "$RUNS"); do
  for mode in 0 1 n1; do
    case $mode in n1) n=1 y=1 ;; *) n=2 y=$mode ;; esac
    # shellcheck disable=SC2086
    OMPI_MCA_mpi_yield_when_idle=$y /usr/bin/time -o time.txt \
      -f "%e %U %S" mpirun --bind-to none -n $n "$zrcube" +I$SCENE.pov \
      +W$SIZE +H$SIZE -A +WT1 -D +V +O$mode.png 2>err.txt >/dev/null
    ranks=$(sed -n 's/.*rank \([0-9]*\): wall s:.* gather \([0-9.]*\) .*process \([0-9.]*\);.*/\1: \2 \3/p' err.txt |
      tr '\n' ' ')
    printf "%-4s %s | %s| %s\n" "$mode" "$(cat time.txt)" "$ranks" \
      "$(cut -d' ' -f1 /proc/loadavg)"
  done
  cmp -s 0.png 1.png && cmp -s 0.png n1.png ||
    { echo "mpi_yield.sh: the modes made other bytes" >&2; exit 1; }
done
