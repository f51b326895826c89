#!/usr/bin/env python3
"""Copy of a scene with more media samples, to learn whether POV-Ray's own
picture of it is converged (bench/media_warp_ssim.sh).

Usage: media_more_samples.py IN.pov OUT.pov [FACTOR]

Every `media { ... }` block of IN.pov gets, just before its closing brace
(later items override earlier ones, reference manual "Media"),
`samples FACTOR*min, FACTOR*max` (the block's own samples, or the default
1, 1) and, for methods 1 and 2, FACTOR times its intervals.  Media given
in other files (includes) are left as they are.
"""
import re
import sys


def blocks(text):
    """(start of the body, index of the closing brace) of each media block."""
    for m in re.finditer(r'\bmedia\s*\{', text):
        depth, i = 1, m.end()
        while i < len(text) and depth:
            c = text[i]
            if c == '/' and text.startswith('//', i):
                i = text.find('\n', i)
                i = len(text) if i < 0 else i
                continue
            if c == '/' and text.startswith('/*', i):
                j = text.find('*/', i + 2)
                i = len(text) if j < 0 else j + 2
                continue
            if c == '"':
                j = text.find('"', i + 1)
                i = len(text) if j < 0 else j + 1
                continue
            depth += (c == '{') - (c == '}')
            i += 1
        if depth == 0:
            yield m.end(), i - 1


def number(body, key, default):
    m = re.search(r'\b' + key + r'\s+([0-9.]+)(\s*,\s*([0-9.]+))?', body)
    if not m:
        return default
    a = float(m.group(1))
    b = float(m.group(3)) if m.group(3) else a
    return (a, b)


def main():
    src, dst = sys.argv[1], sys.argv[2]
    factor = int(sys.argv[3]) if len(sys.argv) > 3 else 4
    text = open(src, encoding='latin-1').read()
    edits = []
    for start, close in blocks(text):
        body = text[start:close]
        lo, hi = number(body, 'samples', (1, 1))
        method = int(number(body, 'method', (3, 3))[0])
        extra = ' samples %d, %d' % (max(factor * lo, factor),
                                     max(factor * hi, factor * lo, factor))
        if method in (1, 2):
            n = int(number(body, 'intervals', (10, 10))[0])
            extra += ' intervals %d' % (factor * n)
        edits.append((close, extra + ' '))
    for at, extra in sorted(edits, reverse=True):
        text = text[:at] + extra + text[at:]
    open(dst, 'w', encoding='latin-1').write(text)
    print(len(edits))


if __name__ == '__main__':
    main()
