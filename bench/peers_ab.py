#!/usr/bin/python3
"""peers_ab.py - two zRcube builds and Tachyon on bench/peers.sh's scenes,
interleaved, for a before/after record of issue 13.

  bench/peers_ab.py OLD_BUILD NEW_BUILD [--scenes flake] [--sizes 512 2048]
                    [--pairs 5]

OLD_BUILD and NEW_BUILD are build folders (their bin/.libs/zrcube runs
with their lib/.libs on LD_LIBRARY_PATH, as bench/zrexe.sh does) or
folders holding a copy of the program beside its libzrcube.so.*.  The
scenes come from bench/peers_gen.py in a temporary folder.  Each round
runs old, new and Tachyon once each, in that order, at one size; the
CPU seconds (user + system) of every whole process come from os.wait4
(microseconds, where /usr/bin/time rounds to 10 ms).  The table gives
the best and the median of each and the ratios new / old and
zRcube / Tachyon (issue 13's target: <= 1), with the load average.
Run it under `chrt -r 20` (as root) to get a core ahead of other jobs.
Timings are printed, never asserted.  The images of old and new are
compared byte for byte ("same" or "DIFFER").
"""
import argparse
import filecmp
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def program(build):
    """The zRcube program of a build folder and its library folder."""
    for exe, lib in (("bin/.libs/zrcube", "lib/.libs"), ("zrcube", ".")):
        path = os.path.join(build, exe)
        if os.access(path, os.X_OK):
            return path, os.path.join(build, lib)
    sys.exit("peers_ab.py: no zrcube in %s" % build)


def cpu_seconds(argv, cwd, env):
    """Runs argv; returns its user + system CPU seconds (None: failed)."""
    pid = os.fork()
    if pid == 0:
        try:
            os.chdir(cwd)
            fd = os.open(os.devnull, os.O_WRONLY)
            os.dup2(fd, 1)
            os.dup2(fd, 2)
            os.execvpe(argv[0], argv, env)
        finally:
            os._exit(127)
    _, status, usage = os.wait4(pid, 0)
    if status != 0:
        return None
    return usage.ru_utime + usage.ru_stime


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--scenes", nargs="+", default=["flake"])
    ap.add_argument("--sizes", nargs="+", type=int, default=[512, 2048])
    ap.add_argument("--pairs", type=int, default=5)
    ap.add_argument("--tachyon", default="tachyon")
    args = ap.parse_args()
    runs = {}
    for tag, build in (("old", args.old), ("new", args.new)):
        exe, lib = program(os.path.abspath(build))
        env = dict(os.environ)
        env["LD_LIBRARY_PATH"] = lib
        runs[tag] = (exe, env)
    has_tachyon = shutil.which(args.tachyon) is not None
    work = tempfile.mkdtemp(prefix="zr-peers-ab.")
    try:
        subprocess.run([sys.executable, os.path.join(HERE, "peers_gen.py"),
                        work], check=True, stdout=subprocess.DEVNULL)
        print("zRcube old (%s) vs new (%s) vs Tachyon, one thread, no AA, "
              "CPU s (user + sys) of the whole process, %d rounds "
              "interleaved" % (runs["old"][0], runs["new"][0], args.pairs))
        print("load at start: %s" % " ".join(
            open("/proc/loadavg").read().split()[:3]))
        print("%-8s %5s %9s %9s %9s %9s %9s %9s %7s %7s %7s %s" % (
            "scene", "size", "old_best", "old_med", "new_best", "new_med",
            "tach_best", "tach_med", "new/old", "old/tach", "new/tach",
            "bytes"))
        for scene in args.scenes:
            for size in args.sizes:
                t = {"old": [], "new": [], "tachyon": []}
                for _ in range(args.pairs):
                    for tag in ("old", "new"):
                        exe, env = runs[tag]
                        t[tag].append(cpu_seconds(
                            [exe, scene + ".pov", "+W%d" % size,
                             "+H%d" % size, "+WT1", "-A", "-V",
                             "+O%s.png" % tag], work, env))
                    if has_tachyon:
                        t["tachyon"].append(cpu_seconds(
                            [args.tachyon, scene + ".dat", "-numthreads",
                             "1", "-res", str(size), str(size), "-o",
                             "t.tga"], work, dict(os.environ)))
                same = filecmp.cmp(os.path.join(work, "old.png"),
                                   os.path.join(work, "new.png"),
                                   shallow=False)

                def stat(v):
                    v = [x for x in v if x is not None]
                    return (min(v), statistics.median(v)) if v else (
                        float("nan"), float("nan"))
                ob, om = stat(t["old"])
                nb, nm = stat(t["new"])
                tb, tm = stat(t["tachyon"])
                print("%-8s %5d %9.4f %9.4f %9.4f %9.4f %9.4f %9.4f "
                      "%7.3f %7.3f %7.3f %s" % (
                          scene, size, ob, om, nb, nm, tb, tm, nb / ob,
                          ob / tb, nb / tb, "same" if same else "DIFFER"))
                sys.stdout.flush()
        print("load at end: %s" % " ".join(
            open("/proc/loadavg").read().split()[:3]))
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
