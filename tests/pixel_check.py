#!/usr/bin/python3
"""pixel_check.py IMAGE 'ROW,COL=R,G,B' ... [--tol N] [--ref REF.png]:
compares pixels of an 8-bit picture with recorded values (povray 3.7's,
each channel within N levels, default 2) and, with --ref, every pixel
with another picture of the same size.  Prints one line per check;
exits 1 when one fails."""
import sys

from skimage import io


def main(argv):
    tol, ref, checks = 2, None, []
    it = iter(argv[2:])
    for a in it:
        if a == '--tol':
            tol = int(next(it))
        elif a == '--ref':
            ref = next(it)
        else:
            checks.append(a)
    img = io.imread(argv[1])[..., :3].astype(int)
    bad = 0
    for c in checks:
        where, want = c.split('=')
        r, q = (int(v) for v in where.split(','))
        want = [int(v) for v in want.split(',')]
        got = [int(v) for v in img[r, q]]
        ok = max(abs(x - y) for x, y in zip(got, want)) <= tol
        bad += not ok
        print('pixel %d,%d: %s, recorded %s %s' % (r, q, got, want,
                                                 'ok' if ok else 'FAIL'))
    if ref:
        other = io.imread(ref)[..., :3].astype(int)
        worst = int(abs(img - other).max()) if img.shape == other.shape else 999
        ok = worst <= tol
        bad += not ok
        print('whole picture against %s: worst channel difference %d %s'
              % (ref, worst, 'ok' if ok else 'FAIL'))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
