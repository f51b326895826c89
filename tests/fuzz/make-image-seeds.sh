#!/bin/sh
# make-image-seeds.sh - writes the fuzz_image seed corpus: one tiny valid
# file per format and variant the decoders read (PNG grey/RGB/palette/
# 16-bit/alpha, GIF, POT, TGA raw and RLE, PPM/PGM/PBM ascii and binary,
# PFM colour and grey, JPEG grey and colour) into tests/fuzz/image-seeds.
# Usage: tests/fuzz/make-image-seeds.sh [OUTDIR]   (needs python3; the
# JPEG seeds need pnmtojpeg from netpbm and are skipped without it; the
# OpenEXR seed needs ZRCUBE=build/bin/zrcube).  Also BMP, HDR and TIFF.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-$here/image-seeds}
mkdir -p "$out"
python3 - "$out" <<'PY'
import struct, sys, zlib
out = sys.argv[1]
def w(name, data):
    open(f"{out}/{name}", "wb").write(data)

# PNG
def chunk(t, d):
    return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
def png(wd, ht, depth, ctype, rows, extra=b""):
    ihdr = struct.pack(">IIBBBBB", wd, ht, depth, ctype, 0, 0, 0)
    raw = b"".join(b"\0" + r for r in rows)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + extra +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
w("grey8.png", png(3, 2, 8, 0, [bytes([0, 128, 255]), bytes([10, 20, 30])]))
w("grey16.png", png(2, 2, 16, 0, [b"\x00\x00\xff\xff", b"\x12\x34\x80\x00"]))
w("grey1.png", png(8, 2, 1, 0, [b"\xa5", b"\x5a"]))
w("rgb8.png", png(2, 2, 8, 2, [bytes([255, 0, 0, 0, 255, 0]), bytes([0, 0, 255, 9, 9, 9])],
                  chunk(b"gAMA", struct.pack(">I", 45455))))
w("rgba16.png", png(1, 2, 16, 6, [bytes(range(8)), bytes(range(8, 16))]))
w("greyalpha.png", png(2, 1, 8, 4, [bytes([1, 2, 3, 4])]))
w("palette.png", png(4, 1, 2, 3, [b"\x1b"],
                     chunk(b"PLTE", bytes([0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255])) +
                     chunk(b"tRNS", b"\x00\x80")))

# GIF: LZW with a clear code before every pixel, so codes stay 9 bits
# wide at most (the simplest valid stream).
def lzw(indices, min_size):
    clear, end = 1 << min_size, (1 << min_size) + 1
    codes = []
    for i in indices:
        codes += [clear, i]
    codes.append(end)
    width = min_size + 1
    bits = acc = 0
    data = bytearray()
    for c in codes:
        acc |= c << bits
        bits += width
        while bits >= 8:
            data.append(acc & 255)
            acc >>= 8
            bits -= 8
    if bits:
        data.append(acc & 255)
    blocks = b"".join(bytes([len(data[i:i + 255])]) + bytes(data[i:i + 255])
                      for i in range(0, len(data), 255))
    return bytes([min_size]) + blocks + b"\0"
def gif(wd, ht, indices, palette, transparent=None, interlace=False):
    n = len(palette) // 3
    bits = max(1, (n - 1).bit_length())
    pal = palette + b"\0" * (3 * (1 << bits) - len(palette))
    g = b"GIF89a" + struct.pack("<HHBBB", wd, ht, 0x80 | (bits - 1), 0, 0) + pal
    if transparent is not None:
        g += b"\x21\xf9\x04\x01\x00\x00" + bytes([transparent]) + b"\x00"
    g += b"\x2c" + struct.pack("<HHHHB", 0, 0, wd, ht, 0x40 if interlace else 0)
    return g + lzw(indices, max(2, bits)) + b"\x3b"
w("image.gif", gif(3, 2, [0, 1, 2, 3, 2, 1], bytes([0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255])))
w("interlaced.gif", gif(2, 5, list(range(10)) and [i % 4 for i in range(10)],
                        bytes([0, 0, 0, 255, 255, 255, 9, 9, 9, 200, 100, 50]),
                        transparent=1, interlace=True))
# POT: a GIF twice as wide as the field, high bytes left, low bytes right.
w("field.pot", gif(4, 2, [0, 1, 2, 3, 3, 2, 1, 0],
                   bytes(3 * i for i in range(12))))

# TGA: uncompressed true colour, grey, colour-mapped, RLE true colour.
def tga(kind, wd, ht, bpp, pixels, cmap=b"", cmap_len=0, desc=0):
    h = struct.pack("<BBBHHBHHHHBB", 0, 1 if cmap else 0, kind, 0, cmap_len,
                    24 if cmap else 0, 0, 0, wd, ht, bpp, desc)
    return h + cmap + pixels
w("rgb24.tga", tga(2, 2, 2, 24, bytes([0, 0, 255, 0, 255, 0, 255, 0, 0, 1, 2, 3])))
w("rgba32-top.tga", tga(2, 2, 1, 32, bytes([1, 2, 3, 255, 4, 5, 6, 0]), desc=0x28))
w("grey8.tga", tga(3, 3, 1, 8, bytes([0, 100, 255])))
w("cmap8.tga", tga(1, 2, 1, 8, bytes([0, 1]), cmap=bytes([0, 0, 255, 255, 0, 0]), cmap_len=2))
w("rle24.tga", tga(10, 4, 1, 24, bytes([0x82, 1, 2, 3, 0x00, 9, 8, 7])))
w("rle-grey.tga", tga(11, 3, 1, 8, bytes([0x81, 50, 0x00, 200])))

# Netpbm and PFM.
w("ascii.pbm", b"P1\n# c\n3 2\n1 0 1\n0 1 0\n")
w("ascii.pgm", b"P2\n2 2\n255\n0 64\n128 255\n")
w("ascii.ppm", b"P3\n2 1\n65535\n0 1000 65535 7 8 9\n")
w("binary.pbm", b"P4\n9 2\n\xaa\x80\x55\x00")
w("binary.pgm", b"P5\n3 1\n255\n\x00\x80\xff")
w("binary16.pgm", b"P5\n2 1\n1000\n\x00\x10\x03\xe8")
w("binary.ppm", b"P6\n2 1\n255\n\xff\x00\x00\x00\xff\x00")
w("colour.pfm", b"PF\n2 1\n-1.0\n" + struct.pack("<6f", 0, .5, 1, 2, 0.25, 0.125))
w("grey-be.pfm", b"Pf\n1 2\n1.0\n" + struct.pack(">2f", .5, 1.5))

# BMP (issue 12): 24-bit bottom-up, 8-bit palette, RLE8, 16-bit fields.
def bmp(wd, ht, bits, comp, body, colours=0, extra=b""):
    off = 54 + len(extra)
    return (b"BM" + struct.pack("<IHHI", off + len(body), 0, 0, off) +
            struct.pack("<IiiHHIIiiII", 40, wd, ht, 1, bits, comp,
                        len(body), 2835, 2835, colours, 0) + extra + body)
w("rgb24.bmp", bmp(2, 2, 24, 0, bytes([1, 2, 3, 4, 5, 6, 0, 0,
                                       7, 8, 9, 10, 11, 12, 0, 0])))
pal = bytes([10, 20, 30, 0, 40, 50, 60, 0])
w("pal8.bmp", bmp(3, -1, 8, 0, bytes([1, 0, 1, 0]), 2, pal))
w("rle8.bmp", bmp(4, 2, 8, 1, bytes([2, 1, 0, 3, 0, 1, 1, 0, 0, 0,
                                     0, 2, 1, 0, 0, 1]), 2, pal))
w("fields16.bmp", bmp(1, 1, 16, 3, b"\x1f\xf8\0\0", 0,
                      struct.pack("<3I", 0xf800, 0x07e0, 0x001f)))

# Radiance HDR (issue 12): flat and run-length encoded scanlines.
w("flat.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n" +
  bytes([128, 64, 32, 129, 1, 1, 1, 1]))
rle = bytes([2, 2, 0, 8]) + b"".join(bytes([136, v]) for v in (128, 64, 0, 130))
w("rle.hdr", b"#?RADIANCE\n\n+Y 1 +X 8\n" + rle)

# TIFF (issue 12): baseline little-endian RGB, one strip, uncompressed.
def tiff(wd, ht, pixels):
    tags = [(256, 3, 1, wd), (257, 3, 1, ht), (258, 3, 1, 8), (259, 3, 1, 1),
            (262, 3, 1, 2), (273, 4, 1, 8), (277, 3, 1, 3), (278, 3, 1, ht),
            (279, 4, 1, len(pixels))]
    ifd = struct.pack("<H", len(tags)) + b"".join(
        struct.pack("<HHII", t, k, n, v) for t, k, n, v in tags) + b"\0" * 4
    return b"II*\0" + struct.pack("<I", 8 + len(pixels)) + pixels + ifd
w("rgb.tif", tiff(2, 1, bytes([255, 0, 0, 0, 0, 255])))
PY
# OpenEXR (issue 12): written by zRcube itself when a build is given.
if [ -n "${ZRCUBE:-}" ] && [ -x "$ZRCUBE" ]; then
  printf 'camera { location -z look_at 0 } background { rgb <2, 1, 0.5> }\n' \
    >"$out/exr-seed.pov"
  "$ZRCUBE" +I"$out/exr-seed.pov" +O"$out/tiny.exr" +W3 +H2 -D -A >/dev/null 2>&1 || true
  rm -f "$out/exr-seed.pov"
fi
if command -v pnmtojpeg >/dev/null 2>&1; then
  printf 'P5\n4 4\n255\n\0\100\200\377\0\100\200\377\0\100\200\377\0\100\200\377' |
    pnmtojpeg --quality=50 >"$out/grey.jpg"
  printf 'P6\n2 2\n255\n\377\0\0\0\377\0\0\0\377\177\177\177' |
    pnmtojpeg --quality=50 >"$out/colour.jpg"
  printf 'P6\n2 2\n255\n\377\0\0\0\377\0\0\0\377\177\177\177' |
    pnmtojpeg --quality=50 --progressive >"$out/progressive.jpg"
fi
