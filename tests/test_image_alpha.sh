#!/bin/sh
# test_image_alpha.sh - an image_map's alpha is its transmittance (the
# manual's "Using the Alpha Channel"): a PNG's alpha channel (8 and 16
# bit) and a palette's tRNS chunk, with "transmit all" (which POV-Ray
# 3.7 adds to 1 - alpha, unclamped), "filter all", interpolation and a
# palette entry's own transmit (tests/image_alpha.pov, cases 1-9),
# against povray 3.7.0.10's pixels (16x8, -A +WT1 -GA; rows 1 and 5,
# columns 1, 5, 9, 13: the middle of each of the picture's 4 x 2
# pixels, in front of a green plane).  The tree before this test dropped
# alpha when it read a PNG: cases 1-8 failed (the picture opaque).
# Cases 10-12: image_pattern's use_alpha, whose value is 1 - alpha
# (povray's grey 0 where opaque, 255 where clear).  Cases 13-17: 32-bit
# TGA and BMP files, whose fourth byte povray reads as straight alpha;
# 18-19 TIFF RGBA.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
cp "$srcdir/tests/image_alpha.pov" . || exit 99
# The pictures, PNGs by hand (zlib): RGBA 8 bit, a palette with tRNS,
# grey + alpha 16 bit.
/usr/bin/python3 - <<'PY' || exit 99
import struct, zlib
def chunk(t, d):
    return (struct.pack(">I", len(d)) + t + d +
            struct.pack(">I", zlib.crc32(t + d) & 0xffffffff))
def png(name, w, h, ctype, depth, raw, extra=b""):
    open(name, "wb").write(
        b"\x89PNG\r\n\x1a\n" +
        chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, ctype, 0, 0, 0)) +
        extra + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
rgba = [[(255, 0, 0, 255), (0, 255, 0, 128), (0, 0, 255, 0), (255, 255, 255, 64)],
        [(255, 255, 0, 200), (0, 255, 255, 30), (255, 0, 255, 255), (60, 60, 60, 128)]]
png("alpha.png", 4, 2, 6, 8,
    b"".join(b"\0" + bytes(v for px in r for v in px) for r in rgba))
pal = bytes([255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255])
png("palette.png", 4, 2, 3, 8,
    b"".join(b"\0" + bytes(r) for r in [[0, 1, 2, 3], [3, 2, 1, 0]]),
    chunk(b"PLTE", pal) + chunk(b"tRNS", bytes([255, 100, 0])))
ga = [[(0, 65535), (30000, 40000), (65535, 0), (50000, 65535)],
      [(10000, 20000), (65535, 65535), (0, 0), (40000, 30000)]]
png("grey16.png", 4, 2, 4, 16,
    b"".join(b"\0" + b"".join(struct.pack(">HH", *px) for px in r) for r in ga))
# The same RGBA pixels as 32-bit TGA and BMP files (rows bottom up,
# blue, green, red, alpha); the TGA's descriptor says 8 alpha bits, the
# second one's says none (povray reads the byte as alpha all the same).
# Then all-clear ones: every alpha byte 0.
def tga(name, desc, px):
    hdr = struct.pack("<BBBHHBHHHHBB", 0, 0, 2, 0, 0, 0, 0, 0, 4, 2, 32, desc)
    open(name, "wb").write(hdr + bytes(v for r in px[::-1]
                                       for (R, G, B, A) in r
                                       for v in (B, G, R, A)))
def bmp(name, px):
    pix = bytes(v for r in px[::-1] for (R, G, B, A) in r for v in (B, G, R, A))
    dib = struct.pack("<IiiHHIIiiII", 40, 4, 2, 1, 32, 0, len(pix), 2835,
                      2835, 0, 0)
    off = 14 + len(dib)
    open(name, "wb").write(b"BM" + struct.pack("<IHHI", off + len(pix), 0, 0,
                                               off) + dib + pix)
tga("alpha.tga", 8, rgba)
tga("noattr.tga", 0, rgba)
bmp("alpha.bmp", rgba)
clear = [[(R, G, B, 0) for (R, G, B, A) in r] for r in rgba]
tga("clear.tga", 0, clear)
bmp("clear.bmp", clear)
# TIFF RGBA, baseline and uncompressed: ExtraSamples 2 (unassociated
# alpha) with the straight colours, ExtraSamples 1 (associated) with
# the colours multiplied by alpha.
def tiff(name, extra, px):
    data = bytes(v for r in px for c in r for v in c)
    ifd_at = 8 + len(data)
    n = 11
    bps_at = ifd_at + 2 + 12 * n + 4
    def e(tag, typ, count, value):
        return struct.pack("<HHII", tag, typ, count, value)
    ifd = b"".join([
        e(256, 4, 1, 4), e(257, 4, 1, 2), e(258, 3, 4, bps_at),
        e(259, 3, 1, 1), e(262, 3, 1, 2), e(273, 4, 1, 8), e(277, 3, 1, 4),
        e(278, 4, 1, 2), e(279, 4, 1, len(data)), e(284, 3, 1, 1),
        e(338, 3, 1, extra)])
    open(name, "wb").write(b"II*\0" + struct.pack("<I", ifd_at) + data +
                           struct.pack("<H", n) + ifd + b"\0\0\0\0" +
                           struct.pack("<HHHH", 8, 8, 8, 8))
tiff("alpha.tiff", 2, rgba)
tiff("assoc.tiff", 1, [[(R * A // 255, G * A // 255, B * A // 255, A)
                        for (R, G, B, A) in r] for r in rgba])
PY
pixel_w=16
pixel_h=8
recorded_1="255,0,0 89,218,89 124,170,124 170,196,170 235,240,59 117,182,148 255,0,255 98,130,98"
recorded_2="255,0,0 98,209,98 124,170,124 255,255,255 255,255,255 124,170,124 98,209,98 255,0,0"
recorded_3="0,0,0 119,140,119 124,170,124 195,195,195 106,145,106 255,255,255 124,170,124 139,163,139"
recorded_4="226,97,69 111,191,111 139,191,0 112,164,112 202,217,90 134,147,66 226,97,226 114,155,114"
recorded_5="162,153,111 139,129,139 162,221,0 0,75,0 120,168,124 157,0,0 162,153,162 136,188,136"
recorded_6="226,0,0 89,191,89 124,170,0 112,164,112 202,217,59 117,147,66 226,0,226 94,127,94"
recorded_7="223,143,104 116,197,115 124,171,117 134,174,135 203,206,88 123,175,131 193,134,212 128,153,130"
recorded_8="255,0,0 89,218,89 124,170,124 255,255,255 255,255,255 124,170,124 89,218,89 255,0,0"
recorded_9="226,97,69 69,234,69 69,97,226 226,234,226 226,234,226 69,97,226 69,234,69 226,97,69"
recorded_10="0,0,0 187,187,187 255,255,255 224,224,224 128,128,128 241,241,241 0,0,0 187,187,187"
recorded_11="0,0,0 205,205,205 255,255,255 0,0,0 0,0,0 255,255,255 205,205,205 0,0,0"
recorded_12="0,0,0 168,168,168 255,255,255 0,0,0 217,217,217 0,0,0 255,255,255 194,194,194"
# 13-17: 32-bit TGA and BMP (the tree before session 22 read them
# opaque), all-clear ones too (povray's picture is the green plane).
recorded_13=$recorded_1
recorded_14=$recorded_1
recorded_15=$recorded_1
recorded_16="124,170,124 124,170,124 124,170,124 124,170,124 124,170,124 124,170,124 124,170,124 124,170,124"
recorded_17=$recorded_16
# 18-19: TIFF RGBA, whose alpha povray takes as associated: the same
# picture from straight and from premultiplied colours (the tree before
# session 22 read both opaque).
recorded_18="255,0,0 89,218,89 124,170,124 170,196,170 235,240,59 117,182,148 255,0,255 128,153,128"
recorded_19=$recorded_18
# 20-24: "premultiplied B" after the file name ("Using the Alpha
# Channel"), refused as unsupported before session 22: on divides a
# PNG's or TGA's linear colour by alpha; off multiplies a TIFF's codes
# by it, before a gamma decodes them (22).
recorded_20="255,0,0 89,255,89 124,170,124 255,255,255 255,255,59 117,255,255 255,0,255 106,136,106"
recorded_21=$recorded_20
recorded_22="255,0,0 89,151,89 124,170,124 112,152,112 187,194,59 117,161,117 255,0,255 92,125,92"
recorded_23=$recorded_1
recorded_24="255,0,0 89,179,89 124,170,124 127,162,127 212,218,59 117,163,121 255,0,255 111,139,111"
pixel_cases image_alpha.pov K \
  "1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24" \
  "1,1 1,5 1,9 1,13 5,1 5,5 5,9 5,13"
status=$?
# An all-clear picture is warned about where it is named.
"$zrcube" +Iimage_alpha.pov +W16 +H8 -A +WT1 -D Declare=K=17 \
  +Oclear.png 2>clear.err
grep -q 'image_alpha.pov:[0-9]*:[0-9]*: warning: every pixel of .clear.bmp. has alpha 0' clear.err ||
  { echo "FAIL: no located warning for clear.bmp"; cat clear.err; status=1; }
exit $status
