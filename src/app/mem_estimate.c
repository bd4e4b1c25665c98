/* mem_estimate.c — memory per rank of a run, from a model of the layout of issue 22, and memory
 * available on a node. The constants were fitted to the peak resident size that the end-of-run
 * summary prints (timings.csv, with each rank's particles by kind and halo), 4 steps of runs:
 * 1-rank runs of four 3D scenes (a full box and the bench's wall-heavy dam break, 1e5 to 2.5e5
 * particles) and six 2D ones (the dam breaks with and without air, a small column in a large
 * tank, 7e3 to 3.7e5 particles) give the process and the bytes per particle of each kind; runs on
 * 2 to 16 ranks (the 3D dam break extruded, the 2D two-phase dam break) the bytes per halo
 * particle; a tiny case on 1 to 64 ranks on one node the bytes per other rank on the node (Open
 * MPI's shared-memory transport). They reproduce those 21 peaks within 15 %. The re-partition's
 * share was refitted once re-partitions kept each part on the rank holding most of it, on 19 runs
 * of 2 to 64 ranks (the 3D dam break extruded to 2e4 and 5e4 particles per rank, the 2D dam
 * breaks; most re-partitioning every 2 steps): within 17.1 % of the largest rank's peak.
 * doc/performance.md compares the estimates with the bench's runs. The cells: every rank holds an
 * owner per top cell; rank 0 builds the METIS graph of the top cells holding particles; a rank
 * holds the cell index of its own region and its halo's reach only; at start-up every rank holds
 * the particle count and first id of every row of lattice nodes (engine/startup.c). */
#include "app/mem_estimate.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>
#include "case/init.h"
#include "base/kinds.h"
#include "engine/engine.h"
#include "parallel/partition.h"
#include "base/mem.h"

/* Bytes of an owned particle of each kind, of a halo particle, and more per owned particle on
 * several ranks (the packed copies of the particles a re-partition moves), in 2D and 3D. A 3D
 * wall ghost's list at its mirror point (nlist_point_add) is in its 320 B: 57 B more than before
 * the lists on the bench's 3D dam break at dx 0.03 m (most of its ghosts, far from the water,
 * keep only the header word), 170 B more in a 3D box full of water; in 2D about 3 B. */
static const double kind_bytes[2][KIND_COUNT] = {{[KIND_FLUID] = 340, [KIND_WALL] = 470, [KIND_SOLID] = 470},
                                                 {[KIND_FLUID] = 820, [KIND_WALL] = 320, [KIND_SOLID] = 320}};
/* An elastic solid's particle is taken at a wall ghost's bytes (the same arrays); the solid's own
 * arrays, replicated on every rank (engine/solids.h), are not estimated: solids are small. */
_Static_assert(KIND_COUNT == 3, "measure the bytes of the new kind's particles for kind_bytes");
static const double halo_particle_bytes[2] = {150, 600};
static const double moving_bytes[2] = {0, 100};
#define PROCESS_BYTES 24e6
#define MPI_PROCESS_BYTES 2e6         /* more per process on several ranks */
#define MPI_PEER_BYTES 0.4e6          /* and per other rank on the same node (shared-memory transport) */
#define TOP_CELL_BYTES 8.0            /* owner and local slot of each top cell, every rank */
#define METIS_BYTES_BASE 64.0         /* METIS graph of the top cells on rank 0: per vertex */
#define METIS_BYTES_PER_LINK 16.0     /* and per neighbour link */
#define PARTITION_CELL_BYTES 12.0     /* rank 0 partitioning: a vertex number and a sweep slot per top cell */
#define LOCAL_CELL_BYTES 24.0         /* cell index of a local cell: start, count, order, rank, bucket */
#define ROW_BYTES 12.0                /* start-up: count and first id of a row of lattice nodes */

/* Halo particles around a share of n particles held as a square (cube) of side n^(1/dim) dx, in
 * a band `layers` cells deep (cell edge `edge` [m]) on the faces that border other ranks: the
 * shares tile the domain as k^dim blocks (k = n_ranks^(1/dim)), so a share has min(2, k - 1)
 * such faces per axis; at most the other ranks' particles. */
static double halo_particles(const struct case_def *c, int layers, double edge, double share, double total,
                             int n_ranks) {
  int dim = c->dimension;
  double side = pow(share, 1.0 / dim), band = layers * edge / c->dx;
  double faces = fmin(2.0, pow(n_ranks, 1.0 / dim) - 1.0);
  double halo = share * (pow(1 + faces * band / side, dim) - 1);
  return fmin(halo, total - share);
}

/* The halo particles of a rank holding `share` of `total` particles: a band as deep as
 * engine_halo_band (the deeper cells around fixed walls' mirror points are a thin strip and are
 * left out). */
static double rank_halo(const struct case_def *c, double support, double share, double total, int n_ranks) {
  struct grid g;
  if (engine_cell_grid(c, support, &g)) return total - share;
  double edge = g.edge[0];
  for (int d = 1; d < c->dimension; d++) edge = fmin(edge, g.edge[d]);
  int layers = engine_halo_band(c, engine_halo_layers(c, &g, support));
  return halo_particles(c, layers, edge, share, total, n_ranks);
}

/* Axis-d index range [first, last] of the cells of t that meet [lo, hi] (last < first: none). */
static void cell_range(const struct grid *t, int d, double lo, double hi, long *first, long *last) {
  *first = (long)fmax(0, floor((lo - t->min[d]) / t->edge[d]));
  *last = (long)fmin((double)t->n[d] - 1, floor((hi - t->min[d]) / t->edge[d]));
}

/* Whether cell (i[0], i[1], i[2]) of t lies strictly inside the box [in_lo, in_hi]. */
static int cell_inside(const struct grid *t, const long *i, const double *in_lo, const double *in_hi) {
  for (int d = 0; d < t->dim; d++) {
    double lo = t->min[d] + (double)i[d] * t->edge[d];
    if (lo <= in_lo[d] || lo + t->edge[d] >= in_hi[d]) return 0;
  }
  return 1;
}

/* Mark the cells of t that may hold nodes of source k (its extent less a tank's interior). */
static void mark_source(const struct grid *t, const struct init_rows *rows, int k, char *mark) {
  double lo[3], hi[3], in_lo[3], in_hi[3];
  long first[3] = {0, 0, 0}, last[3] = {0, 0, 0}, i[3];
  init_source_extent(rows, k, t->dim, lo, hi, in_lo, in_hi);
  for (int d = 0; d < t->dim; d++) cell_range(t, d, lo[d], hi[d], &first[d], &last[d]);
  for (i[2] = first[2]; i[2] <= last[2]; i[2]++)
    for (i[1] = first[1]; i[1] <= last[1]; i[1]++)
      for (i[0] = first[0]; i[0] <= last[0]; i[0]++)
        if (!cell_inside(t, i, in_lo, in_hi)) mark[i[0] + t->n[0] * (i[1] + t->n[1] * i[2])] = 1;
}

/* The top cells that may hold particles at start-up (a bound: each source's extent), the
 * vertices of the METIS graph (parallel/partition_metis.c). */
static long occupied_top_cells(const struct init_rows *rows, const struct grid *top) {
  char *mark = mem_calloc(top->n_cells, 1, "occupied top cells");
  for (int k = 0; k < rows->n_sources; k++) mark_source(top, rows, k, mark);
  long n = 0;
  for (long i = 0; i < top->n_cells; i++) n += mark[i];
  free(mark);
  return n;
}

/* The cell memory of the largest rank (rank 0) [bytes]: the top cells' owners, the METIS graph of
 * those holding particles, and the cell index of a rank's share of the cells held as a square
 * (cube) grown by the halo's reach in whole top cells. */
static double cell_bytes(const struct case_def *c, double support, const struct init_rows *rows, int n_ranks) {
  struct grid g;
  if (engine_cell_grid(c, support, &g)) return INFINITY;
  long block = space_top_block(&g, n_ranks, c->top_cells_per_rank);
  struct grid top = space_top_grid(&g, block);
  int dim = c->dimension, links = dim == 2 ? 8 : 26, layers = engine_halo_layers(c, &g, support);
  double reach = (double)block * ceil((double)layers / (double)block);
  double side = pow((double)g.n_cells / n_ranks, 1.0 / dim);
  double local = fmin((double)g.n_cells, pow(side + 2 * reach, dim));
  double metis = n_ranks > 1 ? (METIS_BYTES_BASE + METIS_BYTES_PER_LINK * links) * occupied_top_cells(rows, &top) +
                                   PARTITION_CELL_BYTES * top.n_cells : 0;
  return (double)top.n_cells * TOP_CELL_BYTES + metis + local * LOCAL_CELL_BYTES;
}

/* A line a . n = b in the plane of the two kinds' counts n. */
struct line {
  double a[KIND_COUNT], b;
};

/* The owned particles of each kind of the rank that needs the most memory: the corner of
 * {0 <= n_k <= n_kind[k], work <= tolerance x mean, particles <= tolerance x mean} (the
 * partition's tolerances, parallel/partition.h) with the most
 * bytes (a linear programme in two unknowns: its optimum lies where two of the bounds meet). */
static void largest_share(const double *n_kind, const double *bytes, int n_ranks, double *owned) {
  double work = 0, particles = 0;
  for (int k = 0; k < KIND_COUNT; k++) {
    work += n_kind[k] * part_kinds[k].work;
    particles += n_kind[k];
  }
  struct line bound[] = {{{1, 0}, 0}, {{0, 1}, 0}, {{1, 0}, n_kind[0]}, {{0, 1}, n_kind[1]},
                         {{part_kinds[0].work, part_kinds[1].work}, partition_tolerance[WEIGHT_WORK] * work / n_ranks},
                         {{1, 1}, partition_tolerance[WEIGHT_PARTICLES] * particles / n_ranks}};
  int n_bounds = (int)(sizeof bound / sizeof bound[0]);
  double best = -1;
  for (int i = 0; i < n_bounds; i++)
    for (int j = i + 1; j < n_bounds; j++) {
      double det = bound[i].a[0] * bound[j].a[1] - bound[i].a[1] * bound[j].a[0];
      if (det == 0) continue;
      double n[2] = {(bound[i].b * bound[j].a[1] - bound[i].a[1] * bound[j].b) / det,
                     (bound[i].a[0] * bound[j].b - bound[i].b * bound[j].a[0]) / det};
      int inside = 1;
      for (int k = 0; k < n_bounds && inside; k++)
        inside = k < 2 ? n[k] >= -1e-9 * (1 + n_kind[k]) : bound[k].a[0] * n[0] + bound[k].a[1] * n[1] <= bound[k].b * (1 + 1e-12);
      double b = n[0] * bytes[0] + n[1] * bytes[1];
      if (inside && b > best) {
        best = b;
        owned[0] = fmax(n[0], 0);
        owned[1] = fmax(n[1], 0);
      }
    }
}

/* Bytes more per fluid particle with multi-resolution (a model, not fitted): a neighbour list's
 * mask has a bit per candidate of the 3^dim cells around its particle's cell, which are sized by
 * the coarsest phase's support (`support` here, dx_ratio r times h's), so it holds r^dim times the
 * single-resolution candidates, 3^dim cells of (skin support(h)/dx)^dim particles at dx. */
static double multires_list_bytes(const struct case_def *c, double support) {
  int r = case_max_dx_ratio(c), dim = c->dimension;
  double cell = ENGINE_CELL_SKIN * support / r / c->dx;   /* the single-resolution cell edge / dx */
  return (pow(r, dim) - 1) * pow(3 * cell, dim) / 8;
}

struct mem_estimate mem_estimate_rank(const struct case_def *c, double support, const double *n_kind,
                                      int n_ranks, int per_node) {
  struct mem_estimate m = {0};   /* owned[KIND_SOLID] stays 0: solids are not estimated (kind_bytes) */
  const double *bytes = kind_bytes[c->dimension - 2];
  double total = 0, share = 0;
  largest_share(n_kind, bytes, n_ranks, m.owned);
  m.particle_bytes = 0;
  for (int k = 0; k < KIND_COUNT; k++) {
    total += n_kind[k];
    share += m.owned[k];
    m.particle_bytes += m.owned[k] * bytes[k];
  }
  m.particle_bytes += m.owned[KIND_FLUID] * multires_list_bytes(c, support);
  m.halo = n_ranks > 1 ? rank_halo(c, support, share, total, n_ranks) : 0;
  m.particle_bytes += m.halo * halo_particle_bytes[c->dimension - 2];
  if (n_ranks > 1) m.particle_bytes += share * moving_bytes[c->dimension - 2];
  m.process = PROCESS_BYTES + (n_ranks > 1 ? MPI_PROCESS_BYTES + MPI_PEER_BYTES * (per_node - 1) : 0);
  struct init_rows rows;   /* the lattice rows: where particles start, and the start-up's row arrays */
  init_rows_open(&rows, c, support);
  m.cells = cell_bytes(c, support, &rows, n_ranks);
  m.startup = (double)rows.n_rows * ROW_BYTES;
  init_rows_close(&rows);
  m.total = m.process + m.cells + m.startup + m.particle_bytes;
  return m;
}

/* MemAvailable of /proc/meminfo [bytes], or -1. */
static double meminfo_available(void) {
  FILE *f = fopen("/proc/meminfo", "r");
  char line[256];
  double kb = -1;
  while (f && fgets(line, sizeof line, f))
    if (sscanf(line, "MemAvailable: %lf kB", &kb) == 1) break;
  if (f) fclose(f);
  return kb >= 0 ? kb * 1024 : -1;
}

double mem_node_available(void) {
  const char *env = getenv("MPSPH_MEMORY_AVAILABLE");
  if (env) {
    char *end;
    double bytes = strtod(env, &end);
    return *env && *end == '\0' && bytes > 0 && isfinite(bytes) ? bytes : -1;
  }
  double avail = meminfo_available();
  if (avail >= 0) return avail;
  return (double)sysconf(_SC_PHYS_PAGES) * (double)sysconf(_SC_PAGE_SIZE);
}
