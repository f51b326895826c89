/*
 * nompi.h - what lib/par/par.c needs of <mpi.h> in a build configured
 * --without-mpi: the types and constants, and functions that fail.
 *
 * par.c calls MPI only when an MPI launcher started the process
 * (launched_by_mpi()); a serial zrcube started by mpirun gets an error
 * from MPI_Init_thread here, and every other call is unreachable.  So
 * these are not a fake MPI: they say "there is none".  MPI code added
 * to par.c needs its names here too (the --without-mpi build says
 * which are missing).
 */
#ifndef ZR_PAR_NOMPI_H
#define ZR_PAR_NOMPI_H

#include <stdio.h>

typedef int MPI_Comm;
typedef int MPI_Datatype;
typedef int MPI_Info;
typedef int MPI_Op;
typedef int MPI_Errhandler;
typedef int MPI_Request;
typedef int MPI_Status;
typedef long MPI_Aint;
typedef int MPI_Win;
#define MPI_STATUS_IGNORE ((MPI_Status *)0)
#define MPI_STATUSES_IGNORE ((MPI_Status *)0)

enum {
  MPI_SUCCESS = 0,
  MPI_ERR_OTHER = 15,
  MPI_COMM_NULL = 0,
  MPI_COMM_WORLD = 1,
  MPI_COMM_TYPE_SHARED = 1,
  MPI_INFO_NULL = 0,
  MPI_ERRORS_RETURN = 1,
  MPI_THREAD_SINGLE = 0,
  MPI_THREAD_FUNNELED = 1,
  MPI_DATATYPE_NULL = 0,
  MPI_BYTE = 1,
  MPI_INT = 2,
  MPI_INT64_T = 3,
  MPI_UINT64_T = 4,
  MPI_FLOAT = 5,
  MPI_DOUBLE = 6,
  MPI_MIN = 1,
  MPI_MAX = 2,
  MPI_SUM = 3,
  MPI_MAX_LIBRARY_VERSION_STRING = 64,
  MPI_WIN_NULL = 0,
  MPI_MODE_NOCHECK = 1
};

static inline int MPI_Init_thread(int *argc, char ***argv, int required,
                                  int *provided) {
  (void)argc, (void)argv, (void)required;
  *provided = MPI_THREAD_SINGLE;
  return MPI_ERR_OTHER; /* built without MPI */
}
static inline int MPI_Finalize(void) { return MPI_SUCCESS; }
static inline int MPI_Get_library_version(char *version, int *len) {
  *len = snprintf(version, MPI_MAX_LIBRARY_VERSION_STRING,
                  "no MPI (built --without-mpi)");
  return MPI_SUCCESS;
}
static inline int MPI_Comm_dup(MPI_Comm c, MPI_Comm *out) {
  (void)c, (void)out;
  return MPI_ERR_OTHER;
}
static inline int MPI_Comm_set_errhandler(MPI_Comm c, MPI_Errhandler e) {
  (void)c, (void)e;
  return MPI_ERR_OTHER;
}
static inline int MPI_Comm_rank(MPI_Comm c, int *rank) {
  (void)c;
  *rank = 0;
  return MPI_ERR_OTHER;
}
static inline int MPI_Comm_size(MPI_Comm c, int *size) {
  (void)c;
  *size = 1;
  return MPI_ERR_OTHER;
}
static inline int MPI_Comm_split_type(MPI_Comm c, int type, int key,
                                      MPI_Info info, MPI_Comm *out) {
  (void)c, (void)type, (void)key, (void)info, (void)out;
  return MPI_ERR_OTHER;
}
static inline int MPI_Comm_free(MPI_Comm *c) {
  *c = MPI_COMM_NULL;
  return MPI_SUCCESS;
}
static inline int MPI_Bcast(void *buf, int n, MPI_Datatype t, int root,
                            MPI_Comm c) {
  (void)buf, (void)n, (void)t, (void)root, (void)c;
  return MPI_ERR_OTHER;
}
static inline int MPI_Allreduce(const void *in, void *out, int n,
                                MPI_Datatype t, MPI_Op op, MPI_Comm c) {
  (void)in, (void)out, (void)n, (void)t, (void)op, (void)c;
  return MPI_ERR_OTHER;
}
static inline int MPI_Reduce(const void *in, void *out, int n,
                             MPI_Datatype t, MPI_Op op, int root,
                             MPI_Comm c) {
  (void)in, (void)out, (void)n, (void)t, (void)op, (void)root, (void)c;
  return MPI_ERR_OTHER;
}
static inline int MPI_Gatherv(const void *in, int n, MPI_Datatype t,
                              void *out, const int *counts,
                              const int *displs, MPI_Datatype rt, int root,
                              MPI_Comm c) {
  (void)in, (void)n, (void)t, (void)out, (void)counts, (void)displs;
  (void)rt, (void)root, (void)c;
  return MPI_ERR_OTHER;
}
static inline int MPI_Gather(const void *in, int n, MPI_Datatype t,
                             void *out, int rn, MPI_Datatype rt, int root,
                             MPI_Comm c) {
  (void)in, (void)n, (void)t, (void)out, (void)rn, (void)rt, (void)root;
  (void)c;
  return MPI_ERR_OTHER;
}
static inline int MPI_Allgatherv(const void *in, int n, MPI_Datatype t,
                                 void *out, const int *counts,
                                 const int *displs, MPI_Datatype rt,
                                 MPI_Comm c) {
  (void)in, (void)n, (void)t, (void)out, (void)counts, (void)displs;
  (void)rt, (void)c;
  return MPI_ERR_OTHER;
}
static inline int MPI_Ibarrier(MPI_Comm c, MPI_Request *req) {
  (void)c;
  *req = 0;
  return MPI_ERR_OTHER;
}
static inline int MPI_Test(MPI_Request *req, int *done, MPI_Status *st) {
  (void)req, (void)st;
  *done = 1;
  return MPI_ERR_OTHER;
}
static inline int MPI_Type_create_resized(MPI_Datatype t, MPI_Aint lb,
                                          MPI_Aint extent,
                                          MPI_Datatype *out) {
  (void)t, (void)lb, (void)extent;
  *out = MPI_DATATYPE_NULL;
  return MPI_ERR_OTHER;
}
static inline int MPI_Irecv(void *buf, int n, MPI_Datatype t, int from,
                            int tag, MPI_Comm c, MPI_Request *req) {
  (void)buf, (void)n, (void)t, (void)from, (void)tag, (void)c;
  *req = 0;
  return MPI_ERR_OTHER;
}
static inline int MPI_Isend(const void *buf, int n, MPI_Datatype t, int to,
                            int tag, MPI_Comm c, MPI_Request *req) {
  (void)buf, (void)n, (void)t, (void)to, (void)tag, (void)c;
  *req = 0;
  return MPI_ERR_OTHER;
}
static inline int MPI_Waitall(int n, MPI_Request *req, MPI_Status *st) {
  (void)n, (void)req, (void)st;
  return MPI_ERR_OTHER;
}
static inline int MPI_Type_contiguous(int n, MPI_Datatype t,
                                      MPI_Datatype *out) {
  (void)n, (void)t, (void)out;
  return MPI_ERR_OTHER;
}
static inline int MPI_Type_commit(MPI_Datatype *t) {
  (void)t;
  return MPI_ERR_OTHER;
}
static inline int MPI_Type_free(MPI_Datatype *t) {
  *t = MPI_DATATYPE_NULL;
  return MPI_SUCCESS;
}
static inline int MPI_Type_create_indexed_block(int n, int length,
                                                const int *displs,
                                                MPI_Datatype t,
                                                MPI_Datatype *out) {
  (void)n, (void)length, (void)displs, (void)t;
  *out = MPI_DATATYPE_NULL;
  return MPI_ERR_OTHER;
}
static inline int MPI_Win_allocate_shared(MPI_Aint size, int disp_unit,
                                          MPI_Info info, MPI_Comm c,
                                          void *base, MPI_Win *win) {
  (void)size, (void)disp_unit, (void)info, (void)c, (void)base;
  *win = MPI_WIN_NULL;
  return MPI_ERR_OTHER;
}
static inline int MPI_Win_shared_query(MPI_Win win, int rank, MPI_Aint *size,
                                       int *disp_unit, void *base) {
  (void)win, (void)rank, (void)size, (void)disp_unit, (void)base;
  return MPI_ERR_OTHER;
}
static inline int MPI_Win_set_errhandler(MPI_Win win, MPI_Errhandler e) {
  (void)win, (void)e;
  return MPI_ERR_OTHER;
}
static inline int MPI_Win_lock_all(int assert, MPI_Win win) {
  (void)assert, (void)win;
  return MPI_ERR_OTHER;
}
static inline int MPI_Win_unlock_all(MPI_Win win) {
  (void)win;
  return MPI_ERR_OTHER;
}
static inline int MPI_Win_sync(MPI_Win win) {
  (void)win;
  return MPI_ERR_OTHER;
}
static inline int MPI_Win_free(MPI_Win *win) {
  *win = MPI_WIN_NULL;
  return MPI_SUCCESS;
}

#endif /* ZR_PAR_NOMPI_H */
