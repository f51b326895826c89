#!/bin/sh
# test_image_gamma_povray.sh - how an image_map's PNG codes become
# colours, zRcube against POV-Ray 3.7 (lib/sdl/build.c,
# codes_as_working): a 4x4 PNG of code 85 without any chunk, as a
# palette and as RGB, with a gAMA chunk (1/2.2) and with an sRGB chunk,
# seen with ambient 1 under #version 3.6 and 3.7, assumed_gamma 1 and
# 2.2, as the file says and with "gamma srgb" after the file name ("The
# Gamma Option": the file is sRGB-encoded, whatever it says).  Each linear value (16-bit PNG output; POV-Ray's with
# File_Gamma=1, zRcube's sRGB decoded) must be within 0.002 of
# POV-Ray's.  Skips (77) when povray is not installed.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
srcdir=${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}
builddir=${ZR_BUILDDIR:-$srcdir/build}
zrcube=$builddir/bin/zrcube
command -v povray >/dev/null 2>&1 || { echo "no povray: skipped"; exit 77; }
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
[ -x "$zrcube" ] || { echo "$zrcube is not built" >&2; exit 99; }
work=$(mktemp -d "${TMPDIR:-/tmp}/zr_imgamma.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT INT TERM
cd "$work" || exit 99
/usr/bin/python3 - "$zrcube" "$srcdir/bench" <<'PY'
import os, struct, subprocess, sys, zlib
sys.path.insert(0, sys.argv[2])
import media_shadow as ms  # its 16-bit PNG reader
zrcube = sys.argv[1]

def chunk(t, b):
    return (struct.pack('>I', len(b)) + t + b +
            struct.pack('>I', zlib.crc32(t + b) & 0xffffffff))

def png(path, ctype, extra=b''):
    d = b'\x89PNG\r\n\x1a\n' + chunk(
        b'IHDR', struct.pack('>IIBBBBB', 4, 4, 8, ctype, 0, 0, 0)) + extra
    if ctype == 3:
        d += chunk(b'PLTE', bytes([85, 85, 85]))
        rows = b''.join(b'\x00' + bytes(4) for _ in range(4))
    else:
        rows = b''.join(b'\x00' + bytes([85] * 12) for _ in range(4))
    d += chunk(b'IDAT', zlib.compress(rows)) + chunk(b'IEND', b'')
    open(path, 'wb').write(d)

png('pal.png', 3)
png('rgb.png', 2)
png('gama.png', 2, chunk(b'gAMA', struct.pack('>I', 45455)))
png('srgb.png', 2, chunk(b'sRGB', b'\x00'))

def dec(v):
    return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4

good = bad = 0
for version in ('3.6', '3.7'):
    for gamma in ('1', '2.2'):
        for f, mod in [(f, mod) for mod in ('', ' gamma srgb')
                       for f in ('pal', 'rgb', 'gama', 'srgb')]:
            with open('t.pov', 'w') as out:
                out.write('#version %s;\nglobal_settings { assumed_gamma %s }\n'
                          'camera { orthographic location <0.5, 0.5, -1> '
                          'look_at <0.5, 0.5, 0> right x up y }\n'
                          'plane { z, 0 pigment { image_map { png "%s.png"%s '
                          'once } } finish { ambient 1 diffuse 0 } }\n'
                          % (version, gamma, f, mod))
            for o in ('p.png', 'z.png'):
                if os.path.exists(o):
                    os.remove(o)
            subprocess.run(['povray', '+It.pov', '+Op.png', '+FN16',
                            'File_Gamma=1.0', '+W4', '+H4', '-D', '-A',
                            '+WT1'], capture_output=True, timeout=60)
            subprocess.run([zrcube, '+It.pov', '+Oz.png', '+FN16', '+W4',
                            '+H4', '-D', '+WT1'], capture_output=True,
                           timeout=60)
            label = '#version %s, assumed_gamma %s, %s.png%s' % (
                version, gamma, f, mod)
            try:
                pv = ms.read_png16('p.png')[2][2]
                zv = dec(ms.read_png16('z.png')[2][2])
            except Exception as e:
                print('%s: no picture (%s) FAIL' % (label, e))
                bad += 1
                continue
            ok = abs(pv - zv) <= 0.002
            print('%s: povray %.4f zrcube %.4f %s'
                  % (label, pv, zv, 'ok' if ok else 'FAIL'))
            good, bad = good + ok, bad + (not ok)
print('%d passed, %d failed' % (good, bad))
sys.exit(1 if bad else 0)
PY
