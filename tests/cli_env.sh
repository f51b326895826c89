# cli_env.sh - sourced by the command-line tests (test_cli.sh,
# test_gi_cli.sh, test_iopolicy.sh, test_faults.sh) after they set
# TEST_NAME: finds zrcube (ZR_BUILDDIR/bin/zrcube, or ./bin/zrcube),
# sets OpenMPI's switches for root and oversubscription, MPI_ASAN (the
# ASAN_OPTIONS for runs under mpirun: OpenMPI leaks at exit, so
# LeakSanitizer is off there only), and makes the temporary folder
# $work, removed at exit unless ZR_KEEP is set.  Exits 99 (a hard error)
# when zrcube is missing or no folder can be made.
ZRCUBE="${ZR_BUILDDIR:-$(pwd)}/bin/zrcube"
MPIRUN="${MPIRUN:-mpirun}"
: "${OMPI_ALLOW_RUN_AS_ROOT:=1}" "${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:=1}"
: "${OMPI_MCA_rmaps_base_oversubscribe:=1}"
export OMPI_ALLOW_RUN_AS_ROOT OMPI_ALLOW_RUN_AS_ROOT_CONFIRM \
  OMPI_MCA_rmaps_base_oversubscribe
# No povray.ini (zrcube reads POV-Ray's, as POV-Ray does; POVINI set
# and empty reads none): tests give every option they need.
POVINI=
export POVINI
MPI_ASAN="detect_leaks=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
# configure --without-mpi: these scripts run ranks under mpirun.
if [ "${ZR_WITH_MPI:-yes}" = no ]; then
  echo "$TEST_NAME: skipped: zrcube was built --without-mpi"
  exit 77
fi
if [ ! -x "$ZRCUBE" ]; then
  echo "$TEST_NAME: no zrcube at $ZRCUBE" >&2
  exit 99
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/zr_$TEST_NAME.XXXXXX") || exit 99
[ -n "${ZR_KEEP:-}" ] || trap 'rm -rf "$work"' EXIT
