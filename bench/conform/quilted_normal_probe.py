#!/usr/bin/python3
"""quilted_normal_probe.py [ZRCUBE] - what POV-Ray 3.7's quilted normal
adds to a normal.

Renders a plane lit by three coloured parallel lights (normal_probe.pov's
set-up, 128x128, orthographic, 16-bit PNG) with a quilted 0.1 normal,
translate z*ZO, scale 0.5, with povray (and zRcube when given), reads each
pixel's tilt back (as normal_probe.py does) and compares it with the model
n0 + A B(r) d / (sqrt 3 / 2): d the offset of the pattern point from the
middle of its unit cube, r = |d|, B the cubic Bezier with control points
0, control0, control1, 1 (quilted's pigment, lib/scene/pattern.c), A the
bump size, n0 the normal facing the viewer.

Result (2026-12-02): root mean square error 1.5e-5 to 1.6e-5 (the 16-bit
read-back's) against a tilt of 0.026 to 0.042, for controls (0, 1) at two
depths ZO, (0.5, 1), the defaults (which are 1, 1: (0, 1) is off by 0.017),
(-2, 3) (B keeps its sign: |B| is off by 0.0067), and the plane turned
away from the viewer (same tilt towards the viewer).  The factor
1 / (sqrt 3 / 2) = 1.1547: 1 is off by 0.0035.  Needs povray and
/usr/bin/python3 with numpy.
"""
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
import png16  # noqa: E402

SCENE = """#version 3.7;
global_settings { assumed_gamma 1 ambient_light 0 }
camera { orthographic location <0,0,-10> look_at 0 right x*2 up y*2 }
light_source { <100, 0, -100> color rgb <1,0,0> parallel point_at 0 }
light_source { <-100, 0, -100> color rgb <0,1,0> parallel point_at 0 }
light_source { <0, 100, -100> color rgb <0,0,1> parallel point_at 0 }
plane { %(pn)s*z, 0
  pigment { rgb 1 }
  finish { ambient 0 diffuse 1 specular 0 phong 0 }
  normal { quilted 0.1 %(ctl)s translate z*%(zo)s scale 0.5 }
}
"""
N = 128
CASES = [  # name, plane normal, controls or None (defaults), depth
    ("c0_0_c1_1", -1, (0, 1), 0.3),
    ("c0_0_c1_1_deeper", -1, (0, 1), 0.1),
    ("c0_0.5_c1_1", -1, (0.5, 1), 0.3),
    ("defaults", -1, None, 0.3),
    ("c0_-2_c1_3", -1, (-2, 3), 0.3),
    ("turned_away", 1, (0, 1), 0.3),
]


def tilts(path):
    nx, ny, nz = png16.probe_normals(path)
    return nx / nz, ny / nz


def model(zo, c0, c1, k=2 / 3 ** 0.5, amount=0.1):
    c = -1 + (np.arange(N) + 0.5) * 2 / N
    x, y = np.meshgrid(c / 0.5, -c / 0.5)
    d = [v - np.floor(v) - 0.5 for v in (x, y, np.full_like(x, -zo))]
    r = np.sqrt(d[0] ** 2 + d[1] ** 2 + d[2] ** 2)
    u = 1 - r
    b = 3 * c0 * r * u * u + 3 * c1 * r * r * u + r ** 3
    vx, vy, vz = (k * amount * b * e for e in d)
    # n0 = (0, 0, -1), towards the viewer: n = n0 + v.
    return vx / (1 - vz), vy / (1 - vz)


def rms(a, b):
    return float(np.sqrt(((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2).mean()))


def main():
    zr = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else None
    if not shutil.which("povray"):
        print("quilted_normal_probe: no povray", file=sys.stderr)
        return 77
    tmp = tempfile.mkdtemp(prefix="zr_qprobe.")
    try:
        for name, pn, ctl, zo in CASES:
            text = SCENE % {
                "pn": pn, "zo": zo,
                "ctl": "" if ctl is None else
                "control0 %g control1 %g" % ctl}
            with open(os.path.join(tmp, "q.pov"), "w") as fh:
                fh.write(text)
            subprocess.run(["povray", "+Iq.pov", "+Opov.png", "+W%d" % N,
                            "+H%d" % N, "-D", "-A", "+WT1", "-GA", "+FN16"],
                           cwd=tmp, check=True, capture_output=True)
            pov = tilts(os.path.join(tmp, "pov.png"))
            c0, c1 = (1, 1) if ctl is None else ctl
            line = "%-18s tilt_rms %.4f model_err %.6f" % (
                name, rms(pov, (0 * pov[0], 0 * pov[1])),
                rms(pov, model(zo, c0, c1)))
            if ctl is None:
                line += " (as 0,1: %.6f)" % rms(pov, model(zo, 0, 1))
            if ctl == (-2, 3):
                line += " (|B|: %.6f)" % rms(pov, model_abs(zo, c0, c1))
            if name == "c0_0_c1_1":
                line += " (factor 1: %.6f)" % rms(pov, model(zo, 0, 1, k=1))
            if zr:
                subprocess.run([zr, "+Iq.pov", "+Ozr.png", "+W%d" % N,
                                "+H%d" % N, "-D", "+WT1", "+FN16", "-q"],
                               cwd=tmp, check=True, capture_output=True)
                line += " zrcube_err %.6f" % rms(
                    pov, tilts(os.path.join(tmp, "zr.png")))
            print(line, flush=True)
    finally:
        shutil.rmtree(tmp)
    return 0


def model_abs(zo, c0, c1, amount=0.1):
    """The model with |B| (what quilted's pigment takes)."""
    c = -1 + (np.arange(N) + 0.5) * 2 / N
    x, y = np.meshgrid(c / 0.5, -c / 0.5)
    d = [v - np.floor(v) - 0.5 for v in (x, y, np.full_like(x, -zo))]
    r = np.sqrt(d[0] ** 2 + d[1] ** 2 + d[2] ** 2)
    u = 1 - r
    b = np.abs(3 * c0 * r * u * u + 3 * c1 * r * r * u + r ** 3)
    k = 2 / 3 ** 0.5
    vx, vy, vz = (k * amount * b * e for e in d)
    return vx / (1 - vz), vy / (1 - vz)


if __name__ == "__main__":
    sys.exit(main())
