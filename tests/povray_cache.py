#!/usr/bin/python3
"""povray_cache.py - POV-Ray with a render cache shared by one `make check`.

`make check` runs every test twice, in the normal build and in the
AddressSanitizer build, and many tests render the same reference scene
with POV-Ray each time.  POV-Ray's picture does not depend on which of
our builds runs the test, so the second render can be taken from the
first.  tests/shim/povray calls this script in place of povray when
ZR_POVRAY_CACHE names a folder (the top-level GNUmakefile sets it and
empties the folder at the start of every `make check`).

The key is the SHA-256 of everything the render can read: the arguments
(a path is replaced by its file's content hash, a folder by the hashes
of its files), the files of the working folder and of the scene's folder
(but not *.log files nor the output file itself), and POV-Ray's version.
A render is cached only when it exits 0, writes the output file its one
+O option names and changes no other file of the working folder;
anything else runs POV-Ray every time.
A hit copies the image and replays POV-Ray's stdout, stderr and exit
status.  ZR_POVRAY_CACHE_LOG, when set, gets one line per call.
"""
import hashlib
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SHIM = os.path.join(HERE, 'shim')


def real_povray():
    for d in os.environ.get('PATH', '').split(os.pathsep):
        if not d or os.path.abspath(d) == SHIM:
            continue
        p = os.path.join(d, 'povray')
        if os.path.isfile(p) and os.access(p, os.X_OK):
            return p
    return None


def file_hash(path, memo={}):
    st = os.stat(path)
    key = (path, st.st_mtime_ns, st.st_size)
    if key not in memo:
        h = hashlib.sha256()
        with open(path, 'rb') as fh:
            for block in iter(lambda: fh.read(1 << 20), b''):
                h.update(block)
        memo[key] = h.hexdigest()
    return memo[key]


def folder_hash(folder, skip):
    h = hashlib.sha256()
    try:
        names = sorted(os.listdir(folder))
    except OSError:
        return 'unreadable'
    for name in names:
        path = os.path.join(folder, name)
        if name.endswith('.log') or os.path.abspath(path) in skip:
            continue
        if os.path.isfile(path):
            h.update(name.encode() + b'\0' + file_hash(path).encode() + b'\n')
    return h.hexdigest()


def output_of(args):
    """The file a +O option names, or None (no option, or several)."""
    outs = [a[2:] for a in args if a[:2] in ('+O', '+o') and len(a) > 2]
    return outs[0] if len(outs) == 1 else None


def key_of(povray, args, out):
    skip = {os.path.abspath(out)}
    h = hashlib.sha256()
    h.update(file_hash(povray).encode())
    folders = {os.getcwd()}
    for a in args:
        h.update(b'\0arg\0')
        body = a[2:] if a[:1] in '+-' and len(a) > 2 else a
        if a[:2] in ('+O', '+o'):
            h.update(a.encode())
        elif os.path.isfile(body):
            h.update(a[:2].encode() + file_hash(body).encode())
            folders.add(os.path.dirname(os.path.abspath(body)))
        elif os.path.isdir(body):
            h.update(a[:2].encode() + folder_hash(body, skip).encode())
        else:
            h.update(a.encode())
    for folder in sorted(folders):
        h.update(b'\0folder\0' + folder_hash(folder, skip).encode())
    return h.hexdigest()


def snapshot(out):
    """The working folder's files but the output: a render that writes
    any other file (#fopen, +UA side files) is not cached."""
    skip = os.path.abspath(out)
    seen = {}
    for name in os.listdir('.'):
        if os.path.abspath(name) == skip or name.endswith('.log'):
            continue
        try:
            st = os.stat(name)
        except OSError:
            continue
        seen[name] = (st.st_mtime_ns, st.st_size)
    return seen


def log(line):
    path = os.environ.get('ZR_POVRAY_CACHE_LOG')
    if path:
        with open(path, 'a') as fh:
            fh.write(line + '\n')


def main():
    args = sys.argv[1:]
    povray = real_povray()
    if povray is None:
        sys.stderr.write('povray: not found\n')
        return 127
    cache = os.environ.get('ZR_POVRAY_CACHE', '')
    out = output_of(args)
    if not cache or out is None:
        os.execv(povray, [povray] + args)
    key = key_of(povray, args, out)
    entry = os.path.join(cache, key)
    if os.path.isfile(entry + '.img'):
        shutil.copyfile(entry + '.img', out)
        with open(entry + '.out', 'rb') as fh:
            sys.stdout.buffer.write(fh.read())
        with open(entry + '.err', 'rb') as fh:
            sys.stderr.buffer.write(fh.read())
        log('hit %s %s' % (key[:12], ' '.join(args)))
        return 0
    if os.path.exists(out):
        os.remove(out)
    before = snapshot(out)
    t0 = time.monotonic()
    run = subprocess.run([povray] + args, stdin=subprocess.DEVNULL,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    secs = time.monotonic() - t0
    sys.stdout.buffer.write(run.stdout)
    sys.stderr.buffer.write(run.stderr)
    if (run.returncode == 0 and os.path.isfile(out) and
            snapshot(out) == before):
        os.makedirs(cache, exist_ok=True)
        tmp = '%s.%d' % (entry, os.getpid())
        with open(tmp + '.out', 'wb') as fh:
            fh.write(run.stdout)
        with open(tmp + '.err', 'wb') as fh:
            fh.write(run.stderr)
        shutil.copyfile(out, tmp + '.img')
        for ext in ('.out', '.err', '.img'):
            os.replace(tmp + ext, entry + ext)
    log('miss %.2fs rc=%d %s %s' % (secs, run.returncode, key[:12],
                                    ' '.join(args)))
    return run.returncode


if __name__ == '__main__':
    sys.exit(main())
