#!/bin/sh
# fuzz.sh - runs the libFuzzer targets (tests/fuzz) one after the other,
# each for SECONDS (default 600), and appends one line per run to
# bench/results/fuzz-<date>.txt: target, seconds, executions, result
# (clean, or the kind of failure libFuzzer reported and the input it
# saved) and the slowest unit.
#
#   bench/fuzz.sh BUILD_DIR [SECONDS [TARGET...]]
#
# BUILD_DIR was configured with `../configure --enable-fuzz CC=clang` and
# has built tests/fuzz/fuzz_parse and tests/fuzz/fuzz_image.  The runs
# are niced: the machine is shared.  A failing input is left in
# BUILD_DIR/fuzz-out/<target>/ (crash-*, leak-*, timeout-*, oom-*); once
# fixed it belongs in tests/fuzz/regress or tests/fuzz/regress-image,
# which every `make check` replays.
set -u
build=$(cd "${1:?usage: bench/fuzz.sh BUILD_DIR [SECONDS]}" && pwd) || exit 1
seconds=${2:-600}
# A unit slower than this (wall clock) is reported as a timeout.  Sixty
# seconds, not libFuzzer's ten: on this shared machine (load 10-20 on 2
# cores) a sanitized unit of 4 s of CPU took 52 s of wall clock.
timeout=${ZR_FUZZ_TIMEOUT:-60}
src=$(cd "$(dirname "$0")/.." && pwd)
out=$src/bench/results/fuzz-$(date -u +%Y-%m-%d).txt
[ -s "$out" ] || printf '# target\tseconds\texecs\tresult\n' > "$out"
shift $(( $# < 2 ? $# : 2 ))
targets=${*:-fuzz_image fuzz_parse}
for target in $targets; do
  bin=$build/tests/fuzz/$target
  [ -x "$bin" ] || { echo "fuzz.sh: no $bin" >&2; exit 1; }
  dir=$build/fuzz-out/$target
  mkdir -p "$dir/corpus"
  case $target in
    fuzz_image) seeds="$src/tests/fuzz/image-seeds $src/tests/fuzz/regress-image"
                dict= ;;
    *) seeds="$src/scenes $src/tests/fuzz/regress"
       dict=-dict=$src/tests/fuzz/pov.dict ;;
  esac
  log=$dir/run.log
  start=$(date +%s)
  # shellcheck disable=SC2086 # $seeds and $dict are lists of words
  (cd "$dir" && nice -n 10 "$bin" -max_total_time="$seconds" \
     -max_len=4096 -timeout="$timeout" -rss_limit_mb=2048 -print_final_stats=1 \
     $dict corpus $seeds) >"$log" 2>&1
  status=$?
  took=$(( $(date +%s) - start ))
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  if [ "$status" -eq 0 ]; then
    result=clean
  else
    result="status $status: $(grep -m 1 -o -e 'ERROR: [A-Za-z]*: [a-z-]*' \
      -e 'ERROR: libFuzzer: [a-z-]*' "$log" | head -n 1); input $(ls "$dir" |
      grep -e '^crash-' -e '^leak-' -e '^timeout-' -e '^oom-' | head -n 1)"
  fi
  slowest=$(sed -n 's/^stat::slowest_unit_time_sec: *//p' "$log" | tail -n 1)
  result="$result; slowest unit ${slowest:-?} s"
  printf '%s\t%s\t%s\t%s\n' "$target" "$took" "${execs:-?}" "$result" |
    tee -a "$out"
done
