#!/usr/bin/python3
"""probe_noise.py - reconstructs POV-Ray 3.7's lattice noise (the
default noise_generator 2, and generator 1 from it) from f_noise3d values
printed by povray, and writes bench/noise/noise_tables.h, which
lib/core/noise.c includes.  Rerunning it rewrites the header byte for
byte.  Run: bench/noise/probe_noise.py [output.h]

What the measurements show (each step checks its claim on every value it
read and stops if one disagrees):
 1. Along a lattice line the noise is exactly (to 5e-16) the cubic
    Hermite blend of two linear functions, v0 + g0 t and v1 + g1 (t - 1),
    with weight 3t^2 - 2t^3: every integer point c carries a value v(c)
    and a gradient g(c), and the noise at p is the sum over the 8 corners
    of its unit cell of w(x) w(y) w(z) (v(c) + g(c) . (p - c)).
 2. On each axis line, the 4096 lattice points of a period hit 256
    distinct values 16 times each, and equal values come with equal
    gradients: the pair is entry (h & 255) of a 256-entry table, where h
    is a 12-bit hash.
 3. The hash is h = T[T[T[x'] ^ y'] ^ z'] with T a permutation of 0..4095
    and x' = (x + K) & 4095 (likewise y', z'), K one offset: moving from
    (0, 0) to (1, 0) or (0, 1) XOR-shifts the sequence along z in z'
    space.  The script finds K, then T from sequences along y and x (the
    XOR shifts), fixing the two unknown constants by T's consistency with
    itself; it checks the hash on 2000 random lattice points up to 30000
    away.
 4. The 256 values and gradients come from a least-squares fit of the
    formula of step 1 to 4000 random points (1024 unknowns); the largest
    residual is printed (about 1e-14).
 5. noise_generator 1 is generator 2 mapped by a + b n and clamped to
    [0, 1]: the script fits a and b on the points not clamped.
 6. Turbulence moves a point by the turbulence vector times a vector
    noise D (octaves 1).  gradient x with warp { turbulence 0.001
    octaves 1 } at a point whose x has a fraction in [0.1, 0.9] (and
    positive coordinates) gives frac(x) + 0.001 D_x exactly, and so on
    for y and z.  Each component is a lattice noise of the same form and
    hash as step 1 with its own table, fitted as in step 4 (residual
    about 1e-12, the precision of the difference quotient).
"""
import sys
import os
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from povprobe import function  # noqa: E402

M = 4095
NOISE = "f_noise3d(x, y, z)"


def fail(msg):
    sys.stderr.write("probe_noise: " + msg + "\n")
    sys.exit(1)


def solve_table(C, z00, V0yz, Vxy0):
    """T under offset C, or None when the data admit none or several."""
    u = np.arange(4096)
    Gp = z00[(u - C) & M]           # Gp(v) = value at (0, 0, z), v = z'
    nz = V0yz.shape[1]
    zp = (np.arange(nz) + C) & M
    e = np.zeros(4096, int)
    for y in range(4096):
        cand = np.nonzero(Gp[u ^ zp[0]] == V0yz[y, 0])[0]
        ok = [c for c in cand if np.all(Gp[c ^ zp] == V0yz[y])]
        if len(ok) != 1:
            return None
        e[y] = ok[0]
    Tp = e[(u - C) & M]            # Tp(v) = T[A0 ^ v] ^ B00
    ny = Vxy0.shape[1]
    yp = (np.arange(ny) + C) & M
    f = np.zeros(4096, int)
    for x in range(4096):
        cand = np.nonzero(Gp[Tp[u ^ yp[0]] ^ C] == Vxy0[x, 0])[0]
        ok = [c for c in cand if np.all(Gp[Tp[c ^ yp] ^ C] == Vxy0[x])]
        if len(ok) != 1:
            return None
        f[x] = ok[0]
    fw = f[(u - C) & M]            # fw(w) = T[w] ^ A0
    sols = []
    for A0 in range(4096):
        B00 = fw[0] ^ A0 ^ Tp[A0]
        T = fw ^ A0
        if np.all(T == (Tp[u ^ A0] ^ B00)) and T[(A0 ^ C) & M] == B00:
            sols.append((T, B00))
    if len(sols) != 1:
        return None
    T, B00 = sols[0]
    Tinv = np.argsort(T)
    F = Gp[B00 ^ Tinv[u]]          # the value of hash w
    return T, F


def hash3(T, C, c):
    x, y, z = ((np.asarray(c, dtype=np.int64) + C) & M).T
    return T[T[T[x] ^ y] ^ z]


def smooth(t):
    return t * t * (3 - 2 * t)


def design(T, C, P):
    """The linear map from the 256 (value, gradient) entries to the noise
    at the points P, as step 1 describes."""
    A = np.zeros((len(P), 1024))
    fl = np.floor(P).astype(np.int64)
    fr = P - fl
    rows = np.arange(len(P))
    for i in (0, 1):
        for j in (0, 1):
            for k in (0, 1):
                c = fl + [i, j, k]
                d = P - c
                w = ((smooth(fr[:, 0]) if i else 1 - smooth(fr[:, 0])) *
                     (smooth(fr[:, 1]) if j else 1 - smooth(fr[:, 1])) *
                     (smooth(fr[:, 2]) if k else 1 - smooth(fr[:, 2])))
                idx = (hash3(T, C, c) & 255) * 4
                np.add.at(A, (rows, idx), w)
                for a in range(3):
                    np.add.at(A, (rows, idx + 1 + a), w * d[:, a])
    return A


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "noise_tables.h")
    # Step 1: the blend along a lattice edge.
    xs = np.linspace(0, 1, 101)
    line = np.array(function(NOISE, [(x, 0, 0) for x in xs]))
    s = smooth(xs)
    B = np.stack([np.ones_like(xs), xs, s, s * xs], 1)
    coef = np.linalg.lstsq(B, line, rcond=None)[0]
    r1 = np.abs(B @ coef - line).max()
    print("step 1: cubic Hermite blend along x in [0, 1]: residual %.1e" % r1)
    if r1 > 1e-12:
        fail("the noise is not a cubic Hermite blend along a lattice edge")
    # Steps 2 and 3: lattice values and the hash.
    n = 4096
    z00 = np.array(function(NOISE, [(0, 0, z) for z in range(n)]))
    z10 = np.array(function(NOISE, [(1, 0, z) for z in range(n)]))
    for seq in (z00, z10):
        _, counts = np.unique(seq, return_counts=True)
        if len(counts) != 256 or np.any(counts != 16):
            fail("a lattice line does not take 256 values 16 times each")
    u = np.arange(n)
    offsets = []
    for C in range(n):
        Su = z00[(u - C) & M]
        Tu = z10[(u - C) & M]
        for d in np.nonzero(Su == Tu[0])[0]:
            if np.all(Su[u ^ d] == Tu):
                offsets.append(C)
                break
    print("step 3: offsets with an XOR shift along z:", offsets)
    V0yz = np.array(function(NOISE, [(0, y, z) for y in range(n)
                                     for z in range(6)])).reshape(n, 6)
    Vxy0 = np.array(function(NOISE, [(x, y, 0) for x in range(n)
                                     for y in range(6)])).reshape(n, 6)
    found = None
    for C in offsets:
        found = solve_table(C, z00, V0yz, Vxy0)
        if found is not None:
            break
    if found is None:
        fail("no offset gives a consistent hash table")
    T, F = found
    for k in range(256):
        if len(set(F[(u & 255) == k])) != 1:
            fail("the value does not depend on the hash's low 8 bits alone")
    print("step 3: offset K = %d, T a permutation: %s"
          % (C, sorted(T.tolist()) == list(range(n))))
    rng = np.random.default_rng(16)
    L = rng.integers(-30000, 30000, size=(2000, 3))
    lv = np.array(function(NOISE, [tuple(p) for p in L]))
    bad = np.sum(F[hash3(T, C, L)] != lv)
    print("step 3: hash checked on 2000 random lattice points: %d wrong" % bad)
    if bad:
        fail("the hash does not reproduce the lattice values")
    # Step 4: the table of values and gradients.
    P = rng.uniform(-50, 50, size=(4000, 3))
    v2 = np.array(function(NOISE, [tuple(p) for p in P]))
    A = design(T, C, P)
    sol = np.linalg.lstsq(A, v2, rcond=None)[0]
    r4 = np.abs(A @ sol - v2).max()
    print("step 4: fit of 256 values and gradients: residual %.1e" % r4)
    if r4 > 1e-12:
        fail("the noise formula does not fit")
    tab = sol.reshape(256, 4)
    if np.abs(tab[:, 0] - F[:256]).max() > 1e-12:
        fail("fitted values disagree with lattice values")
    # Step 5: generator 1.
    v1 = np.array(function("f_noise_generator(x, y, z, 1)",
                           [tuple(p) for p in P]))
    m = (v1 > 0) & (v1 < 1)
    b, a = np.polyfit(v2[m], v1[m], 1)
    r5 = np.abs(np.clip(a + b * v2, 0, 1) - v1).max()
    print("step 5: generator 1 = clamp(%.12g + %.12g n): residual %.1e"
          % (a, b, r5))
    if r5 > 1e-12:
        fail("generator 1 is not an affine map of generator 2")
    # Step 6: the vector noise of turbulence.
    t = 0.001
    dtabs = []
    for ax, axis in enumerate("xyz"):
        Q = rng.uniform(0, 60, size=(4000, 3))
        Q[:, ax] = np.floor(Q[:, ax]) + rng.uniform(0.1, 0.9, size=4000)
        v = np.array(function("pattern { gradient %s warp { turbulence %g "
                              "octaves 1 } }" % (axis, t),
                              [tuple(p) for p in Q]))
        D = (v - (Q[:, ax] - np.floor(Q[:, ax]))) / t
        A = design(T, C, Q)
        sol = np.linalg.lstsq(A, D, rcond=None)[0]
        r6 = np.abs(A @ sol - D).max()
        print("step 6: vector noise %s: residual %.1e" % (axis, r6))
        if r6 > 1e-9:
            fail("the vector noise does not fit")
        dtabs.append(sol.reshape(256, 4))
    with open(out, "w") as f:
        f.write("/* noise_tables.h - POV-Ray 3.7's lattice noise tables, "
                "written by\n   bench/noise/probe_noise.py from povray's "
                "output (do not edit).\n   See lib/core/noise.c for their "
                "use. */\n\n")
        f.write("/* The offset added to lattice coordinates before the "
                "hash. */\n#define NOISE_HASH_OFFSET %d\n\n" % C)
        f.write("/* noise_generator 1 = clamp(A + B n2, 0, 1). */\n")
        f.write("#define NOISE_GEN1_A %.17g\n#define NOISE_GEN1_B %.17g\n\n"
                % (a, b))
        f.write("/* The hash permutation of 0..4095. */\n"
                "static const unsigned short noise_hash[4096] = {\n")
        for i in range(0, n, 12):
            f.write("    " + ", ".join("%d" % t for t in T[i:i + 12]) +
                    ",\n")
        f.write("};\n\n/* Value and gradient (x, y, z) of each hash's low "
                "8 bits. */\nstatic const double noise_lattice[256][4] = "
                "{\n")
        for row in tab:
            f.write("    {" + ", ".join("%.14g" % v for v in row) + "},\n")
        f.write("};\n")
        f.write("\n/* The vector noise of turbulence: for each component x, y, "
                "z, the\n   value and gradient of each hash's low 8 bits. "
                "*/\nstatic const double dnoise_lattice[3][256][4] = {\n")
        for tab in dtabs:
            f.write("  {\n")
            for row in tab:
                f.write("    {" + ", ".join("%.11g" % v for v in row) +
                        "},\n")
            f.write("  },\n")
        f.write("};\n")
    print("wrote", out)


if __name__ == "__main__":
    main()
