#!/usr/bin/python3
"""Fit zRcube's metallic curve to POV-Ray 3.7's measured one (issue 17).

Usage: bench/metallic_probe.sh povray | bench/metallic_fit.py

metallic_probe.sh measures, for reflection { 1 metallic 1 } seen at an
angle t from the normal, the strength k of the surface colour's tint
(1 at t = 0, falling towards grazing).  We model the share of white,
W = 1 - k, as a function of x = t / 90 degrees with
    W(x) = x^a ((1 - s) / (1 - s x))^n,
which is 0 facing (x = 0) and 1 grazing (x = 1) whatever a, s, n; a
shapes the start, s < 1 puts a pole at x = 1 / s beyond grazing that
makes the steep rise, n its strength.  The parameters are fitted by
least squares on the "refl" lines with metallic 1 (their R channel is
exactly 1, so k is measured to about 1e-5); the script prints them and
the residuals, then checks the model on the "spec" and "phong" lines
(highlights: the angle is the light's to the normal) and the metallic
0.5 lines (k halves).  Needs numpy and scipy.
"""
import sys

import numpy as np
from scipy.optimize import least_squares


def white(p, x):
    a, s, n = p
    return x ** a * ((1 - s) / (1 - s * x)) ** n


def main():
    refl, other = [], []
    for line in sys.stdin:
        f = line.split()
        if len(f) != 9:
            continue
        case, light, view, metal = f[0], f[1], f[2], float(f[3])
        kg, kb = float(f[7]), float(f[8])
        k = 0.5 * (kg + kb)
        if case == 'refl':
            t = float(view)
        elif case in ('spec', 'phong'):
            t = float(light)
        else:
            t = 0.0  # view: light along the normal
        (refl if case == 'refl' and metal == 1 else other).append(
            (case, t, metal, k))
    t = np.array([r[1] for r in refl if r[1] > 0])
    w = np.array([1 - r[3] for r in refl if r[1] > 0])
    x = t / 90
    fit = least_squares(lambda p: white(p, x) - w, [0.8, 0.9, 2.0],
                        bounds=([0.1, 0.0, 0.1], [4.0, 0.99, 8.0]))
    a, s, n = fit.x
    print('W(x) = x^a ((1 - s) / (1 - s x))^n')
    print('a = %.4f  s = %.4f  n = %.4f' % (a, s, n))
    p = np.array([round(a, 4), round(s, 4), round(n, 4)])
    print('# refl, metallic 1: angle measured_W model_W difference')
    worst = 0.0
    for ti, wi in zip(t, w):
        m = white(p, ti / 90)
        worst = max(worst, abs(m - wi))
        print('%5.1f %.5f %.5f %+.5f' % (ti, wi, m, m - wi))
    print('largest difference of W: %.5f' % worst)
    print('# other cases: case angle metallic measured_k model_k')
    worst_other = 0.0
    for case, ti, metal, k in other:
        m = metal * (1 - (white(p, ti / 90) if ti > 0 else 0.0))
        worst_other = max(worst_other, abs(m - k))
        print('%-5s %5.1f %.1f %.5f %.5f' % (case, ti, metal, k, m))
    print('largest difference of k elsewhere: %.5f' % worst_other)


if __name__ == '__main__':
    main()
