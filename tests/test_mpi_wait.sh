#!/bin/sh
# tests/mpi_wait.c under mpirun: waits in collectives sleep instead of
# spinning (2 and 3 ranks), and a job on one host names Open MPI's ob1
# layer, its shared-memory transfer, the collectives it would choose,
# the components a rank does not use excluded from five frameworks,
# PMIx's "hash" store, a wait that yields the processor when it polls in
# vain, and hwloc without I/O discovery, each unless the
# environment names it (lib/par/par.c, prefer_shared_memory); under Open
# MPI 4 the launcher's loopback socket sends without Nagle's delay
# (launcher_without_delay).
# Environment: ZR_BUILDDIR, MPIRUN.
set -u
: "${ZR_BUILDDIR:?}"
MPIRUN="${MPIRUN:-mpirun}"
command -v "$MPIRUN" >/dev/null 2>&1 || { echo "no mpirun: skipped"; exit 77; }
WAIT="$ZR_BUILDDIR/tests/mpi_wait"
export ASAN_OPTIONS="${ASAN_OPTIONS:-}${ASAN_OPTIONS:+:}detect_leaks=0"
export OMPI_MCA_rmaps_base_oversubscribe=1
unset OMPI_MCA_pml OMPI_MCA_mtl OMPI_MCA_btl OMPI_MCA_coll OMPI_MCA_osc \
  OMPI_MCA_errmgr OMPI_MCA_state OMPI_MCA_schizo OMPI_MCA_shmem \
  OMPI_MCA_reachable HWLOC_COMPONENTS HWLOC_PLUGINS_BLACKLIST PMIX_MCA_gds \
  OMPI_MCA_mpi_yield_when_idle
gds="PMIX_MCA_gds=hash"
hwloc="HWLOC_COMPONENTS=-pci,-linuxio,-opencl,-gl"
plugins="HWLOC_PLUGINS_BLACKLIST=hwloc_opencl,hwloc_gl,hwloc_pci,hwloc_xml_libxml"
# Open MPI 4's components are named; another version gets the pml only.
ompi4="OMPI_MCA_btl=self,vader OMPI_MCA_coll=basic,libnbc,self,tuned OMPI_MCA_osc=sm
OMPI_MCA_errmgr=^default_hnp,default_orted,default_tool
OMPI_MCA_state=^hnp,novm,orted,tool OMPI_MCA_schizo=^flux,jsm,slurm
OMPI_MCA_shmem=^posix,sysv OMPI_MCA_reachable=^netlink
OMPI_MCA_mpi_yield_when_idle=1"
nodelay=
case $("$MPIRUN" --version 2>/dev/null | head -n 1) in
  *"Open MPI) 4."*) nodelay=nodelay ;;
  *) ompi4="OMPI_MCA_btl=- OMPI_MCA_coll=- OMPI_MCA_osc=- OMPI_MCA_errmgr=-
       OMPI_MCA_state=- OMPI_MCA_schizo=- OMPI_MCA_shmem=-
       OMPI_MCA_reachable=- OMPI_MCA_mpi_yield_when_idle=-" ;;
esac
failed=0
for n in 2 3; do
  # shellcheck disable=SC2086
  "$MPIRUN" --bind-to none -n $n "$WAIT" ob1 $ompi4 "$gds" "$hwloc" \
    "$plugins" $nodelay ||
    { echo "FAIL: mpirun -n $n" >&2; failed=1; }
done
# A pml, a btl and an hwloc choice the user names are left alone (and
# the job runs with them); the other defaults still apply.
OMPI_MCA_pml=^v OMPI_MCA_btl=self,vader,tcp HWLOC_COMPONENTS=-opencl \
  PMIX_MCA_gds=^ds12 OMPI_MCA_reachable=^weighted \
  "$MPIRUN" --bind-to none -n 2 "$WAIT" ^v OMPI_MCA_btl=self,vader,tcp \
  HWLOC_COMPONENTS=-opencl PMIX_MCA_gds=^ds12 "$plugins" \
  OMPI_MCA_reachable=^weighted ||
  { echo "FAIL: the user's OMPI_MCA_pml, OMPI_MCA_btl, HWLOC_COMPONENTS," \
      "PMIX_MCA_gds" >&2
    failed=1; }
exit $failed
