#!/usr/bin/python3
"""dispersion_probe.py - how POV-Ray 3.7 splits a refracted ray into the
spectrum of interior { dispersion D dispersion_samples N } (the manual
says only that D is the ratio of the violet to the red ior and N the
number of colour steps).  Renders bench/conform/dispersion_probe.pov
(see there) with povray at 8000x1, 16 bits, linear, and prints for each
sample its ior / ior (from the edge where its ray stops seeing white) and
the colour it carries (the step of the levels there), then the levels
themselves as the cumulative table C(k/N) of lib/trace/dispersion.c.

    dispersion_probe.py [N [D [IOR]]]     (defaults 100 1.2 1.5)

Measured (povray 3.7.0.10, 2026-12-04): sample i of N, counted from red,
refracts with ior * D^((i + 0.5) / N - 0.5) (N = 2, 3, 7, 100 and D = 0.8
to 4 decimals of the ratio), and carries C((i + 1) / N) - C(i / N) of one
fixed cumulative colour C(t) (N = 2, 3 and 7 agree with the N = 100 table
within 5e-4); C(1) = (0.9938, 1, 0.9962).  No jitter: rows are equal.
"""
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import png16  # noqa: E402

N = int(sys.argv[1]) if len(sys.argv) > 1 else 100
D = float(sys.argv[2]) if len(sys.argv) > 2 else 1.2
IOR = float(sys.argv[3]) if len(sys.argv) > 3 else 1.5
CX, RW, W = -0.33, 0.16, 8000

with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, 'p.png')
    subprocess.run(['povray', '+I' + os.path.join(HERE, 'dispersion_probe.pov'),
                    '+O' + out, '+W%d' % W, '+H1', '-D', '-A', '+WT1', '-GA',
                    '+FN16', 'File_Gamma=1.0', 'Declare=Ds=%d' % N,
                    'Declare=Dv=%g' % D, 'Declare=Ior=%g' % IOR],
                   check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    row = png16.read(out)[0, :, :3]

s = math.sqrt(0.5)
levels, edges = [row[0]], []
for j in range(1, W):
    if abs(row[j] - levels[-1]).max() > 2e-5:
        edges.append(CX - RW / 2 + j * RW / W)
        levels.append(row[j])
if len(edges) != N:
    sys.exit('found %d edges, not %d: widen the view (Cx, Rw)' % (len(edges), N))
# Edge k (from the left) is where the sample with the k-th largest shift,
# the highest ior, stops seeing white: sample N - 1 - k.
print('# sample ior/ior D^((i+0.5)/N-0.5) weight(r g b)')
for k, x in enumerate(edges):
    i = N - 1 - k
    d = -x
    n = math.sqrt((s / (1 - d / s)) ** 2 + 0.5)
    w = levels[k] - levels[k + 1]
    print('%3d %.5f %.5f %.5f %.5f %.5f' % (i, n / IOR, D ** ((i + 0.5) / N - 0.5),
                                            w[0], w[1], w[2]))
print('# C(k/N), k = 0..N (r g b)')
for k in range(N + 1):
    c = levels[N - k]
    print('%3d %.5f %.5f %.5f' % (k, c[0], c[1], c[2]))
