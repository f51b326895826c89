#!/bin/sh
# test_image_pattern.sh - image_pattern { } ("Image Pattern"): a
# picture's grey as the value of a pigment's, a texture's and a normal's
# pattern (tests/image_pattern.pov, cases 1-6: the file's numbers as they
# are, gamma 2.2, interpolate 2, once, a texture_map, a normal), against
# povray 3.7.0.10's pixels (16x12, -A +WT1 -GA; rows 1, 5, 9 and columns
# 1, 5, 9, 13: the middle of each of the picture's 4 x 3 pixels).  The
# tree before this test stopped at 'image_pattern is not supported yet'.
# Bad input: a gamma of 0 and a missing file get a message
# with file, line and column and a non-zero exit.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
cp "$srcdir/tests/image_pattern.pov" . || exit 99
# The picture: 4 x 3 RGB pixels, no gamma chunk (a PNG by hand, zlib).
/usr/bin/python3 - <<'PY' || exit 99
import struct, zlib
rows = [[(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 255)],
        [(40, 80, 120), (200, 100, 50), (10, 10, 10), (128, 128, 128)],
        [(255, 255, 0), (0, 255, 255), (255, 0, 255), (60, 60, 60)]]
raw = b"".join(b"\0" + bytes(v for px in r for v in px) for r in rows)
def chunk(t, d):
    return (struct.pack(">I", len(d)) + t + d +
            struct.pack(">I", zlib.crc32(t + d) & 0xffffffff))
open("image_pattern.png", "wb").write(
    b"\x89PNG\r\n\x1a\n" +
    chunk(b"IHDR", struct.pack(">IIBBBBB", 4, 3, 8, 2, 0, 0, 0)) +
    chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
PY
recorded_1="1,1=148,148,148 1,5=202,202,202 1,9=95,95,95 1,13=255,255,255 5,1=145,145,145 5,5=185,185,185 5,9=56,56,56 5,13=188,188,188 9,1=242,242,242 9,5=218,218,218 9,9=172,172,172 9,13=133,133,133"
recorded_2="1,1=148,148,148 1,5=202,202,202 1,9=95,95,95 1,13=255,255,255 5,1=76,76,76 5,5=138,138,138 5,9=3,3,3 5,13=129,129,129 9,1=242,242,242 9,5=218,218,218 9,9=172,172,172 9,13=57,57,57"
recorded_3="1,1=177,177,177 1,5=199,199,199 1,9=126,126,126 1,13=232,232,232 5,1=154,154,154 5,5=183,183,183 5,9=91,91,91 5,13=187,187,187 9,1=224,224,224 9,5=217,217,217 9,9=170,170,170 9,13=144,144,144"
recorded_4="1,1=0,0,0 1,5=0,0,0 1,9=0,0,0 1,13=0,0,0 5,1=0,0,0 5,5=0,0,0 5,9=0,0,0 5,13=0,0,0 9,1=145,145,145 9,5=56,56,56 9,9=0,0,0 9,13=0,0,0"
recorded_5="1,1=218,0,148 1,5=172,0,202 1,9=242,0,95 1,13=0,0,255 5,1=220,0,145 5,5=190,0,185 5,9=251,0,56 5,13=187,0,188 9,1=95,0,242 9,5=148,0,218 9,9=202,0,172 9,13=227,0,133"
recorded_6="1,1=231,231,231 1,5=246,246,246 1,9=231,231,231 1,13=246,246,246 5,1=214,214,214 5,5=224,224,224 5,9=214,214,214 5,13=224,224,224 9,1=222,222,222 9,5=232,232,232 9,9=222,222,222 9,13=232,232,232"
fail=0
pixel_cases image_pattern.pov K "1 2 3 4 5 6" || fail=1
# bad_case NAME TEXT MESSAGE: a scene whose image_pattern holds TEXT must
# fail with MESSAGE at bad.pov:2:COLUMN.
bad_case() {
  printf 'camera { location -z look_at 0 }\nplane { z, 0 pigment { image_pattern { %s } } }\n' \
    "$2" >bad.pov
  if "$zrcube" +Ibad.pov +Obad.png +W8 +H6 -D >bad.log 2>&1; then
    echo "$1: rendered FAIL"; fail=1
  elif ! grep -q "^bad.pov:2:[0-9]*: error: .*$3" bad.log; then
    echo "$1: no located message FAIL"; cat bad.log; fail=1
  else
    echo "$1: $(grep error bad.log | head -n 1) ok"
  fi
}
bad_case gamma_zero 'png "image_pattern.png" gamma 0' "gamma"
bad_case missing 'png "no_such.png"' "not found"
[ -e bad.png ] && { echo "a failed render wrote bad.png FAIL"; fail=1; }
exit $fail
