#!/usr/bin/python3
"""region_mean.py IMAGE 'R0:R1,C0:C1=R,G,B' ... [--tol N]: compares the
mean colour of rectangles of an 8-bit picture (rows R0..R1-1, columns
C0..C1-1) with recorded values (povray 3.7's), each channel within N
levels (default 12: photon estimates are noisy, and a region's mean is
what a beam's brightness is).  One line per check; exits 1 when one
fails."""
import sys

from skimage import io


def main(argv):
    tol, checks = 12.0, []
    it = iter(argv[2:])
    for a in it:
        if a == '--tol':
            tol = float(next(it))
        else:
            checks.append(a)
    img = io.imread(argv[1])[..., :3].astype(float)
    bad = 0
    for c in checks:
        where, want = c.split('=')
        rows, cols = where.split(',')
        r0, r1 = (int(v) for v in rows.split(':'))
        c0, c1 = (int(v) for v in cols.split(':'))
        want = [float(v) for v in want.split(',')]
        got = img[r0:r1, c0:c1].mean(axis=(0, 1))
        ok = max(abs(x - y) for x, y in zip(got, want)) <= tol
        bad += not ok
        print('%s: %s mean %s, want %s (tol %g)' % (
            'ok' if ok else 'FAIL', where,
            ','.join('%.1f' % v for v in got),
            ','.join('%.1f' % v for v in want), tol))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
