/* redistribute.c — all-to-all redistribution of particles to the owners of their cells (after a
 * re-partition or a restart; the start-up generates particles where they belong). Only the
 * particles that change rank are copied into messages; the others keep their slots. */
#include <stdlib.h>
#include "parallel/proxy.h"
#include "parallel/redistribute.h"
#include "base/mem.h"

/* The owned particles whose cell another rank now owns, grouped by that rank: send_count[r] to
 * rank r (none to this one); their count in *n_leave. */
static long *group_leavers(const struct space *s, const struct parts *p, int *send_count, long *n_leave) {
  int nr = s->n_ranks;
  long *offset = mem_calloc(nr + 1, sizeof(long), "migration offsets");
  long *order = mem_calloc(p->n_owned + 1, sizeof(long), "migration order");
  for (long i = 0; i < p->n_owned; i++) {
    int r = space_cell_owner(s, p->cell[i]);
    if (r != s->rank) send_count[r]++;
  }
  for (int r = 0; r < nr; r++) offset[r + 1] = offset[r] + send_count[r];
  *n_leave = offset[nr];
  for (long i = 0; i < p->n_owned; i++) {
    int r = space_cell_owner(s, p->cell[i]);
    if (r != s->rank) order[offset[r]++] = i;
  }
  free(offset);
  return order;
}

void redistribute_parts(const struct space *s, struct parts *p, MPI_Comm comm) {
  int nr = s->n_ranks, w = parts_packed_size(p, PART_MIGRATE);
  int *cnt = mem_calloc(4 * nr, sizeof(int), "migration counts"), *send_count = cnt, *recv_count = cnt + nr;
  int *sdispl = cnt + 2 * nr, *rdispl = cnt + 3 * nr;
  long n_leave, n_recv = 0;
  long *order = group_leavers(s, p, send_count, &n_leave);
  MPI_Alltoall(send_count, 1, MPI_INT, recv_count, 1, MPI_INT, comm);
  for (int r = 0; r < nr; r++) {   /* in particles: slots fit an int, their doubles may not */
    sdispl[r] = (r ? sdispl[r - 1] + send_count[r - 1] : 0);
    rdispl[r] = (r ? rdispl[r - 1] + recv_count[r - 1] : 0);
    n_recv += recv_count[r];
  }
  double *sbuf = mem_calloc((size_t)n_leave * w + 1, sizeof(double), "migration send buffer");
  double *rbuf = mem_calloc((size_t)n_recv * w + 1, sizeof(double), "migration receive buffer");
  parts_pack(p, PART_MIGRATE, order, n_leave, sbuf);
  free(order);
  space_keep_own(s, p);
  MPI_Datatype particle;   /* one packed particle: w doubles */
  MPI_Type_contiguous(w, MPI_DOUBLE, &particle);
  MPI_Type_commit(&particle);
  MPI_Alltoallv(sbuf, send_count, sdispl, particle, rbuf, recv_count, rdispl, particle, comm);
  MPI_Type_free(&particle);
  free(sbuf);
  parts_reserve(p, p->n_owned + n_recv);
  parts_unpack(p, PART_MIGRATE, p->n_owned, n_recv, rbuf);
  p->n_owned += n_recv;
  p->n_halo = 0;
  free(rbuf);
  free(cnt);
}
