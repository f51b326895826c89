#!/bin/sh
# tests/mpi_wait.c under mpirun: waits in collectives sleep instead of
# spinning (2 and 3 ranks), and a job on one host uses Open MPI's ob1
# layer unless the environment names a pml (lib/par/par.c).
# Environment: ZR_BUILDDIR, MPIRUN.
set -u
: "${ZR_BUILDDIR:?}"
MPIRUN="${MPIRUN:-mpirun}"
command -v "$MPIRUN" >/dev/null 2>&1 || { echo "no mpirun: skipped"; exit 77; }
WAIT="$ZR_BUILDDIR/tests/mpi_wait"
export ASAN_OPTIONS="${ASAN_OPTIONS:-}${ASAN_OPTIONS:+:}detect_leaks=0"
export OMPI_MCA_rmaps_base_oversubscribe=1
unset OMPI_MCA_pml OMPI_MCA_mtl
failed=0
for n in 2 3; do
  "$MPIRUN" --bind-to none -n $n "$WAIT" ob1 ||
    { echo "FAIL: mpirun -n $n" >&2; failed=1; }
done
# A pml the user names is left alone.
OMPI_MCA_pml=^v "$MPIRUN" --bind-to none -n 2 "$WAIT" ^v ||
  { echo "FAIL: OMPI_MCA_pml=^v" >&2; failed=1; }
exit $failed
