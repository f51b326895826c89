#!/usr/bin/python3
"""waves_normal_fit.py: how povray 3.7 tilts a normal by ripples and waves.

An orthographic camera with a normal { } sends every ray along +z (and,
in a second picture, -z); povray tilts it as a surface normal, with the
pattern taken at the screen point (u, v, 0) (lib/trace/camera.c).  The
rays hit a huge sphere painted with their direction, read back from
16-bit PNGs, and the two pictures give the whole tilt vector g (the ray
is n - g normalised).  g is then fitted by least squares with, for each
of the ten wave centres c_k of lib/scene/waves_tables.h, the unit vector
from c_k times the cosine and times the sine of the wave's phase
2 pi (f s_k |p - c_k| + phase) (s_k = 1 for ripples).  Printed: the rms
tilt, the fit's residual and the 20 coefficients.  Measured 2026-12-02:
residual 1e-5, cosines 0, sines -amount / 10 (ripples) and
-amount / 10 / s_k (waves), at frequencies 1 to 3, phases 0 to 0.3,
scales 0.2 and 1.  Needs povray; run from anywhere."""
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import png16  # noqa: E402

PROBE = """#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location 0 right x*4/3 up y
 #if (Back) direction -z #else direction z #end
 normal { %s } }
#declare R = 100000;
sphere { 0, R
  texture { pigment { average pigment_map {
    [1 function { x/R*0.5 + 0.5 } color_map { [0 rgb 0] [1 rgb <3,0,0>] }]
    [1 function { y/R*0.5 + 0.5 } color_map { [0 rgb 0] [1 rgb <0,3,0>] }]
    [1 function { z/R*0.5 + 0.5 } color_map { [0 rgb 0] [1 rgb <0,0,3>] }] } }
  finish { ambient 1 diffuse 0 } }
  hollow }
"""
CASES = [  # kind, amount, frequency, phase, scale
    ('ripples', 0.3, 1, 0, 0.2), ('waves', 0.3, 1, 0, 0.2),
    ('ripples', 0.3, 2, 0, 0.2), ('waves', 0.3, 2, 0, 0.2),
    ('ripples', 0.3, 1, 0, 1), ('waves', 0.3, 1, 0, 1),
    ('waves', 0.3, 1, 0.3, 0.2), ('ripples', 0.3, 3, 0.15, 0.2)]
W, H = 96, 72


def centres():
    src = open(os.path.join(HERE, '..', '..', 'lib', 'scene',
                            'waves_tables.h')).read()
    rows = [l for l in src.splitlines() if l.strip().startswith('{')]
    return np.array([[float(v) for v in re.findall(r'-?\d+\.\d+', l)]
                     for l in rows])


def tilt(tmp, normal):
    pics = []
    for back in (0, 1):
        pov = os.path.join(tmp, 'p.pov')
        out = os.path.join(tmp, 'p%d.png' % back)
        with open(pov, 'w') as fh:
            fh.write('#declare Back = %d;\n' % back + PROBE % normal)
        subprocess.run(['povray', '+I' + pov, '+O' + out, '+FN16',
                        '+W%d' % W, '+H%d' % H, '-D', '-A', '+WT1', '-GA',
                        'File_Gamma=1.0'], cwd=tmp, check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        pics.append(png16.read(out)[..., :3] * 2 - 1)
    a = pics[0][..., :2] / pics[0][..., 2:3]      # -g_xy / (1 - g_z)
    b = pics[1][..., :2] / -pics[1][..., 2:3]     # -g_xy / (1 + g_z)
    with np.errstate(all='ignore'):
        gxy = -2 / (1 / a + 1 / b)
    return gxy


def main():
    c = centres()
    np.set_printoptions(linewidth=200, precision=4, suppress=True)
    with tempfile.TemporaryDirectory() as tmp:
        for kind, amount, f, phase, scale in CASES:
            normal = '%s %g frequency %g phase %g scale %g' % (
                kind, amount, f, phase, scale)
            g = tilt(tmp, normal)
            u = (np.arange(W) + 0.5) / W - 0.5
            v = 0.5 - (np.arange(H) + 0.5) / H
            uu, vv = np.meshgrid(u, v)
            q = np.stack([uu, vv, 0 * uu], -1) / scale
            cols = []
            for k in range(len(c)):
                s = 1.0 if kind == 'ripples' else c[k, 3]
                r = q - c[k, :3]
                d = np.linalg.norm(r, axis=-1)
                th = 2 * np.pi * (f * s * d + phase)
                rh = (r / d[..., None])[..., :2]
                cols.append((rh * np.cos(th)[..., None]).reshape(-1))
                cols.append((rh * np.sin(th)[..., None]).reshape(-1))
            m = np.array(cols).T
            y = g.reshape(-1)
            ok = np.isfinite(y) & (np.abs(y) < 5)
            x = np.linalg.lstsq(m[ok], y[ok], rcond=None)[0]
            res = y[ok] - m[ok] @ x
            print('%s: rms tilt %.4f, residual %.5f' % (
                normal, np.sqrt((y[ok] ** 2).mean()),
                np.sqrt((res ** 2).mean())))
            print('  cosines', x[0::2])
            print('  sines  ', x[1::2])
            want = -amount / 10 / (1 if kind == 'ripples' else c[:, 3])
            print('  sines / (-amount / 10 / s_k)', x[1::2] / want)
    return 0


if __name__ == '__main__':
    sys.exit(main())
