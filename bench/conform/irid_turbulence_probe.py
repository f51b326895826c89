#!/usr/bin/python3
"""irid_turbulence_probe.py - how POV-Ray 3.7's irid turbulence varies the
film's thickness.

Renders, with povray, one pixel of a white plane (diffuse 1, irid 0.5,
thickness 0.1, turbulence 0.2) lit by a parallel light of 0.5 and seen by
an orthographic camera, both along its normal, 16-bit linear PNG, at
points P of the plane.  Each channel is 0.5 (1 + 0.5 cos(4 pi t' / w)),
w the default irid_wavelength <0.70, 0.52, 0.48> (lib/trace/shade.c), so
each gives the thickness t' (the three agree).  povray itself prints
(#debug, f_noise3d) the scalar turbulence sums S_k of k = 4, 5, 6 octaves
(omega 0.5, lambda 2, first term clamped to [0, 1]) at P; the probe fits
t' / t - 1 = u (a S_k + b) by least squares for each k.

Result (2026-12-02): k = 5, a = 2.0000, b = -1.0000, rms 5e-5 (the
read-back's) against a spread of 0.5; k = 4 and 6 leave rms 0.028 and
0.011.  Needs povray and /usr/bin/python3 with numpy.
"""
import math
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import png16  # noqa: E402

SCENE = r'''#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "functions.inc"
#declare P = <PX, PY, 0>;
camera { orthographic location P - z look_at P right x * 0.001 up y * 0.001 }
light_source { P - z * 1000 color rgb 0.5 parallel point_at P }
plane { -z, 0 pigment { rgb 1 }
        finish { ambient 0 diffuse 1 irid { 0.5 thickness 0.1 turbulence 0.2 } } }
#for (K, 4, 6)
  #declare S = 0; #declare A = 1; #declare F = 1;
  #for (I, 0, K - 1)
    #declare Y = P * F;
    #declare V = 2 * f_noise3d(Y.x, Y.y, Y.z) - 0.5;
    #if (I = 0) #declare V = min(1, max(0, V)); #end
    #declare S = S + A * V; #declare A = A * 0.5; #declare F = F * 2;
  #end
  #debug concat("S", str(K, 0, 0), " ", str(S, 0, 9), "\n")
#end
'''
POINTS = [(0.3, 0.2), (1.7, 0.4), (2.2, 3.1), (0.9, 1.3), (4.1, 0.7),
          (3.3, 2.6), (0.15, 5.2), (6.1, 1.9)]
WAVE = (0.70, 0.52, 0.48)


def thickness(rgb):
    """The thickness in (0, 0.175) the three channels agree on."""
    best = None
    for t in np.linspace(0.0005, 0.175, 3500):
        err = sum((0.5 * (1 + 0.5 * math.cos(4 * math.pi * t / w)) - c) ** 2
                  for c, w in zip(rgb, WAVE))
        if best is None or err < best[0]:
            best = (err, t)
    # refine from the red channel alone around the best guess
    x = max(-1.0, min(1.0, (2 * rgb[0] - 1) / 0.5))
    t = math.acos(x) * WAVE[0] / (4 * math.pi)
    return t if abs(t - best[1]) < 0.003 else best[1]


def main():
    g, sums = [], {4: [], 5: [], 6: []}
    with tempfile.TemporaryDirectory() as tmp:
        pov = os.path.join(tmp, 'irid.pov')
        open(pov, 'w').write(SCENE)
        for px, py in POINTS:
            out = os.path.join(tmp, 'irid.png')
            r = subprocess.run(
                ['povray', '+I' + pov, '+O' + out, '+FN16', 'File_Gamma=1.0',
                 '+W1', '+H1', '-D', '-A', '+WT1', 'Declare=PX=%g' % px,
                 'Declare=PY=%g' % py], cwd=tmp, capture_output=True,
                text=True)
            for k in sums:
                sums[k].append(float(re.search(r'^S%d (\S+)' % k,
                                               r.stdout + r.stderr,
                                               re.M)[1]))
            t = thickness(png16.read(out)[0, 0, :3])
            g.append((t / 0.1 - 1) / 0.2)
            print('P (%g, %g): thickness %.5f' % (px, py, t))
    g = np.array(g)
    for k, s in sums.items():
        a = np.stack([np.array(s), np.ones(len(s))], 1)
        coef = np.linalg.lstsq(a, g, rcond=None)[0]
        rms = float(np.sqrt(np.mean((a @ coef - g) ** 2)))
        print('%d octaves: a %.4f b %.4f rms %.5f' % (k, coef[0], coef[1],
                                                     rms))
    return 0


if __name__ == '__main__':
    sys.exit(main())
