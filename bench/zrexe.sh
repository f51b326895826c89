# zrexe.sh - sourced by the timing scripts once $build names a build
# folder: sets zrcube to the program to time.  A build's bin/zrcube is
# libtool's wrapper script, which costs ~0.15-0.2 CPU s a run here (a
# shell and a few sed processes; bench/zrexe.py says the same for the
# Python tools), so the real bin/.libs/zrcube runs instead with the
# library's folder on LD_LIBRARY_PATH, as an installed zrcube runs.
if [ -x "$build/bin/.libs/zrcube" ]; then
  zrcube=$build/bin/.libs/zrcube
  LD_LIBRARY_PATH=$build/lib/.libs${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
  export LD_LIBRARY_PATH
else
  zrcube=$build/bin/zrcube
fi
