#!/bin/sh
# radiosity.sh - radiosity accuracy against time: zRcube and POV-Ray 3.7
# on the emissive Cornell box, against a path-traced ground truth, in the
# same run (issue 4's proof).
#
#   bench/radiosity.sh BUILD_DIR [--quick]
#
# The scene is scenes/cornell.pov (bench/radiosity/cornell.pov when it
# is missing), a copy of ../shared/reference/cbox_emissive.pov: the
# measured Cornell box lit only by an emitting ceiling quad, every surface
# Lambertian.  The ground truth is cbox_emissive-256.pfm beside it, path
# traced with 4096 samples a pixel.  Every render is 256x256 with
# antialiasing (+A0.05 +R3) on one thread (+WT1), timed whole and
# wall-clock (start-up and parse included), and scored by tests/imgcmp
# --rmse: the RMS difference of the two images clipped to [0, 1] in
# linear light, divided by the ground truth's clipped mean.
#
# Ladders, run one after the other:
#   povray   POV-Ray 3.7's radiosity (Ward's irradiance cache) at
#            increasing count and recursion_limit; the scene's radiosity
#            block is replaced in a temporary copy.  Output is Radiance
#            HDR (+FH), linear, which imgcmp reads; 3.7 writes no PFM.
#   none     POV-Ray without radiosity: the emitter alone, everything
#            else black.  The error a renderer without global
#            illumination makes, for scale.
#   zr-bf    zRcube's hierarchical radiosity at a ladder of BF_eps
#            (--radiosity --bf-eps=X; X is relative to the scene's
#            emitted power, zr_radiosity_params.bf_eps, default 1e-4).
#   zr-unif  zRcube with N x N elements on every input surface and no
#            refinement (--radiosity --uniform=N; N a power of two
#            from 2, as --uniform refuses 1).
# The zRcube ladders run when `zrcube --help` mentions --radiosity; they
# read the key=value lines --radiosity-stats prints on stderr (elements,
# links, iterations, residual).
#
# Writes $RADBENCH_OUT (default bench/out) /radiosity.tsv with the columns
# method, setting, seconds, rel_rmse, elements, links, iterations,
# residual ("-" where a method has no such figure), the renders under
# radiosity/, and with gnuplot the
# charts radiosity-error-time.png (log-log, every ladder) and
# radiosity-elements.png (elements and links against BF_eps); it prints
# the table as it goes, then the verdicts of bench/radiosity/summary.awk
# (issue 4's speed and accuracy targets against POV-Ray's best rung, and
# how many fewer elements hierarchical radiosity needs than uniform
# subdivision).  --quick runs only the cheapest rungs of each ladder.
#
# Environment: POVRAY (default povray), RADBENCH_TRUTH (the ground truth
# image), RADBENCH_SCENE, RADBENCH_OUT, RADBENCH_POV_LADDER (rungs
# "count:recursion_limit", space separated), RADBENCH_BF_EPS,
# RADBENCH_UNIFORM (space separated values), RADBENCH_TIMEOUT (seconds a
# render may take, default 900).  A rung that fails or runs out of time
# ends its ladder: the rungs after it cost more.  Timings are printed,
# never asserted.
set -eu
. "$(dirname "$0")/build_args.sh"
povray=${POVRAY:-povray}
size=256
limit=${RADBENCH_TIMEOUT:-900}
out=${RADBENCH_OUT:-$top/bench/out}
truth=${RADBENCH_TRUTH:-$top/../shared/reference/cbox_emissive-256.pfm}
if [ -n "${RADBENCH_SCENE:-}" ]; then
  scene=$RADBENCH_SCENE
elif [ -f "$top/scenes/cornell.pov" ]; then
  scene=$top/scenes/cornell.pov
else
  scene=$here/radiosity/cornell.pov
fi

# The rungs, cheapest first.  POV-Ray's: count and recursion_limit rise
# together, the rest of the scene's block (error_bound 0.2, pretrace down
# to 0.005, nearest_count 20, ...) is kept.
if [ $quick -eq 1 ]; then
  pov_ladder=${RADBENCH_POV_LADDER:-"50:2 100:3"}
  bf_ladder=${RADBENCH_BF_EPS:-"0.01 0.001"}
  uniform_ladder=${RADBENCH_UNIFORM:-"2 4"}
else
  pov_ladder=${RADBENCH_POV_LADDER:-"50:2 100:3 200:4 400:5 800:6 1600:8"}
  bf_ladder=${RADBENCH_BF_EPS:-"0.01 0.003 0.001 0.0003 0.0001 0.00003"}
  uniform_ladder=${RADBENCH_UNIFORM:-"2 4 8 16 32"}
fi

[ -x "$zrcube" ] || { echo "radiosity.sh: $zrcube is not built" >&2; exit 1; }
if [ ! -x "$imgcmp" ]; then
  # imgcmp is a check program: build it when `make check` has not.
  make -C "$build" tests/imgcmp >/dev/null ||
    { echo "radiosity.sh: cannot build $imgcmp" >&2; exit 1; }
fi
command -v "$povray" >/dev/null ||
  { echo "radiosity.sh: $povray not found" >&2; exit 1; }
command -v gnuplot >/dev/null ||
  echo "radiosity.sh: gnuplot not found, no charts" >&2
for f in "$scene" "$truth"; do
  [ -f "$f" ] || { echo "radiosity.sh: $f not found" >&2; exit 1; }
done
grep -q 'radiosity[ 	]*{' "$scene" ||
  { echo "radiosity.sh: $scene has no radiosity block" >&2; exit 1; }

work=$(mktemp -d "${TMPDIR:-/tmp}/zr-radbench.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM
mkdir -p "$out/radiosity"
tsv=$out/radiosity.tsv
printf '%s\t' method setting seconds rel_rmse elements links iterations \
  >"$tsv.tmp"
printf 'residual\n' >>"$tsv.tmp"

# Runs the command with the time limit when timeout(1) exists.
limited() {
  if command -v timeout >/dev/null 2>&1; then
    timeout "$limit" "$@"
  else
    "$@"
  fi
}

# Runs the command, its output in $work/log, and prints its wall-clock
# seconds, or "fail".
seconds() {
  start=$(date +%s.%N)
  if limited "$@" >"$work/log" 2>&1; then
    end=$(date +%s.%N)
    echo "$start $end" | awk '{ printf "%.2f\n", $2 - $1 }'
  else
    echo fail
  fi
}

# The relative RMSE of an image against the ground truth, or "fail"
# after imgcmp's message.
rel_rmse() {
  "$imgcmp" "$1" "$truth" --rmse 2>"$work/cmp.log" |
    sed -n 's/^rmse=//p' | grep . ||
    { sed 's/^/    /' "$work/cmp.log" >&2; echo fail; }
}

# The value of the last key=value word in the output of the last run,
# or "-".
stat() {
  awk -v key="$1=" '{
      for (i = 1; i <= NF; i++)
        if (index($i, key) == 1) v = substr($i, length(key) + 1)
    }
    END { print v == "" ? "-" : v }' "$work/log"
}

# Appends a row to the table and shows it as it comes.
row() {
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$@" >>"$tsv.tmp"
  printf '%-8s %-10s %9s %9s %9s %10s %6s %10s\n' "$@"
}

# The scene with its radiosity block replaced by the file $1 (an empty
# file removes it).  Braces are counted, so the block may span lines.
with_block() {
  awk -v block="$1" -f "$here/radiosity/with_block.awk" "$scene"
}

pov_render() { # name, scene file
  t=$(seconds "$povray" +I"$2" +O"$out/radiosity/$1.hdr" +FH +W$size \
      +H$size +A0.05 +R3 +WT1 -D -V)
  if [ "$t" = fail ]; then
    sed 's/^/    /' "$work/log" | tail -n 5 >&2
    echo "fail fail"
  else
    echo "$t $(rel_rmse "$out/radiosity/$1.hdr")"
  fi
}

echo "radiosity benchmark: $(basename "$scene"), ${size}x$size, +A0.05 +R3," \
  "one thread, against $(basename "$truth")"
echo "POV-Ray: $("$povray" --version 2>&1 | grep -m1 POV-Ray)"
printf '%-8s %-10s %9s %9s %9s %10s %6s %10s\n' method setting seconds \
  rel_rmse elements links iter residual

# POV-Ray without radiosity: the scale of "no indirect light at all".
: >"$work/empty.block"
with_block "$work/empty.block" >"$work/none.pov"
set -- $(pov_render none "$work/none.pov")
row none - "$1" "$2" - - - -

for rung in $pov_ladder; do
  count=${rung%%:*}
  depth=${rung#*:}
  cat >"$work/block" <<EOF
radiosity {
    pretrace_start 0.04 pretrace_end 0.005
    count $count nearest_count 20 error_bound 0.2 recursion_limit $depth
    low_error_factor 0.5 gray_threshold 0 minimum_reuse 0.005 brightness 1
    always_sample off
  }
EOF
  with_block "$work/block" >"$work/pov.pov"
  name=c${count}_r$depth
  set -- $(pov_render "pov_$name" "$work/pov.pov")
  row povray "$name" "$1" "$2" - - - -
  [ "$1" != fail ] || { echo "(the rest of the ladder skipped)"; break; }
done

# zRcube, when it has radiosity.
zr_render() { # name, options...
  name=$1
  shift
  # --bounces=all: the ground truth carries every bounce, and the
  # scene's recursion_limit 8 would stop the solve at 8 (as povray's
  # picture stops; relative RMSE 0.0421 where every bounce gives 0.0405).
  t=$(seconds "$zrcube" "$scene" +W$size +H$size +A0.05 +R3 +WT1 \
      --radiosity --radiosity-stats --bounces=all "$@" \
      +O"$out/radiosity/$name.pfm")
  if [ "$t" = fail ]; then
    sed 's/^/    /' "$work/log" | tail -n 5 >&2
    echo "fail fail - - - -"
  else
    echo "$t $(rel_rmse "$out/radiosity/$name.pfm") $(stat elements)" \
      "$(stat links) $(stat iterations) $(stat residual)"
  fi
}
if "$zrcube" --help 2>&1 | grep -q -- --radiosity; then
  for eps in $bf_ladder; do
    set -- $(zr_render "zr_bf_$eps" --bf-eps="$eps")
    row zr-bf "$eps" "$@"
    [ "$1" != fail ] || { echo "(the rest of the ladder skipped)"; break; }
  done
  for n in $uniform_ladder; do
    set -- $(zr_render "zr_unif_$n" --uniform="$n")
    row zr-unif "$n" "$@"
    [ "$1" != fail ] || { echo "(the rest of the ladder skipped)"; break; }
  done
else
  echo "zRcube radiosity not available yet"
fi
mv "$tsv.tmp" "$tsv"
echo "table: $tsv"
awk -f "$here/radiosity/summary.awk" "$tsv"

command -v gnuplot >/dev/null || exit 0
# The charts.  Failed rungs ("fail") and missing figures ("-") are skipped.
# gnuplot stops on a chart without a single point: count them first.
if ! awk -F '\t' 'NR > 1 && $3 + 0 > 0 && $4 + 0 > 0 { n++ }
                  END { exit !n }' "$tsv"; then
  echo "radiosity.sh: no rung succeeded, no charts" >&2
  exit 1
fi
has_zr=0
awk -F '\t' '$1 == "zr-bf" && $5 + 0 > 0 { n++ } END { exit !n }' "$tsv" &&
  has_zr=1
gnuplot -e "tsv='$tsv'; outdir='$out'; zr=$has_zr" \
  "$here/radiosity/charts.gp" ||
  { echo "radiosity.sh: gnuplot failed" >&2; exit 1; }
echo "charts: $out/radiosity-error-time.png"
[ $has_zr -eq 0 ] || echo "        $out/radiosity-elements.png"
exit 0
