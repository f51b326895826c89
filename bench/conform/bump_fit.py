#!/usr/bin/python3
"""bump_fit.py - what POV-Ray 3.7's bumps, dents and wrinkles add to a
normal.

Renders normal_probe.pov (a plane lit by three coloured parallel lights,
128x128, 16-bit) with povray for bumps, dents and wrinkles at bump size B (0.1,
0.5), scale 0.3, seen from -z and from +z, reads each pixel's normal back
(as normal_probe.py does: tilt t = (nx, ny) / nz towards the viewer) and
compares it with candidate normals n0 + k B V(p) at the pixel's point
p = (x, y, 0) / 0.3, n0 the normal on the viewer's side.  V is
turbulence's vector noise (lib/core/noise.c, tables measured by
bench/noise/probe_noise.py), alone or times the noise to a power, or the
gradient of the noise (what lib/scene/texture.c used to take), or for
wrinkles sums over N octaves (2^i p, weight 2^-i) of the vector noise or
of its componentwise absolute value.  A small
C helper, built here from lib/core/noise.c, evaluates them.

Result (2026-12-02): bumps: V = vector noise, k = 1, per-pixel
correlation 1.00000 for both tilt components, root mean square error
2e-5 (the read-back's), either side; dents: V = vector noise times
noise^3, k = 1, likewise; wrinkles: the sum of |vector noise| over 10
octaves, k = 1, correlation 1.00000 and error 2e-5 but for bump size 0.5
seen from -z (0.99994, 0.0019: lights graze there).  The gradient of the noise correlates about 0
with either.  Needs povray, gcc and /usr/bin/python3 with numpy.
"""
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.join(here, "..", "..")
sys.path.insert(0, here)
import png16  # noqa: E402

HELPER = r"""
#include <stdio.h>
#include "scene/noise.h"
int main(void) {
  double x, y, z;
  while (scanf("%lf %lf %lf", &x, &y, &z) == 3) {
    zr_vec3 d = zr__dnoise_lattice(zr_v3(x, y, z));
    printf("%.12f %.12f %.12f %.12f\n", zr__noise_lattice(zr_v3(x, y, z)),
           d.x, d.y, d.z);
  }
  return 0;
}
"""


def tilts(path):
    nx, ny, nz = png16.probe_normals(path)
    return (nx / nz).ravel(), (ny / nz).ravel()


def main():
    tmp = tempfile.mkdtemp(prefix="zr_bumpfit.")
    try:
        run(tmp)
    finally:
        shutil.rmtree(tmp)


def run(tmp):
    ev = os.path.join(tmp, "ev")
    with open(ev + ".c", "w") as f:
        f.write(HELPER)
    subprocess.run(["gcc", "-O2", "-std=c11", "-I" + os.path.join(top, "lib"),
                    "-I" + os.path.join(top, "include"), "-I" + top, "-o", ev,
                    ev + ".c", os.path.join(top, "lib/core/noise.c"), "-lm"],
                   check=True)

    def evaluate(pts):
        text = "\n".join("%.12f %.12f %.12f" % tuple(p) for p in pts)
        out = subprocess.run([ev], input=text, capture_output=True,
                             text=True, check=True).stdout
        return np.array([[float(v) for v in ln.split()]
                         for ln in out.splitlines()])

    src = open(os.path.join(here, "normal_probe.pov")).read()
    sc = 0.3
    for pat, name in ((1, "bumps"), (5, "dents"), (4, "wrinkles")):
        for amt in (0.1, 0.5):
            for side in (1, -1):
                pov = os.path.join(tmp, "p.pov")
                with open(pov, "w") as f:
                    f.write('#declare PAT=%d; #declare AMT=%g; #declare SC=%g;'
                            ' #declare SIDE=%d; #declare EXTRA="";\n'
                            % (pat, amt, sc, side) + src)
                subprocess.run(["timeout", "60", "povray", "+Ip.pov",
                                "+Op.png", "+W128", "+H128", "-D", "-A",
                                "+WT1", "-GA", "+FN16"], cwd=tmp, check=True,
                               capture_output=True)
                tx, ty = tilts(os.path.join(tmp, "p.png"))
                j, i = np.mgrid[0:128, 0:128]
                # Pixel centres; seen from +z the picture is mirrored in x.
                x = (-1 + (i + 0.5) * 2 / 128) * side
                y = 1 - (j + 0.5) * 2 / 128
                p = np.stack([x / sc, y / sc, 0 * x], -1).reshape(-1, 3)
                e = evaluate(p)
                h = 1e-4
                gx = (evaluate(p + [h, 0, 0])[:, 0] -
                      evaluate(p - [h, 0, 0])[:, 0]) / (2 * h)
                gy = (evaluate(p + [0, h, 0])[:, 0] -
                      evaluate(p - [0, h, 0])[:, 0]) / (2 * h)
                cands = {"gradient of noise": np.stack([-gx, -gy, 0 * gx], 1)}
                for k in range(5):
                    cands["vector noise * noise^%d" % k] = (
                        e[:, 1:] * (e[:, 0] ** k)[:, None])
                if name == "wrinkles":
                    octs = [evaluate(p * 2 ** i)[:, 1:] * 0.5 ** i
                            for i in range(12)]
                    for n in (8, 10, 12):
                        cands["sum %d octaves" % n] = sum(octs[:n])
                        cands["sum %d octaves of |.|" % n] = sum(
                            abs(o) for o in octs[:n])
                print("%s %g side %+d" % (name, amt, side))
                for cname, v in cands.items():
                    m = np.stack([amt * v[:, 0], amt * v[:, 1],
                                  -side + amt * v[:, 2]], 1)
                    px, py = m[:, 0] / (-side * m[:, 2]), m[:, 1] / (-side * m[:, 2])
                    print("    %-26s corr x %8.5f y %8.5f  rms err %.5f" % (
                        cname, np.corrcoef(px, tx)[0, 1],
                        np.corrcoef(py, ty)[0, 1],
                        np.sqrt(((px - tx) ** 2 + (py - ty) ** 2).mean())))


if __name__ == "__main__":
    main()
