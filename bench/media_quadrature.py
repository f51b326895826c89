#!/usr/bin/python3
"""
media_quadrature.py - how POV-Ray 3.7's media method 3 sums a camera
ray's light, measured black-box (lib/trace/media.c, gather_cell(), cites
this script; its output is kept in
bench/results/media-quadrature-2026-12-02.txt).

An orthographic camera looks along +z through a hollow box 0 <= z <= D
holding one medium; the pixel (a 16-bit PNG, File_Gamma 1 for both) is
the light the ray gathers over a black
background.  Four parts:

  thick   emission e, absorption a, depth D, min samples N: povray's
          value against the exact e (1 - exp(-a D)) / a and against the
          cell rule e h sum_{i<n} exp(-a i h), h = D / n,
          n = floor(max(N, 3) / 2) + 1.
  shape   density { function { F(z) } } with aa_threshold 100 (no
          halving): povray against the rule "a cell's source is the mean
          of its two ends and its middle, samples taken at reach
          n / (n + 1)" and against the trapezoid of the ends alone.
  level   a density step at z = 0.05 D and aa_level 2: 1/6 of e D when
          the first cell is not halved, 1/12 when it is; run over e and
          D it brackets the threshold (change times interval length
          against aa_threshold / 3 in zrcube).
  scatter the issue's box (scattering {1, 2} absorption 1, a light
          above): povray, zrcube (ZRCUBE) and the ratio, column by row.

  /usr/bin/python3 bench/media_quadrature.py [ZRCUBE]

Exits 77 without povray.  One thread, no antialiasing.
"""
import math
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from media_shadow import read_png16  # noqa: E402

POVRAY = os.environ.get("POVRAY") or shutil.which("povray") or ""

SLAB = r"""
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -50> look_at 0
         right 0.01 * x up 0.01 * y }
background { rgb 0 }
box { <-1, -1, 0>, <1, 1, %(D)g> hollow pigment { rgbt 1 }
  interior { media { emission %(e)g absorption %(a)g %(extra)s } } }
"""

SCATTER = r"""
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -5> look_at 0 right 4 * x up 3 * y }
light_source { <0, 10, 0>, rgb 1 }
box { -1, 1 hollow pigment { rgbt 1 }
  interior { media { scattering { 1, 2 } absorption 1 } } }
"""


def render(tool, tmp, text, w=1, h=1):
    pov = os.path.join(tmp, "q.pov")
    out = os.path.join(tmp, "q.png")
    with open(pov, "w") as f:
        f.write(text)
    if os.path.exists(out):
        os.remove(out)
    cmd = [tool, "+I" + pov, "+O" + out, "+FN16", "File_Gamma=1.0",
           "+W%d" % w, "+H%d" % h, "-D", "+WT1"]
    if tool == POVRAY:
        cmd += ["-A", "-GA"]
    subprocess.run(cmd, cwd=tmp, capture_output=True, timeout=300)
    return read_png16(out)  # both write linear codes under File_Gamma=1.0


def cells_of(n_samples):
    return max(n_samples, 3) // 2 + 1


def thick(tmp):
    print("# thick: emission e, absorption a, depth D; povray, exact, "
          "cell rule")
    e = 0.05
    for a in (0.5, 1, 2, 4):
        for d in (1, 2):
            for n_samples in (1, 3, 5, 9):
                v = render(POVRAY, tmp, SLAB % dict(
                    D=d, e=e, a=a, extra="samples %d" % n_samples))[0][0]
                n = cells_of(n_samples)
                h = d / n
                rule = e * h * sum(math.exp(-a * i * h) for i in range(n))
                exact = e * (1 - math.exp(-a * d)) / a
                print("a %g D %g samples %d: povray %.5f exact %.5f "
                      "rule %.5f" % (a, d, n_samples, v, exact, rule))


def shape(tmp):
    print("# shape: density F(z), depth 1, emission 0.1, absorption a; "
          "povray, three-sample rule, trapezoid")
    funcs = [("z", lambda z: z), ("1-z", lambda z: 1 - z),
             ("z*z", lambda z: z * z), ("z*z*z", lambda z: z ** 3),
             ("sqrt(z)", math.sqrt)]
    for name, f in funcs:
        for a in (0, 1):
            for n_samples in (3, 5, 9):
                extra = ("samples %d aa_threshold 100 density { function "
                         "{ %s } }" % (n_samples, name))
                v = render(POVRAY, tmp, SLAB % dict(
                    D=1, e=0.1, a=a, extra=extra))[0][0]
                n = cells_of(n_samples)
                h, r = 1.0 / n, n / (n + 1.0)
                out = []
                for three in (True, False):
                    light, t = 0.0, 1.0
                    for i in range(n):
                        zs = [r * h * (i + q) for q in (0, 0.5, 1)]
                        vals = [f(z) for z in zs]
                        m = (sum(vals) / 3 if three
                             else (vals[0] + vals[2]) / 2)
                        light += t * 0.1 * m * h
                        t *= math.exp(-a * m * h)
                    out.append(light)
                print("F %s a %g samples %d: povray %.5f three %.5f "
                      "trapezoid %.5f" % (name, a, n_samples, v, *out))


def level(tmp):
    print("# level: step at 0.05 D, samples 3 aa_level 2; L / (e D) is "
          "1/6 unhalved, 1/12 halved")
    for a in (0, 1):
        for d in (0.25, 1, 4):
            for e in (0.03, 0.06, 0.12, 0.2):
                extra = ("samples 3 aa_level 2 density { function { z < %g "
                         "} }" % (0.05 * d))
                v = render(POVRAY, tmp, SLAB % dict(
                    D=d, e=e, a=a, extra=extra))[0][0]
                r = v / (e * d)
                print("a %g D %g e %g: e D %.3f L/(e D) %.4f %s" % (
                    a, d, e, e * d, r, "halved" if r < 0.125 else "not"))


def scatter(tmp, zrcube):
    print("# scatter: the issue's box, column 80 of 160x120, linear")
    p = render(POVRAY, tmp, SCATTER, 160, 120)
    z = render(zrcube, tmp, SCATTER, 160, 120) if zrcube else None
    for y in range(26, 100, 8):
        line = "row %d: povray %.4f" % (y, p[y][80])
        if z:
            line += " zrcube %.4f ratio %.4f" % (
                z[y][80], p[y][80] / max(z[y][80], 1e-9))
        print(line)


def main():
    if not POVRAY:
        print("no povray: skipped")
        return 77
    zrcube = sys.argv[1] if len(sys.argv) > 1 else ""
    with tempfile.TemporaryDirectory() as tmp:
        thick(tmp)
        shape(tmp)
        level(tmp)
        scatter(tmp, os.path.abspath(zrcube) if zrcube else "")
    return 0


if __name__ == "__main__":
    sys.exit(main())
