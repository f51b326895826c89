#!/usr/bin/python3
"""probe_gen3.py - reconstructs POV-Ray 3.7's noise_generator 3 from
f_noise_generator(x, y, z, 3) values printed by povray and writes
bench/noise/gen3_tables.h, which lib/core/noise.c includes.  Rerunning
it rewrites the header byte for byte.  Run: bench/noise/probe_gen3.py

What the measurements show:
 1. Along each axis the noise is a degree-4 polynomial between knots at
    k - o (o about 0.0232; the script fits polynomials on both sides of
    a knot and solves for the point where they meet): a lattice noise on
    the grid shifted by -o, cubic Hermite weights times a linear term.
 2. At the lattice points its value is one constant a; its gradient g(c)
    has one length everywhere: a gradient noise, a + sum over the 8
    corners of w(x) w(y) w(z) g(c) . (q - c), q = p + o.
 3. Along z the gradients repeat with period 2048 and take 2048 distinct
    values; (1, 0, z) is (0, 0, z + s): the gradient of corner (x, y, z)
    is G[(A(x, y) + z) mod 2048].  Likewise A(1, y) = A(0, y + s'), so
    A(x, y) = S[(R[x] + y) mod 2048]: the script reads S from the corners
    (0, y, 0), R from (x, 0, 0) and (x, 1, 0), G from (0, 0, z), and
    checks the hash on random corners up to 30000 away.
 4. Each gradient component and a come from a least-squares fit of the
    blend along the axis between two corners (8 points a component).
"""
import os
import sys
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from povprobe import function  # noqa: E402

N = 2048
F3 = "f_noise_generator(x, y, z, 3)"


def fail(msg):
    sys.stderr.write("probe_gen3: " + msg + "\n")
    sys.exit(1)


def smooth(t):
    return t * t * (3 - 2 * t)


def knot():
    """The knot near 1 along each axis."""
    out = []
    for ax in range(3):
        polys = []
        for lo, hi in ((0.0, 0.95), (1.0, 1.95)):
            xs = np.linspace(lo, hi, 150)
            P = np.tile([0.31, 0.47, 0.73], (len(xs), 1))
            P[:, ax] = xs
            v = np.array(function(F3, [tuple(p) for p in P]))
            c = np.polyfit(xs, v, 4)
            if np.abs(np.polyval(c, xs) - v).max() > 1e-8:
                fail("not a degree-4 polynomial between knots")
            polys.append(c)
        d = np.polysub(polys[0], polys[1])
        r = np.roots(np.polyder(d))
        r = r[np.abs(r.imag) < 1e-9].real
        out.append(r[np.argmin(np.abs(r - 0.977))])
    return np.array(out)


def gradients(C, o, h=1e-5):
    """Difference quotients at the lattice points C (enough to tell the
    gradients apart)."""
    C = np.asarray(C, float) - o
    q = []
    for c in C:
        for a in range(3):
            for s in (1, -1):
                r = c.copy()
                r[a] += s * h
                q.append(tuple(r))
    v = np.array(function(F3, q)).reshape(len(C), 3, 2)
    return (v[:, :, 0] - v[:, :, 1]) / (2 * h)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        here, "gen3_tables.h")
    k = knot()
    print("step 1: knots at", k)
    if np.ptp(k) > 1e-6:
        fail("the axes' knots differ")
    o = 1 - float(np.mean(k))
    Z = gradients([(0, 0, z) for z in range(2 * N)], o)
    if np.abs(Z[:N] - Z[N:]).max() > 1e-6:
        fail("the gradients along z do not repeat every 2048")
    Z = Z[:N]

    def ids(G):
        d = np.linalg.norm(G[:, None, :] - Z[None, :, :], axis=2)
        i = np.argmin(d, 1)
        if np.any(d[np.arange(len(G)), i] > 1e-3):
            fail("a gradient outside the table")
        return i
    z10 = ids(gradients([(1, 0, z) for z in range(N)], o))
    u = np.arange(N)
    shift = [s for s in range(N) if np.all(np.roll(u, -s) == z10)]
    print("step 3: (1, 0, z) is (0, 0, z + s) for s in", shift)
    if len(shift) != 1:
        fail("no shift along z")
    S = ids(gradients([(0, y, 0) for y in range(N)], o))
    V = ids(gradients([(x, y, 0) for x in range(N) for y in (0, 1)],
                      o)).reshape(N, 2)
    R = np.zeros(N, int)
    for x in range(N):
        c = [j for j in np.nonzero(S == V[x, 0])[0]
             if S[(j + 1) % N] == V[x, 1]]
        if len(c) != 1:
            fail("R[%d] is not unique" % x)
        R[x] = c[0]
    rng = np.random.default_rng(2048)
    L = rng.integers(-30000, 30000, size=(500, 3))
    got = ids(gradients([tuple(c) for c in L], o))
    want = (S[(R[L[:, 0] % N] + L[:, 1]) % N] + L[:, 2]) % N
    bad = int(np.sum(got != want))
    print("step 3: hash checked on 500 random corners: %d wrong" % bad)
    if bad:
        fail("the hash does not hold")
    # Step 4: precise gradients and the constant.
    ts = np.linspace(0.05, 0.4, 8)
    s = smooth(ts)
    A = np.stack([np.ones_like(ts), (1 - s) * ts, s * (ts - 1)], 1)
    G = np.zeros((N, 3))
    consts = []
    for ax in range(3):
        pts = []
        for z in range(N):
            for t in ts:
                c = np.array([0.0, 0.0, z]) - o
                c[ax] += t
                pts.append(tuple(c))
        v = np.array(function(F3, pts)).reshape(N, 8)
        for z in range(N):
            sol, res, _, _ = np.linalg.lstsq(A, v[z], rcond=None)
            G[z, ax] = sol[1]
            consts.append(sol[0])
    a = float(np.median(consts))
    print("step 4: constant %.10f (spread %.1e), gradient length %.6f"
          % (a, np.ptp(consts), np.median(np.linalg.norm(G, axis=1))))
    # Check the whole noise on random points.
    P = rng.uniform(-40, 40, size=(1000, 3))
    v = np.array(function(F3, [tuple(p) for p in P]))
    q = P + o
    fl = np.floor(q).astype(np.int64)
    t = q - fl
    m = np.full(len(P), a)
    for i in (0, 1):
        for j in (0, 1):
            for kk in (0, 1):
                c = fl + [i, j, kk]
                hh = (S[(R[c[:, 0] % N] + c[:, 1]) % N] + c[:, 2]) % N
                w = ((smooth(t[:, 0]) if i else 1 - smooth(t[:, 0])) *
                     (smooth(t[:, 1]) if j else 1 - smooth(t[:, 1])) *
                     (smooth(t[:, 2]) if kk else 1 - smooth(t[:, 2])))
                m += w * (G[hh] * (t - [i, j, kk])).sum(1)
    err = np.abs(m - v).max()
    print("check: 1000 random points, largest difference %.1e" % err)
    if err > 1e-6:
        fail("the reconstruction does not match")
    with open(out, "w") as f:
        f.write("/* gen3_tables.h - POV-Ray 3.7's noise_generator 3, written "
                "by\n   bench/noise/probe_gen3.py from povray's output (do "
                "not edit).\n   See lib/core/noise.c for their use. */\n\n")
        f.write("/* The lattice is shifted by -GEN3_OFFSET; the noise is "
                "GEN3_CONSTANT at\n   its points. */\n")
        f.write("#define GEN3_OFFSET %.9f\n#define GEN3_CONSTANT %.9f\n\n"
                % (o, a))
        for name, tab in (("gen3_s", S), ("gen3_r", R)):
            f.write("static const unsigned short %s[2048] = {\n" % name)
            for i in range(0, N, 12):
                f.write("    " + ", ".join("%d" % x for x in tab[i:i + 12])
                        + ",\n")
            f.write("};\n\n")
        f.write("/* The gradient of hash h. */\n"
                "static const double gen3_gradient[2048][3] = {\n")
        for g in G:
            f.write("    {%.9f, %.9f, %.9f},\n" % tuple(g))
        f.write("};\n")
    print("wrote", out)


if __name__ == "__main__":
    main()
