#!/usr/bin/python3
"""quilted_probe.py - checks lib/scene/pattern.c's quilted against POV-Ray
3.7's values (functions of `pattern { quilted control0 A control1 B }`,
read with #debug by bench/noise/povprobe.py).
Run: bench/conform/quilted_probe.py   (needs povray; exits 1 on mismatch)

What it measures: with d the offset of the point from the middle of its
unit cube, r = |d| and s = |dx| + |dy| + |dz|, the value divided by s is
a cubic polynomial of r without constant term (least squares at 300
random points per control pair leaves 1e-15); its coefficients, printed
per pair, are (2 / (3 sqrt 3)) times those of the Bezier curve
3 c0 r (1 - r)^2 + 3 c1 r^2 (1 - r) + r^3.  The closed form
|B(r)| s 2 / (3 sqrt 3) is then checked at every point (controls 5, 5
give values above 1: no clamp; negative controls give |B|).
"""
import os
import sys
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "noise"))
from povprobe import function  # noqa: E402

PAIRS = [(0, 0), (1, 1), (0, 1), (1, 0), (0.5, 0.5), (0.3, 0.8), (2, -1),
         (-5, 0), (0, -5), (5, 5)]


def closed_form(P, c0, c1):
    d = np.abs(P - np.floor(P) - 0.5)
    r = np.linalg.norm(d, axis=1)
    b = 3 * c0 * r * (1 - r) ** 2 + 3 * c1 * r * r * (1 - r) + r ** 3
    return np.abs(b) * d.sum(1) * 2 / (3 * np.sqrt(3)), r, d.sum(1)


def main():
    P = np.random.default_rng(1).uniform(-3, 3, (300, 3))
    k = 2 / (3 * np.sqrt(3))
    worst = 0.0
    for c0, c1 in PAIRS:
        v = np.array(function("pattern { quilted control0 %r control1 %r }"
                              % (c0, c1), [tuple(p) for p in P]))
        f, r, s = closed_form(P, c0, c1)
        A = np.c_[r, r * r, r ** 3]
        coef = np.linalg.lstsq(A, v / s, rcond=None)[0] / k
        bez = [3 * c0, 3 * c1 - 6 * c0, 1 + 3 * c0 - 3 * c1]
        err = np.abs(v - f).max()
        worst = max(worst, err)
        print("control0 %-4g control1 %-4g  fit/k %s  Bezier %s  max error "
              "%.1e" % (c0, c1, np.round(coef, 6), np.round(bez, 6), err))
    if worst > 1e-8:
        sys.stderr.write("quilted_probe: the closed form misses by %.1e\n"
                         % worst)
        sys.exit(1)


main()
