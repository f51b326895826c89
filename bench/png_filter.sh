#!/bin/sh
# png_filter.sh - which PNG row filter and zlib strategy zRcube writes
# with (issue 13; lib/image/png.c cites this table).
#
#   bench/png_filter.sh BUILD_DIR [SIZE]
#
# Renders bench/peers_gen.py's sphereflake, terrain and CSG scenes and
# three textured stock scenes (advanced/woodbox, advanced/landscape,
# textures/patterns/granite) at SIZE x SIZE (default 512), one thread,
# no antialiasing, then rewrites each picture in memory with
# bench/png_filter.c at zlib levels 1, 2, 3, 6 and 9: libpng's adaptive
# filter ("all", its default), each single filter, and zlib's default,
# filtered and RLE strategies, best CPU time of REPEAT writes (default
# 5).  t/all and B/all are the time and size against the adaptive
# filter's at the same level.  Timings are printed, never asserted.
set -eu
[ $# -ge 1 ] || { echo "usage: bench/png_filter.sh BUILD_DIR [SIZE]" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$1" && pwd)
size=${2:-512}
repeat=${REPEAT:-5}
python=${PYTHON:-/usr/bin/python3}
stock=${POV_SCENES:-/usr/share/povray-3.7/scenes}
. "$here/zrexe.sh"
work=$(mktemp -d "${TMPDIR:-/tmp}/zr-pngf.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM
${CC:-cc} -O2 -std=c11 "$here/png_filter.c" -o "$work/png_filter" \
  $(pkg-config --cflags --libs libpng) -lz
"$python" "$here/peers_gen.py" "$work"
files=
render() { # DIR SCENE NAME
  (cd "$1" && "$zrcube" "$2" "+W$size" "+H$size" -A +WT1 \
     "+O$work/$3.png" >/dev/null 2>&1) &&
    files="$files $work/$3.png" ||
    echo "png_filter.sh: $2 did not render; left out" >&2
}
render "$work" flake.pov flake
render "$work" terrain.pov terrain
render "$work" csg.pov csg
render "$stock/advanced" woodbox.pov woodbox
render "$stock/advanced" landscape.pov landscape
render "$stock/textures/patterns" granite.pov granite
echo "PNG rewrites of ${size}x$size renders, best of $repeat, load $(cut -d' ' -f1-3 /proc/loadavg)"
# shellcheck disable=SC2086
"$work/png_filter" "$repeat" 1,2,3,6,9 $files
