/* mem_estimate.c — memory per rank of a run and memory available on a node. The constants were
 * measured with the peak resident size that the end-of-run summary prints (engine_report.c),
 * between two resolutions of the same case on one rank, with the neighbour lists as bit masks:
 * 380-390 bytes per particle in 2D (the one- and two-phase dam breaks, 4.4e4 to 1.8e5
 * particles), 640 in 3D (the tests' hydrostatic box, 2.2e4 to 5.2e4 particles, 60 % wall ghosts);
 * the constants keep a margin over these. About 25 MB for a process with a few particles; 155
 * bytes per cell of a 2D grid on the rank that runs METIS. */
#include "app/mem_estimate.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#define BYTES_PER_PARTICLE_2D 450.0
#define BYTES_PER_PARTICLE_3D 800.0
#define PROCESS_BYTES 30e6
#define CELL_BYTES_BASE 64.0       /* cell arrays of every rank */
#define CELL_BYTES_PER_LINK 16.0   /* METIS graph and work arrays per neighbour link */
#define HALO_CELLS 3               /* halo depth [cells of about one support] with walls */

/* Halo particles around a share of n particles held as a square (cube) of side n^(1/dim) dx,
 * in a band HALO_CELLS cells deep; at most the other ranks' particles. */
static double halo_particles(const struct case_def *c, double support, double share, double total) {
  int dim = c->dimension;
  double side = pow(share, 1.0 / dim), band = HALO_CELLS * support / c->dx;
  double halo = share * (pow(1 + 2 * band / side, dim) - 1);
  return fmin(halo, total - share);
}

/* Cells of the grid: at most the domain volume over support^dim, one per axis at least. */
static double grid_cells(const struct case_def *c, double support) {
  double n = 1;
  for (int d = 0; d < c->dimension; d++)
    n *= fmax(1.0, (c->domain_max[d] - c->domain_min[d]) / support);
  return n;
}

struct mem_estimate mem_estimate_rank(const struct case_def *c, double support, double n_particles,
                                      int n_ranks) {
  struct mem_estimate m;
  int links = c->dimension == 2 ? 8 : 26;
  double share = n_particles / n_ranks;
  m.particles = share + (n_ranks > 1 ? halo_particles(c, support, share, n_particles) : 0);
  m.bytes_per_particle = c->dimension == 2 ? BYTES_PER_PARTICLE_2D : BYTES_PER_PARTICLE_3D;
  m.process = PROCESS_BYTES;
  m.cells = grid_cells(c, support) * (CELL_BYTES_BASE + CELL_BYTES_PER_LINK * links);
  m.total = m.process + m.cells + m.particles * m.bytes_per_particle;
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
