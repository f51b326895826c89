#!/bin/sh
# gi_cpu_ab.sh OLD_BUILD NEW_BUILD [ROUNDS] [SCENE...] - CPU seconds
# (user+sys) of stock radiosity scenes at 160x120, one thread, -D, no AA,
# for two zRcube builds and povray 3.7 (-A +WT1), interleaved (each round
# runs old, new, povray on every scene), best of ROUNDS (3).  RT=1 runs
# each under chrt -r 20 (root).  Prints scene, the three bests, new/old
# and new/povray, and the load average at the end.
set -u
old=$(cd "$1" && pwd); new=$(cd "$2" && pwd); rounds=${3:-3}
shift 2; [ $# -gt 0 ] && shift
scenes=${*:-"advanced/blocks/stackerday.pov advanced/blocks/stackernight.pov
  radiosity/patio-radio_36.pov radiosity/patio-radio_37.pov
  advanced/balcony/balcony.pov radiosity/radiosity_36.pov"}
ex=/usr/share/doc/povray/examples
inc=/usr/share/povray-3.7/include
rt=""; [ "${RT:-0}" = 1 ] && rt="chrt -r 20"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/gi_cpu.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
cpu() { # cpu LOG: user+sys from /usr/bin/time -f '%U %S'
  tail -n 1 "$1" | awk '{ printf "%.3f", $1 + $2 }'
}
run() { # run WHO SCENE
  dir=$ex/$(dirname "$2")
  case $1 in
  povray) ( cd "$dir" && $rt /usr/bin/time -f '%U %S' -o "$tmp/t" povray \
      +I"$ex/$2" +O"$tmp/p.png" +W160 +H120 -D -A +WT1 -GA +L"$inc" \
      +L"$dir" >/dev/null 2>&1 ) ;;
  *) ( cd "$dir" && LD_LIBRARY_PATH=$1/lib/.libs $rt /usr/bin/time \
      -f '%U %S' -o "$tmp/t" "$1/bin/.libs/zrcube" +I"$ex/$2" \
      +O"$tmp/z.png" +W160 +H120 -D +WT1 +L"$inc" +L"$dir" \
      >/dev/null 2>&1 ) ;;
  esac
  cpu "$tmp/t"
}
printf '# scene\told_cpu\tnew_cpu\tpovray_cpu\tnew/old\tnew/povray\n'
for s in $scenes; do
  bo=999; bn=999; bp=999
  r=0
  while [ $r -lt "$rounds" ]; do
    o=$(run "$old" "$s"); n=$(run "$new" "$s"); p=$(run povray "$s")
    bo=$(echo "$bo $o" | awk '{ print ($2 < $1) ? $2 : $1 }')
    bn=$(echo "$bn $n" | awk '{ print ($2 < $1) ? $2 : $1 }')
    bp=$(echo "$bp $p" | awk '{ print ($2 < $1) ? $2 : $1 }')
    r=$((r + 1))
  done
  echo "$s $bo $bn $bp" | awk '{ printf "%s\t%.2f\t%.2f\t%.2f\t%.3f\t%.3f\n",
    $1, $2, $3, $4, $3 / $2, $3 / $4 }'
done
echo "# load: $(cat /proc/loadavg)"
