#!/usr/bin/python3
"""legacy_gamma_probe.py: how POV-Ray 3.7 writes flat colours under each
combination of #version (none, 3.5, 3.6, 3.7, before or after
global_settings, changed back at the end), assumed_gamma (absent, 1.0,
2.2) and the File_Gamma / Display_Gamma options, for PNG and PPM output;
the rule behind lib/sdl/directive.c's legacy gamma and the encoders
(scene description, "Gamma in Legacy Scenes": "If the scene does neither
specify an assumed_gamma statement, nor explicitly specify a version of
3.7 or later, gamma correction will be turned off").

Seven boxes with ambient 1 (rgb 0.002 0.01 0.05 0.135 0.3 0.5 0.8) are
rendered 70x10 without antialiasing; the table gives the 8-bit code of
each column's centre, POV-Ray's and (with --zrcube) ours.

usage: legacy_gamma_probe.py [--zrcube build/bin/zrcube] [--out DIR]
"""
import argparse
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import png16  # noqa: E402

VALUES = (0.002, 0.01, 0.05, 0.135, 0.3, 0.5, 0.8)

BODY = ''.join(
    'box { <%d, 0, 0>, <%d, 1, 1> pigment { rgb %g } '
    'finish { ambient 1 diffuse 0 } }\n' % (i, i + 1, v)
    for i, v in enumerate(VALUES)) + (
    'camera { orthographic location <3.5, 0.5, -2> look_at <3.5, 0.5, 0> '
    'right 7*x up y }\n')

GS1 = 'global_settings { assumed_gamma 1.0 }\n'
GS22 = 'global_settings { assumed_gamma 2.2 }\n'
GSNONE = 'global_settings { max_trace_level 5 }\n'

# (label, header, footer)
CASES = (
    ('none', '', ''),
    ('v3.5', '#version 3.5;\n', ''),
    ('v3.6', '#version 3.6;\n', ''),
    ('v3.7', '#version 3.7;\n', ''),
    ('gs-then-v3.7', GSNONE + '#version 3.7;\n', ''),
    ('v3.7-at-end', '', '#version 3.7;\n'),
    ('v3.7-then-v3.6-at-end', '#version 3.7;\n', '#version 3.6;\n'),
    ('v3.6-then-v3.7-at-end', '#version 3.6;\n', '#version 3.7;\n'),
    ('colors.inc', '#include "colors.inc"\n', ''),
    ('ag1', GS1, ''),
    ('ag2.2', GS22, ''),
    ('v3.6 ag1', '#version 3.6;\n' + GS1, ''),
    ('v3.6 ag2.2', '#version 3.6;\n' + GS22, ''),
    ('v3.7 ag1', '#version 3.7;\n' + GS1, ''),
    ('v3.7 ag2.2', '#version 3.7;\n' + GS22, ''),
    ('ag2.2-then-v3.7', GS22 + '#version 3.7;\n', ''),
)

OPTIONS = (
    ('', []),
    ('File_Gamma=1.0', ['File_Gamma=1.0']),
    ('File_Gamma=2.2', ['File_Gamma=2.2']),
    ('Display_Gamma=1.8', ['Display_Gamma=1.8']),
)


def codes(path, ppm):
    if ppm:
        data = open(path, 'rb').read()
        fields, pos = [], 0
        while len(fields) < 4:  # magic, width, height, maxval; # comments
            while data[pos:pos + 1].isspace():
                pos += 1
            if data[pos:pos + 1] == b'#':
                pos = data.index(b'\n', pos)
                continue
            end = pos
            while not data[end:end + 1].isspace():
                end += 1
            fields.append(data[pos:end])
            pos = end
        w = int(fields[1])
        pix = data[pos + 1:]
        row = 5 * w * 3
        return [pix[row + (10 * i + 5) * 3] for i in range(len(VALUES))]
    img = png16.read(path)
    return [int(round(img[5][10 * i + 5][0] * 255)) for i in range(len(VALUES))]


def render(cmd, scene, out, opts, ppm):
    if os.path.exists(out):
        os.remove(out)
    args = [cmd, '+I' + scene, '+O' + out, '+W70', '+H10', '-D', '-A',
            '+WT1', '+FP' if ppm else '+FN'] + opts
    subprocess.run(args, capture_output=True, timeout=120)
    try:
        return codes(out, ppm)
    except (OSError, AssertionError, IndexError, ValueError):
        return None



# ---- image_map pixels ----
CODES = (40, 85, 200)
IMAGE_CASES = (
    ('none', '', ''),
    ('v3.6', '#version 3.6;\n', ''),
    ('v3.7', '#version 3.7;\n', ''),
    ('ag1', GS1, ''),
    ('ag2.2', GS22, ''),
    ('v3.6 ag1', '#version 3.6;\n' + GS1, ''),
    ('v3.6 ag2.2', '#version 3.6;\n' + GS22, ''),
    ('v3.7 ag2.2', '#version 3.7;\n' + GS22, ''),
)


IMAGE_SCENE = (
    'plane { z, 0 pigment { image_map { %s "%s" } scale <7, 1, 1> } '
    'finish { ambient 1 diffuse 0 } }\n'
    'camera { orthographic location <3.5, 0.5, -2> '
    'look_at <3.5, 0.5, 0> right 7*x up y }\n')


def png_file(path, ctype, extra=b''):
    import struct
    import zlib

    def chunk(t, b):
        return (struct.pack('>I', len(b)) + t + b +
                struct.pack('>I', zlib.crc32(t + b) & 0xffffffff))
    w = 3 * 8
    d = b'\x89PNG\r\n\x1a\n' + chunk(
        b'IHDR', struct.pack('>IIBBBBB', w, 8, 8, ctype, 0, 0, 0)) + extra
    if ctype == 3:
        d += chunk(b'PLTE', bytes(c for c in CODES for _ in range(3)))
        line = bytes(i for i in range(3) for _ in range(8))
    else:
        line = bytes(c for c in CODES for _ in range(8 * 3))
    rows = b''.join(b'\x00' + line for _ in range(8))
    d += chunk(b'IDAT', zlib.compress(rows)) + chunk(b'IEND', b'')
    open(path, 'wb').write(d)


def image_files():
    """Name -> SDL image type; a 24x8 picture, 3 columns of grey codes."""
    import struct
    from PIL import Image
    png_file('plain.png', 2)
    png_file('pal.png', 3)
    # gAMA 1/2.2 and sRGB chunks.
    import zlib

    def chunk(t, b):
        return (struct.pack('>I', len(b)) + t + b +
                struct.pack('>I', zlib.crc32(t + b) & 0xffffffff))
    png_file('gama.png', 2, chunk(b'gAMA', struct.pack('>I', 45455)))
    png_file('srgb.png', 2, chunk(b'sRGB', b'\x00'))
    im = Image.new('RGB', (24, 8))
    for x in range(24):
        for y in range(8):
            c = CODES[x // 8]
            im.putpixel((x, y), (c, c, c))
    im.save('img.ppm')
    im.save('img.tga')
    im.save('img.bmp')
    im.save('img.gif')
    im.save('img.jpg', quality=100)
    return (('plain.png', 'png'), ('pal.png', 'png'), ('gama.png', 'png'),
            ('srgb.png', 'png'), ('img.ppm', 'ppm'), ('img.tga', 'tga'),
            ('img.bmp', 'bmp'), ('img.gif', 'gif'), ('img.jpg', 'jpeg'))


def image_section(zr, povray):
    files = image_files()
    print('\nimage_map of grey codes ' + ' '.join(map(str, CODES)) +
          ', ambient 1, written as 8-bit PNG')
    print('%-12s %-10s %-14s %s' % ('scene', 'file', 'povray', 'zrcube'))
    for label, head, foot in IMAGE_CASES:
        for name, kind in files:
            with open('i.pov', 'w') as f:
                f.write(head + IMAGE_SCENE % (kind, name) + foot)
            pv = render(povray, 'i.pov', 'p.png', [], False)
            zv = render(zr, 'i.pov', 'z.png', [], False) if zr else None
            pick = (lambda v: v and [v[1], v[3], v[5]])
            print('%-12s %-10s %-14s %s' % (
                label, name, ' '.join(map(str, pick(pv))) if pv else 'FAIL',
                (' '.join(map(str, pick(zv))) if zv else 'FAIL')
                if zr else ''))
            sys.stdout.flush()


# ---- the antialiasing threshold ----
AA_CASES = (
    ('none', '', ''),
    ('v3.7 ag1', '#version 3.7;\n' + GS1, ''),
    ('v3.7 ag2.2', '#version 3.7;\n' + GS22, ''),
    ('v3.6 ag2.2', '#version 3.6;\n' + GS22, ''),
)


AA_SCENE = (
    'box { <-10, -10, 0>, <0.3, 10, 1> pigment { rgb <0.01, 0, 0> }'
    ' finish { ambient 1 diffuse 0 } }\n'
    'box { <0.3, -10, 0>, <10, 10, 1> pigment { rgb <0.05, 0, 0> }'
    ' finish { ambient 1 diffuse 0 } }\n'
    'camera { orthographic location <0, 0, -2> look_at <0, 0, 0> '
    'right 20*x up 2*y }\n')


def aa_blended(cmd, threshold):
    """Whether the edge pixel of aa.pov is supersampled at +A threshold."""
    if os.path.exists('aa.png'):
        os.remove('aa.png')
    subprocess.run([cmd, '+Iaa.pov', '+Oaa.png', '+W20', '+H2', '-D',
                    '+A%g' % threshold, '+AM1', '+R3', '+WT1', '+FN16'],
                   capture_output=True, timeout=120)
    img = png16.read('aa.png')
    # The edge crosses column 10 at 0.3 of its width: its centre is dark.
    return abs(img[0][10][0] - img[0][11][0]) > 1e-4


def aa_threshold(cmd):
    lo, hi = 0.0, 0.5
    if aa_blended(cmd, hi):
        return '>%g' % hi
    for _ in range(9):
        mid = (lo + hi) / 2
        if aa_blended(cmd, mid):
            lo = mid
        else:
            hi = mid
    return '%.4f' % ((lo + hi) / 2)


def aa_section(zr, povray):
    print('\nantialiasing threshold (+AM1) at which an edge between red '
          '0.01 and 0.05 stops being supersampled')
    print('  (exponent e: |0.05^e - 0.01^e|; e=1 0.0400, e=0.88 0.0541, '
          'e=0.4 0.1433)')
    print('%-12s %-10s %s' % ('scene', 'povray', 'zrcube'))
    for label, head, foot in AA_CASES:
        with open('aa.pov', 'w') as f:
            f.write(head + AA_SCENE + foot)
        pv = aa_threshold(povray)
        zv = aa_threshold(zr) if zr else ''
        print('%-12s %-10s %s' % (label, pv, zv))
        sys.stdout.flush()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--zrcube')
    ap.add_argument('--out', default='/tmp/legacy_gamma_probe')
    ap.add_argument('--povray', default='povray')
    ap.add_argument('--section', default='all',
                    choices=('all', 'colours', 'images', 'aa'))
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    zr = os.path.abspath(a.zrcube) if a.zrcube else None
    os.chdir(a.out)
    if a.section in ('all', 'images'):
        image_section(zr, a.povray)
    if a.section in ('all', 'aa'):
        aa_section(zr, a.povray)
    if a.section not in ('all', 'colours'):
        return
    print('values: ' + ' '.join('%g' % v for v in VALUES))
    print('%-24s %-18s %-4s %-30s %s' % ('scene', 'option', 'fmt', 'povray',
                                         'zrcube'))
    for label, head, foot in CASES:
        with open('p.pov', 'w') as f:
            f.write(head + BODY + foot)
        for olabel, opts in OPTIONS:
            for ppm in (False, True):
                if ppm and olabel:
                    continue
                ext = '.ppm' if ppm else '.png'
                pv = render(a.povray, 'p.pov', 'p' + ext, opts, ppm)
                zv = render(zr, 'p.pov', 'z' + ext, opts, ppm) if zr else None
                print('%-24s %-18s %-4s %-30s %s' % (
                    label, olabel or '-', ext[1:],
                    ' '.join(map(str, pv)) if pv else 'FAIL',
                    (' '.join(map(str, zv)) if zv else 'FAIL') if zr else ''))
                sys.stdout.flush()


if __name__ == '__main__':
    main()
