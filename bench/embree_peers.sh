#!/bin/sh
# embree_peers.sh - issue 13's Embree backend in whole runs: zRcube with
# --accel=builtin and with --accel=embree against Tachyon 0.99 and
# POV-Ray 3.7 on bench/peers.sh's scenes (bench/peers_gen.py), side by
# side in one run, one thread, no antialiasing.
#
#   bench/embree_peers.sh BUILD_DIR      (BUILD_DIR configured --with-embree)
#
# Environment: SIZES (default "512 2048"), SCENES (default "terrain
# flake"), REPEAT (default 3).  Each figure is the CPU time (user + sys
# from /usr/bin/time) of the whole process, the best of REPEAT runs,
# taken round-robin (builtin, embree, Tachyon, POV-Ray, then again) so
# a change of the machine's load falls on all four alike.  Also printed:
# SSIM (bench/conform/ssim.py) of the Embree picture against the
# built-in one, and zRcube's own parse time from +V for both.  POV-Ray
# is skipped at 2048 unless POV2048=1 (it takes minutes there).
# Timings are printed, never asserted.
set -eu
[ $# -ge 1 ] || { echo "usage: bench/embree_peers.sh BUILD_DIR" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$1" && pwd)
sizes=${SIZES:-512 2048}
scenes=${SCENES:-terrain flake}
repeat=${REPEAT:-3}
python=${PYTHON:-/usr/bin/python3}
. "$here/zrexe.sh"
for tool in "$python" /usr/bin/time tachyon povray; do
  command -v "$tool" >/dev/null 2>&1 || { echo "embree_peers.sh: no $tool" >&2; exit 77; }
done
work=$(mktemp -d "${TMPDIR:-/tmp}/zr-embree-peers.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM
"$python" "$here/peers_gen.py" "$work"
cd "$work"
"$zrcube" +Iterrain.pov +W8 +H8 -A --accel=embree -D +Oprobe.png \
  >/dev/null 2>&1 || { echo "embree_peers.sh: $zrcube has no Embree" >&2; exit 77; }

# CPU seconds of one run of "$@", or "fail"; its output in $tag.log.
cpu() {
  tag=$1
  shift
  if /usr/bin/time -f '%U %S' -o "$tag.cpu" "$@" >"$tag.out" 2>&1; then
    awk '{ printf "%.2f\n", $1 + $2 }' "$tag.cpu"
  else
    echo fail
  fi
}

best() { # best of the list of figures
  echo "$@" | tr ' ' '\n' | awk '$1 != "fail" && (b == "" || $1 < b) { b = $1 }
                                 END { print (b == "" ? "fail" : b) }'
}

parse_s() {
  awk '/time: parse/ { for (i = 1; i <= NF; i++) if ($i == "parse") print $(i + 1) }' "$1"
}

echo "zRcube builtin vs embree ($zrcube) vs Tachyon vs POV-Ray: CPU s (user+sys), one thread, no AA, best of $repeat"
echo "host: $(uname -m), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-8s %5s %8s %8s %8s %8s %7s %7s %7s %8s %8s %7s\n' scene size \
  builtin embree tachyon povray emb/bi emb/ta emb/pov parse_bi parse_em ssim
for size in $sizes; do
  for scene in $scenes; do
    tb= te= tt= tp=
    i=0
    while [ "$i" -lt "$repeat" ]; do
      tb="$tb $(cpu b "$zrcube" "+I$scene.pov" +Ob.png "+W$size" "+H$size" -A +WT1 +V -D --accel=builtin)"
      cp b.out b.log
      te="$te $(cpu e "$zrcube" "+I$scene.pov" +Oe.png "+W$size" "+H$size" -A +WT1 +V -D --accel=embree)"
      cp e.out e.log
      tt="$tt $(cpu t tachyon "$scene.dat" -res "$size" "$size" -numthreads 1 -format TARGA -o t.tga)"
      if [ "$size" -le 1024 ] || [ "${POV2048:-0}" = 1 ]; then
        tp="$tp $(cpu p povray "+I$scene.pov" +Op.png "+W$size" "+H$size" -A +WT1 -D)"
      else
        tp="$tp -"
      fi
      i=$((i + 1))
    done
    b=$(best $tb); e=$(best $te); t=$(best $tt)
    case $tp in *-*) p=- ;; *) p=$(best $tp) ;; esac
    r() { echo "$1 $2" | awk '{ if ($1 == "fail" || $2 == "fail" || $2 == "-" || $2 <= 0) print "-"; else printf "%.2f", $1 / $2 }'; }
    ssim=$("$python" "$here/conform/ssim.py" e.png b.png 2>/dev/null | awk '{ print $NF }' || echo -)
    printf '%-8s %5s %8s %8s %8s %8s %7s %7s %7s %8s %8s %7s\n' "$scene" "$size" \
      "$b" "$e" "$t" "$p" "$(r "$e" "$b")" "$(r "$e" "$t")" "$(r "$e" "$p")" \
      "$(parse_s b.log)" "$(parse_s e.log)" "$ssim"
    if cmp -s b.png e.png; then echo "         ($scene $size: the same image bytes)"; fi
  done
done
