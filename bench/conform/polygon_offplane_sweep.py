#!/usr/bin/python3
"""polygon_offplane_sweep.py - when POV-Ray 3.7 refuses a non-planar polygon.

The manual says a polygon's points must lie in one plane and says nothing
of what happens otherwise.  POV-Ray 3.7 draws nothing, without a word,
for a polygon one of whose points is off the plane of the first points
that span one by more than a threshold.  This probe renders, with povray,
a square polygon of half-size S (0.01 to 100) whose fourth point is lifted
by D along the normal (D from 2e-11 to 1e-8), scaled to fill a 16x16
frame, and reads the centre pixel back: drawn or not.  It prints the
table and, per size, the largest D drawn and the smallest refused, so it
shows whether the threshold is absolute (the same D at every S) or
relative to the polygon's size.

Result (2026-12-03): drawn up to D = 1e-10 and refused from 1.1e-10 at
every size from 0.01 to 100, so the threshold is absolute, 1e-10:
lib/sdl/build_shape.c off_plane() uses it, tests/legacy/polygon_offplane.pov
checks it in a picture.  With --zrcube BIN the same table is rendered by
zRcube too and the two compared (exit 1 on a difference).
Needs povray and /usr/bin/python3 with numpy.
"""
import argparse
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import png16  # noqa: E402

SIZES = [0.01, 0.1, 1.0, 10.0, 100.0]
LIFTS = [2e-11, 5e-11, 9e-11, 1e-10, 1.1e-10, 1.5e-10, 2e-10, 5e-10, 1e-9, 1e-8]

SCENE = """#version 3.7;
global_settings {{ assumed_gamma 1 }}
camera {{ orthographic location <0, 0, -10> look_at 0 right x up y }}
background {{ rgb 0 }}
polygon {{ 5, <-{s}, -{s}, 0>, <{s}, -{s}, 0>, <{s}, {s}, 0>,
  <-{s}, {s}, {d}>, <-{s}, -{s}, 0>
  pigment {{ rgb 1 }} finish {{ ambient 1 diffuse 0 }} scale {k} }}
"""


def centre_lit(png):
    """The centre pixel of the PNG is white (the polygon drawn)."""
    img = png16.read(png)
    return img[img.shape[0] // 2, img.shape[1] // 2, 0] > 0.5


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--zrcube', help='also render with this zrcube binary')
    args = ap.parse_args()
    povray = lambda pov, png: ['povray', '-D', '-A', '+W16', '+H16', '+WT1',
                               '+I' + pov, '+O' + png]
    tmp = tempfile.mkdtemp(prefix='polyprobe')
    bad = 0
    print('# size\tlift\tpovray\tzrcube')
    for s in SIZES:
        drawn, refused = None, None
        for d in LIFTS:
            pov = os.path.join(tmp, 'p.pov')
            with open(pov, 'w') as f:
                f.write(SCENE.format(s=repr(s), d=repr(d), k=repr(3.0 / s)))
            pr = subprocess.run(povray(pov, os.path.join(tmp, 'p.png')),
                                cwd=tmp, capture_output=True, text=True,
                                timeout=120)
            if pr.returncode != 0:
                sys.exit('povray failed:\n' + pr.stderr[-2000:])
            pv = centre_lit(os.path.join(tmp, 'p.png'))
            zv = '-'
            if args.zrcube:
                zpng = os.path.join(tmp, 'z.png')
                zr = subprocess.run([args.zrcube, pov, '-D', '-A', '+W16',
                                     '+H16', '+WT1', '+O' + zpng],
                                    cwd=tmp, capture_output=True, text=True,
                                    timeout=120)
                if zr.returncode != 0:
                    sys.exit('zrcube failed:\n' + zr.stderr[-2000:])
                zv = 'drawn' if centre_lit(zpng) else 'none'
                bad += (zv == 'drawn') != pv
            print('%g\t%g\t%s\t%s' % (s, d, 'drawn' if pv else 'none', zv))
            if pv:
                drawn = d
            elif refused is None:
                refused = d
        print('# size %g: largest lift drawn %s, smallest refused %s'
              % (s, drawn, refused))
    if args.zrcube:
        print('# zrcube differs from povray in %d cases' % bad)
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
