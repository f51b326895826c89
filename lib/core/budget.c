/*
 * budget.c - the memory budget of a run (see budget.h).
 *
 * The default is half of physical memory: enough for any scene of the
 * stock set (the largest needs a few hundred MiB) while leaving room
 * for the allocations no one charges (the BVH, small strings, the
 * render's image) and for other processes.  Under an address-space
 * limit (ulimit -v) or data limit (ulimit -d) the budget is three
 * quarters of that limit, so the budget, not a failed malloc deep in
 * a decoder, is what stops a scene too big for it.
 */
#include "core/budget.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <unistd.h>

zr_budget *zr__budget_new(size_t limit) {
  zr_budget *b = malloc(sizeof *b);
  if (!b)
    return NULL;
  atomic_init(&b->used, 0);
  atomic_init(&b->peak, 0);
  atomic_init(&b->refs, 1);
  b->limit = limit;
  return b;
}

zr_budget *zr__budget_ref(zr_budget *b) {
  if (b)
    atomic_fetch_add(&b->refs, 1);
  return b;
}

void zr__budget_unref(zr_budget *b) {
  if (b && atomic_fetch_sub(&b->refs, 1) == 1)
    free(b);
}

bool zr__budget_charge(zr_budget *b, size_t bytes) {
  if (!b)
    return true;
  size_t used = atomic_load(&b->used);
  for (;;) {
    if (bytes > SIZE_MAX - used ||
        (b->limit && used + bytes > b->limit))
      return false;
    if (atomic_compare_exchange_weak(&b->used, &used, used + bytes))
      break;
  }
  size_t now = used + bytes, peak = atomic_load(&b->peak);
  while (now > peak && !atomic_compare_exchange_weak(&b->peak, &peak, now))
    ;
  return true;
}

void zr__budget_release(zr_budget *b, size_t bytes) {
  if (b && bytes)
    atomic_fetch_sub(&b->used, bytes);
}

static size_t limit_of(int resource) {
  struct rlimit rl;
  if (getrlimit(resource, &rl) != 0 || rl.rlim_cur == RLIM_INFINITY)
    return SIZE_MAX;
  return (size_t)(rl.rlim_cur / 4 * 3);
}

size_t zr__budget_default_limit(void) {
  long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  size_t limit = pages > 0 && page > 0
                     ? (size_t)pages / 2 * (size_t)page
                     : (size_t)1 << 32;
  size_t as = limit_of(RLIMIT_AS), data = limit_of(RLIMIT_DATA);
  if (as < limit)
    limit = as;
  if (data < limit)
    limit = data;
  return limit;
}

const char *zr__budget_size_text(size_t bytes, char *buf, size_t size) {
  static const char *const units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
  double v = (double)bytes;
  int u = 0;
  while (v >= 1024 && u < 4) {
    v /= 1024;
    u++;
  }
  if (u == 0)
    snprintf(buf, size, "%zu bytes", bytes);
  else
    snprintf(buf, size, "%.3g %s", v, units[u]);
  return buf;
}
