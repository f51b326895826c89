#!/bin/sh
# run.sh - zRcube against POV-Ray 3.7 on every scene, in the same run.
#
#   bench/run.sh BUILD_DIR [WIDTH HEIGHT]      (default 320 240)
#
# Each scenes/NAME.pov is rendered by BUILD_DIR/bin/zrcube on one thread
# (+WT1, no mpirun) and by POV-Ray (`povray +WT1`, scenes/NAME.ref.pov
# when the scene uses a zRcube extension) at the same size, without
# antialiasing or display.  Each command is timed whole, wall-clock, best
# of REPEAT runs (default 3): POV-Ray's time includes its start-up and
# parse, and so does zRcube's.  The table gives both times and the ratio
# zRcube / POV-Ray (below 1 is faster than POV-Ray), then the geometric
# mean of the ratios.  Renders go to a temporary directory; set BENCH_KEEP
# to a directory to keep them.  Timings are printed, never asserted.
set -eu
if [ $# -lt 1 ]; then
  echo "usage: bench/run.sh BUILD_DIR [WIDTH HEIGHT]" >&2
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/.." && pwd)
build=$(cd "$1" && pwd)
width=${2:-320}
height=${3:-240}
repeat=${REPEAT:-3}
zrcube=$build/bin/zrcube
povray=${POVRAY:-povray}
[ -x "$zrcube" ] || { echo "run.sh: $zrcube is not built" >&2; exit 1; }
command -v "$povray" >/dev/null ||
  { echo "run.sh: $povray not found" >&2; exit 1; }

work=$(mktemp -d "${TMPDIR:-/tmp}/zr-bench.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM
out_dir=${BENCH_KEEP:-$work}
mkdir -p "$out_dir"

# Prints the wall-clock seconds of the command, or "fail".
seconds() {
  start=$(date +%s.%N)
  if "$@" >"$work/log" 2>&1; then
    end=$(date +%s.%N)
    echo "$start $end" | awk '{ printf "%.3f\n", $2 - $1 }'
  else
    echo fail
  fi
}

# Best of $repeat runs of the command.
best_of() {
  best=fail
  i=0
  while [ $i -lt "$repeat" ]; do
    t=$(seconds "$@")
    if [ "$t" = fail ]; then
      best=fail
      break
    fi
    best=$(echo "$best $t" |
           awk '{ print ($1 == "fail" || $2 < $1) ? $2 : $1 }')
    i=$((i + 1))
  done
  echo "$best"
}

echo "zRcube $(basename "$build") vs $("$povray" --version 2>&1 |
  grep -m1 POV-Ray), ${width}x${height}, no AA, one thread, best of $repeat"
printf '%-14s %10s %10s %8s\n' scene zRcube_s POV-Ray_s ratio
log_sum=0
count=0
failures=0
for scene in "$top"/scenes/*.pov; do
  name=$(basename "$scene" .pov)
  case $name in *.ref) continue ;; esac
  # "// golden: skip WHY" (scenes/cornell.pov): benchmarked elsewhere
  # (bench/radiosity.sh).
  head -n 1 "$scene" | grep -q '^// golden: skip' && continue
  pov_scene=$scene
  [ -f "$top/scenes/$name.ref.pov" ] && pov_scene=$top/scenes/$name.ref.pov
  tz=$(best_of "$zrcube" "$scene" +W"$width" +H"$height" -A +WT1 \
       +O"$out_dir/$name.zr.png" +L"$top/scenes")
  [ "$tz" = fail ] && sed 's/^/    /' "$work/log" | head -5 >&2
  tp=$(best_of "$povray" +I"$pov_scene" +O"$out_dir/$name.pov.png" \
       +W"$width" +H"$height" -A +FN -D -V +WT1 +L"$top/scenes")
  if [ "$tz" = fail ] || [ "$tp" = fail ]; then
    printf '%-14s %10s %10s %8s\n' "$name" "$tz" "$tp" -
    failures=$((failures + 1))
    continue
  fi
  ratio=$(echo "$tz $tp" | awk '{ printf "%.3f", $1 / $2 }')
  printf '%-14s %10s %10s %8s\n' "$name" "$tz" "$tp" "$ratio"
  # The mean uses the unrounded ratio; a 0 ms time counts as 1 ms.
  log_sum=$(echo "$log_sum $tz $tp" |
            awk '{ z = $2 > 0.001 ? $2 : 0.001
                   p = $3 > 0.001 ? $3 : 0.001
                   printf "%.6f", $1 + log(z / p) }')
  count=$((count + 1))
done
# For scale: POV-Ray's cost for a scene with nothing in it, mostly its
# start-up, which every row above includes.
printf '#version 3.7;\ncamera { location -z look_at 0 }\n' >"$work/empty.pov"
te=$(best_of "$povray" +I"$work/empty.pov" +O"$work/empty.png" \
     +W"$width" +H"$height" -A +FN -D -V +WT1)
echo "POV-Ray on an empty scene: $te s"
if [ $count -gt 0 ]; then
  echo "$log_sum $count" |
    awk '{ printf "geometric mean of ratios: %.3f over %d scenes\n",
           exp($1 / $2), $2 }'
fi
[ $failures -eq 0 ] || echo "$failures scene(s) failed to render" >&2
[ $failures -eq 0 ]
