/* redistribute.c — all-to-all redistribution of particles to the owners of their cells (after a
 * re-partition or a restart; the start-up generates particles where they belong). */
#include <stdlib.h>
#include "parallel/proxy.h"
#include "parallel/redistribute.h"
#include "base/mem.h"

/* Counts per destination rank and a packing order grouped by destination. */
static long *group_by_owner(const struct space *s, const struct parts *p, int *send_count) {
  int nr = s->n_ranks;
  long *offset = mem_calloc(nr + 1, sizeof(long), "migration offsets");
  long *order = mem_calloc(p->n_owned + 1, sizeof(long), "migration order");
  for (long i = 0; i < p->n_owned; i++) send_count[space_cell_owner(s, p->cell[i])]++;
  for (int r = 0; r < nr; r++) offset[r + 1] = offset[r] + send_count[r];
  for (long i = 0; i < p->n_owned; i++) order[offset[space_cell_owner(s, p->cell[i])]++] = i;
  free(offset);
  return order;
}

void redistribute_parts(const struct space *s, struct parts *p, MPI_Comm comm) {
  int nr = s->n_ranks, w = parts_packed_size(p, PART_MIGRATE);
  int *cnt = mem_calloc(4 * nr, sizeof(int), "migration counts"), *send_count = cnt, *recv_count = cnt + nr;
  int *sdispl = cnt + 2 * nr, *rdispl = cnt + 3 * nr;
  long *order = group_by_owner(s, p, send_count);
  MPI_Alltoall(send_count, 1, MPI_INT, recv_count, 1, MPI_INT, comm);
  long n_recv = 0;
  for (int r = 0; r < nr; r++) {   /* in particles: slots fit an int, their doubles may not */
    sdispl[r] = (r ? sdispl[r - 1] + send_count[r - 1] : 0);
    rdispl[r] = (r ? rdispl[r - 1] + recv_count[r - 1] : 0);
    n_recv += recv_count[r];
  }
  double *sbuf = mem_calloc((size_t)p->n_owned * w + 1, sizeof(double), "migration send buffer");
  double *rbuf = mem_calloc((size_t)n_recv * w + 1, sizeof(double), "migration receive buffer");
  parts_pack(p, PART_MIGRATE, order, p->n_owned, sbuf);
  MPI_Datatype particle;   /* one packed particle: w doubles */
  MPI_Type_contiguous(w, MPI_DOUBLE, &particle);
  MPI_Type_commit(&particle);
  MPI_Alltoallv(sbuf, send_count, sdispl, particle, rbuf, recv_count, rdispl, particle, comm);
  MPI_Type_free(&particle);
  parts_reserve(p, n_recv);
  parts_unpack(p, PART_MIGRATE, 0, n_recv, rbuf);
  p->n_owned = n_recv;
  p->n_halo = 0;
  free(sbuf);
  free(rbuf);
  free(order);
  free(cnt);
}
