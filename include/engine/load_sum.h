/* load_sum.h — loads (physics/pass_ctx.h's struct body_load) gathered from every rank and put in
 * one order, so that every rank sums them alike whatever the partition: by target (a body's wall,
 * or a solid particle's index), then by fluid particle id, then by source. */
#ifndef MPSPH_LOAD_SUM_H
#define MPSPH_LOAD_SUM_H

#include <mpi.h>
#include "physics/pass_ctx.h"

/** The gathered loads and what gathering them needs. */
struct load_gather {
  struct body_load *all;     /* every rank's loads, sorted (capacity cap) */
  long cap;
  int *counts, *displs;      /* loads per rank and their offsets in all */
  MPI_Datatype type;         /* one struct body_load */
};

/** Set up g for a communicator of n_ranks ranks. */
void load_gather_init(struct load_gather *g, int n_ranks);

/** Gather every rank's loads `mine` into g->all in the sum order and empty mine; returns their
 *  count. Collective. */
long load_gather_all(struct load_gather *g, struct body_loads *mine, MPI_Comm comm);

/** Free g (and nothing if it was never set up). */
void load_gather_free(struct load_gather *g);

#endif
