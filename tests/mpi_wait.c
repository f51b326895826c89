/*
 * mpi_wait.c - a rank that waits in a collective for a slower one sleeps
 * instead of spinning (lib/par/par.c, meet), and a job on one host skips
 * Open MPI's probe of network devices and the components it would not
 * choose (prefer_shared_memory).  Run by tests/test_mpi_wait.sh under
 * mpirun -n 2 and -n 3.
 *
 *   mpi_wait [NAME=VALUE]...
 *
 * Each NAME=VALUE: what environment variable NAME must be after
 * zr__par_init ("-": unset); a lone VALUE is OMPI_MCA_pml's; the word
 * "nodelay": the rank must have a TCP connection to a loopback address
 * (Open MPI 4's to its launcher) and every such connection must have
 * Nagle's algorithm off (par.c, launcher_without_delay).  The
 * last rank sleeps 2 s (no CPU) before it joins zr__par_agree with a
 * failure; every other rank is in the agreement meanwhile and must spend
 * under 0.2 s of CPU there (a spinning wait takes the whole 2 s of a
 * core on an idle machine), then every rank must get the failure.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <arpa/inet.h>
#include <dirent.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <sys/stat.h>

#include "par/par.h"

/* This process's TCP connections to loopback addresses: how many, and
   how many of them still delay small writes (TCP_NODELAY unset). */
static void loopback_sockets(int *count, int *delaying) {
  *count = *delaying = 0;
  DIR *fds = opendir("/proc/self/fd");
  if (!fds)
    return;
  struct dirent *e;
  while ((e = readdir(fds)) != NULL) {
    int fd = atoi(e->d_name);
    struct stat st;
    int type = 0, nodelay = 0;
    socklen_t len = sizeof type;
    if (e->d_name[0] == '.' || fd == dirfd(fds) || fstat(fd, &st) != 0 ||
        !S_ISSOCK(st.st_mode) ||
        getsockopt(fd, SOL_SOCKET, SO_TYPE, &type, &len) != 0 ||
        type != SOCK_STREAM)
      continue;
    struct sockaddr_storage peer;
    len = sizeof peer;
    if (getpeername(fd, (struct sockaddr *)&peer, &len) != 0)
      continue;
    int loopback =
        peer.ss_family == AF_INET
            ? (ntohl(((struct sockaddr_in *)&peer)->sin_addr.s_addr) >>
               24) == 127
            : peer.ss_family == AF_INET6 &&
                  IN6_IS_ADDR_LOOPBACK(
                      &((struct sockaddr_in6 *)&peer)->sin6_addr);
    if (!loopback)
      continue;
    len = sizeof nodelay;
    ++*count;
    if (getsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &nodelay, &len) != 0 ||
        !nodelay)
      ++*delaying;
  }
  closedir(fds);
}

int main(int argc, char **argv) {
  zr_par *par = NULL;
  if (zr__par_init(&argc, &argv, &par) != ZR_OK) {
    fprintf(stderr, "mpi_wait: cannot start MPI\n");
    return 1;
  }
  int failed = 0;
  int rank = zr__par_rank(par), size = zr__par_size(par);
  for (int i = 1; i < argc; i++) {
    if (strcmp(argv[i], "nodelay") == 0) {
      int count, delaying;
      loopback_sockets(&count, &delaying);
      if (count == 0 || delaying > 0) {
        fprintf(stderr, "mpi_wait: rank %d: %d of %d loopback TCP "
                        "connections delay small writes\n", rank,
                delaying, count);
        failed = 1;
      }
      continue;
    }
    const char *eq = strchr(argv[i], '=');
    char name[64] = "OMPI_MCA_pml";
    const char *want = argv[i];
    if (eq) {
      snprintf(name, sizeof name, "%.*s", (int)(eq - argv[i]), argv[i]);
      want = eq + 1;
    }
    if (strcmp(want, "-") == 0)
      want = NULL;
    const char *have = getenv(name);
    if ((have == NULL) != (want == NULL) || (have && strcmp(have, want))) {
      fprintf(stderr, "mpi_wait: rank %d: %s is %s, not %s\n", rank, name,
              have ? have : "unset", want ? want : "unset");
      failed = 1;
    }
  }
  if (size < 2 || !zr__par_uses_mpi(par)) {
    fprintf(stderr, "mpi_wait: needs 2 or more ranks under mpirun\n");
    failed = 1;
  }
  /* Start together, then the last rank comes 2 s late. */
  if (!failed && zr__par_agree(par, ZR_OK) != ZR_OK)
    failed = 1;
  int late = rank == size - 1;
  double wall = zr__par_now(), cpu = zr__par_cpu();
  if (late) {
    struct timespec two = {2, 0};
    nanosleep(&two, NULL);
  }
  zr_status s = zr__par_agree(par, late ? ZR_ENOMEM : ZR_OK);
  wall = zr__par_now() - wall;
  cpu = zr__par_cpu() - cpu;
  printf("rank %d: %.3f s in the agreement, %.3f s of CPU\n", rank, wall,
         cpu);
  if (s != ZR_ENOMEM) {
    fprintf(stderr, "mpi_wait: rank %d: agreed on %s, not the late "
                    "rank's failure\n", rank, zr_status_str(s));
    failed = 1;
  }
  if (!late && wall < 1.5) {
    fprintf(stderr, "mpi_wait: rank %d: left after %.3f s, before the "
                    "late rank came\n", rank, wall);
    failed = 1;
  }
  if (!late && cpu > 0.2) {
    fprintf(stderr, "mpi_wait: rank %d: %.3f s of CPU waiting %.3f s: "
                    "the wait spins\n", rank, cpu, wall);
    failed = 1;
  }
  zr__par_finalize(par);
  return failed;
}
