#!/bin/sh
# test_mpirun_wrapper.sh - the README's MPI command works as written:
# build/bin/zrcube-mpirun runs 3 ranks (more than this machine's cores
# when it has fewer) with none of OpenMPI's switches in the environment
# (as root too, when the test runs as root), and the picture is the same
# bytes as one process renders; and mpirun's own topology discovery is
# cut to the processors on a job of this host alone, and Open MPI 4's
# components no such job uses are excluded (see the wrapper).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
srcdir=${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}
builddir=${ZR_BUILDDIR:-$srcdir/build}
wrapper=$builddir/bin/zrcube-mpirun
[ -x "$wrapper" ] || { echo "test_mpirun_wrapper.sh: $wrapper is not built" >&2; exit 99; }
work=$(mktemp -d "${TMPDIR:-/tmp}/zr_mpirun.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT INT TERM
cd "$work" || exit 99
cat >s.pov <<'POV'
#version 3.7;
camera { location <0, 1, -3> look_at 0 }
light_source { <2, 4, -3> rgb 1 }
sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }
POV
failed=0
# What make check exports for the other tests is taken away here.
# OpenMPI's own allocations outlive MPI_Finalize: under ASan the ranks
# run without leak detection, as in the other mpirun tests (cli_env.sh).
if env -u OMPI_ALLOW_RUN_AS_ROOT -u OMPI_ALLOW_RUN_AS_ROOT_CONFIRM \
     -u OMPI_MCA_rmaps_base_oversubscribe -u MPIRUN \
     ASAN_OPTIONS="detect_leaks=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}" \
     timeout 120 "$wrapper" -n 3 +Is.pov +W40 +H30 -D +WT1 +Ompi.png \
     </dev/null >mpi.log 2>&1; then
  echo "zrcube-mpirun -n 3 (uid $(id -u), $(nproc) cores): ok"
else
  echo "zrcube-mpirun -n 3 failed:"; tail -5 mpi.log
  failed=1
fi
timeout 120 "$builddir/bin/zrcube" +Is.pov +W40 +H30 -D +WT1 +Oone.png \
  </dev/null >one.log 2>&1 || { echo "zrcube alone failed"; tail -3 one.log; exit 99; }
if [ "$failed" = 0 ] && cmp -s mpi.png one.png; then
  echo "3 ranks and one process: same bytes"
else
  echo "3 ranks and one process differ"; failed=1
fi
if "$wrapper" -n x s.pov 2>err.log; then
  echo "a bad rank count was accepted"; failed=1
else
  grep -q "'x' is not a number of ranks" err.log || { echo "message: $(cat err.log)"; failed=1; }
fi
# What mpirun is given to find the topology with (MPIRUN names a stand-in
# that writes hwloc's two variables down): on this host alone the I/O
# discovery is off, a user's value is kept, and a batch system's job
# (which may span hosts) is left as it is.
cat >fake-mpirun <<'SH'
#!/bin/sh
echo "${HWLOC_COMPONENTS-unset} ${HWLOC_PLUGINS_BLACKLIST-unset}" >hwloc.txt
echo "${OMPI_MCA_errmgr-unset} ${OMPI_MCA_shmem-unset} ${OMPI_MCA_reachable-unset} ${PMIX_MCA_prm-unset}" >mca.txt
SH
chmod +x fake-mpirun
hwloc_of() { # hwloc_of [VAR=VALUE...]: what the wrapper gives mpirun
  rm -f hwloc.txt
  env -u HWLOC_COMPONENTS -u HWLOC_PLUGINS_BLACKLIST -u SLURM_JOB_ID \
    -u PBS_JOBID -u LSB_JOBID -u PE_HOSTFILE \
    -u OMPI_MCA_orte_default_hostfile "$@" MPIRUN=./fake-mpirun \
    "$wrapper" -n 2 s.pov >/dev/null 2>&1
  cat hwloc.txt 2>/dev/null || echo "not run"
}
one_host="-pci,-linuxio,-opencl,-gl hwloc_opencl,hwloc_gl,hwloc_pci,hwloc_xml_libxml"
if grep -q '^[[:space:]]*[^#[:space:]]' /etc/openmpi/openmpi-default-hostfile \
     2>/dev/null; then
  echo "hwloc: not checked on one host: the default host file names hosts"
else
  got=$(hwloc_of)
  [ "$got" = "$one_host" ] || { echo "hwloc on one host: '$got'"; failed=1; }
fi
got=$(hwloc_of HWLOC_COMPONENTS=-gl)
case $got in "-gl "*) ;; *) echo "a user's HWLOC_COMPONENTS: '$got'"; failed=1 ;; esac
got=$(hwloc_of SLURM_JOB_ID=7)
[ "$got" = "unset unset" ] || { echo "hwloc in a Slurm job: '$got'"; failed=1; }
# Open MPI 4's launcher on one host: the components no job of this host
# uses are excluded (a few frameworks shown), a user's list is kept,
# and neither a batch job nor an mpirun not said to be Open MPI 4's
# gets them.
mca_of() { # mca_of [VAR=VALUE...]: the MCA lists the wrapper gives mpirun
  rm -f mca.txt
  env -u OMPI_MCA_errmgr -u OMPI_MCA_shmem -u OMPI_MCA_reachable \
    -u PMIX_MCA_prm -u SLURM_JOB_ID -u PBS_JOBID -u LSB_JOBID -u PE_HOSTFILE \
    -u OMPI_MCA_orte_default_hostfile -u MPIRUN_OMPI4 "$@" \
    MPIRUN=./fake-mpirun "$wrapper" -n 2 s.pov >/dev/null 2>&1
  cat mca.txt 2>/dev/null || echo "not run"
}
narrow="^default_orted,default_tool ^posix,sysv ^netlink ^slurm"
if grep -q '^[[:space:]]*[^#[:space:]]' /etc/openmpi/openmpi-default-hostfile \
     2>/dev/null; then
  echo "MCA lists: not checked on one host: the default host file names hosts"
else
  got=$(mca_of MPIRUN_OMPI4=yes)
  [ "$got" = "$narrow" ] || { echo "Open MPI 4 on one host: '$got'"; failed=1; }
  got=$(mca_of MPIRUN_OMPI4=yes OMPI_MCA_shmem=sysv)
  [ "$got" = "^default_orted,default_tool sysv ^netlink ^slurm" ] ||
    { echo "a user's OMPI_MCA_shmem: '$got'"; failed=1; }
fi
got=$(mca_of)
[ "$got" = "unset unset unset unset" ] ||
  { echo "an mpirun not said to be Open MPI 4's: '$got'"; failed=1; }
got=$(mca_of MPIRUN_OMPI4=yes SLURM_JOB_ID=7)
[ "$got" = "unset unset unset unset" ] ||
  { echo "MCA lists in a Slurm job: '$got'"; failed=1; }
[ "$failed" = 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit "$failed"
