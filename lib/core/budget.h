/*
 * budget.h - the memory budget of a run.
 *
 * A hostile or mistaken scene must stop with a located error, not grow
 * until the kernel kills the process.  The large allocations a scene
 * drives (token arrays, the scene arena that holds arrays and objects,
 * meshes, decoded images, radiosity elements and links) are charged to
 * one budget before they are made and given back when they are freed.
 * The budget is shared by a context and everything made with it (a scene
 * may outlive its context), so it is reference counted; its counter is
 * atomic because radiosity workers and renders run on threads.
 */
#ifndef ZR_CORE_BUDGET_H
#define ZR_CORE_BUDGET_H

#include <stdatomic.h>
#include <stdbool.h>
#include <stddef.h>

typedef struct zr_budget {
  atomic_size_t used;   /* bytes charged and not yet given back */
  atomic_size_t peak;   /* the most ever charged at once */
  size_t limit;         /* 0: no limit */
  atomic_int refs;
} zr_budget;

/* A budget of limit bytes (0: none), one reference; NULL without memory. */
zr_budget *zr__budget_new(size_t limit);
zr_budget *zr__budget_ref(zr_budget *b);
void zr__budget_unref(zr_budget *b);
/* Charges bytes: false (and nothing charged) when they would pass the
   limit.  A NULL budget accepts everything. */
bool zr__budget_charge(zr_budget *b, size_t bytes);
void zr__budget_release(zr_budget *b, size_t bytes);
/* The default limit: a fraction of physical memory, lowered to fit the
   process's address-space and data limits (ulimit -v, ulimit -d). */
size_t zr__budget_default_limit(void);
/* "1.5 GiB": bytes for messages, in buf. */
const char *zr__budget_size_text(size_t bytes, char *buf, size_t size);

#endif /* ZR_CORE_BUDGET_H */
