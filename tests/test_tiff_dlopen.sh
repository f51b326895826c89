#!/bin/sh
# test_tiff_dlopen.sh - libtiff is opened when a TIFF is read, not
# linked (lib/image/tiff.c, issue 13: loading it and its 8 libraries
# cost every process ~5 ms of CPU):
#   - libzrcube's shared object does not name libtiff among the
#     libraries it needs (objdump -p or readelf -d; skipped without
#     either, or in a build without a shared library);
#   - zrcube, which then starts without libtiff, still reads a TIFF
#     image map (tests/fuzz/image-seeds/rgb.tif: 2x1, pure red and pure
#     green, so the picture's mean is 1/3 and its max 1) seen whole by
#     an orthographic camera with ambient light only.
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
fail() { echo "FAIL: $*" >&2; exit 1; }

so=$(ls "$builddir"/lib/.libs/libzrcube.so.* 2>/dev/null | head -1)
if [ -n "$so" ]; then
  if command -v objdump >/dev/null 2>&1; then
    needed=$(objdump -p "$so" | awk '$1 == "NEEDED" { print $2 }')
  elif command -v readelf >/dev/null 2>&1; then
    needed=$(readelf -d "$so" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
  else
    needed=unknown
  fi
  if [ "$needed" != unknown ]; then
    [ -n "$needed" ] || fail "no NEEDED entries read from $so"
    echo "$needed" | grep -q '^libtiff' &&
      fail "$so is linked with libtiff: $(echo $needed)"
    echo "libzrcube needs: $(echo $needed)"
  fi
fi

cp "$srcdir/tests/fuzz/image-seeds/rgb.tif" rgb.tif || exit 99
cat > tiff.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0.5, 0.5, -1> right x up y direction z
  look_at <0.5, 0.5, 0> }
plane { z, 0 pigment { image_map { tiff "rgb.tif" interpolate 0 } }
  finish { ambient 1 diffuse 0 } }
POV
timeout 60 "$zrcube" +Itiff.pov +Otiff.png +W16 +H12 -D +WT1 -A \
  </dev/null >tiff.log 2>&1 || { cat tiff.log >&2; fail "the TIFF map"; }
info=$("$imgcmp" --info tiff.png) || fail "no picture written"
echo "$info"
echo "$info" | grep -q ' mean=0\.3333[0-9]* ' || fail "mean is not 1/3"
echo "$info" | grep -q ' max=1\.0000' || fail "max is not 1"
echo "PASS: libtiff opened at run time; the TIFF map read"
