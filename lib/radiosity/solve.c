/*
 * solve.c - solving the hierarchical radiosity system on its links, and
 * the energy bookkeeping that checks it.
 *
 * Gathering with push-pull (Hanrahan, Salzman and Aupperle, SIGGRAPH
 * 1991, section 4): every link carries rho_p F_pq V_pq B_q from its source
 * node into the receiver node at whatever level it is attached; then one
 * sweep down each quadtree pushes what a node gathered into its children
 * (radiosity is per unit area, so a parent's share is simply added), and
 * the way back up pulls the area mean of the children into the parent,
 * so every node again holds the mean of its subtree, B = E + gathered.
 * One gather plus push-pull is a Jacobi sweep; it is repeated until the
 * radiosity moved in a sweep, summed as power over all leaves, falls
 * below the residual threshold times the emitted power.
 *
 * Southwell shooting (the progressive refinement of Cohen, Chen, Wallace
 * and Greenberg, SIGGRAPH 1988, on the hierarchy): each leaf keeps the
 * radiosity it has received but not yet passed on.  A shot takes the
 * surface side with the most unshot power, sends its unshot radiosity
 * along every link leaving that surface side (as a pulled area mean at
 * the node each link starts from), zeroes it, and pushes what receivers
 * got down to their leaves, where it becomes both radiosity and new
 * unshot radiosity.  It stops when the largest unshot power falls below
 * the residual threshold; nothing is lost, since what remains unshot is
 * what the threshold allows.
 *
 * Energy.  A final gather also collects the incident radiosity H (the
 * irradiance over pi) and the sum of F * V per leaf side (its closure,
 * 1 inside a closed scene); the absorbed power is the sum over leaf
 * sides of A (1 - rho) H.  In a closed scene that equals the power its
 * inner sides emit: a check that form factors, visibility and solution
 * together conserve energy.
 *
 * Threads.  A gather sweep runs over receiver nodes, each adding its
 * links in link order, and push-pull over surfaces, each summing its
 * own change, added up over surfaces in order afterwards: the solution
 * and the residual are the same bits for any number of threads.
 * Shooting stays on one thread (one shot is a small step).
 */
#include "radiosity/radiosity.h"

#include <stdlib.h>
#include <string.h>

#include "core/team.h"
#include "radiosity/workers.h"

/* Clears what links deposit at every node. */
static void clear_gathered(zr_radiosity *rad) {
  for (size_t n = 0; n < rad->n_nodes; n++) {
    zr__rad_node *node = &rad->nodes[n];
    memset(node->bg, 0, sizeof node->bg);
    memset(node->hg, 0, sizeof node->hg);
    node->closure[0] = node->closure[1] = 0.0;
  }
}

/* Adds link l's transfer of src_b (a radiosity triple) to its receiver. */
static void transfer(zr_radiosity *rad, const zr__rad_link *l,
                     const double src_b[3]) {
  zr__rad_node *p = &rad->nodes[l->recv];
  const double *rho = rad->surfs[p->surf].rho;
  for (int c = 0; c < 3; c++) {
    double h = l->ff * src_b[c];
    p->hg[l->rside][c] += h;
    p->bg[l->rside][c] += rho[c] * h;
  }
  p->closure[l->rside] += l->ff;
}

/* The live links grouped by receiver node, in link order within each
   (a counting sort): links[start[n] .. start[n + 1]) end at node n. */
typedef struct recv_index {
  uint32_t *start, *links;
} recv_index;

static void index_by_receiver(const zr_radiosity *rad, recv_index *ix) {
  ix->start = calloc(rad->n_nodes + 2, sizeof *ix->start);
  ix->links = malloc((rad->n_links + 1) * sizeof *ix->links);
  if (ix->start == NULL || ix->links == NULL) {
    free(ix->start);
    free(ix->links);
    ix->start = ix->links = NULL;
    return; /* gather() then runs on one thread, to the same bits */
  }
  for (size_t i = 0; i < rad->n_links; i++)
    if (!rad->links[i].dead)
      ix->start[rad->links[i].recv + 2]++;
  for (size_t n = 2; n < rad->n_nodes + 2; n++)
    ix->start[n] += ix->start[n - 1];
  for (size_t i = 0; i < rad->n_links; i++)
    if (!rad->links[i].dead)
      ix->links[ix->start[rad->links[i].recv + 1]++] = (uint32_t)i;
}

static void free_index(recv_index *ix) {
  free(ix->start);
  free(ix->links);
}

typedef struct gatherer {
  zr_radiosity *rad;
  const recv_index *ix;
} gatherer;

/* Gathers into the receivers [begin, end): a worker writes only its own
   receivers and adds their links in link order, as one thread would, so
   the sums are the same bits for any number of threads. */
static void gather_range(void *user, size_t begin, size_t end, int worker) {
  (void)worker;
  const gatherer *g = user;
  zr_radiosity *rad = g->rad;
  for (size_t n = begin; n < end; n++) {
    zr__rad_node *node = &rad->nodes[n];
    memset(node->bg, 0, sizeof node->bg);
    memset(node->hg, 0, sizeof node->hg);
    node->closure[0] = node->closure[1] = 0.0;
    for (uint32_t k = g->ix->start[n]; k < g->ix->start[n + 1]; k++) {
      const zr__rad_link *l = &rad->links[g->ix->links[k]];
      transfer(rad, l, rad->nodes[l->src].b[l->sside]);
    }
  }
}

static void gather(zr_radiosity *rad, const recv_index *ix) {
  if (ix->start != NULL) {
    gatherer g = {rad, ix};
    zr__rad_parallel(rad->params.threads, rad->n_nodes, 256, gather_range,
                     &g);
    return;
  }
  clear_gathered(rad);
  for (size_t i = 0; i < rad->n_links; i++) {
    const zr__rad_link *l = &rad->links[i];
    if (!l->dead)
      transfer(rad, l, rad->nodes[l->src].b[l->sside]);
  }
}

/*
 * Push-pull below node n for one side: down is what the ancestors
 * gathered; the subtree's new area mean goes into b and out.  *change
 * adds the area-weighted change of the leaves (largest channel).
 */
static void push_pull(zr_radiosity *rad, int32_t n, int side,
                      const double down[3], double up[3], double *change) {
  zr__rad_node *node = &rad->nodes[n];
  double d[3];
  for (int c = 0; c < 3; c++)
    d[c] = down[c] + node->bg[side][c];
  if (node->child < 0) {
    double e[3]; /* E + rho H_d: emission and light sources (direct.c) */
    zr__rad_leaf_source(rad, node, side, e);
    double diff = 0.0;
    for (int c = 0; c < 3; c++) {
      up[c] = e[c] + d[c];
      diff = fmax(diff, fabs(up[c] - node->b[side][c]));
      node->b[side][c] = up[c];
    }
    *change += node->area * diff;
    return;
  }
  double sum[3] = {0, 0, 0}, area = 0.0;
  int32_t first = node->child;
  for (int k = 0; k < 4; k++) {
    double cu[3];
    push_pull(rad, first + k, side, d, cu, change);
    double a = rad->nodes[first + k].area;
    for (int c = 0; c < 3; c++)
      sum[c] += a * cu[c];
    area += a;
  }
  node = &rad->nodes[n];
  for (int c = 0; c < 3; c++) {
    up[c] = area > 0.0 ? sum[c] / area : 0.0;
    node->b[side][c] = up[c];
  }
}

/* Push-pull of surfaces [begin, end), each tree by one worker; each
   surface's change goes to its own slot. */
typedef struct puller {
  zr_radiosity *rad;
  double *change;
} puller;

static void push_pull_range(void *user, size_t begin, size_t end,
                            int worker) {
  (void)worker;
  const puller *w = user;
  double zero[3] = {0, 0, 0}, up[3];
  for (size_t s = begin; s < end; s++) {
    double change = 0.0;
    for (int side = 0; side < 2; side++)
      push_pull(w->rad, w->rad->surfs[s].root, side, zero, up, &change);
    w->change[s] = change;
  }
}

/* The change, summed per surface and then over surfaces in order, so
   the residual is the same bits for any number of threads. */
static double push_pull_all(zr_radiosity *rad, double *change) {
  puller w = {rad, change};
  zr__rad_parallel(rad->params.threads, rad->n_surfs, 4, push_pull_range,
                   &w);
  double sum = 0.0;
  for (size_t s = 0; s < rad->n_surfs; s++)
    sum += change[s];
  return sum;
}

/* ---- gathering across a team (zr_team, core/team.h) ----
 *
 * Each member owns whole surfaces (their quadtrees), dealt so that the
 * links the members gather over are about equal: surfaces by falling
 * link count, each to the member with the fewest links so far (ties to
 * the lower rank), a rule every member evaluates alike.  A sweep
 * gathers into the owned surfaces' nodes and pushes and pulls their
 * trees, then the members exchange each owned surface's change and the
 * radiosity b that the others will read in the next sweep: b[side] of
 * a node is read by a sweep only where a link leaves that side of it,
 * so a member sends the sides of its nodes from which a link runs to
 * another member's surface (in surface, node and side order), and
 * keeps the rest until the solve ends, when one more exchange sends
 * them all, so every member then holds every node's b.  Gathering
 * reads only the b of the sweep before (Jacobi), so the sweeps are the
 * same bits as one process's, and so is the residual, summed over the
 * surfaces in order from the same per-surface changes.  The links and
 * nodes stay on every member: refinement replays on each, and the
 * render's final gather at a ray hit may read any link.
 *
 * scenes/cornell.pov (64x64, 2 ranks) sent 64.1 MB in 179 sweeps when
 * every node's two sides went every sweep, and unpacked its own part
 * too; the sides another member reads are a third of that: 20.6 MB in
 * 179 sweeps and the 6 ends of its solves (sweep exchange 19 -> 9 ms
 * of CPU a rank). */

/* The b triples a member sends in an exchange: entries node * 2 + side,
   member after member (entry[first[r] .. first[r + 1]) are member r's),
   and the bytes of each member's part. */
typedef struct team_sends {
  uint32_t *entry;
  size_t *first;
  size_t *part_bytes;
} team_sends;

typedef struct team_gather {
  int32_t *owner;     /* member of each surface */
  uint32_t *by_surf;  /* node indices grouped by surface, node order */
  size_t *surf_start; /* nodes of surface s: by_surf[start[s]..[s+1]) */
  uint32_t *mine;     /* nodes of this member's surfaces, node order */
  size_t n_mine;
  /* A sweep's part of each member is the same size every sweep (its
     surfaces' changes and the b its links to other members' surfaces
     read), known to every member from the owners and the links: one
     allgather a sweep into room made once, where a general exchange
     (zr__team_exchange) takes three (statuses and sizes, room agreed,
     parts).  The b no other member reads in a sweep goes once, at the
     end (rest, without changes). */
  team_sends sweep, rest;
  /* This member's part; every part, rank after rank: the solve's kept
     buffers (rad->team_send, rad->team_room), not the gather's. */
  char *send, *recv;
} team_gather;

static void team_sends_free(team_sends *ts) {
  free(ts->entry);
  free(ts->first);
  free(ts->part_bytes);
}

static void team_gather_free(team_gather *tg) {
  free(tg->owner);
  free(tg->by_surf);
  free(tg->surf_start);
  free(tg->mine);
  team_sends_free(&tg->sweep);
  team_sends_free(&tg->rest);
}

/* The entries of sends: those whose side is in need (wanted 1) or not
   (wanted 0), member after member, each in surface, node and side
   order; with_change adds a double a surface to each part.  Returns
   the total bytes, or SIZE_MAX when out of memory. */
static size_t team_sends_make(const zr_radiosity *rad, const team_gather *tg,
                              int n, const uint8_t *need, int wanted,
                              bool with_change, team_sends *ts) {
  size_t ns = rad->n_surfs, count = 0;
  for (size_t v = 0; v < rad->n_nodes; v++)
    for (int side = 0; side < 2; side++)
      count += ((need[v] >> side) & 1) == wanted;
  ts->entry = malloc((count + 1) * sizeof *ts->entry);
  ts->first = calloc((size_t)n + 1, sizeof *ts->first);
  ts->part_bytes = calloc((size_t)n, sizeof *ts->part_bytes);
  if (!ts->entry || !ts->first || !ts->part_bytes)
    return SIZE_MAX;
  size_t k = 0, total = 0;
  for (int r = 0; r < n; r++) {
    ts->first[r] = k;
    size_t k0 = k, surfs = 0;
    for (size_t sf = 0; sf < ns; sf++) {
      if (tg->owner[sf] != r)
        continue;
      surfs++;
      for (size_t j = tg->surf_start[sf]; j < tg->surf_start[sf + 1]; j++) {
        uint32_t v = tg->by_surf[j];
        for (int side = 0; side < 2; side++)
          if (((need[v] >> side) & 1) == wanted)
            ts->entry[k++] = 2 * v + (uint32_t)side;
      }
    }
    ts->part_bytes[r] = (with_change ? surfs * sizeof(double) : 0) +
                        (k - k0) * sizeof rad->nodes[0].b[0];
    total += ts->part_bytes[r];
  }
  ts->first[n] = k;
  return total;
}

static zr_status team_gather_init(zr_radiosity *rad, const recv_index *ix,
                                  team_gather *tg) {
  const zr_team *team = rad->params.team;
  int n = zr__team_size(team), me = zr__team_rank(team);
  size_t ns = rad->n_surfs;
  memset(tg, 0, sizeof *tg);
  tg->owner = malloc((ns + 1) * sizeof *tg->owner);
  tg->by_surf = malloc((rad->n_nodes + 1) * sizeof *tg->by_surf);
  tg->surf_start = calloc(ns + 2, sizeof *tg->surf_start);
  tg->mine = malloc((rad->n_nodes + 1) * sizeof *tg->mine);
  uint64_t *cost = calloc(ns + 1, sizeof *cost);
  uint64_t *load = calloc((size_t)n, sizeof *load);
  uint32_t *order = malloc((ns + 1) * sizeof *order);
  uint8_t *need = calloc(rad->n_nodes + 1, sizeof *need);
  zr_status st = ZR_OK;
  if (!tg->owner || !tg->by_surf || !tg->surf_start || !tg->mine ||
      !cost || !load || !order || !need)
    st = ZR_ENOMEM;
  if (st == ZR_OK) {
    for (size_t v = 0; v < rad->n_nodes; v++) {
      size_t sf = (size_t)rad->nodes[v].surf;
      cost[sf] += 1 + ix->start[v + 1] - ix->start[v];
      tg->surf_start[sf + 2]++;
    }
    for (size_t k = 2; k < ns + 2; k++)
      tg->surf_start[k] += tg->surf_start[k - 1];
    for (size_t v = 0; v < rad->n_nodes; v++)
      tg->by_surf[tg->surf_start[rad->nodes[v].surf + 1]++] = (uint32_t)v;
    /* Surfaces by falling cost, ties by index (insertion sort: a scene
       has tens to thousands of surfaces, sorted once a solve). */
    for (size_t k = 0; k < ns; k++) {
      size_t j = k;
      while (j > 0 && cost[order[j - 1]] < cost[k]) {
        order[j] = order[j - 1];
        j--;
      }
      order[j] = (uint32_t)k;
    }
    for (size_t k = 0; k < ns; k++) {
      int best = 0;
      for (int r = 1; r < n; r++)
        if (load[r] < load[best])
          best = r;
      tg->owner[order[k]] = best;
      load[best] += cost[order[k]];
    }
    for (size_t v = 0; v < rad->n_nodes; v++)
      if (tg->owner[rad->nodes[v].surf] == me)
        tg->mine[tg->n_mine++] = (uint32_t)v;
    /* The sides another member's receivers read. */
    for (size_t i = 0; i < rad->n_links; i++) {
      const zr__rad_link *l = &rad->links[i];
      if (!l->dead && tg->owner[rad->nodes[l->recv].surf] !=
                          tg->owner[rad->nodes[l->src].surf])
        need[l->src] |= (uint8_t)(1u << l->sside);
    }
    size_t total = team_sends_make(rad, tg, n, need, 1, true, &tg->sweep);
    size_t rest = team_sends_make(rad, tg, n, need, 0, false, &tg->rest);
    if (total == SIZE_MAX || rest == SIZE_MAX)
      st = ZR_ENOMEM;
    if (st == ZR_OK) {
      size_t mine = tg->sweep.part_bytes[me] > tg->rest.part_bytes[me]
                        ? tg->sweep.part_bytes[me]
                        : tg->rest.part_bytes[me];
      if (rest > total)
        total = rest;
      tg->send = zr__team_room_get(&rad->team_send, mine ? mine : 1);
      tg->recv = zr__team_room_get(&rad->team_room, total ? total : 1);
      if (tg->send == NULL || tg->recv == NULL)
        st = ZR_ENOMEM;
    }
  }
  free(cost);
  free(load);
  free(order);
  free(need);
  if (st != ZR_OK)
    team_gather_free(tg);
  return st;
}

/* gather_range over a list of nodes. */
typedef struct list_gatherer {
  gatherer g;
  const uint32_t *nodes;
} list_gatherer;

static void gather_list(void *user, size_t begin, size_t end, int worker) {
  const list_gatherer *lg = user;
  for (size_t k = begin; k < end; k++)
    gather_range((void *)&lg->g, lg->nodes[k], lg->nodes[k] + 1, worker);
}

/* Push-pull of the member's surfaces; the others' changes stay 0. */
typedef struct team_puller {
  zr_radiosity *rad;
  double *change;
  const int32_t *owner;
  int me;
} team_puller;

static void team_push_pull_range(void *user, size_t begin, size_t end,
                                 int worker) {
  const team_puller *w = user;
  puller one = {w->rad, w->change};
  for (size_t s = begin; s < end; s++)
    if (w->owner[s] == w->me)
      push_pull_range(&one, s, s + 1, worker);
}

/* One exchange of ts's entries (and with change, the members' surface
   changes): each member sends its own, and writes the others'. */
static zr_status team_send(zr_radiosity *rad, const team_gather *tg,
                           const team_sends *ts, double *change) {
  const zr_team *team = rad->params.team;
  int me = zr__team_rank(team);
  const size_t b_size = sizeof rad->nodes[0].b[0];
  char *at = tg->send;
  for (size_t sf = 0; change != NULL && sf < rad->n_surfs; sf++)
    if (tg->owner[sf] == me) {
      memcpy(at, &change[sf], sizeof change[sf]);
      at += sizeof change[sf];
    }
  for (size_t k = ts->first[me]; k < ts->first[me + 1]; k++) {
    uint32_t e = ts->entry[k];
    memcpy(at, rad->nodes[e >> 1].b[e & 1], b_size);
    at += b_size;
  }
  zr_status st = team->allgather(team->user, tg->send, tg->recv,
                                 ts->part_bytes);
  const char *from = tg->recv;
  for (int r = 0; st == ZR_OK && r < team->size; r++) {
    if (r == me) { /* its values are in place */
      from += ts->part_bytes[r];
      continue;
    }
    for (size_t sf = 0; change != NULL && sf < rad->n_surfs; sf++)
      if (tg->owner[sf] == r) {
        memcpy(&change[sf], from, sizeof change[sf]);
        from += sizeof change[sf];
      }
    for (size_t k = ts->first[r]; k < ts->first[r + 1]; k++) {
      uint32_t e = ts->entry[k];
      memcpy(rad->nodes[e >> 1].b[e & 1], from, b_size);
      from += b_size;
    }
  }
  return st;
}

/* One sweep across the team; *residual_power is the summed change. */
static zr_status team_sweep(zr_radiosity *rad, const recv_index *ix,
                            const team_gather *tg, double *change,
                            double *residual_power) {
  const zr_team *team = rad->params.team;
  int me = zr__team_rank(team);
  list_gatherer lg = {{rad, ix}, tg->mine};
  zr__rad_parallel(rad->params.threads, tg->n_mine, 256, gather_list, &lg);
  team_puller tp = {rad, change, tg->owner, me};
  zr__rad_parallel(rad->params.threads, rad->n_surfs, 4,
                   team_push_pull_range, &tp);
  zr_status st = team_send(rad, tg, &tg->sweep, change);
  double sum = 0.0;
  for (size_t sf = 0; sf < rad->n_surfs; sf++)
    sum += change[sf];
  *residual_power = sum;
  return st;
}

/*
 * Bounded bounces (params.bounces N > 0, POV-Ray's recursion_limit): the
 * sweeps start from B = 0, so the first leaves B_0 = E (emission and
 * the light sources' direct light, direct.c) and sweep k + 1 leaves
 * B_k = E + rho F B_(k-1), the light of at most k bounces.  A ray hit
 * gathers once more from B (the final gather, radiosity.c), so N sweeps
 * show N bounces; the smoothed lookup reads B itself, so it takes one
 * sweep more.  Returns the sweeps a solve may take: max_iterations when
 * the bounces are not bounded.  Jacobi sweeps from zero are exactly
 * the bounce orders; every solve (refinement round) starts again.
 */
static int sweeps_allowed(zr_radiosity *rad) {
  int n = rad->params.max_iterations;
  if (rad->params.bounces <= 0)
    return n;
  for (size_t v = 0; v < rad->n_nodes; v++)
    memset(rad->nodes[v].b, 0, sizeof rad->nodes[v].b);
  int sweeps = rad->params.bounces +
               (rad->params.lookup == ZR_RAD_LOOKUP_SMOOTH ? 1 : 0);
  return sweeps < n ? sweeps : n;
}

static zr_status solve_gather_team(zr_radiosity *rad, recv_index *ix,
                                   double *change) {
  team_gather tg;
  zr_status made = team_gather_init(rad, ix, &tg);
  zr_status st = zr__team_agree(rad->params.team, made);
  int it = 0, sweeps = sweeps_allowed(rad);
  double residual = 0.0;
  while (st == ZR_OK && it < sweeps) {
    double power = 0.0;
    st = team_sweep(rad, ix, &tg, change, &power);
    residual = power / rad->power_ref;
    it++;
    if (!(residual > rad->params.residual))
      break;
  }
  /* The b no sweep sent, to every member. */
  if (st == ZR_OK)
    st = team_send(rad, &tg, &tg.rest, NULL);
  rad->stats.iterations = it;
  rad->stats.residual = residual;
  if (made == ZR_OK)
    team_gather_free(&tg);
  return st;
}

static zr_status solve_gather(zr_radiosity *rad) {
  double *change = malloc((rad->n_surfs + 1) * sizeof *change);
  if (change == NULL)
    return ZR_ENOMEM;
  recv_index ix;
  index_by_receiver(rad, &ix);
  if (zr__team_size(rad->params.team) > 1) {
    /* Without the index (out of memory) the team fails together. */
    zr_status st = ix.start ? ZR_OK : ZR_ENOMEM;
    st = zr__team_agree(rad->params.team, st);
    if (st == ZR_OK)
      st = solve_gather_team(rad, &ix, change);
    free_index(&ix);
    free(change);
    return st;
  }
  int it = 0, sweeps = sweeps_allowed(rad);
  double residual = 0.0;
  zr_status st = ZR_OK;
  while (it < sweeps && (st = zr__rad_progress(rad)) == ZR_OK) {
    gather(rad, &ix);
    if (rad->clustered)
      zr__rad_vol_gather(rad);
    residual = push_pull_all(rad, change) / rad->power_ref;
    it++;
    if (!(residual > rad->params.residual))
      break;
  }
  /* A cluster link's incident light (what a ray hit reads, volume.c)
     is from the sweep before the last; with the bounces bounded that
     is one bounce short, so it is gathered once more from the final B
     (the nodes' gathered sums are cleared by the next gather). */
  if (st == ZR_OK && rad->clustered && rad->params.bounces > 0)
    zr__rad_vol_gather(rad);
  rad->stats.iterations = it;
  rad->stats.residual = residual;
  free_index(&ix);
  free(change);
  return st;
}

/* ---- Southwell shooting ---- */

/* Pulls field (b or un) up: interior nodes get their children's mean. */
static void pull(zr_radiosity *rad, int32_t n, bool unshot) {
  zr__rad_node *node = &rad->nodes[n];
  if (node->child < 0)
    return;
  double sum[2][3] = {{0}}, area = 0.0;
  for (int k = 0; k < 4; k++) {
    int32_t c = rad->nodes[n].child + k;
    pull(rad, c, unshot);
    const zr__rad_node *ch = &rad->nodes[c];
    for (int side = 0; side < 2; side++)
      for (int j = 0; j < 3; j++)
        sum[side][j] += ch->area * (unshot ? ch->un : ch->b)[side][j];
    area += ch->area;
  }
  node = &rad->nodes[n];
  for (int side = 0; side < 2; side++)
    for (int j = 0; j < 3; j++)
      (unshot ? node->un : node->b)[side][j] =
          area > 0.0 ? sum[side][j] / area : 0.0;
}

/* Pushes what a shot deposited down to the leaves of n's subtree. */
static void push_shot(zr_radiosity *rad, int32_t n, int side,
                      const double down[3]) {
  zr__rad_node *node = &rad->nodes[n];
  double d[3];
  for (int c = 0; c < 3; c++) {
    d[c] = down[c] + node->bg[side][c];
    node->bg[side][c] = 0.0;
  }
  if (node->child < 0) {
    for (int c = 0; c < 3; c++) {
      node->b[side][c] += d[c];
      node->un[side][c] += d[c];
    }
    return;
  }
  for (int k = 0; k < 4; k++)
    push_shot(rad, rad->nodes[n].child + k, side, d);
}

static void zero_unshot(zr_radiosity *rad, int32_t n, int side) {
  zr__rad_node *node = &rad->nodes[n];
  memset(node->un[side], 0, sizeof node->un[side]);
  if (node->child >= 0)
    for (int k = 0; k < 4; k++)
      zero_unshot(rad, node->child + k, side);
}

/* The surface side with the most unshot power; its power. */
static double pick_shooter(zr_radiosity *rad, size_t *surf, int *side) {
  double best = -1.0;
  for (size_t s = 0; s < rad->n_surfs; s++) {
    pull(rad, rad->surfs[s].root, true);
    const zr__rad_node *root = &rad->nodes[rad->surfs[s].root];
    for (int k = 0; k < 2; k++) {
      double p = root->area * zr__rad_max3(root->un[k]);
      if (p > best) {
        best = p;
        *surf = s;
        *side = k;
      }
    }
  }
  return best;
}

/* Link indices grouped by source surface: order[start[s]..start[s+1]). */
static zr_status links_by_source(const zr_radiosity *rad, size_t **order,
                                 size_t **start) {
  *start = calloc(rad->n_surfs + 2, sizeof **start);
  *order = malloc((rad->n_links + 1) * sizeof **order);
  if (*start == NULL || *order == NULL)
    return ZR_ENOMEM;
  for (size_t i = 0; i < rad->n_links; i++)
    (*start)[rad->nodes[rad->links[i].src].surf + 2]++;
  for (size_t s = 2; s < rad->n_surfs + 2; s++)
    (*start)[s] += (*start)[s - 1];
  for (size_t i = 0; i < rad->n_links; i++)
    (*order)[(*start)[rad->nodes[rad->links[i].src].surf + 1]++] = i;
  return ZR_OK;
}

static void shoot(zr_radiosity *rad, const size_t *order,
                  const size_t *start, size_t s, int side) {
  for (size_t k = start[s]; k < start[s + 1]; k++) {
    const zr__rad_link *l = &rad->links[order[k]];
    if (!l->dead && l->sside == side)
      transfer(rad, l, rad->nodes[l->src].un[side]);
  }
  zero_unshot(rad, rad->surfs[s].root, side);
  double zero[3] = {0, 0, 0};
  for (size_t r = 0; r < rad->n_surfs; r++)
    for (int k = 0; k < 2; k++)
      push_shot(rad, rad->surfs[r].root, k, zero);
}

static zr_status solve_shooting(zr_radiosity *rad) {
  size_t *order, *start;
  zr_status st = links_by_source(rad, &order, &start);
  if (st == ZR_OK) {
    clear_gathered(rad);
    for (size_t n = 0; n < rad->n_nodes; n++) {
      zr__rad_node *node = &rad->nodes[n];
      for (int side = 0; side < 2; side++) {
        double e[3] = {0, 0, 0};
        if (node->child < 0)
          zr__rad_leaf_source(rad, node, side, e);
        for (int c = 0; c < 3; c++)
          node->b[side][c] = node->un[side][c] = e[c];
      }
    }
    int it = 0;
    double residual = 0.0;
    while (it < rad->params.max_iterations) {
      size_t s = 0;
      int side = 0;
      residual = pick_shooter(rad, &s, &side) / rad->power_ref;
      if (!(residual > rad->params.residual))
        break;
      shoot(rad, order, start, s, side);
      it++;
      /* A shot is quick: ask every 64th. */
      if ((it & 63) == 0 && (st = zr__rad_progress(rad)) != ZR_OK)
        break;
    }
    for (size_t s = 0; s < rad->n_surfs; s++)
      pull(rad, rad->surfs[s].root, false);
    rad->stats.iterations = it;
    rad->stats.residual = residual;
  }
  free(order);
  free(start);
  return st;
}

zr_status zr__rad_solve(zr_radiosity *rad, zr_context *ctx) {
  if (!(rad->power_ref > 0.0)) {
    /* Nothing emits: the solution is dark everywhere, exactly. */
    for (size_t n = 0; n < rad->n_nodes; n++)
      memset(rad->nodes[n].b, 0, sizeof rad->nodes[n].b);
    rad->stats.iterations = 0;
    rad->stats.residual = 0.0;
    return ZR_OK;
  }
  /* Shooting carries every bounce: bounded bounces gather (sweeps). */
  zr_status st = rad->params.shooting && rad->params.bounces <= 0
                     ? solve_shooting(rad)
                     : solve_gather(rad);
  if (st == ZR_ECANCELLED)
    return st; /* solve_rounds says so */
  if (st == ZR_EMPI)
    return zr__diag(ctx, ZR_DIAG_ERROR, st, NULL,
                    "radiosity: the processes solving together could not "
                    "exchange their radiosities");
  if (st != ZR_OK)
    return zr__diag(ctx, ZR_DIAG_ERROR, st, NULL,
                    rad->params.shooting
                        ? "radiosity: out of memory while shooting"
                        : "radiosity: out of memory while gathering");
  return ZR_OK;
}

/* ---- energy ---- */

typedef struct energy_sums {
  double emitted, absorbed, light;
  double closure_area, closure_sum, closure_min, closure_max;
} energy_sums;

static void energy_leaf(const zr_radiosity *rad, const zr__rad_node *node,
                        int side, const double h[3], double closure,
                        energy_sums *e) {
  const zr__rad_surface *s = &rad->surfs[node->surf];
  for (int c = 0; c < 3; c++) {
    /* h holds the links' light; hd the light sources' (direct.c). */
    double hc = h[c] + node->hd[side][c];
    e->emitted += node->area * s->emission[side][c] / 3.0;
    e->light += node->area * node->hd[side][c] / 3.0;
    e->absorbed += node->area * (1.0 - s->rho[c]) * hc / 3.0;
  }
  if (closure > 0.0) {
    e->closure_area += node->area;
    e->closure_sum += node->area * closure;
    e->closure_min = fmin(e->closure_min, closure);
    e->closure_max = fmax(e->closure_max, closure);
  }
}

static void energy_walk(const zr_radiosity *rad, int32_t n, int side,
                        const double down[3], double closure,
                        energy_sums *e) {
  const zr__rad_node *node = &rad->nodes[n];
  double h[3];
  for (int c = 0; c < 3; c++)
    h[c] = down[c] + node->hg[side][c];
  closure += node->closure[side];
  if (node->child < 0) {
    energy_leaf(rad, node, side, h, closure, e);
    return;
  }
  for (int k = 0; k < 4; k++)
    energy_walk(rad, node->child + k, side, h, closure, e);
}

void zr__rad_energy(zr_radiosity *rad) {
  recv_index ix;
  index_by_receiver(rad, &ix);
  gather(rad, &ix);
  free_index(&ix);
  energy_sums e = {0.0, 0.0, 0.0, 0.0, 0.0, INFINITY, 0.0};
  double zero[3] = {0, 0, 0};
  for (size_t s = 0; s < rad->n_surfs; s++)
    for (int side = 0; side < 2; side++)
      energy_walk(rad, rad->surfs[s].root, side, zero, 0.0, &e);
  rad->stats.emitted_power = e.emitted;
  rad->stats.absorbed_power = e.absorbed;
  rad->stats.light_power = e.light;
  rad->stats.closure_mean =
      e.closure_area > 0.0 ? e.closure_sum / e.closure_area : 0.0;
  rad->stats.closure_min = e.closure_area > 0.0 ? e.closure_min : 0.0;
  rad->stats.closure_max = e.closure_max;
  clear_gathered(rad);
}
