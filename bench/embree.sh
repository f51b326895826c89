#!/bin/sh
# embree.sh - issue 13's Embree question, measured: zRcube's hierarchy
# against Embree 3 (Debian libembree-dev) on bench/peers.sh's terrain,
# the same camera and shadow rays, one thread (bench/embree_probe.c says
# what is timed and compared).
#
#   bench/embree.sh BUILD_DIR [SIZE...]   (default sizes: 512 2048)
#
# Then the sphereflake's spheres as Embree user geometry with our
# double-precision sphere test against zRcube's hierarchy, camera rays
# (bench/embree_spheres.c).
#
# Links the probe against BUILD_DIR's static library (its internal
# calls are hidden in the shared one).  Exits 77 when libembree-dev or
# python3 is missing.  Timings are printed, never asserted.
set -eu
[ $# -ge 1 ] || { echo "usage: bench/embree.sh BUILD_DIR [SIZE...]" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/.." && pwd)
build=$(cd "$1" && pwd)
shift
sizes=${*:-512 2048}
python=${PYTHON:-/usr/bin/python3}
[ -f /usr/include/embree3/rtcore.h ] ||
  { echo "embree.sh: apt-get install libembree-dev" >&2; exit 77; }
command -v "$python" >/dev/null 2>&1 || exit 77
[ -f "$build/lib/.libs/libzrcube.a" ] ||
  { echo "embree.sh: $build/lib/.libs/libzrcube.a is not built" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/zr-embree.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM
deps=$(sed -n "s/^dependency_libs='\(.*\)'/\1/p" "$build/lib/libzrcube.la")
# shellcheck disable=SC2086
${CC:-cc} -O2 -std=c11 -I"$top/lib" -I"$top/include" -I"$build" \
  "$here/embree_probe.c" "$build/lib/.libs/libzrcube.a" -lembree3 $deps \
  -lm -lpthread -o "$work/embree_probe"
# shellcheck disable=SC2086
${CC:-cc} -O2 -std=c11 -I"$top/lib" -I"$top/include" -I"$build" \
  "$here/embree_spheres.c" "$build/lib/.libs/libzrcube.a" -lembree3 $deps \
  -lm -lpthread -o "$work/embree_spheres"
"$python" "$here/peers_gen.py" "$work"
echo "host: $(uname -m), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
for size in $sizes; do
  "$work/embree_probe" "$work/terrain.pov" "$size"
  "$work/embree_spheres" "$work/flake.pov" "$size"
done
