#!/bin/sh
# ab.sh - one build of zRcube against another, scene by scene, in the
# same run: the time of each and whether the images are the same bytes.
#
#   bench/ab.sh OLD_ZRCUBE NEW_ZRCUBE [WIDTH HEIGHT]   (default 320 240)
#
# OLD_ZRCUBE and NEW_ZRCUBE are programs (a build's bin/zrcube, or a
# copy kept before a change).  Each scenes/NAME.pov is rendered by both
# as bench/run.sh renders it (one thread, no antialiasing), the two runs
# alternating, best of REPEAT (default 3) CPU times each; the table
# gives both times, their ratio new / old (below 1: the new is faster)
# and "same" or "DIFFER" for the PNG bytes, then the geometric mean of
# the ratios.  SCENES="a b" limits the run to those scenes.  Times have
# /usr/bin/time's 10 ms resolution: give small scenes a larger size.
# The exit status is 1 when some images differ.  Timings
# are printed, never asserted.
set -eu
if [ $# -lt 2 ]; then
  echo "usage: bench/ab.sh OLD_ZRCUBE NEW_ZRCUBE [WIDTH HEIGHT]" >&2
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/.." && pwd)
old=$1
new=$2
width=${3:-320}
height=${4:-240}
repeat=${REPEAT:-3}
work=$(mktemp -d "${TMPDIR:-/tmp}/zr-ab.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM

# CPU seconds (user + system) of the command, or "fail": on a shared
# machine they vary far less than wall-clock time, and a render on one
# thread uses one CPU.
seconds() {
  if /usr/bin/time -f '%U %S' -o "$work/time" "$@" >"$work/log" 2>&1; then
    tail -n 1 "$work/time" | awk '{ printf "%.3f\n", $1 + $2 }'
  else
    echo fail
  fi
}

min() { echo "$1 $2" | awk '{ print ($1 == "-" || $2 < $1) ? $2 : $1 }'; }

printf '%-16s %9s %9s %7s %s\n' scene old_s new_s ratio bytes
log_sum=0
count=0
differ=0
for scene in "$top"/scenes/*.pov; do
  name=$(basename "$scene" .pov)
  case $name in *.ref) continue ;; esac
  head -n 1 "$scene" | grep -q '^// golden: skip' && continue
  if [ -n "${SCENES:-}" ]; then
    case " $SCENES " in *" $name "*) ;; *) continue ;; esac
  fi
  to=- tn=-
  i=0
  while [ $i -lt "$repeat" ]; do
    t=$(seconds timeout 600 "$old" "$scene" +W"$width" +H"$height" -A \
        +WT1 +O"$work/$name.old.png" +L"$top/scenes")
    [ "$t" = fail ] && { to=fail; break; }
    to=$(min "$to" "$t")
    t=$(seconds timeout 600 "$new" "$scene" +W"$width" +H"$height" -A \
        +WT1 +O"$work/$name.new.png" +L"$top/scenes")
    [ "$t" = fail ] && { tn=fail; break; }
    tn=$(min "$tn" "$t")
    i=$((i + 1))
  done
  if [ "$to" = fail ] || [ "$tn" = fail ]; then
    printf '%-16s %9s %9s %7s %s\n' "$name" "$to" "$tn" - -
    differ=$((differ + 1))
    continue
  fi
  same=same
  cmp -s "$work/$name.old.png" "$work/$name.new.png" || {
    same=DIFFER
    differ=$((differ + 1))
  }
  ratio=$(echo "$tn $to" | awk '{ printf "%.3f", $1 / $2 }')
  printf '%-16s %9s %9s %7s %s\n' "$name" "$to" "$tn" "$ratio" "$same"
  log_sum=$(echo "$log_sum $tn $to" |
            awk '{ n = $2 > 0.001 ? $2 : 0.001
                   o = $3 > 0.001 ? $3 : 0.001
                   printf "%.6f", $1 + log(n / o) }')
  count=$((count + 1))
done
[ $count -gt 0 ] && echo "$log_sum $count" |
  awk '{ printf "geometric mean of new/old: %.3f over %d scenes\n",
         exp($1 / $2), $2 }'
[ $differ -eq 0 ]
