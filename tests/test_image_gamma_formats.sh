#!/bin/sh
# test_image_gamma_formats.sh - "gamma G" / "gamma srgb" after an
# image_map's file name decode a JPEG's, BMP's, PPM's and TIFF's samples
# as a PNG's (the manual's "The Gamma Option" example is a JPEG's gamma
# 1.8; "Gamma in Input Images": "This applies ... to all file formats
# without exception"), and a TIFF's samples are in the scene's working
# space as PPM's are (POV-Ray 3.7.0.10 measured; its manual presumes
# sRGB), under assumed_gamma 1 (cases 1-11) and 2.2 (21-31), against
# povray 3.7.0.10's pixels (16x8, -A +WT1; the middle of each 8 x 8
# block of tests/image_gamma_formats.pov's picture).  The tree before
# session 22 refused gamma for all but PNG, GIF and TGA (cases 2-6, 10,
# 22-26, 30 failed with an error) and showed a TIFF's code 60 as sRGB
# (cases 11, 31).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
cp "$srcdir/tests/image_gamma_formats.pov" . || exit 99
cp "$srcdir/tests/image_gamma.jpg" g.jpg || exit 99
# The same eight flat blocks as BMP (24 bit), PPM, TIFF (baseline,
# uncompressed) and PNG files, written by hand.
/usr/bin/python3 - <<'PY' || exit 99
import struct, zlib
cols = [(60, 60, 60), (128, 128, 128), (200, 200, 200), (255, 128, 0),
        (30, 90, 150), (0, 0, 0), (255, 255, 255), (100, 200, 50)]
w, h = 32, 16
rows = [[cols[(x // 8) + 4 * (y // 8)] for x in range(w)] for y in range(h)]
rgb = b"".join(bytes(c) for r in rows for c in r)
open("g.ppm", "wb").write(b"P6\n%d %d\n255\n" % (w, h) + rgb)
pix = b"".join(bytes((b, g, r)) for row in rows[::-1] for (r, g, b) in row)
dib = struct.pack("<IiiHHIIiiII", 40, w, h, 1, 24, 0, len(pix), 2835, 2835,
                  0, 0)
off = 14 + len(dib)
open("g.bmp", "wb").write(b"BM" + struct.pack("<IHHI", off + len(pix), 0, 0,
                                              off) + dib + pix)
def chunk(t, d):
    return (struct.pack(">I", len(d)) + t + d +
            struct.pack(">I", zlib.crc32(t + d) & 0xffffffff))
open("g.png", "wb").write(
    b"\x89PNG\r\n\x1a\n" +
    chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
    chunk(b"IDAT", zlib.compress(b"".join(
        b"\0" + rgb[3 * w * y:3 * w * (y + 1)] for y in range(h)))) +
    chunk(b"IEND", b""))
# TIFF: header, the pixels, then one IFD of 10 entries and the
# BitsPerSample values.
data_at = 8
ifd_at = data_at + len(rgb)
n = 10
bps_at = ifd_at + 2 + 12 * n + 4
def entry(tag, typ, count, value):
    return struct.pack("<HHII", tag, typ, count, value)
ifd = b"".join([
    entry(256, 4, 1, w), entry(257, 4, 1, h), entry(258, 3, 3, bps_at),
    entry(259, 3, 1, 1), entry(262, 3, 1, 2), entry(273, 4, 1, data_at),
    entry(277, 3, 1, 3), entry(278, 4, 1, h), entry(279, 4, 1, len(rgb)),
    entry(284, 3, 1, 1)])
open("g.tiff", "wb").write(b"II*\0" + struct.pack("<I", ifd_at) + rgb +
                           struct.pack("<H", n) + ifd + b"\0\0\0\0" +
                           struct.pack("<HHH", 8, 8, 8))
PY
pixel_w=16
pixel_h=8
recorded_1="60,60,60 128,128,128 200,200,200 255,127,0 30,90,150 0,0,0 255,255,255 100,200,50"
recorded_2="77,77,77 146,146,146 210,210,210 255,145,0 40,109,167 0,0,0 255,255,255 119,210,65"
recorded_3="60,60,60 128,128,128 200,200,200 255,127,0 30,90,150 0,0,0 255,255,255 100,200,50"
recorded_4="133,133,133 188,188,188 229,229,229 255,187,0 96,160,202 0,0,0 255,255,255 168,229,122"
recorded_5="77,77,77 146,146,146 210,210,210 255,146,0 40,109,167 0,0,0 255,255,255 119,210,65"
recorded_6="77,77,77 146,146,146 210,210,210 255,146,0 40,109,167 0,0,0 255,255,255 119,210,65"
recorded_7="133,133,133 188,188,188 229,229,229 255,188,0 96,160,202 0,0,0 255,255,255 168,229,122"
recorded_8="60,60,60 128,128,128 200,200,200 255,128,0 30,90,150 0,0,0 255,255,255 100,200,50"
recorded_9="77,77,77 146,146,146 210,210,210 255,146,0 40,109,167 0,0,0 255,255,255 119,210,65"
recorded_10="77,77,77 146,146,146 210,210,210 255,146,0 40,109,167 0,0,0 255,255,255 119,210,65"
recorded_11="133,133,133 188,188,188 229,229,229 255,188,0 96,160,202 0,0,0 255,255,255 168,229,122"
recorded_21="60,60,60 128,128,128 200,200,200 255,127,0 30,90,150 0,0,0 255,255,255 100,200,50"
recorded_22="77,77,77 146,146,146 210,210,210 255,145,0 40,109,167 0,0,0 255,255,255 119,210,65"
recorded_23="60,60,60 128,128,128 200,200,200 255,127,0 30,90,150 0,0,0 255,255,255 100,200,50"
recorded_24="133,133,133 188,188,188 229,229,229 255,187,0 96,160,202 0,0,0 255,255,255 168,229,122"
recorded_25="77,77,77 146,146,146 210,210,210 255,146,0 40,109,167 0,0,0 255,255,255 119,210,65"
recorded_26="77,77,77 146,146,146 210,210,210 255,146,0 40,109,167 0,0,0 255,255,255 119,210,65"
recorded_27="57,57,57 129,129,129 201,201,201 255,129,0 24,90,151 0,0,0 255,255,255 100,201,46"
recorded_28="60,60,60 128,128,128 200,200,200 255,128,0 30,90,150 0,0,0 255,255,255 100,200,50"
recorded_29="77,77,77 146,146,146 210,210,210 255,146,0 40,109,167 0,0,0 255,255,255 119,210,65"
recorded_30="77,77,77 146,146,146 210,210,210 255,146,0 40,109,167 0,0,0 255,255,255 119,210,65"
recorded_31="57,57,57 129,129,129 201,201,201 255,129,0 24,90,151 0,0,0 255,255,255 100,201,46"
pixel_cases image_gamma_formats.pov K \
  "1 2 3 4 5 6 7 8 9 10 11 21 22 23 24 25 26 27 28 29 30 31" \
  "2,2 2,6 2,10 2,14 6,2 6,6 6,10 6,14"
status=$?
# Float pictures have no samples to decode: a located error.
printf '#version 3.7;\nplane { z, 0 pigment { image_map { hdr "x.hdr" gamma 2 } } }\n' >float.pov
/usr/bin/python3 -c '
import sys
sys.stdout.buffer.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n" + bytes((128, 128, 128, 129)))' >x.hdr
if "$zrcube" +Ifloat.pov +W8 +H8 -D +Ofloat.png 2>float.err; then
  echo "FAIL: gamma on a Radiance HDR file was accepted"; status=1
elif ! grep -q 'float.pov:2:54: error: image_map gamma is for files of stored samples' float.err; then
  echo "FAIL: no located error for gamma on a float file"; cat float.err; status=1
fi
exit $status
