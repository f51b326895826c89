#!/usr/bin/python3
"""Speed against POV-Ray in CPU seconds: which scenes zRcube renders more
than 1.5x slower than POV-Ray 3.7 (issue 16's target).

Usage (run with /usr/bin/python3):

    speed.py [--zrcube PATH] [--povray PATH] [--set stock|corpus]
             [--only SUBSTRING] [--floor S] [--pairs N] [--timeout S]

Each scene is rendered as bench/conformance.py and the corpus's compare.py
render it (160x120, no antialiasing, one thread, from its own folder; the
image goes to a scratch file), and the CPU seconds of the whole process
(user + system, parse included, children included: os.wait4's resource use)
are recorded.  CPU seconds, not wall seconds, because the project machine's
two cores are shared by many jobs: wall time there is 3-10x the CPU time
and varies from run to run.

POV-Ray spends about 0.1 s of CPU on a one-sphere scene (0.6 s wall on an
idle machine: start-up is mostly waiting), so a scene that zRcube renders
in less than FLOOR CPU seconds (default 0.15 = 1.5 x 0.1) cannot be over
the target; POV-Ray is timed only for the others (the candidates), zRcube
and POV-Ray one after the other, PAIRS times (default 1; 2 or 3 to re-time
the suspects), and the smaller CPU time of each is kept.

Output: one tab-separated line per scene
    scene  zrcube_exit  zrcube_cpu  povray_cpu-or-'-'  ratio-or-'-'
and a summary line with the scenes over 1.5x.
"""
import argparse
import os
import signal
import subprocess
import sys
import tempfile
import threading

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import zrexe  # noqa: E402

EXAMPLES = '/usr/share/doc/povray/examples'
CORPUS = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                      '..', '..', 'shared', 'corpus')
INCLUDE = '/usr/share/povray-3.7/include'
SIZE = ['+W160', '+H120', '-D', '+WT1']


def cpu_run(argv, cwd, timeout):
    """Runs argv; returns (exit code, CPU seconds of it and its children).
    Exit 124 when it was killed after TIMEOUT wall seconds."""
    p = subprocess.Popen(argv, cwd=cwd, stdin=subprocess.DEVNULL,
                         stdout=subprocess.DEVNULL,
                         stderr=subprocess.DEVNULL, start_new_session=True)
    killed = []

    def kill():
        killed.append(True)
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    timer = threading.Timer(timeout, kill)
    timer.start()
    _, status, usage = os.wait4(p.pid, 0)
    timer.cancel()
    p.returncode = os.waitstatus_to_exitcode(status)
    rc = 124 if killed else p.returncode
    return rc, usage.ru_utime + usage.ru_stime


def scenes_of(args):
    if args.set == 'stock':
        base = args.examples
        out = []
        for root, _, files in os.walk(base):
            out += [os.path.relpath(os.path.join(root, f), base)
                    for f in files if f.endswith('.pov')]
        # Only what POV-Ray renders: the lead's cached references say so.
        refs = args.povray_refs
        if refs and os.path.isdir(refs):
            def ref(rel):
                return os.path.join(refs, rel[:-4].replace('/', '_') + '.png')
            out = [s for s in out if os.path.exists(ref(s))]
        return base, sorted(out)
    base = os.path.join(args.corpus, 'scenes')
    out = []
    with open(os.path.join(args.corpus, 'povray37-160x120.tsv')) as fh:
        for line in fh:
            f = line.rstrip('\n').split('\t')
            if len(f) >= 2 and f[1] == '0':
                out.append(f[0])
    return base, sorted(out)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--zrcube',
                    default=os.path.join(here, '..', 'build', 'bin', 'zrcube'))
    ap.add_argument('--povray', default='povray')
    ap.add_argument('--set', choices=('stock', 'corpus'), default='stock')
    ap.add_argument('--examples', default=EXAMPLES)
    ap.add_argument('--corpus', default=CORPUS)
    ap.add_argument('--povray-refs', default='/work/conf/out/povray',
                    help='folder of cached POV-Ray renders of the stock '
                    'scenes (conformance.py names); scenes without one are '
                    'left out when it exists')
    ap.add_argument('--only', help='only scenes whose path contains this')
    ap.add_argument('--floor', type=float, default=0.15)
    ap.add_argument('--pairs', type=int, default=1)
    ap.add_argument('--timeout', type=float, default=120.0)
    args = ap.parse_args()
    args.zrcube = zrexe.unwrap(os.path.abspath(args.zrcube))
    base, scenes = scenes_of(args)
    if args.only:
        scenes = [s for s in scenes if args.only in s]
    scratch = tempfile.mkdtemp(prefix='zr-speed-')
    print(f'# zrcube: {args.zrcube}; set {args.set}; floor {args.floor} s; '
          f'best of {args.pairs} pairs; CPU s = user + sys', flush=True)
    print('# scene\tzrcube_exit\tzrcube_cpu\tpovray_cpu\tratio', flush=True)
    slow = []
    for rel in scenes:
        path = os.path.join(base, rel)
        cwd = os.path.dirname(path)
        zr = [args.zrcube, '+I' + path, '+O' + os.path.join(scratch, 'z.png')]
        zr += SIZE + ['+L' + INCLUDE, '+L' + cwd]
        pv = [args.povray, '+I' + path, '+O' + os.path.join(scratch, 'p.png')]
        pv += SIZE + ['-A', '-GA', '+L' + INCLUDE, '+L' + cwd]
        rc, zcpu = cpu_run(zr, cwd, args.timeout)
        pcpu = None
        if rc != 0 or zcpu >= args.floor:
            pcpu = cpu_run(pv, cwd, args.timeout)[1]
            for _ in range(args.pairs - 1):
                rc2, z2 = cpu_run(zr, cwd, args.timeout)
                zcpu = min(zcpu, z2) if rc2 == rc else zcpu
                pcpu = min(pcpu, cpu_run(pv, cwd, args.timeout)[1])
        ratio = zcpu / pcpu if pcpu else None
        if ratio is not None and ratio > 1.5:
            slow.append(rel)
        p = '-' if pcpu is None else f'{pcpu:.2f}'
        r = '-' if ratio is None else f'{ratio:.2f}'
        print(f'{rel}\t{rc}\t{zcpu:.2f}\t{p}\t{r}', flush=True)
    print(f'# summary\tscenes={len(scenes)}\tslower_than_1.5x={len(slow)}'
          f'\t{" ".join(slow)}', flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
