#!/bin/sh
# parse_faults.sh - page faults and CPU time of the parse alone, two
# builds interleaved (issue 13: every rank of `mpirun -n 2` parses the
# whole scene, and a first touch of a 4 KiB page costs ~14 us on this
# project's VM).
#
#   bench/parse_faults.sh OLD_BUILD NEW_BUILD [RUNS]
#
# Makes bench/peers_gen.py's scenes (flake: 7,381 spheres; terrain:
# 130,050 triangles in one mesh; empty: camera and lights) and runs each
# build's real program (bench/zrexe.sh) as `zrcube --parse-only SCENE`
# under `perf stat -e page-faults,task-clock`, RUNS times (default 5),
# OLD and NEW alternating, under `chrt -r 20` when run as root.  Prints
# every run, then per build and scene the least and median faults and
# the best and median task-clock (ms), with the load.  Faults counted
# here are the processor's (a page taken by madvise MADV_POPULATE_WRITE
# is not one, though it costs about half as much).  Printed, never
# asserted.
set -eu
if [ $# -lt 2 ]; then
  echo "usage: bench/parse_faults.sh OLD_BUILD NEW_BUILD [RUNS]" >&2
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
old=$(cd "$1" && pwd)
new=$(cd "$2" && pwd)
runs=${3:-5}
python=${PYTHON:-/usr/bin/python3}
command -v perf >/dev/null 2>&1 || {
  echo "parse_faults.sh: needs perf" >&2
  exit 77
}
rt=
[ "$(id -u)" = 0 ] && command -v chrt >/dev/null 2>&1 && rt="chrt -r 20"
work=$(mktemp -d "${TMPDIR:-/tmp}/zr-faults.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM
"$python" "$here/peers_gen.py" "$work" >/dev/null
echo "load at start: $(cat /proc/loadavg)"
for i in $(seq "$runs"); do
  for scene in empty flake terrain; do
    for which in old new; do
      if [ $which = old ]; then build=$old; else build=$new; fi
      (
        . "$here/zrexe.sh"
        $rt perf stat -x, -e page-faults,task-clock -o "$work/stat" \
          "$zrcube" --parse-only "$work/$scene.pov" >/dev/null 2>&1
      )
      faults=$(awk -F, '$3 == "page-faults" {print $1}' "$work/stat")
      ms=$(awk -F, '$3 == "task-clock" {print $1}' "$work/stat")
      echo "$which $scene $faults $ms" | tee -a "$work/all"
    done
  done
done
echo "load at end: $(cat /proc/loadavg)"
echo "build scene  faults_min faults_med  ms_best  ms_med  (n $runs)"
for which in old new; do
  for scene in empty flake terrain; do
    awk -v w=$which -v s=$scene '$1 == w && $2 == s {print $3, $4}' \
      "$work/all" | sort -n >"$work/f"
    fmin=$(head -n 1 "$work/f" | cut -d' ' -f1)
    fmed=$(awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}' "$work/f")
    cut -d' ' -f2 "$work/f" | sort -g >"$work/m"
    mbest=$(head -n 1 "$work/m")
    mmed=$(awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}' "$work/m")
    printf '%-5s %-7s %10s %10s %8.2f %7.2f\n' "$which" "$scene" "$fmin" \
      "$fmed" "$mbest" "$mmed"
  done
done
echo "old: $old"
echo "new: $new"
