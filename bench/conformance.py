#!/usr/bin/python3
"""Pixel conformance: render POV-Ray's stock example scenes with zRcube and
with POV-Ray 3.7, and compare the pictures.

Usage (run with /usr/bin/python3; needs python3-numpy and python3-skimage):

    conformance.py [--zrcube PATH] [--povray PATH] [--out DIR] [--timeout S]
                   [--jobs N] [--only SUBSTRING] [--examples DIR]

Every scene is rendered at 160x120, no antialiasing, one thread, from its own
folder, by both renderers.  POV-Ray's images are kept in OUT/povray and reused
on the next run (delete them, or pass --povray-again, to render them anew);
zRcube's go to OUT/zrcube.  The comparison is the corpus's
(../shared/corpus/compare.py): both images as 8-bit RGB, each 2x2 block
averaged, then SSIM; >= 0.95 is a match and >= 0.80 close.

Output: one tab-separated line per scene POV-Ray renders
    scene  zrcube-exit  zrcube-seconds  ssim-or-'-'  povray-seconds  last-stderr-line
and a summary line.  Scenes POV-Ray itself does not render (it exits
non-zero or reports a parse error) are counted and left out.
"""
import argparse
import concurrent.futures
import math
import os
import re
import signal
import subprocess
import sys
import time

import numpy as np
from skimage import io as skio
from skimage.metrics import structural_similarity

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import zrexe  # noqa: E402

EXAMPLES = '/usr/share/doc/povray/examples'
INCLUDE = '/usr/share/povray-3.7/include'
MATCH = 0.95
CLOSE = 0.80
SIZE = ['+W160', '+H120']


def to_rgb8(img):
    img = np.asarray(img)
    if img.dtype == np.uint16:
        img = (img.astype(np.float64) / 257.0).round()
    img = img.astype(np.float64)
    if img.ndim == 2:
        img = np.stack([img] * 3, axis=-1)
    if img.shape[-1] == 2:
        img = np.concatenate([img[..., :1]] * 3, axis=-1)
    return np.clip(img[..., :3], 0, 255).astype(np.uint8)


def box2(img):
    h, w = img.shape[0] // 2 * 2, img.shape[1] // 2 * 2
    a = img[:h, :w].astype(np.float64)
    return (a[0::2, 0::2] + a[1::2, 0::2] + a[0::2, 1::2] + a[1::2, 1::2]) / 4.0


def ssim(a_path, b_path):
    a = to_rgb8(skio.imread(a_path))
    b = to_rgb8(skio.imread(b_path))
    if a.shape != b.shape:
        raise ValueError(f'size {a.shape[1]}x{a.shape[0]}, '
                         f'reference {b.shape[1]}x{b.shape[0]}')
    return float(structural_similarity(box2(a), box2(b), channel_axis=2,
                                       data_range=255.0))


def last_line(data):
    text = data.decode('utf-8', 'replace')
    lines = [l.strip() for l in re.split(r'[\r\n]+', text) if l.strip()]
    return lines[-1].replace('\t', ' ')[:200] if lines else ''


def run(argv, cwd, timeout):
    """Runs argv in its own process group; returns (rc, seconds, stderr)."""
    t0 = time.monotonic()
    try:
        p = subprocess.Popen(argv, cwd=cwd, stdin=subprocess.DEVNULL,
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                             start_new_session=True)
    except OSError as e:
        return 127, 0.0, str(e).encode()
    try:
        _, err = p.communicate(timeout=timeout)
        rc = p.returncode
    except subprocess.TimeoutExpired:
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        _, err = p.communicate()
        rc = 124
    return rc, time.monotonic() - t0, err


def flat(rel):
    return re.sub(r'\.pov$', '', rel).replace('/', '_') + '.png'


def povray_ref(args, rel):
    """POV-Ray's render of one scene, cached: (path or None, seconds)."""
    out = os.path.join(args.out, 'povray', flat(rel))
    meta = out + '.txt'
    if not args.povray_again and os.path.exists(meta):
        with open(meta) as fh:
            rc, secs = fh.read().split()
        return (out if rc == '0' else None), float(secs)
    path = os.path.join(args.examples, rel)
    cwd = os.path.dirname(path)
    if os.path.exists(out):
        os.remove(out)
    rc, secs, err = run([args.povray, '+I' + path, '+O' + out] + SIZE +
                        ['-D', '-A', '+WT1', '-GA', '+L' + INCLUDE,
                         '+L' + cwd], cwd, args.timeout)
    text = err.decode('utf-8', 'replace')
    parse_error = any('Parse Error' in l and 'Possible' not in l
                      for l in text.splitlines())
    ok = rc == 0 and not parse_error and os.path.exists(out)
    with open(meta, 'w') as fh:
        fh.write(f'{0 if ok else 1} {secs:.2f}\n')
    return (out if ok else None), secs


def one(args, rel):
    ref, pov_secs = povray_ref(args, rel)
    if ref is None:
        return None
    path = os.path.join(args.examples, rel)
    cwd = os.path.dirname(path)
    out = os.path.join(args.out, 'zrcube', flat(rel))
    if os.path.exists(out):
        os.remove(out)
    rc, secs, err = run([args.zrcube, '+I' + path, '+O' + out] + SIZE +
                        ['-D', '+WT1', '+L' + INCLUDE, '+L' + cwd], cwd,
                        args.timeout)
    note = last_line(err) if rc != 124 else f'[killed after {args.timeout:g} s]'
    value = None
    if rc == 0:
        try:
            value = ssim(out, ref)
        except Exception as e:  # missing, unreadable or wrong size
            note = f'[{e}] ' + note
    return rel, rc, secs, value, pov_secs, note


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--zrcube', default=os.path.join(here, '..', 'build', 'bin', 'zrcube'))
    ap.add_argument('--povray', default='povray')
    ap.add_argument('--out', default=os.path.join(here, 'out', 'conformance'))
    ap.add_argument('--timeout', type=float, default=60.0)
    ap.add_argument('--jobs', type=int, default=1)
    ap.add_argument('--only', help='only scenes whose path contains this')
    ap.add_argument('--examples', default=EXAMPLES)
    ap.add_argument('--povray-again', action='store_true',
                    help='render the POV-Ray references again')
    args = ap.parse_args()
    if not os.path.isdir(args.examples):
        print(f'conformance: {args.examples} missing '
              '(apt-get install povray-examples)', file=sys.stderr)
        return 77
    args.zrcube = zrexe.unwrap(os.path.abspath(args.zrcube))
    args.out = os.path.abspath(args.out)
    for sub in ('povray', 'zrcube'):
        os.makedirs(os.path.join(args.out, sub), exist_ok=True)
    scenes = []
    for root, _, files in os.walk(args.examples):
        for f in files:
            if f.endswith('.pov'):
                scenes.append(os.path.relpath(os.path.join(root, f), args.examples))
    scenes.sort()
    if args.only:
        scenes = [s for s in scenes if args.only in s]
    print(f'# zrcube: {args.zrcube}', flush=True)
    print('# scene\texit\tseconds\tssim\tpovray_seconds\tlast_stderr', flush=True)
    results = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = [pool.submit(one, args, s) for s in scenes]
        for fut in futures:
            r = fut.result()
            if r is None:
                continue
            rel, rc, secs, value, pov_secs, note = r
            results.append(r)
            s = '-' if value is None else f'{value:.4f}'
            print(f'{rel}\t{rc}\t{secs:.2f}\t{s}\t{pov_secs:.2f}\t{note}', flush=True)
    rendered = [r for r in results if r[1] == 0 and r[3] is not None]
    close = [r for r in rendered if r[3] >= CLOSE]
    match = [r for r in rendered if r[3] >= MATCH]
    timeouts = [r for r in results if r[1] == 124]
    slow = [r for r in rendered if r[4] > 0 and r[2] > 1.5 * r[4]]
    ratios = [r[2] / r[4] for r in match if r[4] > 0 and r[2] > 0]
    gm = math.exp(sum(map(math.log, ratios)) / len(ratios)) if ratios else float('nan')
    n = len(results)
    pct = 100.0 * len(match) / n if n else 0.0
    print(f'# summary\tscenes={n}\trendered={len(rendered)}\tclose={len(close)}'
          f'\tmatch={len(match)} ({pct:.1f}%)\ttimeouts={len(timeouts)}'
          f'\tslower_than_1.5x={len(slow)}'
          f'\ttime_ratio_geomean_on_matches={gm:.3f}', flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
