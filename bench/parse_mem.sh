#!/bin/sh
# parse_mem.sh - parse time and memory per primitive against Tachyon's
# .dat reader on the same data (issue 13: "memory per triangle and per
# sphere stated and within 1.5x of Tachyon's"; parse within 1.5x).
#
#   bench/parse_mem.sh BUILD_DIR [OTHER_BUILD_DIR]
#
# Makes the scenes of bench/peers.sh (bench/peers_gen.py: flake = 7,381
# spheres and a plane, terrain = 130,050 triangles in one mesh, empty =
# camera and lights) in both formats and runs each renderer on them at
# 1x1 pixels, one thread: zRcube `+W1 +H1 -A +WT1 -D` (start-up, read,
# lex, parse, BVH build; its real binary, not the libtool wrapper) and
# `tachyon -res 1 1 -numthreads 1` (start-up, parse, preprocessing).
# Each run is measured by /usr/bin/time -f '%U %S %M': CPU seconds (user
# + system) and the peak resident set in KiB.  The renderers alternate
# (interleaved), REPEAT times (default 5), and the best CPU and the
# least peak of each are kept.  Bytes per primitive are the peak above
# the empty scene's over the primitive count (the flake's plane is
# counted with its spheres, 7,382).  With OTHER_BUILD_DIR, that build's
# zRcube is run too, interleaved with the rest (before/after figures).
# Figures are printed, never asserted.
set -eu
if [ $# -lt 1 ]; then
  echo "usage: bench/parse_mem.sh BUILD_DIR [OTHER_BUILD_DIR]" >&2
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
repeat=${REPEAT:-5}
tachyon=${TACHYON:-tachyon}
python=${PYTHON:-/usr/bin/python3}
command -v "$tachyon" >/dev/null 2>&1 && [ -x /usr/bin/time ] || {
  echo "parse_mem.sh: needs tachyon and /usr/bin/time (apt-get install" \
       "tachyon time)" >&2
  exit 77
}
# The real program of a build directory and its library path.
real_zrcube() {
  if [ -x "$1/bin/.libs/zrcube" ]; then
    echo "$1/bin/.libs/zrcube $1/lib/.libs"
  else
    echo "$1/bin/zrcube -"
  fi
}
builds="$(cd "$1" && pwd)"
[ $# -ge 2 ] && builds="$builds $(cd "$2" && pwd)"

work=$(mktemp -d "${TMPDIR:-/tmp}/zr-parsemem.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM
"$python" "$here/peers_gen.py" "$work" >/dev/null
cd "$work"

# run NAME SCENE CMD...: one measured run, appended to NAME.SCENE.
run() {
  name=$1 scene=$2
  shift 2
  /usr/bin/time -f '%U %S %M' -o t.out "$@" >/dev/null 2>&1 || true
  tail -n 1 t.out >>"$name.$scene"
}
for i in $(seq "$repeat"); do
  for scene in empty flake terrain; do
    k=0
    for b in $builds; do
      set -- $(real_zrcube "$b")
      exe=$1 lib=$2
      [ "$lib" = - ] && lib=
      LD_LIBRARY_PATH=$lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH} \
        run "zr$k" "$scene" "$exe" "+I$scene.pov" +Oz.png +W1 +H1 -A \
        +WT1 -D
      k=$((k + 1))
    done
    run tachyon "$scene" "$tachyon" "$scene.dat" -res 1 1 -numthreads 1 \
      -format TARGA -o t.tga
  done
done

# best NAME SCENE: "cpu kib", the least of each.
best() {
  awk '{ c = $1 + $2; if (n++ == 0 || c < bc) bc = c;
         if (n == 1 || $3 < bm) bm = $3 }
       END { printf "%.2f %d", bc, bm }' "$1.$2"
}
echo "parse at 1x1, one thread, best of $repeat interleaved;" \
  "load $(cut -d' ' -f1-3 /proc/loadavg)"
k=0
names=
for b in $builds; do
  echo "zr$k = $b"
  names="$names zr$k"
  k=$((k + 1))
done
names="$names tachyon"
printf '%-8s %-8s %8s %10s %10s\n' renderer scene cpu_s peak_KiB B/prim
for name in $names; do
  set -- $(best "$name" empty)
  empty_kib=$2
  printf '%-8s %-8s %8s %10s %10s\n' "$name" empty "$1" "$2" -
  for scene in flake terrain; do
    case $scene in flake) count=7382 ;; terrain) count=130050 ;; esac
    set -- $(best "$name" "$scene")
    printf '%-8s %-8s %8s %10s %10s\n' "$name" "$scene" "$1" "$2" \
      "$(awk -v m="$2" -v e="$empty_kib" -v n=$count \
           'BEGIN { printf "%.0f", (m - e) * 1024 / n }')"
  done
done
