#!/usr/bin/python3
"""waves_probe.py - recovers POV-Ray 3.7's ripples and waves patterns from
the povray binary's values (functions of `pattern { ripples }` and
`pattern { waves }`, read with #debug by bench/noise/povprobe.py) and
writes lib/scene/waves_tables.h, which lib/scene/pattern.c includes.
Rerunning it rewrites the header byte for byte (seeded random numbers,
values rounded to 10 decimals).
Run: bench/conform/waves_probe.py [output.h]

What the measurements show (residuals printed by the script):
 1. Far from the origin (|p| = 1e5) ripples along any ray is a pure
    sinusoid of period 1 about 0.5, so each wave is a sine of the
    distance with no falloff.  Its complex amplitude over 2400 directions
    and frequencies 0.25..1 is a sum of 10 plane-wave terms exp(-2 pi i
    f u.c_k): a least-squares fit of 10 centres c_k (seeded restarts)
    finds points on the unit sphere, not in the unit cube.
 2. Near the origin (1500 points in [-4, 5]^3) ripples is exactly
        0.5 + 0.05 sum_k sin(2 pi (f |p - c_k| + phase))
    then frequency f and phase applied once more to the value (v f +
    phase, wrapped to [0, 1)).  The fit from 1.'s centres leaves a root
    mean square residual of 1e-15.
 3. waves along a far ray holds 10 distinct spatial frequencies s_k
    (a fit of 10 sinusoids to 2560 values leaves 1e-10), each of
    amplitude 0.02 / s_k; its phase along three rays matches exactly one
    of the ripples centres, so waves is
        0.5 + 0.02 sum_k sin(2 pi (f s_k |p - c_k| + phase)) / s_k
    with the same centres (a free fit of the centres moves them by less
    than 1e-9) and the same outer frequency and phase.
 4. global_settings { number_of_waves } changes neither value (1, 3, 20).
"""
import os
import sys
import numpy as np
from scipy.optimize import least_squares

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "noise"))
from povprobe import evaluate, function  # noqa: E402

K = 10
FAR = 1e5


def fail(msg):
    sys.stderr.write("waves_probe: " + msg + "\n")
    sys.exit(1)


def near_fit(P, v, x0, columns):
    def design(x):
        return np.c_[np.ones(len(P)), columns(x)]

    def res(x):
        A = design(x)
        return A @ np.linalg.lstsq(A, v, rcond=None)[0] - v
    r = least_squares(res, x0, method="lm", max_nfev=600, xtol=1e-15,
                      ftol=1e-15)
    A = design(r.x)
    return r.x, np.linalg.lstsq(A, v, rcond=None)[0], \
        np.sqrt(np.mean(r.fun ** 2))


def dist(P, c):
    return np.linalg.norm(P[:, None, :] - c.reshape(-1, 3)[None], axis=2)


def far_line(u, s):
    """waves along the ray u from FAR on: each frequency s_k's complex
    amplitude Z_k, the wave being Re(Z_k exp(2 pi i s_k r))."""
    xs = np.arange(0, 64, 0.25)
    r = FAR + xs
    v = np.array(function("pattern { waves }", [tuple(t * u) for t in r]))
    A = np.c_[np.ones(len(r)), np.cos(2 * np.pi * np.outer(r, s)),
              np.sin(2 * np.pi * np.outer(r, s))]
    q = np.linalg.lstsq(A, v, rcond=None)[0]
    return q[1:K + 1] - 1j * q[K + 1:]


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        here, "..", "..", "lib", "scene", "waves_tables.h")
    # 1. waves' frequencies along one far ray.
    x = np.arange(0, 128, 0.05)
    u = np.array([0.6, 0.48, 0.64])
    vl = np.array(function("pattern { waves }",
                           [tuple((1e4 + t) * u) for t in x]))
    spec = np.abs(np.fft.rfft((vl - vl.mean()) * np.hanning(len(vl))))
    fr = np.fft.rfftfreq(len(vl), 0.05)
    peaks = [i for i in range(1, len(spec) - 1)
             if spec[i] > spec[i - 1] and spec[i] > spec[i + 1]]
    peaks = sorted(sorted(peaks, key=lambda i: -spec[i])[:K])
    s, co, e = near_fit(x, vl, fr[peaks], lambda s: np.c_[
        np.cos(2 * np.pi * np.outer(x, s)), np.sin(2 * np.pi * np.outer(x, s))])
    amp = np.hypot(co[1:K + 1], co[K + 1:])
    print("waves far: rms residual %.2e, frequencies %s, amplitude * "
          "frequency %s" % (e, np.round(s, 6), np.round(amp * s, 6)))
    # 2. Each frequency's phase around three great circles of directions
    # is -2 pi s_k u.c_k plus a constant: unwrapped and fitted, it gives
    # the centre of that frequency's waves.
    phases = []
    for a, b in ((0, 1), (1, 2), (2, 0)):
        th = np.arange(36) * 2 * np.pi / 36
        U = np.zeros((36, 3))
        U[:, a], U[:, b] = np.cos(th), np.sin(th)
        ph = np.unwrap(np.array([np.angle(far_line(d, s)) for d in U]),
                       axis=0)
        phases.append(ph)
    c0 = np.zeros((K, 3))
    for k in range(K):
        A, y = [], []
        for ci, (a, b) in enumerate(((0, 1), (1, 2), (2, 0))):
            th = np.arange(36) * 2 * np.pi / 36
            for i in range(36):
                uu = np.zeros(3)
                uu[a], uu[b] = np.cos(th[i]), np.sin(th[i])
                A.append(np.r_[-2 * np.pi * s[k] * uu, np.eye(3)[ci]])
                y.append(phases[ci][i, k])
        sol = np.linalg.lstsq(np.array(A), np.array(y), rcond=None)
        c0[k] = sol[0][:3]
    print("far-field centres: |c_k| %s" % np.round(np.linalg.norm(c0, axis=1),
                                                    4))
    # 3. Near the origin, ripples and waves from those centres.
    P = np.random.default_rng(5).uniform(-4, 5, (1500, 3))
    pts = [tuple(p) for p in P]
    vr = np.array(function("pattern { ripples }", pts))
    c, co, e = near_fit(P, vr, c0.ravel(), lambda x: np.c_[
        np.sin(2 * np.pi * dist(P, x)), np.cos(2 * np.pi * dist(P, x))])
    c = c.reshape(K, 3)
    print("ripples near: rms residual %.2e, mean %.12f, sine weights "
          "%s, cosine weights %s" % (e, co[0], np.round(co[1:K + 1], 9),
                                     np.round(co[K + 1:], 9)))
    if e > 1e-9 or np.abs(co[1:K + 1] - 0.05).max() > 1e-9:
        fail("ripples is not 0.5 + 0.05 sum sin(2 pi |p - c|)")
    print("|c_k| - 1: %s" % np.round(np.linalg.norm(c, axis=1) - 1, 12))
    vw = np.array(function("pattern { waves }", pts))
    xw, co, e = near_fit(P, vw, np.r_[c.ravel(), s], lambda x: np.c_[
        np.sin(2 * np.pi * dist(P, x[:3 * K]) * x[3 * K:]) / x[3 * K:],
        np.cos(2 * np.pi * dist(P, x[:3 * K]) * x[3 * K:]) / x[3 * K:]])
    moved = np.abs(xw[:3 * K] - c.ravel()).max()
    print("waves near: rms residual %.2e, centres moved %.1e, weights %s"
          % (e, moved, np.round(co[1:K + 1], 9)))
    if e > 1e-9 or moved > 1e-8 or np.abs(co[1:K + 1] - 0.02).max() > 1e-9:
        fail("waves is not 0.5 + 0.02 sum sin(2 pi s |p - c|) / s")
    freq = xw[3 * K:]
    with open(out, "w") as f:
        f.write("/* Generated by bench/conform/waves_probe.py from POV-Ray "
                "3.7's ripples and\n   waves values; do not edit.  The "
                "wave centres (unit vectors) and the\n   spatial frequency "
                "of each centre's waves (ripples use 1). */\n")
        f.write("static const double zr__wave_centres[%d][4] = {\n" % K)
        for k in range(K):
            f.write("    {%.10f, %.10f, %.10f, %.10f},\n"
                    % (c[k, 0], c[k, 1], c[k, 2], freq[k]))
        f.write("};\n")
    print("wrote " + out)


main()
