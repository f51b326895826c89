#!/bin/sh
# bench/launch.sh - what starting under mpirun costs (issues 13 and 15).
#
# Times, best of REPEAT (default 5) runs taken in turn, wall and CPU
# seconds (user + system of mpirun and its ranks, /usr/bin/time):
#   true      mpirun -n N true: the launcher alone;
#   probe     mpirun -n N zrcube of an empty 16x16 scene with Open MPI
#             choosing its point-to-point layer itself
#             (OMPI_MCA_pml=^v names a pml, so zrcube leaves the choice
#             alone, and excludes only the never-chosen "v");
#   ob1       the same with zrcube's own choice on one host (ob1, shared
#             memory: lib/par/par.c, prefer_shared_memory);
#   plain     zrcube alone, no mpirun;
# for N = 1 and 2.  RT=1 (as root) runs everything under the round-robin
# real-time policy (chrt -r 20), which serves the runs before other
# sessions' processes, as an idle machine would; wall times are then
# meaningful on this shared machine.
#   bench/launch.sh [build-dir]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$(dirname "$here")/build}" && pwd)
REPEAT=${REPEAT:-5}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
unset OMPI_MCA_pml OMPI_MCA_mtl
. "$here/zrexe.sh"
. "$here/timing.sh"
cat >"$tmp/empty.pov" <<'EOF'
camera { location <0, 0, -3> look_at 0 }
light_source { <5, 5, -5> rgb 1 }
sphere { 0, 1 pigment { rgb 1 } }
EOF
cd "$tmp"
zr="$zrcube +Iempty.pov +Oe.png +W16 +H16 -A +WT1 -D"
echo "load before: $(cat /proc/loadavg)"
for rep in $(seq 1 "$REPEAT"); do
  for n in 1 2; do
    one "true-n$n" mpirun --bind-to none -n $n true
    # shellcheck disable=SC2086
    one "probe-n$n" env OMPI_MCA_pml=^v mpirun --bind-to none -n $n $zr
    # shellcheck disable=SC2086
    one "ob1-n$n" mpirun --bind-to none -n $n $zr
  done
  # shellcheck disable=SC2086
  one plain $zr
done
echo "load after: $(cat /proc/loadavg)"
printf '%-10s %8s %8s   (best of %s; %s)\n' run wall_s cpu_s "$REPEAT" \
  "${rt:-no real-time policy}"
awk '{ c = $3 + $4
       if (!($1 in w) || $2 < w[$1]) w[$1] = $2
       if (!($1 in u) || c < u[$1]) u[$1] = c }
     END { for (k in w) printf "%-10s %8.3f %8.3f\n", k, w[k], u[k] }' \
  "$tmp/t" | sort
