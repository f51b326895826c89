#!/usr/bin/python3
"""Write bench/noise/noise_lanes.h from bench/noise/noise_tables.h.

The AVX2 blend of lib/core/noise.c computes the three components of
turbulence's vector noise (and the value noise) in the four lanes of one
register, so it wants the tables interleaved: entry [h][c][m] is
coefficient c (value, then the x, y, z gradient) of hash h for lane m,
lanes 0-2 the vector noise's components (dnoise_lattice[m][h][c]) and
lane 3 the value noise (noise_lattice[h][c]).  The numbers are the same
doubles, printed so that they read back exactly (Python's repr); the
test noise_lanes in tests/test_noise.c compares the two headers.

Usage: /usr/bin/python3 bench/noise/lanes.py   (rewrites the header)
"""
import os
import re

HERE = os.path.dirname(os.path.abspath(__file__))


def table(src, name, count):
    m = re.search(r'\b' + name + r'\[[^=]*=\s*\{(.*?)\n\};', src, re.S)
    nums = [float(x) for x in re.findall(
        r'[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?', m.group(1))]
    assert len(nums) == count, (name, len(nums))
    return nums


def main():
    src = open(os.path.join(HERE, 'noise_tables.h')).read()
    value = table(src, 'noise_lattice', 256 * 4)
    vector = table(src, 'dnoise_lattice', 3 * 256 * 4)
    out = ['/* noise_lanes.h - noise_tables.h\'s noise_lattice and '
           'dnoise_lattice',
           '   interleaved for the AVX2 blend, written by '
           'bench/noise/lanes.py',
           '   (do not edit): noise_lanes[h][c][m] is coefficient c of hash '
           'h',
           '   for lane m, lanes 0-2 dnoise_lattice[m][h][c], lane 3',
           '   noise_lattice[h][c]. */',
           '',
           'static const _Alignas(32) double noise_lanes[256][4][4] = {']
    for h in range(256):
        rows = []
        for c in range(4):
            lanes = [vector[(m * 256 + h) * 4 + c] for m in range(3)]
            lanes.append(value[h * 4 + c])
            rows.append('{' + ', '.join(repr(v) for v in lanes) + '}')
        out.append('    {' + ',\n     '.join(rows) + '},')
    out.append('};')
    with open(os.path.join(HERE, 'noise_lanes.h'), 'w') as f:
        f.write('\n'.join(out) + '\n')


if __name__ == '__main__':
    main()
