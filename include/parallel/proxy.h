/* proxy.h — halo exchange with neighbouring ranks: one proxy per neighbouring rank holding the
 * cells this rank sends to it, the particles it receives, buffers and requests. Halo messages
 * are received in place (MPI datatypes over the particle arrays' halo slots). */
#ifndef MPSPH_PROXY_H
#define MPSPH_PROXY_H

#include <mpi.h>
#include "base/parts.h"
#include "parallel/space.h"

struct proxy {
  int rank;               /* the neighbouring rank */
  long n_cells_out;
  long *cells_out;        /* owned cells the neighbour wants in its halo, ascending */
  long n_send, n_recv;    /* particles sent / received in the current halo */
  int *send_index;        /* owned slots sent, in the sort's order (the displacements of pick) */
  long send_index_cap;
  long recv_first;        /* first halo slot of the received particles */
  MPI_Datatype pick[N_PART_TYPES];   /* the elements send_index of an array of each element type */
  int has_picks;
  double *send_buf, *recv_buf;       /* packed values: halo updates (sent), migration */
  long send_cap, recv_cap;           /* buffer capacities in doubles */
};

struct halo {
  MPI_Comm comm;
  int n_proxies;
  struct proxy *proxies;
  int *proxy_of_rank;     /* proxy index of each rank, -1 if not a neighbour */
  MPI_Request *requests;  /* scratch: 2 (n_proxies + 1) requests */
  long *counts;           /* scratch: 4 (n_proxies + 1) counts */
  int n_pending;          /* requests posted and not yet waited for */
  long n_messages, n_bytes;   /* counters since start */
};

/** Bytes held by the proxies (cell and send lists, message buffers). */
long halo_bytes(const struct halo *h);

/** Build the proxies from the cell ownership of s (after every partition change). This rank's halo
 *  holds the foreign cells within `layers` (at most s->halo_layers) of its owned cells and within
 *  one layer of each of the cells reads[0..n_reads) (cells around which its passes read besides
 *  their own, e.g. its wall ghosts' mirror points, all within s->halo_layers - 1 of an owned cell);
 *  each rank tells the ranks within s->halo_layers of its cells which of their cells it wants, and
 *  the proxies are the ranks it sends to or receives from. Collective over the communicator. */
void halo_build(struct halo *h, const struct space *s, int layers, const long *reads, long n_reads,
                MPI_Comm comm);

/** Free the proxies. */
void halo_free(struct halo *h);

/** Copy every field of the owned particles in the neighbours' halo cells into this rank's halo
 *  slots [n_owned, n_owned + n_halo); sets p->n_halo. Owned particles must be sorted. */
void halo_rebuild(struct halo *h, const struct space *s, struct parts *p);

/** Refresh the listed per-particle arrays (indexed by slot) in the halo slots, with
 *  non-blocking messages to the neighbouring ranks only: halo_update_begin then halo_update_end. */
void halo_update(struct halo *h, double *const *fields, int n_fields);

/** Start a halo update: pack the owned values the neighbours need and post the messages. Until
 *  halo_update_end the halo slots of the fields are not yet valid (the owned slots may be read). */
void halo_update_begin(struct halo *h, double *const *fields, int n_fields);

/** Let the posted messages of a halo update progress (MPI_Testall), e.g. between cells of the
 *  work that overlaps it. */
void halo_update_progress(struct halo *h);

/** Finish a halo update: wait for its messages (received in place into the halo slots). */
void halo_update_end(struct halo *h);

/** Send owned particles whose cell now belongs to another rank to that rank (a neighbour) and
 *  append the particles received. Returns the id of a particle that moved beyond the
 *  neighbouring ranks (then nothing is sent or changed), or -1. */
int64_t halo_migrate(struct halo *h, const struct space *s, struct parts *p);

/** Values per particle in a particle message of operation op (PART_HALO or PART_MIGRATE): the
 *  components of the fields of parts_fields that op carries. */
int parts_packed_size(const struct parts *p, unsigned op);

/** Pack particles index[0..n) into rows 0..n-1 of buf (parts_packed_size(p, op) doubles each);
 *  field by field, each a loop over the particles. */
void parts_pack(const struct parts *p, unsigned op, const long *index, long n, double *buf);

/** Unpack rows 0..n-1 of buf (packed by parts_pack with the same op) into slots first.. of p. */
void parts_unpack(struct parts *p, unsigned op, long first, long n, const double *buf);

#endif
