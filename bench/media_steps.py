#!/usr/bin/env python3
"""Where a renderer samples media along a ray, measured black-box.

Usage: media_steps.py RENDERER [SAMPLES [METHOD [STEPS]]]
  RENDERER: 'povray' or the path of a zrcube binary.

One pixel of an orthographic camera looks along +z through a hollow
slab 0 <= z <= 1 that holds an emitting medium (emission 0.5, no
absorption, intervals 1, the given samples and method) whose density is
1 for z < T and 0 beyond (gradient z, a colour_map step).  With no
absorption the pixel is the sum over the samples of weight x density,
so as T runs from 0 to 1 the pixel climbs a staircase: each step is a
sample at that depth and its height the sample's share of the slab.
Prints every step ("z share") and the depth of the last one: where the
samples stop.  A constant medium gives 0.5 whatever the placement, so
the staircase is what tells two quadratures apart.

Pixels are read from a 16-bit PNG: povray writes linear values
(File_Gamma=1.0), zrcube sRGB ones, decoded here.
"""
import os
import struct
import subprocess
import sys
import tempfile
import zlib

SCENE = """#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -1> look_at <0, 0, 0>
         right x*0.01 up y*0.01 }
background { rgb 0 }
box { <-1, -1, 0>, <1, 1, 1> hollow pigment { rgbt 1 }
  interior { media { emission 0.5 method %(method)d samples %(samples)d
                     intervals 1
    density { gradient z
      colour_map { [0 rgb 1] [%(t)g rgb 1] [%(t)g rgb 0] [1 rgb 0] } } } } }
"""


def first_pixel(path):
    data = open(path, 'rb').read()
    i, idat = 8, b''
    while i < len(data):
        n, kind = struct.unpack('>I4s', data[i:i + 8])
        if kind == b'IDAT':
            idat += data[i + 8:i + 8 + n]
        i += 12 + n
    raw = zlib.decompress(idat)
    if data[24] == 16:
        return (raw[1] << 8 | raw[2]) / 65535.0
    return raw[1] / 255.0


def srgb_decode(v):
    return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4


def render(renderer, folder, t, samples, method):
    pov = os.path.join(folder, 'p.pov')
    png = os.path.join(folder, 'o.png')
    with open(pov, 'w') as f:
        f.write(SCENE % {'t': t, 'samples': samples, 'method': method})
    if renderer == 'povray':
        cmd = ['povray', '+I' + pov, '+O' + png, '+W1', '+H1', '-D', '-A',
               '+FN16', 'File_Gamma=1.0', '-GA']
    else:
        cmd = [renderer, '+I' + pov, '+O' + png, '+W1', '+H1', '-D',
               '+FN16', '-q', '--io-restrictions=none']
    subprocess.run(cmd, cwd=folder, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, timeout=60, check=True)
    v = first_pixel(png)
    return v if renderer == 'povray' else srgb_decode(v)


def main():
    renderer = sys.argv[1]
    samples = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    method = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    steps = int(sys.argv[4]) if len(sys.argv) > 4 else 200
    with tempfile.TemporaryDirectory() as folder:
        prev, last = 0.0, 0.0
        print('# %s samples %d method %d: step depth, share of the slab'
              % (renderer, samples, method))
        for k in range(1, steps + 1):
            t = k / steps
            v = render(renderer, folder, t, samples, method)
            if abs(v - prev) > 2e-4:
                # The sample lies in ((k - 1) / steps, k / steps].
                print('%.4f %.5f' % ((k - 0.5) / steps, 2 * (v - prev)))
                last = (k - 0.5) / steps
            prev = v
        print('# last sample near z = %.4f; total %.5f (exact 1)'
              % (last, 2 * prev))


if __name__ == '__main__':
    main()
