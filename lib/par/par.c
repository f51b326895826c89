/*
 * par.c - MPI for zrcube: joining the world, sharing the scene files,
 * rendering interleaved rows and gathering the picture.
 *
 * This is the only file of the project that includes <mpi.h>, after
 * Tachyon's parallel.c; the library never sees a communicator.  The
 * design follows ARCHITECTURE.md ("Parallelism"):
 *   - rank 0 reads the scene files, every rank parses the same bytes
 *     (zr__par_share_bundle);
 *   - the ranks render rows with a pool of threads each (pool.c): on
 *     one host they take rows from a counter in shared memory as they
 *     finish others (shared_rows), across hosts rank r renders rows r,
 *     r + n, ... of each chunk (the static deal of rows.h);
 *   - antialiasing needs each pixel's neighbours, so the centres of pass 1
 *     are assembled on every rank before pass 2;
 *   - rank 0 gathers the rows and the statistics; after antialiasing's
 *     pass 2 only the pixels that differ from their centre
 *     (collect_changes).  Bands as wide as the image are rendered into
 *     their places and the other ranks' rows received into theirs
 *     (exchange_rows); a window's bands go through MPI_Gatherv or
 *     MPI_Allgatherv (collect_rows);
 *   - a rank that waits for the others sleeps (meet) instead of spinning
 *     in MPI's progress loop;
 *   - on one host MPI starts with only what such a job uses
 *     (prefer_shared_memory), MPI_Finalize is not held up by Nagle's
 *     algorithm on the launcher's socket (launcher_without_delay), and
 *     a render's image-sized buffers sit in huge pages (float_alloc).
 * Rows travel as an MPI datatype of one row, so counts stay small
 * integers for any image MPI can hold.  Each collective is preceded by an
 * agreement on the status of the work before it, so a rank that fails
 * (out of memory) makes every rank return that failure instead of leaving
 * the others blocked in a collective.
 *
 * Without an MPI launcher in the environment the world has one rank and
 * MPI is not initialised: a plain `zrcube scene.pov` starts no daemon.
 */
#define _GNU_SOURCE /* sched_getaffinity, CPU_COUNT */
#include "par/par.h"

#include "config.h"
#include <limits.h>
#include <math.h>
#ifdef ZR_HAVE_MPI
#include <mpi.h>
#else
#include "par/nompi.h" /* configure --without-mpi: one process */
#endif
#include <sched.h>
#include <sys/mman.h>
#ifdef __linux__
#include <arpa/inet.h>
#include <dirent.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <sys/stat.h>
#endif
#include <stdatomic.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "core/hugepage.h"
#include "par/rows.h"
#include "par/writer.h"

struct zr_par {
  int uses_mpi;
  int threads_allowed; /* the MPI library allows threads beside MPI */
  int rank;
  int size;
  int local_size;
  MPI_Comm comm;
  int owns_mpi;     /* zr__par_init started MPI and finalises it */
  int *team_counts; /* the team's MPI_Allgatherv counts and offsets */
  zr_par_traffic traffic;
};

/* Environment variables that MPI launchers set in the processes they start
   (OpenMPI's mpirun, PMIx, MPICH's hydra and Slurm's PMI). */
static const char *const launcher_vars[] = {
    "OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE",
};

/* The variables that hold this process's rank (for zr__par_mark). */
static const char *const rank_vars[] = {
    "OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK",
};

static int launched_by_mpi(void) {
  for (size_t i = 0; i < sizeof launcher_vars / sizeof *launcher_vars; i++)
    if (getenv(launcher_vars[i]))
      return 1;
  return 0;
}

static zr_status mpi_status(int rc) {
  return rc == MPI_SUCCESS ? ZR_OK : ZR_EMPI;
}

/*
 * What Open MPI 4 does at MPI_Init besides joining the job costs a rank
 * more than zrcube's whole parse of a small scene, and on one host most
 * of it is spent on nothing the job uses (bench/launch.sh; strace and
 * perf of a rank of `mpirun -n 1` of an empty scene: 49 plugins opened,
 * 25% of the rank's CPU in the dynamic loader):
 *   - it picks its point-to-point layer (pml) by opening every
 *     candidate, and Debian's build probes libfabric, PSM, PSM2 and UCX
 *     devices first: 0.2 to 0.3 s of wall time a rank before it settled
 *     on ob1 with shared memory anyway (0.71 s -> 0.39 s, session 6);
 *   - hwloc, which it asks for the machine's topology, loads its OpenCL,
 *     OpenGL (X11), PCI and libxml2 (ICU) plugins and walks PCI devices,
 *     block devices and network interfaces; ranks on one host talk
 *     through shared memory and need the processors and memory only;
 *   - the byte transfer layers (btl), collective (coll) and one-sided
 *     (osc) frameworks open every component before they choose: tcp
 *     between processes of one host, and collective modules that are
 *     never chosen for an intra-communicator by default (their priority
 *     is 0, or they act only when asked: adapt, han, sm, sync,
 *     monitoring, inter; `ompi_info --param coll all --level 9`).
 * So when every rank of the job runs on this host (Open MPI says so
 * before MPI_Init, in OMPI_COMM_WORLD_SIZE and OMPI_COMM_WORLD_LOCAL_SIZE)
 * no network is used, and the choices Open MPI would make are named
 * directly: pml ob1 (unless the user named a pml or an mtl, which needs
 * the cm pml), btl self and vader (shared memory), coll basic, libnbc
 * (MPI_Ibarrier), self and tuned, osc sm (zrcube opens no window), and
 * hwloc without I/O discovery and without those plugins.  Each variable
 * the user set is left alone.  Measured (bench/launch.sh, RT=1, best of
 * 6): mpirun -n 2 of an empty scene 0.39 -> 0.33 s wall and 0.48 ->
 * 0.36 CPU s; with pml alone named it was 0.39 / 0.48.  The lists name
 * Open MPI 4's components; another version gets the pml only.
 */
static const char *const one_host_env[][2] = {
#if defined(OMPI_MAJOR_VERSION) && OMPI_MAJOR_VERSION == 4
    {"OMPI_MCA_btl", "self,vader"},
    {"OMPI_MCA_coll", "basic,libnbc,self,tuned"},
    {"OMPI_MCA_osc", "sm"},
    /* Frameworks a rank opens every component of and then keeps one
       (or none) of: the error manager and state machine of a rank are
       "default_app" and "app", the others serve mpirun, its daemons and
       tools; schizo's flux, jsm and slurm serve other launchers (mpirun
       itself narrows "ess" and "pmix" in the ranks' environment, which
       is then left as it is); shared memory segments are
       made by mmap (its highest priority); "reachable" serves the tcp
       btl.  Named as exclusions, which Open MPI accepts for components
       a build lacks (an inclusion of a missing one stops MPI_Init).
       Each component skipped is a dlopen, its relocation, and a dlclose
       whose munmap interrupts the other processor to flush its TLB.
       MPI_Init of a rank of mpirun -n 2 (a probe of MPI_Init_thread
       alone with the other variables here, 24 ranks each, interleaved
       under chrt -r 20, load 3.4-3.6): CPU mean 0.0337 -> 0.0283 s (best
       0.0267 -> 0.0219), wall mean 0.0413 -> 0.0348 s. */
    {"OMPI_MCA_errmgr", "^default_hnp,default_orted,default_tool"},
    {"OMPI_MCA_state", "^hnp,novm,orted,tool"},
    {"OMPI_MCA_schizo", "^flux,jsm,slurm"},
    {"OMPI_MCA_shmem", "^posix,sysv"},
    {"OMPI_MCA_reachable", "^netlink"},
    /* A rank in a blocking call (the rows' exchange after a chunk, a
       reduction) polls Open MPI's progress engine until the other side
       has done its part; with this, a poll that finds nothing calls
       sched_yield, so the processor goes to whatever else may run (the
       rank's own PNG encoder, the rank it waits for, other work on the
       host) and comes back at once when nothing else wants it.  Open
       MPI sets it itself only when it knows the host oversubscribed.
       A busy machine (two other sessions' renders, load 6-8) was the
       case (bench/mpi_yield.sh): flake 2048^2 under zrcube-mpirun -n 2,
       3 runs alternated,
       -v's gather (the exchange's wall time) 0.16, 0.04, 2.97 s
       without, 0.010, 0.021, 0.057 s with, the two ranks' CPU 5.10,
       4.31, 7.44 s without, 4.74, 4.43, 4.46 s with. */
    {"OMPI_MCA_mpi_yield_when_idle", "1"},
#endif
    /* PMIx keeps the job's data for the ranks in its "gds" store; its
       default on this host (ds21) has the launcher create and fill two
       4 MiB shared-memory segments while MPI_Init waits for them (strace
       of mpirun: 34 ms between a rank's first request and the reply,
       spent touching the segments' pages), where "hash" sends the few
       keys of a one-host job over the socket the rank has anyway.
       MPI_Init of a rank, wall (a probe of MPI_Init_thread and
       MPI_Finalize alone under mpirun -n 1 and -n 2, 3 runs each):
       0.065 -> 0.030 s. */
    {"PMIX_MCA_gds", "hash"},
    {"HWLOC_COMPONENTS", "-pci,-linuxio,-opencl,-gl"},
    {"HWLOC_PLUGINS_BLACKLIST",
     "hwloc_opencl,hwloc_gl,hwloc_pci,hwloc_xml_libxml"},
};

static void prefer_shared_memory(void) {
  const char *size = getenv("OMPI_COMM_WORLD_SIZE");
  const char *local = getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  if (!size || !local || strcmp(size, local) != 0)
    return;
  if (!getenv("OMPI_MCA_pml") && !getenv("OMPI_MCA_mtl"))
    setenv("OMPI_MCA_pml", "ob1", 0);
  for (size_t i = 0; i < sizeof one_host_env / sizeof *one_host_env; i++)
    setenv(one_host_env[i][0], one_host_env[i][1], 0);
}

/*
 * Waits until every rank has arrived, without spinning: an MPI_Ibarrier
 * tested with short sleeps in between.  A blocking collective spins
 * while it waits for a slower rank (Open MPI polls its progress engine:
 * 38% of a rank's CPU in a 2-rank render of default.pov was that spin,
 * and on a shared core the spin takes the time the rank it waits for
 * needs), so every collective that may wait for another rank's work
 * (zr__par_agree, the team's exchanges) first meets the others here and
 * then runs with all of them present.  The sleeps grow by half from
 * 20 us to 1 ms: a wait that is over within a few milliseconds ends
 * within a sleep of a third of its length after the last rank arrives,
 * a longer one within 1 ms, and a waiting rank polls a thousand times a
 * second (tests/mpi_wait.c: under 10% of a core while it waits).
 */
static zr_status meet(zr_par *par) {
  MPI_Request req;
  if (MPI_Ibarrier(par->comm, &req) != MPI_SUCCESS)
    return ZR_EMPI;
  long nap_ns = 20000;
  int polls = 0;
  for (;;) {
    int done = 0;
    if (MPI_Test(&req, &done, MPI_STATUS_IGNORE) != MPI_SUCCESS)
      return ZR_EMPI;
    if (done)
      return ZR_OK;
    /* A few free polls first: the others are often there already. */
    if (++polls < 16)
      continue;
    struct timespec nap = {0, nap_ns};
    nanosleep(&nap, NULL);
    nap_ns += nap_ns / 2;
    if (nap_ns > 1000000)
      nap_ns = 1000000;
  }
}

/*
 * MPI_Finalize of Open MPI 4 sends its launcher (the PMIx server in
 * mpirun, or in orted, on this host) a few small messages in a row over
 * a loopback TCP connection, and waits for the answer to the last.  The
 * server answers the first of them with nothing, so its acknowledgement
 * is delayed (40 ms on Linux), and the rank's socket holds the next
 * message until it comes (Nagle's algorithm): strace of mpirun -n 1
 * showed the second message reach the server 41 ms after it was
 * written, and MPI_Finalize took 0.047-0.055 s of wall time for 0.005 s
 * of CPU on every rank.  So after MPI_Init the rank turns Nagle off
 * (TCP_NODELAY) on its TCP connections to loopback addresses, which on
 * a rank of zrcube are the launcher's: the option changes only when
 * bytes leave, never what they are.  MPI_Finalize: 0.050 -> 0.008 s
 * wall (a probe of MPI_Init_thread + MPI_Finalize under mpirun -n 1 and
 * -n 2, 3 runs each).  Nothing is done where /proc/self/fd cannot be
 * read, and a socket the option does not apply to is left as it is.
 */
static void launcher_without_delay(void) {
#ifdef __linux__
  DIR *fds = opendir("/proc/self/fd");
  if (!fds)
    return;
  struct dirent *e;
  while ((e = readdir(fds)) != NULL) {
    char *end;
    long fd = strtol(e->d_name, &end, 10);
    if (*end != '\0' || end == e->d_name || fd < 0 || fd > INT_MAX ||
        fd == dirfd(fds))
      continue;
    struct stat st;
    int type = 0;
    socklen_t len = sizeof type;
    if (fstat((int)fd, &st) != 0 || !S_ISSOCK(st.st_mode) ||
        getsockopt((int)fd, SOL_SOCKET, SO_TYPE, &type, &len) != 0 ||
        type != SOCK_STREAM)
      continue;
    struct sockaddr_storage peer;
    len = sizeof peer;
    if (getpeername((int)fd, (struct sockaddr *)&peer, &len) != 0)
      continue;
    int loopback = 0;
    if (peer.ss_family == AF_INET) {
      const struct sockaddr_in *in = (const struct sockaddr_in *)&peer;
      loopback = (ntohl(in->sin_addr.s_addr) >> 24) == 127;
    } else if (peer.ss_family == AF_INET6) {
      const struct sockaddr_in6 *in6 = (const struct sockaddr_in6 *)&peer;
      loopback = IN6_IS_ADDR_LOOPBACK(&in6->sin6_addr);
    }
    int one = 1;
    if (loopback)
      (void)setsockopt((int)fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  }
  closedir(fds);
#endif
}

/*
 * par's own duplicate of comm, returning errors instead of aborting, with
 * its rank, size and the number of ranks on this node; an MPI error code
 * when any step fails (par->comm is then freed by zr__par_finalize).
 */
static int join_comm(zr_par *par, MPI_Comm comm) {
  MPI_Comm node = MPI_COMM_NULL;
  int rc = MPI_Comm_dup(comm, &par->comm);
  if (rc == MPI_SUCCESS)
    rc = MPI_Comm_set_errhandler(par->comm, MPI_ERRORS_RETURN);
  if (rc == MPI_SUCCESS)
    rc = MPI_Comm_rank(par->comm, &par->rank);
  if (rc == MPI_SUCCESS)
    rc = MPI_Comm_size(par->comm, &par->size);
  if (rc == MPI_SUCCESS)
    rc = MPI_Comm_split_type(par->comm, MPI_COMM_TYPE_SHARED, par->rank,
                             MPI_INFO_NULL, &node);
  if (rc == MPI_SUCCESS)
    rc = MPI_Comm_size(node, &par->local_size);
  if (node != MPI_COMM_NULL)
    MPI_Comm_free(&node);
  return rc;
}

zr_status zr__par_init(int *argc, char ***argv, zr_par **out) {
  zr_par *par = calloc(1, sizeof *par);
  if (!par)
    return ZR_ENOMEM;
  par->size = 1;
  par->local_size = 1;
  par->comm = MPI_COMM_NULL;
  par->threads_allowed = 1;
  if (launched_by_mpi()) {
    int provided;
    prefer_shared_memory();
    /* Only the main thread calls MPI; workers only render. */
    if (MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided) !=
        MPI_SUCCESS) {
      free(par);
      return ZR_EMPI;
    }
    par->uses_mpi = 1;
    par->owns_mpi = 1;
    launcher_without_delay();
    /* With MPI_THREAD_SINGLE even threads that never call MPI are not
       allowed, so such an MPI gets one thread per rank. */
    par->threads_allowed = provided >= MPI_THREAD_FUNNELED;
    if (join_comm(par, MPI_COMM_WORLD) != MPI_SUCCESS) {
      zr__par_finalize(par);
      return ZR_EMPI;
    }
  }
  *out = par;
  return ZR_OK;
}

#ifdef ZR_HAVE_MPI
zr_status zr__par_from_comm(void *comm_ptr, zr_par **out) {
  MPI_Comm comm = *(MPI_Comm *)comm_ptr;
  *out = NULL;
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (!initialized || finalized || comm == MPI_COMM_NULL)
    return ZR_EINVAL;
  zr_par *par = calloc(1, sizeof *par);
  if (!par)
    return ZR_ENOMEM;
  par->uses_mpi = 1;
  par->comm = MPI_COMM_NULL;
  int provided = MPI_THREAD_SINGLE;
  MPI_Query_thread(&provided);
  par->threads_allowed = provided >= MPI_THREAD_FUNNELED;
  /* The caller's communicator is duplicated (join_comm), so our
     collectives never match the caller's messages, and its error
     handler is left alone. */
  if (join_comm(par, comm) != MPI_SUCCESS) {
    zr__par_finalize(par);
    return ZR_EMPI;
  }
  *out = par;
  return ZR_OK;
}
#else
/* Built without MPI (configure --without-mpi): there is no caller's
   communicator to join; libzrcube_mpi is not built then. */
zr_status zr__par_from_comm(void *comm_ptr, zr_par **out) {
  (void)comm_ptr;
  *out = NULL;
  return ZR_EINVAL;
}
#endif

void zr__par_finalize(zr_par *par) {
  if (!par)
    return;
  free(par->team_counts);
  if (par->uses_mpi) {
    if (par->comm != MPI_COMM_NULL)
      MPI_Comm_free(&par->comm);
    if (par->owns_mpi)
      MPI_Finalize();
  }
  free(par);
}

int zr__par_rank(const zr_par *par) { return par->rank; }
int zr__par_size(const zr_par *par) { return par->size; }
int zr__par_uses_mpi(const zr_par *par) { return par->uses_mpi; }
int zr__par_local_size(const zr_par *par) { return par->local_size; }

int zr__par_threads(const zr_par *par, int wanted) {
  if (!par->threads_allowed)
    return 1;
  return wanted > 0 ? wanted : zr__par_default_threads(par);
}

int zr__par_cpus_allowed(void) {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) >= 1)
    return CPU_COUNT(&set);
  long online = sysconf(_SC_NPROCESSORS_ONLN);
  return online < 1 ? 1 : (int)online;
}

int zr__par_default_threads(const zr_par *par) {
  long online = sysconf(_SC_NPROCESSORS_ONLN);
  if (online < 1)
    online = 1;
  long share = online / (par->local_size > 0 ? par->local_size : 1);
  int allowed = zr__par_cpus_allowed();
  if (allowed < share)
    share = allowed;
  return share < 1 ? 1 : (int)share;
}

void zr__par_mpi_version(char *buf, size_t size) {
  char version[MPI_MAX_LIBRARY_VERSION_STRING];
  int len = 0;
  if (size == 0)
    return;
  if (MPI_Get_library_version(version, &len) != MPI_SUCCESS)
    len = 0;
  /* Open MPI's text runs on with build details after its first line. */
  int first_line = 0;
  while (first_line < len && version[first_line] != '\n' &&
         version[first_line] != ',')
    first_line++;
  snprintf(buf, size, "%.*s", first_line, version);
}

double zr__par_cpu(void) {
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/*
 * ZRCUBE_TIMELINE set (to anything): a line on stderr at each step of a
 * run, for bench/timeline.sh, which lays the ranks' lines side by side
 * from the moment mpirun started.  The wall clock is CLOCK_REALTIME
 * (the only clock a script and every rank share), CPU the process's
 * and the calling thread's, so a step whose process CPU grows more
 * than its thread's had other threads working (the image's writer).
 * The rank is the launcher's (the first mark comes before MPI_Init).
 */
void zr__par_mark(const char *what) {
  static int on = -1;
  if (on < 0)
    on = getenv("ZRCUBE_TIMELINE") != NULL;
  if (!on)
    return;
  struct timespec wall, thread;
  clock_gettime(CLOCK_REALTIME, &wall);
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &thread);
  const char *rank = NULL;
  for (size_t i = 0; !rank && i < sizeof rank_vars / sizeof *rank_vars; i++)
    rank = getenv(rank_vars[i]);
  fprintf(stderr, "zrcube: timeline: rank %s wall %.6f cpu %.4f thread %.4f"
          " %s\n", rank ? rank : "0",
          (double)wall.tv_sec + 1e-9 * (double)wall.tv_nsec, zr__par_cpu(),
          (double)thread.tv_sec + 1e-9 * (double)thread.tv_nsec, what);
}

double zr__par_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* MPI counts are ints: large blobs go in pieces of at most 1 GiB. */
#define BCAST_CHUNK ((size_t)1 << 30)

static zr_status bcast_bytes(zr_par *par, char *bytes, size_t size) {
  for (size_t off = 0; off < size; off += BCAST_CHUNK) {
    size_t n = size - off < BCAST_CHUNK ? size - off : BCAST_CHUNK;
    int rc = MPI_Bcast(bytes + off, (int)n, MPI_BYTE, 0, par->comm);
    if (rc != MPI_SUCCESS)
      return ZR_EMPI;
    if (par->rank == 0)
      par->traffic.bcast_bytes_sent += n;
  }
  return ZR_OK;
}

zr_status zr__par_share_bundle(zr_par *par, zr_bundle *bundle,
                               zr_status *root_status) {
  if (!par->uses_mpi || par->size == 1)
    return ZR_OK;
  char *blob = NULL;
  size_t blob_size = 0;
  int64_t header[2] = {0, 0}; /* rank 0's parse status, blob size */
  if (par->rank == 0) {
    zr_status s = *root_status;
    if (s == ZR_OK)
      s = zr__bundle_serialise(bundle, &blob, &blob_size);
    header[0] = s;
    header[1] = s == ZR_OK ? (int64_t)blob_size : 0;
  }
  zr_status s = mpi_status(MPI_Bcast(header, 2, MPI_INT64_T, 0, par->comm));
  if (s != ZR_OK) {
    free(blob);
    return s;
  }
  if (par->rank != 0) {
    blob_size = (size_t)header[1];
    blob = malloc(blob_size ? blob_size : 1);
  }
  /* All ranks agree that the blob fits before it is sent, so none is
     left waiting in a broadcast that another rank has given up on. */
  s = zr__par_agree(par, par->rank == 0 || blob ? ZR_OK : ZR_ENOMEM);
  if (s == ZR_OK && blob_size > 0)
    s = bcast_bytes(par, blob, blob_size);
  /* Rank 0 learns it too: its parse may have worked and the bundle not. */
  *root_status = (zr_status)header[0];
  if (s == ZR_OK && par->rank != 0) {
    if (header[0] == ZR_OK)
      s = zr__bundle_deserialise(bundle, blob, blob_size);
  }
  free(blob);
  return s;
}

zr_status zr__par_share_string(zr_par *par, char **text) {
  if (!par->uses_mpi || par->size == 1)
    return ZR_OK;
  /* The length, or -1 for NULL, then the bytes with their NUL. */
  int64_t length = par->rank == 0 && *text ? (int64_t)strlen(*text) : -1;
  if (MPI_Bcast(&length, 1, MPI_INT64_T, 0, par->comm) != MPI_SUCCESS)
    return ZR_EMPI;
  char *copy = NULL;
  if (par->rank != 0 && length >= 0)
    copy = malloc((size_t)length + 1);
  zr_status s = zr__par_agree(
      par, par->rank == 0 || length < 0 || copy ? ZR_OK : ZR_ENOMEM);
  if (s == ZR_OK && length >= 0)
    s = bcast_bytes(par, par->rank == 0 ? *text : copy, (size_t)length + 1);
  if (s != ZR_OK || par->rank == 0) {
    free(copy);
    return s;
  }
  free(*text);
  *text = copy;
  return ZR_OK;
}

zr_status zr__par_agree(zr_par *par, zr_status local) {
  if (!par->uses_mpi || par->size == 1)
    return local;
  /* Failures are negative: the minimum is a failure if any rank failed. */
  int mine = (int)local, worst;
  if (meet(par) != ZR_OK)
    return ZR_EMPI;
  if (MPI_Allreduce(&mine, &worst, 1, MPI_INT, MPI_MIN, par->comm) !=
      MPI_SUCCESS)
    return ZR_EMPI;
  return (zr_status)worst;
}

/* The layout of an MPI_Gatherv of every rank's rows, rank after rank. */
typedef struct row_layout {
  int *counts; /* rows of each rank */
  int *displs; /* first row of each rank in the rank-major buffer */
} row_layout;

static zr_status layout_new(const zr_par *par, int height, row_layout *l) {
  l->counts = malloc((size_t)par->size * sizeof *l->counts);
  l->displs = malloc((size_t)par->size * sizeof *l->displs);
  if (!l->counts || !l->displs)
    return ZR_ENOMEM;
  int first = 0;
  for (int r = 0; r < par->size; r++) {
    l->counts[r] = zr__rows_count(height, r, par->size);
    l->displs[r] = first;
    first += l->counts[r];
  }
  return ZR_OK;
}

static void layout_free(row_layout *l) {
  free(l->counts);
  free(l->displs);
}

/*
 * Collects every rank's rows (mine, in order) into image, top to bottom:
 * on every rank (everyone) or on rank 0 only.  rank_major is scratch room
 * for height rows, used where the MPI call lands rows rank after rank.
 */
static zr_status collect_rows(zr_par *par, const float *mine, float *image,
                              float *rank_major, int width, int height,
                              int channels, int everyone) {
  size_t row_floats = (size_t)width * (size_t)channels;
  if (!par->uses_mpi || par->size == 1) {
    zr__rows_uninterleave(mine, image, height, 1, row_floats);
    return ZR_OK;
  }
  row_layout layout = {NULL, NULL};
  MPI_Datatype row = MPI_DATATYPE_NULL;
  zr_status s = layout_new(par, height, &layout);
  s = zr__par_agree(par, s);
  if (s == ZR_OK)
    s = mpi_status(MPI_Type_contiguous((int)row_floats, MPI_FLOAT, &row));
  if (s == ZR_OK)
    s = mpi_status(MPI_Type_commit(&row));
  if (s == ZR_OK) {
    /* MPI's send buffers are const only from MPI 3 on. */
    float *send = (float *)mine;
    int count = layout.counts[par->rank];
    s = mpi_status(everyone ? MPI_Allgatherv(send, count, row, rank_major,
                                             layout.counts, layout.displs,
                                             row, par->comm)
                            : MPI_Gatherv(send, count, row, rank_major,
                                          layout.counts, layout.displs, row,
                                          0, par->comm));
  }
  if (s == ZR_OK)
    par->traffic.pixel_bytes_sent +=
        (uint64_t)layout.counts[par->rank] * row_floats * sizeof(float);
  if (s == ZR_OK && (everyone || par->rank == 0))
    zr__rows_uninterleave(rank_major, image, height, par->size, row_floats);
  if (row != MPI_DATATYPE_NULL)
    MPI_Type_free(&row);
  layout_free(&layout);
  return s;
}

/*
 * Each rank's rows of a chunk, as offsets from the chunk's first row in
 * increasing order, rank after rank: rank r's are at[start[r]] ..
 * at[start[r + 1] - 1].  Every rank holds the same lists (they say who
 * sends which rows where), made either from the static deal or from the
 * owners the ranks wrote while they took rows (shared_rows).
 */
typedef struct rank_rows {
  int *start; /* size + 1 */
  int *at;    /* one a row of the largest chunk (the image's height) */
} rank_rows;

static int rank_count(const rank_rows *rr, int r) {
  return rr->start[r + 1] - rr->start[r];
}

/*
 * The static deal of a chunk of rows rows among the ranks first .. n - 1
 * (first is 0, or 1 for the last bands, which rank 0 leaves to the
 * others while it writes the image, zr__par_render): rank r's i-th row
 * is r - first + i (n - first), zr__rows_row.
 */
static void rank_rows_dealt(rank_rows *rr, int rows, int first, int n) {
  int k = 0;
  for (int r = 0; r < n; r++) {
    rr->start[r] = k;
    int count = r < first ? 0 : zr__rows_count(rows, r - first, n - first);
    for (int i = 0; i < count; i++)
      rr->at[k++] = zr__rows_row(i, r - first, n - first);
  }
  rr->start[n] = k;
}

/* The rows as taken: owner[i] is the rank that rendered the chunk's row
   i.  ZR_EMPI for an owner that is no rank (a row nobody took). */
static zr_status rank_rows_taken(rank_rows *rr, const int *owner, int rows,
                                 int n) {
  for (int r = 0; r <= n; r++)
    rr->start[r] = 0;
  for (int i = 0; i < rows; i++) {
    if (owner[i] < 0 || owner[i] >= n)
      return ZR_EMPI;
    rr->start[owner[i] + 1]++;
  }
  for (int r = 0; r < n; r++)
    rr->start[r + 1] += rr->start[r];
  /* Counting sort, stable: each rank's rows stay in increasing order.
     start[r] runs up to start[r + 1] and is put back after. */
  for (int i = 0; i < rows; i++)
    rr->at[rr->start[owner[i]]++] = i;
  for (int r = n; r > 0; r--)
    rr->start[r] = rr->start[r - 1];
  rr->start[0] = 0;
  return ZR_OK;
}

/*
 * Pass 2's rows (this rank's rows of the chunk's rows y0 .. y1 - 1 and
 * columns x0 .. x1 - 1, in mine: packed in order when packed, else each
 * at its offset in the chunk) into band on rank 0, sending only the
 * pixels that differ from their pass-1 centre (bit for bit): a pixel
 * pass 2 did not supersample is its centre, which every rank holds
 * already, so rank 0 starts from the centres and applies the others
 * (about 1% of the pixels of default.pov at +A0.3, against every pixel
 * as floats before).  A rank sends a mask of its rows' pixels, a bit
 * each (1: changed), then the changed pixels' floats in row order: never
 * more than 1/96 above the rows themselves.  With root_in_place, rank 0
 * rendered its own rows into their places in band already: it sends
 * nothing and they are left alone (it spared rank 0, the busiest rank, a
 * half image of fresh pages, a compare and a copy of its rows).  rr says
 * whose rows are which.
 */
static zr_status collect_changes(zr_par *par, const float *mine, int packed,
                                 float *band, const float *centres,
                                 int image_width, int y0, int x0, int x1,
                                 int channels, int root_in_place,
                                 const rank_rows *rr) {
  int n = par->size, width = x1 - x0;
  size_t px_bytes = (size_t)channels * sizeof(float);
  size_t row_floats = (size_t)width * (size_t)channels;
  /* The centre of pixel x of row y. */
#define CENTRE(y, x)                                                     \
  (centres + ((size_t)(y) * (size_t)image_width + (size_t)x0 +           \
              (size_t)(x)) * (size_t)channels)
  const int *my_rows = rr->at + rr->start[par->rank];
  /* This rank's i-th row in mine. */
#define MINE(i)                                                          \
  (mine + (size_t)(packed ? (i) : my_rows[i]) * row_floats)
  int rows = root_in_place && par->rank == 0 ? 0 : rank_count(rr, par->rank);
  size_t mask_bytes = ((size_t)rows * (size_t)width + 7) / 8;
  size_t changed = 0;
  for (int i = 0; i < rows; i++) {
    int y = y0 + my_rows[i];
    for (int x = 0; x < width; x++)
      changed += memcmp(MINE(i) + (size_t)x * channels, CENTRE(y, x),
                        px_bytes) != 0;
  }
  zr_status s = ZR_OK;
  size_t bytes = mask_bytes + changed * px_bytes;
  unsigned char *pack = NULL;
  if (bytes > (size_t)INT_MAX)
    s = ZR_ELIMIT;
  else if (!(pack = calloc(bytes ? bytes : 1, 1)))
    s = ZR_ENOMEM;
  unsigned char *at = pack + mask_bytes;
  for (int i = 0; s == ZR_OK && i < rows; i++) {
    int y = y0 + my_rows[i];
    for (int x = 0; x < width; x++) {
      const float *mp = MINE(i) + (size_t)x * channels;
      if (memcmp(mp, CENTRE(y, x), px_bytes) == 0)
        continue;
      size_t bit = (size_t)i * (size_t)width + (size_t)x;
      pack[bit / 8] |= (unsigned char)(1u << (bit % 8));
      memcpy(at, mp, px_bytes);
      at += px_bytes;
    }
  }
#undef MINE
  int *counts = NULL, *displs = NULL;
  unsigned char *all = NULL;
  if (par->rank == 0) {
    counts = calloc((size_t)n, sizeof *counts);
    displs = calloc((size_t)n, sizeof *displs);
    if (!counts || !displs)
      s = ZR_ENOMEM;
  }
  s = zr__par_agree(par, s);
  int mine_bytes = s == ZR_OK ? (int)bytes : 0;
  if (s == ZR_OK)
    s = mpi_status(MPI_Gather(&mine_bytes, 1, MPI_INT, counts, 1, MPI_INT,
                              0, par->comm));
  zr_status room = ZR_OK;
  if (s == ZR_OK && par->rank == 0) {
    size_t total = 0;
    for (int r = 0; r < n; r++) {
      if (total > (size_t)INT_MAX - (size_t)counts[r]) {
        room = ZR_ELIMIT;
        break;
      }
      displs[r] = (int)total;
      total += (size_t)counts[r];
    }
    if (room == ZR_OK && !(all = malloc(total ? total : 1)))
      room = ZR_ENOMEM;
  }
  if (s == ZR_OK)
    s = zr__par_agree(par, room);
  if (s == ZR_OK)
    s = mpi_status(MPI_Gatherv(pack, mine_bytes, MPI_BYTE, all, counts,
                               displs, MPI_BYTE, 0, par->comm));
  if (s == ZR_OK)
    par->traffic.pixel_bytes_sent += (uint64_t)mine_bytes;
  for (int r = root_in_place; s == ZR_OK && par->rank == 0 && r < n; r++) {
    /* Rank r's rows: the centres, then its changed pixels. */
    int r_rows = rank_count(rr, r);
    const int *r_at = rr->at + rr->start[r];
    size_t r_mask = ((size_t)r_rows * (size_t)width + 7) / 8;
    const unsigned char *mask = all + displs[r], *end = mask + counts[r];
    const unsigned char *from = mask + r_mask;
    if (from > end) {
      s = ZR_EMPI;
      break;
    }
    for (int i = 0; s == ZR_OK && i < r_rows; i++) {
      int y = y0 + r_at[i];
      float *dst = band + (size_t)(y - y0) * row_floats;
      memcpy(dst, CENTRE(y, 0), row_floats * sizeof(float));
      for (int x = 0; x < width; x++) {
        size_t bit = (size_t)i * (size_t)width + (size_t)x;
        if (!(mask[bit / 8] & (1u << (bit % 8))))
          continue;
        if ((size_t)(end - from) < px_bytes) {
          s = ZR_EMPI; /* a rank sent fewer pixels than its mask says */
          break;
        }
        memcpy(dst + (size_t)x * channels, from, px_bytes);
        from += px_bytes;
      }
    }
  }
#undef CENTRE
  free(pack);
  free(all);
  free(counts);
  free(displs);
  return s;
}

/*
 * The rows of a band as wide as the image, straight into place: band
 * holds the chunk's rows (row_floats floats each) and rank r's rows of
 * it are rr's.  Where band is given (rank 0, or every rank with
 * everyone) the pool rendered this rank's rows into it already; the
 * others' arrive as point-to-point messages whose receive type is the
 * rank's rows at their offsets (an indexed type of rows), so they land
 * in their rows with no copy.  A rank without band (not everyone, rank
 * != 0) sends its rows to rank 0 from mine: packed in order when packed
 * (the static deal), else each at its offset in the chunk (rows taken
 * from the shared counter).  This replaced an MPI_Gatherv into a
 * rank-major buffer, its reordering into the band and a copy of the
 * band into the image: on this machine, a virtual one where first
 * touching a page costs about 14 us, rank 0's two extra copies of the
 * image and their fresh pages were 12 to 27% of its CPU in a 2-rank
 * 2048x2048 render of bench/peers.sh's terrain (perf; -v's gather 0.44
 * s wall).  A rank with no rows in the chunk sends nothing and nothing
 * is awaited from it (every rank knows every count from rr).
 */
#define ROWS_TAG 15

static zr_status exchange_rows(zr_par *par, const float *mine, int packed,
                               float *band, size_t row_floats, int everyone,
                               const rank_rows *rr) {
  int n = par->size, me = par->rank;
  MPI_Datatype row = MPI_DATATYPE_NULL;
  MPI_Request *req = malloc(2 * (size_t)n * sizeof *req);
  MPI_Datatype *placed = malloc((size_t)n * sizeof *placed);
  zr_status s = row_floats > (size_t)INT_MAX ? ZR_ELIMIT
                : req && placed              ? ZR_OK
                                             : ZR_ENOMEM;
  for (int r = 0; placed && r < n; r++)
    placed[r] = MPI_DATATYPE_NULL;
  s = zr__par_agree(par, s);
  if (s == ZR_OK)
    s = mpi_status(MPI_Type_contiguous((int)row_floats, MPI_FLOAT, &row));
  if (s == ZR_OK)
    s = mpi_status(MPI_Type_commit(&row));
  /* Rank r's rows at their places in band (or in mine, for this rank's
     own rows when they are not packed). */
  for (int r = 0; s == ZR_OK && r < n; r++) {
    if (rank_count(rr, r) == 0)
      continue;
    s = mpi_status(MPI_Type_create_indexed_block(
        rank_count(rr, r), 1, rr->at + rr->start[r], row, &placed[r]));
    if (s == ZR_OK)
      s = mpi_status(MPI_Type_commit(&placed[r]));
  }
  int posted = 0, mine_rows = s == ZR_OK ? rank_count(rr, me) : 0;
  uint64_t sent = 0;
  for (int r = 0; s == ZR_OK && r < n; r++) {
    if (r == me)
      continue;
    int rc = MPI_SUCCESS;
    if ((everyone || me == 0) && rank_count(rr, r) > 0)
      rc = MPI_Irecv(band, 1, placed[r], r, ROWS_TAG, par->comm,
                     &req[posted++]);
    if (rc == MPI_SUCCESS && mine_rows > 0 && everyone) {
      rc = MPI_Isend(band, 1, placed[me], r, ROWS_TAG, par->comm,
                     &req[posted++]);
      sent += (uint64_t)mine_rows * row_floats * sizeof(float);
    } else if (rc == MPI_SUCCESS && mine_rows > 0 && me != 0 && r == 0) {
      /* MPI's send buffers are const only from MPI 3 on. */
      rc = MPI_Isend((float *)mine, packed ? mine_rows : 1,
                     packed ? row : placed[me], 0, ROWS_TAG, par->comm,
                     &req[posted++]);
      sent += (uint64_t)mine_rows * row_floats * sizeof(float);
    }
    s = mpi_status(rc);
  }
  /* Posted requests are completed even after a failure, so that none
     refers to freed memory. */
  if (posted > 0 &&
      MPI_Waitall(posted, req, MPI_STATUSES_IGNORE) != MPI_SUCCESS)
    s = ZR_EMPI;
  if (s == ZR_OK)
    par->traffic.pixel_bytes_sent += sent;
  for (int r = 0; placed && r < n; r++)
    if (placed[r] != MPI_DATATYPE_NULL)
      MPI_Type_free(&placed[r]);
  if (row != MPI_DATATYPE_NULL)
    MPI_Type_free(&row);
  free(placed);
  free(req);
  return s;
}

/*
 * Rows handed out as the ranks ask for them, on one host.  The static
 * deal gives each rank the same number of rows of a chunk, and a rank
 * that runs slower for a while (on this virtual machine a virtual CPU
 * ran 20-45% slower for 0.3-1 s spells under load, counted as the
 * task's own CPU since the guest reports no steal time:
 * bench/results/mpi-2026-12-03-s15.md) makes the others wait for it at
 * the chunk's end, while the threads of one process, which take rows
 * from one counter, do not wait.  So when every rank shares this host
 * the ranks take rows from one counter too: rank 0's shared-memory
 * window (MPI-3, MPI_Win_allocate_shared, osc sm) holds a counter a
 * pass (zr__rows_claim, on cache lines of their own) and, a row each,
 * the rank that took it, which is all the exchange after the chunk
 * needs to know where each rank's rows go.  The pixels themselves still
 * travel as messages into rank 0's image: a shared image would sit in
 * shared memory, which this kernel gives no huge pages
 * (transparent_hugepage/shmem_enabled "never"), and at about 14 us a
 * fresh 4 KiB page on this machine a 2048x2048 image touched by both
 * ranks would cost them ~0.25 s of page faults.  Which rank renders a
 * row does not change its pixels (pool.h), so the image is the same
 * bytes as with the static deal.  ZRCUBE_ROWS=static keeps the static
 * deal (the tests compare the two; a job that spans hosts always has
 * it).
 */
#define SHARED_LINE 64

typedef struct shared_rows {
  MPI_Win win;
  atomic_int *next[2]; /* a pass's next row */
  int *owner;          /* a row of the image each */
} shared_rows;

/* 1 when the ranks should take rows from a shared counter. */
static int rows_shared_wanted(const zr_par *par) {
  const char *how = getenv("ZRCUBE_ROWS");
  return par->uses_mpi && par->size > 1 && par->local_size == par->size &&
         !(how && strcmp(how, "static") == 0);
}

/* Collective: the window, its counters at 0 (rank 0 sets them before the
   others may read them: the agreement after this is the barrier). */
static zr_status shared_rows_new(zr_par *par, int height, shared_rows *sh) {
  sh->win = MPI_WIN_NULL;
  size_t bytes = 2 * SHARED_LINE + (size_t)height * sizeof(int);
  char *base = NULL;
  MPI_Aint size = 0;
  int unit = 1;
  if (MPI_Win_allocate_shared(par->rank == 0 ? (MPI_Aint)bytes : 0, 1,
                              MPI_INFO_NULL, par->comm, &base,
                              &sh->win) != MPI_SUCCESS)
    return ZR_EMPI;
  MPI_Win_set_errhandler(sh->win, MPI_ERRORS_RETURN);
  if (MPI_Win_shared_query(sh->win, 0, &size, &unit, &base) != MPI_SUCCESS ||
      (size_t)size < bytes || !base ||
      (uintptr_t)base % _Alignof(atomic_int) != 0)
    return ZR_EMPI;
  if (MPI_Win_lock_all(MPI_MODE_NOCHECK, sh->win) != MPI_SUCCESS)
    return ZR_EMPI;
  sh->next[0] = (atomic_int *)(void *)base;
  sh->next[1] = (atomic_int *)(void *)(base + SHARED_LINE);
  sh->owner = (int *)(void *)(base + 2 * SHARED_LINE);
  if (par->rank == 0) {
    atomic_init(sh->next[0], 0);
    atomic_init(sh->next[1], 0);
    for (int y = 0; y < height; y++)
      sh->owner[y] = -1;
  }
  return mpi_status(MPI_Win_sync(sh->win));
}

/* Collective (MPI_Win_free); nothing without a window. */
static void shared_rows_free(shared_rows *sh) {
  if (sh->win == MPI_WIN_NULL)
    return;
  MPI_Win_unlock_all(sh->win);
  MPI_Win_free(&sh->win);
}

/* Sums the statistics of all ranks into *stats on rank 0. */
static zr_status reduce_stats(zr_par *par, zr_render_stats *stats,
                              double *seconds) {
  if (!par->uses_mpi || par->size == 1)
    return ZR_OK;
  uint64_t mine[6] = {stats->camera_rays,    stats->supersample_rays,
                      stats->reflected_rays, stats->refracted_rays,
                      stats->shadow_rays,    stats->supersampled_pixels};
  uint64_t sum[6] = {0};
  double slowest = 0;
  int rc = MPI_Reduce(mine, sum, 6, MPI_UINT64_T, MPI_SUM, 0, par->comm);
  if (rc == MPI_SUCCESS)
    rc = MPI_Reduce(seconds, &slowest, 1, MPI_DOUBLE, MPI_MAX, 0, par->comm);
  if (rc != MPI_SUCCESS)
    return ZR_EMPI;
  if (par->rank == 0) {
    stats->camera_rays = sum[0];
    stats->supersample_rays = sum[1];
    stats->reflected_rays = sum[2];
    stats->refracted_rays = sum[3];
    stats->shadow_rays = sum[4];
    stats->supersampled_pixels = sum[5];
    *seconds = slowest;
  }
  return ZR_OK;
}

/*
 * The image-sized buffers of a render (the centres, this rank's rows, the
 * picture on rank 0) in 2 MiB pages where the kernel offers them for
 * the asking (Linux's transparent huge pages in "madvise" mode, as
 * here): on this virtual machine first touching a 4 KiB page costs
 * about 14 us, and a 2048x1536 image of floats is 9,216 of them.
 * Measured (a calloc'ed 37.7 MB buffer set with memset, best of 3):
 * 0.155 s of CPU in 4 KiB pages, 0.014 s in 2 MiB ones; perf of a
 * 2-rank render of scenes/default.pov at 2048x1536 +A0.3 put 11% of
 * rank 0's CPU in page faults.  Pages are only advised, never
 * required: where the advice is unknown or refused the buffers are
 * ordinary memory (core/hugepage.h, the advice lib/core gives too).
 *
 * A malloc of n floats (zeroed when zero is 1) that also succeeds (one
 * float) for n == 0; from 2 MiB on, aligned on and advised to huge
 * pages.  Freed with free.
 */
static float *float_alloc(size_t n, int zero) {
  if (n > (SIZE_MAX - ZR__HUGE_PAGE) / sizeof(float))
    return NULL;
  size_t bytes = (n ? n : 1) * sizeof(float);
  if (bytes < ZR__HUGE_PAGE)
    return zero ? calloc(bytes, 1) : malloc(bytes);
  bytes = (bytes + ZR__HUGE_PAGE - 1) & ~(ZR__HUGE_PAGE - 1);
  void *p = NULL;
  if (posix_memalign(&p, ZR__HUGE_PAGE, bytes) != 0)
    return NULL;
  zr__mem_advise_huge(p, bytes);
  if (zero)
    memset(p, 0, bytes);
  return p;
}

/*
 * n floats, all 0, for a buffer the render may not have written
 * everywhere before it reads it (the centres of pass 1, the picture with
 * alpha): from 2 MiB on a fresh anonymous mapping, zero as the kernel
 * gives it, so its pages are first touched by the rows that write them,
 * during the render the ranks share, instead of by a memset on every
 * rank before it (float_alloc's zero: 48 MiB of centres at 2048^2 with
 * +A, bench/results/session18-2026-12-04.md).  Below 2 MiB, or where
 * mappings fail, float_alloc's.  Freed with float_unmap(p, n).
 */
static float *float_zeroed(size_t n) {
  if (n > (SIZE_MAX - ZR__HUGE_PAGE) / sizeof(float))
    return NULL;
  size_t bytes = (n ? n : 1) * sizeof(float);
  if (bytes < ZR__HUGE_PAGE)
    return calloc(bytes, 1);
  bytes = (bytes + ZR__HUGE_PAGE - 1) & ~(ZR__HUGE_PAGE - 1);
#ifdef MAP_ANONYMOUS
  void *p = mmap(NULL, bytes, PROT_READ | PROT_WRITE,
                 MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED)
    return NULL;
  zr__mem_advise_huge(p, bytes);
  return p;
#else
  return float_alloc(n, 1);
#endif
}

static void float_unmap(float *p, size_t n) {
  if (!p)
    return;
  size_t bytes = (n ? n : 1) * sizeof(float);
#ifdef MAP_ANONYMOUS
  if (bytes >= ZR__HUGE_PAGE) {
    munmap(p, (bytes + ZR__HUGE_PAGE - 1) & ~(ZR__HUGE_PAGE - 1));
    return;
  }
#endif
  free(p);
}

zr_status zr__par_solo(const zr_par *par, zr_par **out) {
  zr_par *solo = calloc(1, sizeof *solo);
  if (!solo)
    return ZR_ENOMEM;
  solo->uses_mpi = 0;
  solo->threads_allowed = par->threads_allowed;
  solo->rank = 0;
  solo->size = 1;
  solo->local_size = par->local_size;
  solo->comm = MPI_COMM_NULL;
  *out = solo;
  return ZR_OK;
}

/* The bands of a render: at most 64 a pass, their size set by the
   image only, so a state file serves any number of ranks.  The ranks
   render runs of bands (chunks) between two meetings, sized so a chunk
   takes about job->band_seconds: every meeting makes ranks wait for
   the slowest, which cost 80% on two busy ranks when each band was
   one. */
#define MAX_BANDS 64

void zr__par_render_layout(const zr_par *par, const zr_par_render *job,
                           int *passes, int *bands, int *band_rows) {
  (void)par;
  int height = job->params->height > 0 ? job->params->height : 1;
  *passes = job->params->antialias ? 2 : 1;
  *band_rows = (height + MAX_BANDS - 1) / MAX_BANDS;
  *bands = (height + *band_rows - 1) / *band_rows;
}

/* One pass over the rows y0 .. y1 - 1 and columns x0 .. x1 - 1 of this
   rank (y0 + rank, + size, ...; with first 1, ranks 1 .. size - 1 share
   them and rank 0 has none), into rows_rgb. */
/* One rank alone, whole rows in place: the rows of the band its
   threads have finished, told to the writer as they come (a third
   thread beside two renderers takes the moments a band's last rows
   leave a thread idle, and the rest of its time from both alike, so
   the write ends with the render instead of after it). */
typedef struct follow {
  zr_par_writer *writer;
  int y0;
} follow;

static void rows_final(int rows, void *user) {
  const follow *f = user;
  zr__par_writer_rows(f->writer, f->y0 + rows);
}

static zr_status render_band(zr_par *par, zr_par_render *job,
                             const float *centres, float *rows_rgb,
                             size_t row_stride, int y0, int y1, int x0,
                             int x1, size_t progress_base,
                             size_t progress_total, int first,
                             zr_par_writer *writer, shared_rows *sh,
                             int pass, zr_par_writer *join) {
  zr_status s = ZR_OK;
  int joined = 0;
  if (par->rank < first && join && sh) {
    /* Rank 0 in the tail: its encoder has rank 0's processor until it
       has encoded every row told so far; then rank 0 takes rows from
       the counter beside the others while any are left.  The tail's
       length is an estimate; this makes a long one cost rank 0 little
       and the ranks end the tail together. */
    while (atomic_load(sh->next[pass]) < y1)
      if (zr__par_writer_wait_idle(join, 0.001)) {
        joined = 1;
        break;
      }
  }
  if (par->rank >= first || joined) {
    follow f = {writer, y0};
    zr_pool_job pool = {
        .scene = job->scene,
        .params = job->params,
        .rank = joined ? par->rank : par->rank - first,
        .nranks = joined ? par->size : par->size - first,
        .centres = centres,
        .rows_rgb = rows_rgb,
        .row_stride = row_stride,
        .threads = job->threads,
        .stats = &job->stats,
        .progress = job->progress,
        .progress_user = job->progress_user,
        .progress_base = progress_base,
        .progress_total = progress_total,
        .first_row = y0,
        .end_row = y1,
        .first_col = x0,
        .end_col = x1,
        .rows_final = writer ? rows_final : NULL,
        .rows_final_user = &f,
        .claim = sh ? sh->next[pass] : NULL,
        .owner = sh ? sh->owner : NULL,
        .owner_rank = par->rank,
    };
    s = zr__pool_render(&pool);
    /* Rank 0 marks its tail rows (joined) as the others mark theirs. */
    zr__par_mark(first ? "render: tail rows of this rank done"
                       : "render: rows of this rank done");
  }
  /* The owners this rank wrote, seen by the others after the meeting
     (MPI's rule for a shared window: a sync on both sides of it). */
  if (sh && s == ZR_OK)
    s = mpi_status(MPI_Win_sync(sh->win));
  s = zr__par_agree(par, s);
  if (sh && s == ZR_OK)
    s = mpi_status(MPI_Win_sync(sh->win));
  return s;
}

/* Rank 0's v[0 .. count - 1] on every rank. */
static zr_status share_ints(zr_par *par, int *v, int count) {
  if (!par->uses_mpi || par->size == 1)
    return ZR_OK;
  return mpi_status(MPI_Bcast(v, count, MPI_INT, 0, par->comm));
}

/* Copies a band's rows (x1 - x0 pixels each) into the full image. */
static void place_band(const float *band, float *image, int width, int y0,
                       int y1, int x0, int x1, int channels) {
  size_t n = (size_t)(x1 - x0) * (size_t)channels;
  for (int y = y0; y < y1; y++)
    memcpy(image + ((size_t)y * (size_t)width + (size_t)x0) * channels,
           band + (size_t)(y - y0) * n, n * sizeof *band);
}

/*
 * +UA: the gathered pixels (premultiplied colour and alpha) into the
 * image's colours and alpha plane.  Image files keep colours
 * unmultiplied, as povray's PNG, TGA and BMP do (measured: a pixel of
 * alpha 0.75 stores its colour divided by 0.75); a clear pixel is black.
 */
static void finish_alpha(const float *rgba, zr_image *image) {
  float *rgb = zr_image_pixels(image), *alpha = zr_image_alpha(image);
  size_t n = (size_t)zr_image_width(image) * (size_t)zr_image_height(image);
  for (size_t i = 0; i < n; i++) {
    float a = rgba[4 * i + 3];
    for (int k = 0; k < 3; k++)
      rgb[3 * i + k] = a > 0.0f ? rgba[4 * i + k] / a : 0.0f;
    alpha[i] = a;
  }
}

/* Rank 0's state to continue from, sent to every rank: the flags, and
   the centres every rank needs for the antialiasing pass. */
static zr_status share_resume(zr_par *par, zr_par_render *job,
                              zr_par_progress *pr, size_t image_floats) {
  /* 1: a state to continue from; -1: one of another layout (every
     rank fails); 0: none. */
  int have = 0;
  if (par->rank == 0 && job->resume) {
    const zr_par_progress *r = job->resume;
    have = r->passes == pr->passes && r->bands == pr->bands &&
                   r->band_rows == pr->band_rows
               ? 1 : -1;
  }
  if (par->uses_mpi && par->size > 1 &&
      MPI_Bcast(&have, 1, MPI_INT, 0, par->comm) != MPI_SUCCESS)
    return ZR_EMPI;
  if (have <= 0)
    return have < 0 ? ZR_EINVAL : ZR_OK;
  if (par->rank == 0) {
    const zr_par_progress *r = job->resume;
    for (int p = 0; p < pr->passes; p++)
      memcpy(pr->done[p], r->done[p], (size_t)pr->bands);
    if (pr->centres)
      memcpy(pr->centres, r->centres, image_floats * sizeof(float));
    memcpy(pr->image, r->image, image_floats * sizeof(float));
  }
  if (!par->uses_mpi || par->size == 1)
    return ZR_OK;
  zr_status s = ZR_OK;
  for (int p = 0; p < pr->passes && s == ZR_OK; p++)
    s = bcast_bytes(par, (char *)pr->done[p], (size_t)pr->bands);
  if (s == ZR_OK && pr->centres)
    s = bcast_bytes(par, (char *)pr->centres, image_floats * sizeof(float));
  return s;
}

zr_status zr__par_render(zr_par *par, zr_par_render *job) {
  double start = zr__par_now();
  memset(&job->stats, 0, sizeof job->stats);
  job->render_seconds = 0;
  job->gather_seconds = 0;
  job->tail_root_rows = 0;
  int width = job->params->width, height = job->params->height;
  zr_status s = ZR_OK;
  if (width < 1 || height < 1)
    s = ZR_EINVAL;
  /* Pixels are named y * width + x in 32 bits by zr_render_pixels. */
  else if ((uint64_t)width * (uint64_t)height > UINT32_MAX)
    s = ZR_ELIMIT;
  else if (par->rank == 0 &&
           (!job->image || zr_image_width(job->image) != width ||
            zr_image_height(job->image) != height))
    s = ZR_EINVAL;
  int r0 = 0, r1 = height, c0 = 0, c1 = width;
  if (s == ZR_OK && (job->row1 || job->col1)) {
    r0 = job->row0, r1 = job->row1, c0 = job->col0, c1 = job->col1;
    if (r0 < 0 || r1 > height || r0 >= r1 || c0 < 0 || c1 > width ||
        c0 >= c1)
      s = ZR_EINVAL;
  }
  zr_par_progress pr;
  memset(&pr, 0, sizeof pr);
  zr__par_render_layout(par, job, &pr.passes, &pr.bands, &pr.band_rows);
  /* Pass 1 with antialiasing also covers the window's neighbours. */
  int aa = pr.passes == 2;
  int p1r0 = aa && r0 > 0 ? r0 - 1 : r0, p1r1 = aa && r1 < height ? r1 + 1 : r1;
  int p1c0 = aa && c0 > 0 ? c0 - 1 : c0, p1c1 = aa && c1 < width ? c1 + 1 : c1;
  /* +UA: 4 floats a pixel, the colour premultiplied by alpha, and the
     alpha; rank 0 gathers them here and splits them into the image at
     the end (finish_alpha). */
  int channels = job->params->alpha ? 4 : 3;
  pr.channels = channels;
  size_t image_floats = (size_t)(width > 0 ? width : 0) *
                        (size_t)(height > 0 ? height : 0) * (size_t)channels;
  /* A chunk may hold every row. */
  size_t band_floats = image_floats;
  float *mine = NULL, *band = NULL, *rank_major = NULL;
  /* Rank 0 keeps the picture; every rank keeps the centres (pass 2
     reads each pixel's neighbours). */
  if (s == ZR_OK) {
    pr.done[0] = calloc((size_t)pr.bands, 1);
    pr.done[1] = calloc((size_t)pr.bands, 1);
    if (par->rank == 0 && channels == 4)
      pr.image = float_zeroed(image_floats);
    else
      pr.image = par->rank == 0 ? zr_image_pixels(job->image) : NULL;
    if (aa)
      pr.centres = float_zeroed(image_floats);
    mine = float_alloc(band_floats, 0);
    band = float_alloc(band_floats, 0);
    rank_major = float_alloc(band_floats, 0);
    if (!pr.done[0] || !pr.done[1] || (aa && !pr.centres) || !mine ||
        !band || !rank_major || (par->rank == 0 && !pr.image) ||
        (par->rank == 0 && channels == 4 &&
         zr_image_add_alpha(job->image) != ZR_OK))
      s = ZR_ENOMEM;
    if (pr.image && channels == 3 && !job->image_zero) {
      /* The picture (lib/image's) is still untouched here when it is
         fresh: its pages can still be huge ones.  One known to be zero
         is left untouched (job->image_zero): bench/timeline.sh, terrain
         2048^2, mpirun -n 2, this memset of its 48 MiB took rank 0
         0.005-0.006 s while rank 1 waited in the next meeting. */
      zr__mem_advise_huge(pr.image, image_floats * sizeof(float));
      memset(pr.image, 0, image_floats * sizeof(float));
    }
  }
  int multi = par->uses_mpi && par->size > 1;
  /* Each rank's rows of a chunk (exchange_rows, collect_changes). */
  rank_rows rr = {NULL, NULL};
  if (s == ZR_OK && multi) {
    rr.start = malloc(((size_t)par->size + 1) * sizeof *rr.start);
    rr.at = malloc((size_t)height * sizeof *rr.at);
    if (!rr.start || !rr.at)
      s = ZR_ENOMEM;
  }
  zr__par_mark("render: buffers ready");
  s = zr__par_agree(par, s);
  zr__par_mark("render: all ranks ready");
  if (s == ZR_OK)
    s = zr__par_agree(par, share_resume(par, job, &pr, image_floats));
  /* One host: rows taken from a shared counter (shared_rows); where the
     window cannot be made, the static deal, which needs none. */
  shared_rows shared_window = {MPI_WIN_NULL, {NULL, NULL}, NULL};
  shared_rows *sh = NULL;
  if (s == ZR_OK && rows_shared_wanted(par)) {
    zr_status made = shared_rows_new(par, height, &shared_window);
    if (zr__par_agree(par, made) == ZR_OK)
      sh = &shared_window;
    else
      shared_rows_free(&shared_window);
  }
  if (s == ZR_OK && multi)
    zr__par_mark(sh ? "render: rows shared" : "render: rows dealt");
  /* This rank's rows still to render, for the progress line. */
  /* This rank's share of the rows still to render, for the progress
     line (the chunks' interleaving may make it a row or two off). */
  size_t total = 0, done_rows = 0;
  for (int p = 0; p < pr.passes && s == ZR_OK; p++)
    for (int b = 0; b < pr.bands; b++) {
      int y0 = b * pr.band_rows, y1 = y0 + pr.band_rows;
      int lo = p == 0 ? p1r0 : r0, hi = p == 0 ? p1r1 : r1;
      y0 = y0 < lo ? lo : y0;
      y1 = y1 > hi ? hi : y1;
      if (y1 > y0 && !pr.done[p][b])
        total += (size_t)(y1 - y0);
    }
  total = (total + (size_t)par->size - 1) / (size_t)par->size;
  job->gather_seconds = 0;
  int chunk = 1;          /* bands in the next chunk (rank 0 decides) */
  double band_time = 0;   /* seconds a band took, last chunk */
  /* Rank 0 with a writer, on a whole image of colours alone: the rows
     of job->image are told to the writer as they become final from the
     tail on (at the end without one), and the
     last bands of the last pass go to the other ranks alone (first 1)
     from band tail_from on, which rank 0 sets once it has timed a chunk
     of that pass, and every rank learns with the chunk. */
  int whole = r0 == 0 && r1 == height && c0 == 0 && c1 == width;
  int feed = par->rank == 0 && job->writer && channels == 3 && whole;
  int tail_from = pr.bands;
  double pass_seconds = 0; /* the last pass's chunks so far, wall */
  int pass_bands = 0;      /* and their bands */
  for (int p = 0; p < pr.passes && s == ZR_OK; p++) {
    int lo = p == 0 ? p1r0 : r0, hi = p == 0 ? p1r1 : r1;
    int x0 = p == 0 ? p1c0 : c0, x1 = p == 0 ? p1c1 : c1;
    int everyone = p == 0 && aa;
    int last = p == pr.passes - 1;
    float *target = everyone ? pr.centres : pr.image;
    int b = 0;
    while (b < pr.bands && s == ZR_OK) {
      if (pr.done[p][b]) {
        b++;
        continue;
      }
      /* The chunk: up to chunk bands not yet done, from b on. */
      if (par->rank == 0) {
        if (job->band_seconds <= 0)
          chunk = 1;
        else if (band_time > 0)
          chunk = (int)fmin(pr.bands, fmax(1.0, job->band_seconds /
                                                    band_time));
        if (feed && multi && last && tail_from == pr.bands) {
          /* The bands of this pass up to half of them first (a single
             band is a poor measure: the top of a picture is often
             sky), then the tail from their mean time. */
          int half = pr.bands / 2;
          if (b < half) {
            chunk = (int)fmin(chunk, half - b);
          } else if (pass_bands > 0 && job->write_row_seconds > 0) {
            /* k bands of n - 1 ranks take about as long as the
               encoder takes for the bands before them. */
            int left = 0;
            for (int k = b; k < pr.bands; k++)
              left += !pr.done[p][k];
            double enc = job->write_row_seconds * pr.band_rows;
            double alone = pass_seconds / pass_bands * par->size /
                           (par->size - 1);
            /* The encoder has the rows above the tail to encode, the
               pass's bands but k: k alone = (bands - k) enc.  Rounded
               up, since rank 0 joins the tail once its encoder is done
               (render_band): a tail too long costs little, one too
               short leaves the others idle while rank 0 encodes. */
            int k = (int)ceil((double)pr.bands * enc / (alone + enc));
            if (k > left - 1)
              k = left - 1; /* a chunk of every rank first */
            if (k >= 1)
              tail_from = pr.bands - k;
          }
        }
      }
      /* The tail in one chunk, which rank 0 joins once its encoder is
         done: a meeting while the encoder runs puts three threads on
         two processors, and a rank that spins in the exchange takes the
         processor the other rank needs (a band at a time, flake's first
         two tail bands met 0.034 and 0.040 s late, bench/timeline.sh
         under chrt). */
      if (par->rank == 0 && feed && multi && last && b >= tail_from)
        chunk = pr.bands;
      int plan[2] = {chunk, tail_from};
      s = zr__par_agree(par, share_ints(par, plan, 2));
      if (s != ZR_OK)
        break;
      chunk = plan[0];
      tail_from = plan[1];
      int first = last && b >= tail_from ? 1 : 0;
      int e = b;
      while (e < pr.bands && e - b < chunk && !pr.done[p][e] &&
             (first || !last || e < tail_from))
        e++;
      int y0 = b * pr.band_rows, y1 = e * pr.band_rows;
      y0 = y0 < lo ? lo : y0;
      y1 = y1 > hi ? hi : y1;
      double t0 = zr__par_now();
      if (y1 > y0) {
        /* A band as wide as the image goes straight into target where
           this rank has it: the pool renders the rank's rows into their
           places (unless pass 2 of several ranks, which compares them
           with the centres first), the others' rows arrive in theirs
           (exchange_rows).  Every rank takes the same branch. */
        int changes = p == 1 && multi;
        size_t row_floats = (size_t)width * (size_t)channels;
        float *dest = x0 == 0 && x1 == width && target
                          ? target + (size_t)y0 * row_floats
                          : NULL;
        int in_place = x0 == 0 && x1 == width && !changes;
        /* Pass 2 of several ranks: rank 0 renders its own rows into
           their places too, and collects only the others' changes. */
        int root_in_place = changes && dest && par->rank == 0;
        /* The chunk's rows taken from the shared counter when they are
           as wide as the image (a window of columns keeps the deal:
           collect_rows). */
        shared_rows *take = sh && x0 == 0 && x1 == width ? sh : NULL;
        float *rows = mine;
        size_t stride = 0;
        int packed = 1;
        if (take) {
          /* Each row at its offset in the chunk, in place or in mine. */
          if ((in_place || root_in_place) && dest)
            rows = dest;
          stride = row_floats;
          packed = 0;
        } else if ((in_place || root_in_place) && dest &&
                   par->rank >= first) {
          rows = dest + (size_t)(par->rank - first) * row_floats;
          stride = (size_t)(par->size - first) * row_floats;
          packed = 0;
        }
        /* One rank alone follows its rows to the writer (the last
           pass's rows are final as they are written in place). */
        zr_par_writer *follow_writer =
            feed && !multi && last && in_place && dest ? job->writer
                                                       : NULL;
        s = render_band(par, job, p == 1 ? pr.centres : NULL, rows, stride,
                        y0, y1, x0, x1, done_rows, total, first,
                        follow_writer, take, p,
                        first && feed ? job->writer : NULL);
        /* Every rank reads the same owners (render_band's syncs), so
           every rank makes the same lists and the same status: no
           agreement is needed. */
        if (s == ZR_OK && take)
          s = rank_rows_taken(&rr, take->owner + y0, y1 - y0, par->size);
        else if (s == ZR_OK && multi)
          rank_rows_dealt(&rr, y1 - y0, first, par->size);
        if (s == ZR_OK)
          done_rows += multi ? (size_t)rank_count(&rr, par->rank)
                             : (size_t)(y1 - y0);
        if (s == ZR_OK && first && par->rank == 0)
          job->tail_root_rows += rank_count(&rr, 0);
        zr__par_mark(first ? "render: tail chunk rendered"
                           : "render: chunk rendered");
        double gather_start = zr__par_now();
        float *into = dest ? dest : band;
        if (s == ZR_OK && changes)
          s = zr__par_agree(par, collect_changes(par, mine, packed, into,
                                                 pr.centres, width, y0, x0,
                                                 x1, channels,
                                                 root_in_place, &rr));
        else if (s == ZR_OK && in_place && multi)
          s = zr__par_agree(par, exchange_rows(par, mine, packed, dest,
                                               row_floats, everyone, &rr));
        else if (s == ZR_OK && !in_place)
          s = zr__par_agree(par, collect_rows(par, mine, band, rank_major,
                                              x1 - x0, y1 - y0, channels,
                                              everyone));
        job->gather_seconds += zr__par_now() - gather_start;
        zr__par_mark("render: chunk gathered");
        if (s == ZR_OK && target && !dest)
          place_band(band, target, width, y0, y1, x0, x1, channels);
      }
      band_time = (zr__par_now() - t0) / (double)(e - b);
      if (last) {
        pass_seconds += band_time * (double)(e - b);
        pass_bands += e - b;
      }
      for (int k = b; k < e; k++)
        pr.done[p][k] = 1;
      b = e;
      if (s == ZR_OK && par->rank == 0 && job->band_done)
        job->band_done(&pr, job->band_user);
      if (s == ZR_OK && feed && last && (!multi || b >= tail_from)) {
        /* The rows above the first band still to do are final: told
           from the tail on, when rank 0 has nothing else to do (told
           sooner, the encoder took processor time from the ranks'
           renders: 3 threads on 2 cores, and rank 0 idle in the
           tail).  One rank alone has told them row by row already
           (render_band's follow). */
        int f = 0;
        while (f < pr.bands && pr.done[p][f])
          f++;
        zr__par_writer_rows(job->writer, f * pr.band_rows < height
                                             ? f * pr.band_rows
                                             : height);
      }
    }
  }
  job->tail_bands = pr.bands - tail_from;
  if (s == ZR_OK && par->rank == 0 && channels == 4)
    finish_alpha(pr.image, job->image);
  if (s == ZR_OK && par->rank == 0 && job->writer)
    zr__par_writer_rows(job->writer, height);
  if (channels == 4)
    float_unmap(pr.image, image_floats);
  job->render_seconds = zr__par_now() - start;
  zr__par_mark("render: last chunk done");
  if (s == ZR_OK)
    s = zr__par_agree(par, reduce_stats(par, &job->stats,
                                        &job->render_seconds));
  shared_rows_free(&shared_window);
  free(rr.start);
  free(rr.at);
  free(pr.done[0]);
  free(pr.done[1]);
  float_unmap(pr.centres, image_floats);
  free(mine);
  free(band);
  free(rank_major);
  return s;
}

/* ---- the team of a radiosity solve or cache pretrace (zr_team) ---- */

/* MPI counts are ints: a part of 2 GiB or more cannot travel in one
   MPI_Allgatherv.  Every member sees the same counts, so every member
   refuses alike, and no agreement is needed first (the count arrays
   were made with the team). */
static zr_status team_allgather(void *user, const void *mine, void *all,
                                const size_t *counts) {
  zr_par *par = user;
  int n = par->size;
  if (par->team_counts == NULL)
    return ZR_ENOMEM; /* on every rank: zr__par_team agreed on it */
  int *c = par->team_counts, *d = par->team_counts + n;
  size_t total = 0;
  for (int r = 0; r < n; r++) {
    if (counts[r] > INT_MAX || total > INT_MAX - counts[r])
      return ZR_ELIMIT;
    c[r] = (int)counts[r];
    d[r] = (int)total;
    total += counts[r];
  }
  double start = zr__par_now(), cpu = zr__par_cpu();
  zr_status s = meet(par);
  if (s == ZR_OK)
    s = mpi_status(MPI_Allgatherv((void *)mine, c[par->rank], MPI_BYTE,
                                  all, c, d, MPI_BYTE, par->comm));
  par->traffic.team_seconds += zr__par_now() - start;
  par->traffic.team_cpu_seconds += zr__par_cpu() - cpu;
  if (s == ZR_OK) {
    par->traffic.team_bytes_sent += counts[par->rank];
    par->traffic.team_calls++;
  }
  return s;
}

zr_status zr__par_team(zr_par *par, zr_team *team) {
  team->rank = par->rank;
  team->size = par->uses_mpi ? par->size : 1;
  team->allgather = team_allgather;
  team->user = par;
  if (team->size == 1 || par->team_counts != NULL)
    return ZR_OK;
  par->team_counts = malloc(2 * (size_t)par->size * sizeof(int));
  zr_status s = zr__par_agree(par, par->team_counts ? ZR_OK : ZR_ENOMEM);
  if (s != ZR_OK) {
    free(par->team_counts);
    par->team_counts = NULL;
  }
  return s;
}

void zr__par_get_traffic(const zr_par *par, zr_par_traffic *out) {
  *out = par->traffic;
}
