/* partition_metis.c — METIS k-way partition of the cell graph on rank 0, broadcast to all. */
#include <metis.h>
#include <stdio.h>
#include <stdlib.h>
#include "parallel/partition.h"
#include "base/mem.h"

#define METIS_SEED 42
static const real_t imbalance_allowed[PARTITION_CONSTRAINTS] = {[WEIGHT_WORK] = 1.03f, [WEIGHT_PARTICLES] = 1.10f};

/* CSR adjacency of the cells: each cell linked to its 3^dim - 1 neighbours. */
static void cell_graph(const struct grid *g, idx_t **xadj_out, idx_t **adjncy_out) {
  int max_nb = g->dim == 2 ? 9 : 27;
  idx_t *xadj = mem_calloc(g->n_cells + 1, sizeof(idx_t), "METIS cell graph");
  idx_t *adjncy = mem_calloc((size_t)g->n_cells * max_nb, sizeof(idx_t), "METIS cell graph");
  long nb[27];
  xadj[0] = 0;
  for (long c = 0; c < g->n_cells; c++) {
    int n = grid_stencil(g, c, 1, nb);
    idx_t k = xadj[c];
    for (int j = 0; j < n; j++)
      if (nb[j] != c) adjncy[k++] = (idx_t)nb[j];
    xadj[c + 1] = k;
  }
  *xadj_out = xadj;
  *adjncy_out = adjncy;
}

/* Rank 0: run METIS into owner. Returns the METIS status. */
static int metis_partition(const struct grid *g, const int64_t *weight, int n_parts, int *owner) {
  idx_t *xadj, *adjncy;
  cell_graph(g, &xadj, &adjncy);
  idx_t nvtxs = (idx_t)g->n_cells, ncon = PARTITION_CONSTRAINTS, nparts = n_parts, objval;
  idx_t *vwgt = mem_calloc((size_t)g->n_cells * ncon, sizeof(idx_t), "METIS cell weights");
  idx_t *part = mem_calloc(g->n_cells, sizeof(idx_t), "METIS partition");
  for (long k = 0; k < g->n_cells * ncon; k++) vwgt[k] = (idx_t)weight[k];
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_OBJTYPE] = METIS_OBJTYPE_CUT;
  options[METIS_OPTION_SEED] = METIS_SEED;
  options[METIS_OPTION_NUMBERING] = 0;
  real_t ubvec[PARTITION_CONSTRAINTS];
  for (int k = 0; k < PARTITION_CONSTRAINTS; k++) ubvec[k] = imbalance_allowed[k];
  int status = METIS_PartGraphKway(&nvtxs, &ncon, xadj, adjncy, vwgt, NULL, NULL, &nparts, NULL,
                                   ubvec, options, &objval, part);
  for (long c = 0; c < g->n_cells; c++) owner[c] = (int)part[c];
  free(xadj);
  free(adjncy);
  free(vwgt);
  free(part);
  return status;
}

/* The first part that received no cell, or -1. */
static int empty_part(const struct grid *g, const int *owner, int n_parts) {
  int *count = mem_calloc(n_parts, sizeof(int), "cells per rank");
  for (long c = 0; c < g->n_cells; c++) count[owner[c]]++;
  int empty = -1;
  for (int r = n_parts - 1; r >= 0; r--)
    if (count[r] == 0) empty = r;
  free(count);
  return empty;
}

int partition_cells(const struct grid *g, const int64_t *weight, int n_parts, MPI_Comm comm,
                    int *owner, char *err, size_t err_len) {
  int rank, status[2] = {0, -1};
  MPI_Comm_rank(comm, &rank);
  if (rank == 0) {
    if (g->n_cells < n_parts) {
      status[0] = 2;
    } else if (n_parts == 1) {
      for (long c = 0; c < g->n_cells; c++) owner[c] = 0;
    } else {
      int metis = metis_partition(g, weight, n_parts, owner);
      status[0] = metis == METIS_OK ? 0 : 1;
      if (metis == METIS_OK) status[1] = empty_part(g, owner, n_parts);
    }
  }
  MPI_Bcast(status, 2, MPI_INT, 0, comm);
  if (status[0] == 2) {
    snprintf(err, err_len, "the domain has %ld cells but %d ranks were started: use at most %ld "
             "ranks, or a larger domain / finer resolution", g->n_cells, n_parts, g->n_cells);
    return 1;
  }
  if (status[0] == 1) {
    snprintf(err, err_len, "METIS_PartGraphKway failed on the %ld-cell graph", g->n_cells);
    return 1;
  }
  if (status[1] >= 0) {
    snprintf(err, err_len, "the partition gave rank %d no cell (%ld cells for %d ranks): use "
             "fewer ranks", status[1], g->n_cells, n_parts);
    return 1;
  }
  MPI_Bcast(owner, (int)g->n_cells, MPI_INT, 0, comm);
  return 0;
}

double partition_imbalance(const struct grid *g, const int64_t *weight, int k, const int *owner,
                           int n_parts) {
  double *load = mem_calloc(n_parts, sizeof(double), "load per rank"), total = 0, max = 0;
  for (long c = 0; c < g->n_cells; c++) load[owner[c]] += (double)weight[c * PARTITION_CONSTRAINTS + k];
  for (int r = 0; r < n_parts; r++) {
    total += load[r];
    if (load[r] > max) max = load[r];
  }
  free(load);
  return total > 0 ? max / (total / n_parts) - 1.0 : 0.0;
}
