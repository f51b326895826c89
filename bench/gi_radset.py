#!/usr/bin/python3
"""The stock scenes with a radiosity{} block, rendered by one zRcube build
and compared with POV-Ray 3.7's pictures (bench/conformance.py's size,
options, cached references and SSIM).

Usage: gi_radset.py ZRCUBE OUTDIR [--only SUBSTRING ...] [--jobs N]

Prints scene, exit, seconds, SSIM (scenes without a POV-Ray reference
are left out); the list is every scene under
/usr/share/povray-3.7/scenes whose text names `radiosity` (18 files in
povray 3.7.0.10, the same as in the examples folder).
"""
import argparse
import concurrent.futures
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import conformance as cf  # noqa: E402
import zrexe  # noqa: E402

SCENES = '/usr/share/povray-3.7/scenes'


def radiosity_scenes():
    out = []
    for root, _, files in os.walk(SCENES):
        for f in files:
            if f.endswith('.pov'):
                p = os.path.join(root, f)
                with open(p, 'rb') as fh:
                    if b'radiosity' in fh.read():
                        out.append(os.path.relpath(p, SCENES))
    return sorted(out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('zrcube')
    ap.add_argument('out')
    ap.add_argument('--only', action='append', default=[])
    ap.add_argument('--jobs', type=int, default=1)
    ap.add_argument('--timeout', type=float, default=120.0)
    a = ap.parse_args()
    here = os.path.dirname(os.path.abspath(__file__))
    refs = os.path.join(here, 'out', 'conformance', 'povray')
    zr = zrexe.unwrap(os.path.abspath(a.zrcube))
    os.makedirs(a.out, exist_ok=True)
    scenes = radiosity_scenes()
    if a.only:
        scenes = [s for s in scenes if any(o in s for o in a.only)]
    # Scenes POV-Ray did not render (no reference: diffuse_back.pov
    # passes conformance.py's 60 s) are left out.
    scenes = [s for s in scenes
              if os.path.exists(os.path.join(refs, cf.flat(s)))]

    def one(rel):
        path = os.path.join(cf.EXAMPLES, rel)
        cwd = os.path.dirname(path)
        out = os.path.join(a.out, cf.flat(rel))
        rc, secs, err = cf.run([zr, '+I' + path, '+O' + out] + cf.SIZE +
                               ['-D', '+WT1', '+L' + cf.INCLUDE, '+L' + cwd],
                               cwd, a.timeout)
        ref = os.path.join(refs, cf.flat(rel))
        v = None
        if rc == 0 and os.path.exists(ref):
            v = cf.ssim(out, ref)
        return rel, rc, secs, v

    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        for rel, rc, secs, v in pool.map(one, scenes):
            s = '-' if v is None else f'{v:.4f}'
            print(f'{rel}\t{rc}\t{secs:.2f}\t{s}', flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
