"""refused.py - the corpus scenes POV-Ray 3.7 refuses, run through zrcube.

    /usr/bin/python3 bench/refused.py [--build build] [--out bench/out/refused]
        [--jobs 1] [--only SUBSTRING] [--notes bench/refused-notes.tsv]
        [--povray-cache DIR] [--before OLD.tsv]
        > bench/results/refused-DATE.tsv

For every scene with exit code 1 in the corpus's povray37-160x120.tsv
(POV-Ray refused it), from the scene's own directory as the corpus
README says:

  povray +I<scene> +O<png> +W160 +H120 -D -A +WT1 +L<std include>
      (timeout 25 s; the README's options without -GA, which silences
      the parser's message and leaves only 'Cannot parse input')
  zrcube +I<scene> +O<png> +W160 +H120 -D +WT1   (timeout 60 s)

Both stderrs are kept in OUT/povray/NAME.err and OUT/zrcube/NAME.err.
One tab-separated line a scene:

  scene  pov_rc  pov_where  pov_message  zr_rc  zr_seconds  zr_where
  zr_message  place  class  note

pov_where is FILE:LINE of POV-Ray's last 'Parse Error' (or other
error), zr_where FILE:LINE:COL of zrcube's first 'error:' line.  place
is 'same' when both name the same file (base name) and line, 'file'
when only the file agrees, else 'other'.  class is worked out here:

  crash     zrcube died of a signal or a sanitizer spoke
  hang      zrcube ran out of its 60 s
  renders   zrcube exited 0 (what povray refuses)
  same      zrcube refused as well, for the same kind of problem
            (semicolon, include, image, font, version, undeclared,
            syntax) in the same file
  other:P/Z zrcube refused for another kind (P povray's, Z zrcube's) or
            in another file

and NOTES (scene, class, note; a hand-made verdict after reading both
messages and the scene) replaces class and gives the note.  The last
line counts the classes."""
import argparse
import concurrent.futures
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import zrexe  # noqa: E402

CORPUS = '/work/shared/corpus'
INCLUDE = '/usr/share/povray-3.7/include'


def name_of(scene):
    return re.sub(r'\.pov$', '', scene.replace('/', '_'), flags=re.I)


def run(cmd, cwd, timeout, err_path):
    """Runs CMD in CWD in its own process group; returns (rc, seconds,
    stderr text).  A timeout kills the group and gives 124."""
    t0 = time.monotonic()
    with open(err_path, 'wb') as err:
        p = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.DEVNULL,
                             stderr=err, start_new_session=True)
        try:
            rc = p.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, 9)
            p.wait()
            rc = 124
    secs = time.monotonic() - t0
    with open(err_path, 'rb') as f:
        text = f.read().decode('utf-8', 'replace')
    return rc, secs, text


POV_ERR = re.compile(r"^File '([^']*)' line (\d+): (Parse Error|Error|"
                     r"Fatal Error|Parse Warning)?:? ?(.*)$")


def povray_message(text):
    """(where, message) of POV-Ray's last error in TEXT: 'File .. line
    N: Parse Error: ...' with its continuation lines joined; a 'Possible
    Parse Error' (POV-Ray's warning) when no error names a place."""
    lines = text.splitlines()
    errors, possible = [], []
    i = 0
    while i < len(lines):
        m = POV_ERR.match(lines[i])
        if m:
            msg = m.group(4)
            j = i + 1
            while j < len(lines) and lines[j].startswith(' ') and \
                    not lines[j].startswith('  '):
                msg += ' ' + lines[j].strip()
                j += 1
            msg = re.sub(r'^Possible Parse Error: ', '', msg)
            entry = ('%s:%s' % (m.group(1), m.group(2)), msg)
            if 'Possible' in lines[i] or 'Warning' in lines[i]:
                possible.append(entry)
            else:
                errors.append(entry)
            i = j
            continue
        i += 1
    if errors:
        return errors[-1]
    fatal = [l for l in lines if l.startswith('Fatal error')]
    if possible:
        w, msg = possible[-1]
        if fatal:
            msg += ' (' + fatal[-1].strip() + ')'
        return (w, msg)
    for line in lines:
        if re.search(r'error', line, re.I) and 'Cannot parse input' \
                not in line and 'Render failed' not in line:
            return ('-', line.strip())
    return ('-', 'Cannot parse input' if 'Cannot parse input' in text
            else '-')


ZR_ERR = re.compile(r'^(.*?):(\d+):(\d+): (?:fatal )?error: (.*)$')


def zrcube_message(text):
    for line in text.splitlines():
        m = ZR_ERR.match(line)
        if m:
            return ('%s:%s:%s' % m.group(1, 2, 3), m.group(4))
    for line in text.splitlines():
        if re.search(r'error|Sanitizer|runtime error', line, re.I):
            return ('-', line.strip())
    last = [l for l in text.splitlines() if l.strip()]
    return ('-', last[-1].strip() if last else '-')


POV_CAUSES = [
    ('semicolon', r'require semi-colon'),
    ('include', r'Cannot open include file'),
    ('image', r'Cannot find image file|Cannot open image'),
    ('font', r'Cannot open font file'),
    ('version', r'requires POV-Ray version'),
    ('undeclared', r'undeclared identifier|uninitialized identifier'),
]
ZR_CAUSES = [
    ('semicolon', r"needs ';' at its end"),
    ('include', r'cannot find include file'),
    ('image', r'^(image_map|height_field|bump_map|image_pattern|[a-z_]+) '
              r'file .* not found'),
    ('font', r'cannot find font'),
    ('version', r'needs POV-Ray version'),
    ('undeclared', r'undefined identifier'),
]


def cause(message, table):
    """The kind of problem a message names (the same words for both
    renderers), 'syntax' for the rest."""
    for name, pattern in table:
        if re.search(pattern, message):
            return name
    return 'syntax'


def place(pov_where, zr_where):
    if pov_where == '-' or zr_where == '-':
        return '-'
    pf, pl = pov_where.rsplit(':', 1)
    zf, zl = zr_where.split(':')[0:2]
    if os.path.basename(pf) != os.path.basename(zf):
        return 'other'
    return 'same' if pl == zl else 'file'


def one(scene, args, zr):
    d = os.path.join(CORPUS, 'scenes', os.path.dirname(scene))
    b = os.path.basename(scene)
    n = name_of(scene)
    pov_err = os.path.join(args.out, 'povray', n + '.err')
    cached = args.povray_cache and os.path.join(args.povray_cache,
                                                n + '.err')
    if cached and os.path.exists(cached):
        prc = int(open(cached[:-4] + '.rc').read())
        ptext = open(cached, encoding='utf-8', errors='replace').read()
        with open(pov_err, 'w') as f:
            f.write(ptext)
    else:
        prc, _, ptext = run(['nice', '-n', '10', 'povray', '+I' + b,
                             '+O' + os.path.join(args.out, 'povray',
                                                 n + '.png'),
                             '+W160', '+H120', '-D', '-A', '+WT1',
                             '+L' + INCLUDE], d, 25, pov_err)
        with open(pov_err[:-4] + '.rc', 'w') as f:
            f.write('%d\n' % prc)
    zpng = os.path.join(args.out, 'zrcube', n + '.png')
    if os.path.exists(zpng):
        os.unlink(zpng)
    zrc, zsecs, ztext = run(['nice', '-n', '10', zr, '+I' + b, '+O' + zpng,
                             '+W160', '+H120', '-D', '+WT1'], d, 60,
                            os.path.join(args.out, 'zrcube', n + '.err'))
    pw, pm = povray_message(ptext)
    zw, zm = zrcube_message(ztext)
    if zrc >= 128 or zrc < 0 or re.search(
            r'Sanitizer|runtime error:|Segmentation|Aborted', ztext):
        cls = 'crash'
    elif zrc == 124:
        cls = 'hang'
    elif zrc == 0:
        cls = 'renders'
    else:
        cls = 'refuses'
    if cls == 'refuses':
        pc, zc = cause(pm, POV_CAUSES), cause(zm, ZR_CAUSES)
        pl = place(pw, zw)
        # The same problem in the same file: POV-Ray names the line where
        # it noticed (often the next token's), zrcube the token's own.
        cls = 'same' if pc == zc and pl in ('same', 'file') else \
            'other:%s/%s' % (pc, zc)
    return [scene, str(prc), pw, pm, str(zrc), '%.2f' % zsecs, zw, zm,
            place(pw, zw), cls, '']


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', default='build')
    ap.add_argument('--out', default='bench/out/refused')
    ap.add_argument('--jobs', type=int, default=1)
    ap.add_argument('--only', default='')
    ap.add_argument('--notes', default=os.path.join(HERE,
                                                    'refused-notes.tsv'))
    ap.add_argument('--povray-cache', default='')
    ap.add_argument('--before', default='',
                    help='an earlier table (of main): where zrcube said '
                    'something else then, the note says what')
    args = ap.parse_args()
    args.out = os.path.abspath(args.out)
    for sub in ('povray', 'zrcube'):
        os.makedirs(os.path.join(args.out, sub), exist_ok=True)
    zr = zrexe.unwrap(os.path.abspath(os.path.join(args.build, 'bin',
                                                   'zrcube')))
    scenes = []
    with open(os.path.join(CORPUS, 'povray37-160x120.tsv')) as f:
        for line in f:
            p = line.rstrip('\n').split('\t')
            if len(p) >= 2 and p[1] == '1' and args.only in p[0]:
                scenes.append(p[0])
    notes = {}
    if os.path.exists(args.notes):
        with open(args.notes) as f:
            for line in f:
                if line.startswith('#') or not line.strip():
                    continue
                p = line.rstrip('\n').split('\t')
                notes[p[0]] = (p[1], p[2] if len(p) > 2 else '')
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as ex:
        rows = list(ex.map(lambda s: one(s, args, zr), scenes))
    before = {}
    if args.before:
        with open(args.before) as f:
            for line in f:
                p = line.rstrip('\n').split('\t')
                if len(p) >= 8 and not line.startswith(('#', 'scene\t')):
                    before[p[0]] = p
    counts = {}
    print('\t'.join(['scene', 'pov_rc', 'pov_where', 'pov_message',
                     'zr_rc', 'zr_seconds', 'zr_where', 'zr_message',
                     'place', 'class', 'note']))
    for r in rows:
        if r[0] in notes:
            auto = r[9]
            r[9], r[10] = notes[r[0]]
            # A verdict made for a refusal does not hide a new crash.
            if auto in ('crash', 'hang') and r[9] != auto:
                r[9] = auto
        b = before.get(r[0])
        if b and (b[4] != r[4] or b[6] != r[6]):
            was = 'rendered it (exit 0)' if b[4] == '0' else \
                'exit %s, %s %s' % (b[4], b[6], b[7])
            r[10] = ('main: %s; %s' % (was, r[10])).rstrip('; ')
        counts[r[9]] = counts.get(r[9], 0) + 1
        print('\t'.join(x.replace('\t', ' ') for x in r))
    print('# summary\tscenes=%d\t%s' % (len(rows), '\t'.join(
        '%s=%d' % kv for kv in sorted(counts.items()))))


if __name__ == '__main__':
    main()
