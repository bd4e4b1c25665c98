/* mem_estimate.c — memory per rank of a run, from a model of the layout of issue 22, and memory
 * available on a node. The constants were measured with the peak resident size that the
 * end-of-run summary prints (engine_report.c), 5 steps of runs: between two resolutions of the
 * same case on one rank, 424 bytes per particle in 2D (the two-phase dam break, 4.4e4 and
 * 1.7e5 particles) and 676 in 3D (the tests' 3D dam break, 7.2e3 and 7.6e4 particles, half of
 * them wall ghosts), about 23 MB for the process without particles, and about 4 MB more per
 * process on several ranks (Open MPI's buffers, measured on 4 and 8 ranks); the constants keep a
 * small margin over these. doc/performance.md compares the estimates with measured peaks. The
 * cells: every rank holds an owner per top cell; rank 0 builds the METIS graph of the top cells; a
 * rank holds the cell index of its own region and its halo's reach only; at start-up every rank
 * holds the particle count and first id of every row of lattice nodes (engine/startup.c). */
#include "app/mem_estimate.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>
#include "case/init.h"
#include "engine/engine.h"

#define BYTES_PER_PARTICLE_2D 440.0
#define BYTES_PER_PARTICLE_3D 700.0
#define PROCESS_BYTES 24e6
#define MPI_PROCESS_BYTES 4e6         /* more per process on several ranks */
#define TOP_CELL_BYTES 8.0            /* owner and local slot of each top cell, every rank */
#define METIS_BYTES_BASE 64.0         /* METIS graph of the top cells on rank 0: per vertex */
#define METIS_BYTES_PER_LINK 16.0     /* and per neighbour link */
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

/* The cell memory of the largest rank (rank 0) [bytes]: the top cells' owners, their METIS
 * graph, and the cell index of a rank's share of the cells held as a square (cube) grown by the
 * halo's reach in whole top cells. */
static double cell_bytes(const struct case_def *c, double support, int n_ranks) {
  struct grid g;
  if (engine_cell_grid(c, support, &g)) return INFINITY;
  long block = space_top_block(&g, n_ranks, c->top_cells_per_rank);
  struct grid top = space_top_grid(&g, block);
  int dim = c->dimension, links = dim == 2 ? 8 : 26, layers = engine_halo_layers(c, &g, support);
  double reach = (double)block * ceil((double)layers / (double)block);
  double side = pow((double)g.n_cells / n_ranks, 1.0 / dim);
  double local = fmin((double)g.n_cells, pow(side + 2 * reach, dim));
  double metis = n_ranks > 1 ? METIS_BYTES_BASE + METIS_BYTES_PER_LINK * links : 0;
  return (double)top.n_cells * (TOP_CELL_BYTES + metis) + local * LOCAL_CELL_BYTES;
}

/* The start-up's row arrays [bytes]. */
static double startup_bytes(const struct case_def *c, double support) {
  struct init_rows rows;
  init_rows_open(&rows, c, support);
  double bytes = (double)rows.n_rows * ROW_BYTES;
  init_rows_close(&rows);
  return bytes;
}

struct mem_estimate mem_estimate_rank(const struct case_def *c, double support, double n_particles,
                                      int n_ranks) {
  struct mem_estimate m;
  double share = n_particles / n_ranks;
  m.particles = share + (n_ranks > 1 ? rank_halo(c, support, share, n_particles, n_ranks) : 0);
  m.bytes_per_particle = c->dimension == 2 ? BYTES_PER_PARTICLE_2D : BYTES_PER_PARTICLE_3D;
  m.process = PROCESS_BYTES + (n_ranks > 1 ? MPI_PROCESS_BYTES : 0);
  m.cells = cell_bytes(c, support, n_ranks);
  m.startup = startup_bytes(c, support);
  m.total = m.process + m.cells + m.startup + m.particles * m.bytes_per_particle;
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
