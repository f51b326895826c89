#!/bin/sh
# png_level.sh - what the PNG compression level costs (issue 13).
#
#   bench/png_level.sh BUILD_DIR [SCENE [SIZE]]
#
# Renders SCENE (default scenes/default.pov) once at SIZE x SIZE (default
# 512), one thread, no antialiasing, then writes it at every zlib level
# 0 to 9 (`--png-level`), REPEAT times each (default 3), and prints the
# best write time zrcube's +V statistics report, that time as a share of
# the render, and the file's size.  The default level (include/zrcube.h,
# ZR_DEFAULT_PNG_LEVEL) was chosen from this table: the smallest level
# whose write costs under 10% of a small render.  Timings are printed,
# never asserted.
set -eu
if [ $# -lt 1 ]; then
  echo "usage: bench/png_level.sh BUILD_DIR [SCENE [SIZE]]" >&2
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$1" && pwd)
scene=$(cd "$(dirname "${2:-$here/../scenes/default.pov}")" && pwd)/$(basename "${2:-default.pov}")
size=${3:-512}
repeat=${REPEAT:-3}
. "$here/zrexe.sh"
work=$(mktemp -d "${TMPDIR:-/tmp}/zr-png.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM
cd "$(dirname "$scene")"
echo "$(basename "$scene") at ${size}x$size, one thread, best of $repeat"
printf '%5s %9s %9s %8s %9s\n' level write_s render_s share bytes
for level in 0 1 2 3 4 5 6 7 8 9; do
  best=
  render=
  i=0
  while [ "$i" -lt "$repeat" ]; do
    "$zrcube" "$scene" "+W$size" "+H$size" -A +WT1 +V \
      "--png-level=$level" "+O$work/out.png" 2>"$work/log"
    line=$(grep 'time: parse' "$work/log")
    w=$(echo "$line" | sed 's/.*write \([0-9.]*\) s.*/\1/')
    r=$(echo "$line" | sed 's/.*render \([0-9.]*\) s.*/\1/')
    if [ -z "$best" ] || [ "$(echo "$w $best" | awk '{ print ($1 < $2) }')" = 1 ]
    then
      best=$w
      render=$r
    fi
    i=$((i + 1))
  done
  printf '%5s %9s %9s %7s%% %9s\n' "$level" "$best" "$render" \
    "$(echo "$best $render" | awk '{ printf "%.1f", 100 * $1 / $2 }')" \
    "$(wc -c <"$work/out.png")"
done
