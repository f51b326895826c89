"""zrexe.py - the program a build's bin/zrcube stands for.

In a build tree, bin/zrcube is libtool's wrapper script: it finds the
uninstalled library, sets LD_LIBRARY_PATH and runs bin/.libs/zrcube.
The wrapper costs about 0.15-0.2 CPU seconds a run here (a shell and
a few sed processes), as much as a whole small render, so timing tools
run the real program with the library's folder on LD_LIBRARY_PATH, as
an installed zrcube runs (bench/peers.sh does the same in shell)."""
import os


def unwrap(path):
    """The real program behind PATH when PATH is a build's libtool
    wrapper (LD_LIBRARY_PATH of this process then names the build's
    library folder, for the children); else PATH itself."""
    folder, name = os.path.split(os.path.abspath(path))
    real = os.path.join(folder, '.libs', name)
    lib = os.path.join(os.path.dirname(folder), 'lib', '.libs')
    if not (os.path.isfile(real) and os.access(real, os.X_OK) and
            os.path.isdir(lib)):
        return path
    old = os.environ.get('LD_LIBRARY_PATH')
    os.environ['LD_LIBRARY_PATH'] = lib + (':' + old if old else '')
    return real
