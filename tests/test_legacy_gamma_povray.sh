#!/bin/sh
# test_legacy_gamma_povray.sh - gamma correction in legacy scenes,
# zRcube against POV-Ray 3.7 ("Gamma in Legacy Scenes": a scene with
# neither assumed_gamma nor a #version 3.7 in force at its end is written
# with no gamma correction).  Seven flat colours seen with ambient 1 under
# several headers and File_Gamma settings; image_map codes (PNG with and
# without a gAMA or sRGB chunk, BMP, PPM) under legacy, 3.6 and 3.7
# rules; and whether an edge between red 0.01 and 0.05 is antialiased at
# threshold 0.1 (yes with gamma correction off, no under assumed_gamma
# 2.2).  Every 8-bit code must be within 1 of POV-Ray's.  The cases come
# from bench/conform/legacy_gamma_probe.py, which prints the full table.
# Skips (77) when povray is not installed.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
srcdir=${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}
builddir=${ZR_BUILDDIR:-$srcdir/build}
zrcube=$builddir/bin/zrcube
command -v povray >/dev/null 2>&1 || { echo "no povray: skipped"; exit 77; }
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
/usr/bin/python3 -c 'import numpy, PIL' 2>/dev/null ||
  { echo "no numpy or PIL: skipped"; exit 77; }
[ -x "$zrcube" ] || { echo "$zrcube is not built" >&2; exit 99; }
work=$(mktemp -d "${TMPDIR:-/tmp}/zr_legacy_gamma.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT INT TERM
cd "$work" || exit 99
/usr/bin/python3 - "$zrcube" "$srcdir/bench/conform" <<'PY'
import sys
sys.path.insert(0, sys.argv[2])
import legacy_gamma_probe as lg
zrcube = sys.argv[1]
good = bad = 0


def check(label, pv, zv):
    global good, bad
    ok = (pv is not None and zv is not None and len(pv) == len(zv) and
          all(abs(a - b) <= 1 for a, b in zip(pv, zv)))
    print('%s: povray %s zrcube %s %s' % (label, pv, zv,
                                          'ok' if ok else 'FAIL'))
    good, bad = good + ok, bad + (not ok)


cases = dict((c[0], c) for c in lg.CASES)
for name, opts in (('none', []), ('none', ['File_Gamma=1.0']),
                   ('v3.6', []), ('v3.7-then-v3.6-at-end', []),
                   ('v3.7', []), ('v3.7', ['File_Gamma=2.2']),
                   ('v3.6-then-v3.7-at-end', []), ('ag2.2', []),
                   ('ag2.2', ['File_Gamma=1.0'])):
    label, head, foot = cases[name]
    with open('p.pov', 'w') as f:
        f.write(head + lg.BODY + foot)
    for ppm in (False, True):
        ext = '.ppm' if ppm else '.png'
        check('%s %s %s' % (label, ' '.join(opts), ext[1:]),
              lg.render('povray', 'p.pov', 'p' + ext, opts, ppm),
              lg.render(zrcube, 'p.pov', 'z' + ext, opts, ppm))

lg.image_files()
heads = dict((c[0], c[1]) for c in lg.IMAGE_CASES)
for scene, name, kind in (('none', 'gama.png', 'png'),
                          ('none', 'srgb.png', 'png'),
                          ('none', 'plain.png', 'png'),
                          ('none', 'img.bmp', 'bmp'),
                          ('v3.6', 'img.ppm', 'ppm'),
                          ('v3.7', 'img.ppm', 'ppm'),
                          ('v3.7', 'gama.png', 'png'),
                          ('v3.6 ag1', 'img.bmp', 'bmp'),
                          ('v3.6 ag2.2', 'img.bmp', 'bmp'),
                          ('v3.7 ag2.2', 'img.ppm', 'ppm')):
    with open('i.pov', 'w') as f:
        f.write(heads[scene] + lg.IMAGE_SCENE % (kind, name))
    check('image_map %s %s' % (scene, name),
          lg.render('povray', 'i.pov', 'p.png', [], False),
          lg.render(zrcube, 'i.pov', 'z.png', [], False))

for label, head, foot in lg.AA_CASES:
    with open('aa.pov', 'w') as f:
        f.write(head + lg.AA_SCENE + foot)
    pv = lg.aa_blended('povray', 0.1)
    zv = lg.aa_blended(zrcube, 0.1)
    check('antialiasing at 0.1, %s' % label, [int(pv)], [int(zv)])

print('%d passed, %d failed' % (good, bad))
sys.exit(1 if bad else 0)
PY
