/* proxy.c — proxies (one per neighbouring rank), halo rebuild, per-field halo updates and
 * migration of particles between neighbouring ranks. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "base/mem.h"
#include "parallel/proxy.h"

enum { TAG_COUNT = 11, TAG_PARTS = 12, TAG_FIELDS = 13, TAG_MIGRATE_COUNT = 14, TAG_MIGRATE = 15,
       TAG_WANT_COUNT = 16, TAG_WANT = 17 };

int parts_packed_size(const struct parts *p, unsigned op) {
  int w = 0;
  for (const struct part_field *f = parts_fields; f < parts_fields + parts_n_fields; f++)
    if ((f->ops & op) && parts_has_field(p, f)) w += parts_field_ncomp(p, f);
  return w;
}

/* Column col of rows of width w in b from particles index[0..n) of the array a of type T. */
#define PACK_COLUMN(T, a)                                                         \
  do {                                                                            \
    const T *src = (const T *)(a);                                                \
    for (long r = 0; r < n; r++) b[r * w + col] = (double)src[index[r]];          \
  } while (0)

void parts_pack(const struct parts *p, unsigned op, const long *index, long n, double *b) {
  int w = parts_packed_size(p, op), col = 0;
  for (const struct part_field *f = parts_fields; f < parts_fields + parts_n_fields; f++) {
    if (!(f->ops & op) || !parts_has_field(p, f)) continue;
    for (int k = 0; k < parts_field_ncomp(p, f); k++, col++) {
      const void *a = parts_field_array(p, f, k);
      if (f->type == PART_DOUBLE) PACK_COLUMN(double, a);
      else if (f->type == PART_INT) PACK_COLUMN(int, a);
      else PACK_COLUMN(int64_t, a);
    }
  }
}

/* Column col of rows of width w in b into slots first.. of the array a of type T. */
#define UNPACK_COLUMN(T, a)                                                       \
  do {                                                                            \
    T *dst = (T *)(a) + first;                                                    \
    for (long r = 0; r < n; r++) dst[r] = (T)b[r * w + col];                      \
  } while (0)

void parts_unpack(struct parts *p, unsigned op, long first, long n, const double *b) {
  int w = parts_packed_size(p, op), col = 0;
  for (const struct part_field *f = parts_fields; f < parts_fields + parts_n_fields; f++) {
    if (!(f->ops & op) || !parts_has_field(p, f)) continue;
    for (int k = 0; k < parts_field_ncomp(p, f); k++, col++) {
      void *a = parts_field_array(p, f, k);
      if (f->type == PART_DOUBLE) UNPACK_COLUMN(double, a);
      else if (f->type == PART_INT) UNPACK_COLUMN(int, a);
      else UNPACK_COLUMN(int64_t, a);
    }
  }
}

static void reserve_buf(double **buf, long *cap, long n) {
  if (n <= *cap) return;
  *cap = n + n / 4 + 64;
  *buf = mem_realloc(*buf, mem_bytes(*cap, sizeof(double), "halo buffer"), "halo buffer");
}

/* The columns of a halo message: per-particle arrays indexed by slot, each of one element type.
 * A message to a proxy carries, column after column, the values of the particles it is sent
 * (send_index); a message from it fills the slots recv_first.. of each column. The messages are
 * described by MPI datatypes over the arrays themselves, so no buffer holds a copy. */
#define MAX_COLUMNS 64
struct columns {
  int n;
  void *base[MAX_COLUMNS];
  enum part_type type[MAX_COLUMNS];
};

static void add_column(struct columns *c, void *base, enum part_type type) {
  if (c->n == MAX_COLUMNS) {
    fprintf(stderr, "mpsph: internal error: a halo message of more than %d columns\n", MAX_COLUMNS);
    MPI_Abort(MPI_COMM_WORLD, 3);
  }
  c->base[c->n] = base;
  c->type[c->n++] = type;
}

static MPI_Datatype mpi_type(enum part_type type) {
  return type == PART_DOUBLE ? MPI_DOUBLE : type == PART_INT ? MPI_INT : MPI_INT64_T;
}

static size_t type_bytes(enum part_type type) {
  return type == PART_DOUBLE ? sizeof(double) : type == PART_INT ? sizeof(int) : sizeof(int64_t);
}

/* Build px->pick[t]: the elements send_index[0..n_send) of an array of element type t. */
static void build_picks(struct proxy *px) {
  for (int t = 0; t < N_PART_TYPES; t++) {
    MPI_Type_create_indexed_block((int)px->n_send, 1, px->send_index, mpi_type((enum part_type)t), &px->pick[t]);
    MPI_Type_commit(&px->pick[t]);
  }
  px->has_picks = 1;
}

static void free_picks(struct proxy *px) {
  for (int t = 0; px->has_picks && t < N_PART_TYPES; t++) MPI_Type_free(&px->pick[t]);
  px->has_picks = 0;
}

/* The committed datatype, relative to MPI_BOTTOM, of px's message of the columns c: what it is
 * sent (send) or what it sends here. */
static MPI_Datatype message_type(const struct proxy *px, const struct columns *c, int send) {
  int len[MAX_COLUMNS];
  MPI_Aint disp[MAX_COLUMNS];
  MPI_Datatype types[MAX_COLUMNS], message;
  for (int k = 0; k < c->n; k++) {
    char *first = (char *)c->base[k] + (send ? 0 : (size_t)px->recv_first * type_bytes(c->type[k]));
    MPI_Get_address(first, &disp[k]);
    len[k] = send ? 1 : (int)px->n_recv;
    types[k] = send ? px->pick[c->type[k]] : mpi_type(c->type[k]);
  }
  MPI_Type_create_struct(c->n, len, disp, types, &message);
  MPI_Type_commit(&message);
  return message;
}

/* Post the messages of the columns c with every proxy (requests h->requests[0..h->n_pending)):
 * received in place; sent from the arrays, or (packed) from the proxies' send buffers, holding
 * the columns one after the other (double columns only). */
static void post_columns(struct halo *h, const struct columns *c, int packed, int tag) {
  MPI_Request *req = h->requests;
  int nreq = 0;
  for (int k = 0; k < h->n_proxies; k++) {
    struct proxy *px = &h->proxies[k];
    MPI_Datatype t;
    if (px->n_recv) {
      t = message_type(px, c, 0);
      MPI_Irecv(MPI_BOTTOM, 1, t, px->rank, tag, h->comm, &req[nreq++]);
      MPI_Type_free(&t);
    }
    if (px->n_send && packed) {
      MPI_Isend(px->send_buf, (int)(px->n_send * c->n), MPI_DOUBLE, px->rank, tag, h->comm, &req[nreq++]);
      h->n_bytes += px->n_send * c->n * (long)sizeof(double);
    } else if (px->n_send) {
      int bytes;
      t = message_type(px, c, 1);
      MPI_Type_size(t, &bytes);
      MPI_Isend(MPI_BOTTOM, 1, t, px->rank, tag, h->comm, &req[nreq++]);
      MPI_Type_free(&t);
      h->n_bytes += bytes;
    }
    h->n_messages += px->n_send > 0;
  }
  h->n_pending = nreq;
}

/* Set cand[r] for every other rank owning a fine cell within the space's halo reach (halo_layers)
 * of a cell of this rank: a symmetric relation, the ranks that may exchange halo cells with it. */
static void mark_candidates(const struct space *s, char *cand) {
  long *nb = mem_calloc(grid_stencil_size(&s->grid, s->halo_layers), sizeof(long), "halo cell stencil");
  for (long k = 0; k < s->n_owned_cells; k++) {
    int n = grid_stencil(&s->grid, s->owned_cells[k], s->halo_layers, nb);
    for (int j = 0; j < n; j++) cand[space_cell_owner(s, nb[j])] = 1;
  }
  cand[s->rank] = 0;
  free(nb);
}

/* A foreign cell this rank wants in its halo, with its owner. */
struct wanted_cell {
  int owner;
  long cell;
};

/* The foreign cells wanted so far: marked in seen (by local cell) and listed in cells. */
struct wanted {
  char *seen;
  struct wanted_cell *cells;
  long n, cap;
  long *nb;   /* stencil scratch */
};

/* Add the foreign cells within `layers` of cell c to w. Returns 1 when one of them is out of the
 * halo's reach (not a local cell), else 0. */
static int want_around(struct wanted *w, const struct space *s, long c, int layers) {
  int n = grid_stencil(&s->grid, c, layers, w->nb);
  for (int j = 0; j < n; j++) {
    long cell = w->nb[j], l = space_local_cell(s, cell);
    int owner = space_cell_owner(s, cell);
    if (l < 0) return 1;
    if (owner == s->rank || w->seen[l]) continue;
    w->seen[l] = 1;
    if (w->n == w->cap) {
      w->cap = 2 * w->cap + 64;
      w->cells = mem_realloc(w->cells, mem_bytes(w->cap, sizeof(*w->cells), "halo cells wanted"),
                             "halo cells wanted");
    }
    w->cells[w->n++] = (struct wanted_cell){owner, cell};
  }
  return 0;
}

static int by_owner_and_cell(const void *a, const void *b) {
  const struct wanted_cell *x = a, *y = b;
  if (x->owner != y->owner) return (x->owner > y->owner) - (x->owner < y->owner);
  return (x->cell > y->cell) - (x->cell < y->cell);
}

/* The foreign cells within `layers` of an owned cell or within one layer of a cell of
 * reads[0..n_reads), sorted by owner and global index; *n their number. Returns NULL when a read
 * cell's neighbours lie beyond the halo's reach (the caller stops the run: beyond_reach). */
static struct wanted_cell *wanted_cells(const struct space *s, int layers, const long *reads, long n_reads,
                                        long *n) {
  struct wanted w = {.seen = mem_calloc(s->n_local_tops * s->cells_per_top + 1, 1, "halo cell marks"),
                     .nb = mem_calloc(grid_stencil_size(&s->grid, layers), sizeof(long), "halo cell stencil"),
                     .cells = mem_calloc(1, sizeof(struct wanted_cell), "halo cells wanted"), .cap = 1};
  int beyond = 0;
  for (long k = 0; k < s->n_owned_cells; k++) beyond |= want_around(&w, s, s->owned_cells[k], layers);
  for (long k = 0; k < n_reads && !beyond; k++) beyond |= want_around(&w, s, reads[k], 1);
  free(w.seen);
  free(w.nb);
  if (beyond) {
    free(w.cells);
    return NULL;
  }
  if (w.n > 1) qsort(w.cells, w.n, sizeof(*w.cells), by_owner_and_cell);
  *n = w.n;
  return w.cells;
}

/* Stop every rank on a halo request beyond the reach halo_layers promises (an internal error: the
 * engine's halo depth must cover what its passes read). */
static void beyond_reach(const struct space *s, MPI_Comm comm) {
  fprintf(stderr, "mpsph: internal error on rank %d: a halo cell the passes read lies beyond the halo "
          "reach of %d cell layers\n", s->rank, s->halo_layers);
  MPI_Abort(comm, 70);
}

/* Exchange the wanted cells with the candidate ranks: tell candidate k (rank ranks[k]) the n_want[k]
 * cells of want_by[k] and receive the cells it wants from this rank into cells_in[k] (n_in[k]). */
static void exchange_wanted(MPI_Comm comm, const int *ranks, int n_cand, long *const *want_by,
                            const long *n_want, long **cells_in, long *n_in) {
  MPI_Request *req = mem_calloc(2 * n_cand + 1, sizeof(MPI_Request), "halo requests");
  for (int k = 0; k < n_cand; k++) {
    MPI_Irecv(&n_in[k], 1, MPI_LONG, ranks[k], TAG_WANT_COUNT, comm, &req[2 * k]);
    MPI_Isend(&n_want[k], 1, MPI_LONG, ranks[k], TAG_WANT_COUNT, comm, &req[2 * k + 1]);
  }
  MPI_Waitall(2 * n_cand, req, MPI_STATUSES_IGNORE);
  int nreq = 0;
  for (int k = 0; k < n_cand; k++) {
    cells_in[k] = mem_calloc(n_in[k] + 1, sizeof(long), "halo cells to send");
    if (n_in[k]) MPI_Irecv(cells_in[k], (int)n_in[k], MPI_LONG, ranks[k], TAG_WANT, comm, &req[nreq++]);
    if (n_want[k]) MPI_Isend(want_by[k], (int)n_want[k], MPI_LONG, ranks[k], TAG_WANT, comm, &req[nreq++]);
  }
  MPI_Waitall(nreq, req, MPI_STATUSES_IGNORE);
  free(req);
}

/* The wanted cells want[0..n) (sorted by owner) as global indices in cells, with the first and the
 * number of those of each candidate (want_by[k], n_want[k]; candidate_of_rank maps a rank to its
 * candidate index). Returns 1 when a wanted cell's owner is not a candidate. */
static int group_wanted(const struct wanted_cell *want, long n, const int *candidate_of_rank, long *cells,
                        long **want_by, long *n_want) {
  for (long i = 0; i < n; i++) {
    int k = candidate_of_rank[want[i].owner];
    if (k < 0) return 1;
    if (!n_want[k]) want_by[k] = cells + i;
    cells[i] = want[i].cell;
    n_want[k]++;
  }
  return 0;
}

void halo_build(struct halo *h, const struct space *s, int layers, const long *reads, long n_reads,
                MPI_Comm comm) {
  halo_free(h);
  h->comm = comm;
  h->proxy_of_rank = mem_calloc(s->n_ranks, sizeof(int), "halo proxy table");
  char *cand = mem_calloc(s->n_ranks, 1, "halo candidate ranks");
  mark_candidates(s, cand);
  int n_cand = 0, *ranks = mem_calloc(s->n_ranks, sizeof(int), "halo candidate ranks");
  for (int r = 0; r < s->n_ranks; r++) {
    h->proxy_of_rank[r] = cand[r] ? n_cand : -1;
    if (cand[r]) ranks[n_cand++] = r;
  }
  free(cand);
  long n = 0, **want_by = mem_calloc(n_cand + 1, sizeof(long *), "halo cells wanted"),
       **cells_in = mem_calloc(n_cand + 1, sizeof(long *), "halo cells to send"),
       *n_want = mem_calloc(2 * (n_cand + 1), sizeof(long), "halo cell counts"), *n_in = n_want + n_cand + 1;
  struct wanted_cell *want = wanted_cells(s, layers, reads, n_reads, &n);
  long *cells = mem_calloc(n + 1, sizeof(long), "halo cells wanted");
  if (!want || group_wanted(want, n, h->proxy_of_rank, cells, want_by, n_want)) beyond_reach(s, comm);
  free(want);
  exchange_wanted(comm, ranks, n_cand, want_by, n_want, cells_in, n_in);
  h->proxies = mem_calloc(n_cand + 1, sizeof(struct proxy), "halo proxies");
  for (int k = 0; k < n_cand; k++) {
    int used = n_in[k] || n_want[k];
    h->proxy_of_rank[ranks[k]] = used ? h->n_proxies : -1;
    if (!used) {
      free(cells_in[k]);
      continue;
    }
    struct proxy *px = &h->proxies[h->n_proxies++];
    px->rank = ranks[k];
    px->cells_out = cells_in[k];
    px->n_cells_out = n_in[k];
  }
  free(ranks);
  free(want_by);
  free(cells_in);
  free(n_want);
  free(cells);
  h->requests = mem_calloc(2 * (h->n_proxies + 1), sizeof(MPI_Request), "halo requests");
  h->counts = mem_calloc(4 * (h->n_proxies + 1), sizeof(long), "halo counts");
}

long halo_bytes(const struct halo *h) {
  long bytes = 0;
  for (int k = 0; k < h->n_proxies; k++) {
    const struct proxy *px = &h->proxies[k];
    bytes += px->n_cells_out * (long)sizeof(long) + px->send_index_cap * (long)sizeof(int) +
             (px->send_cap + px->recv_cap) * (long)sizeof(double);
  }
  return bytes;
}

/* The halo's count scratch (4 rows of n_proxies + 1), zeroed. */
static long *zeroed_counts(struct halo *h) {
  memset(h->counts, 0, 4 * (h->n_proxies + 1) * sizeof(long));
  return h->counts;
}

void halo_free(struct halo *h) {
  for (int k = 0; k < h->n_proxies; k++) {
    struct proxy *px = &h->proxies[k];
    free(px->cells_out);
    free(px->send_index);
    free_picks(px);
    free(px->send_buf);
    free(px->recv_buf);
  }
  free(h->proxies);
  free(h->proxy_of_rank);
  free(h->requests);
  free(h->counts);
  long messages = h->n_messages, bytes = h->n_bytes;
  memset(h, 0, sizeof(*h));
  h->n_messages = messages;
  h->n_bytes = bytes;
}

/* Fill send_index with the owned slots of the particles in cells_out. */
static void collect_send(struct proxy *px, const struct space *s) {
  long n = 0;
  for (long k = 0; k < px->n_cells_out; k++) n += space_cell_size(s, px->cells_out[k]);
  if (n > px->send_index_cap) {
    px->send_index_cap = n + n / 4 + 64;
    px->send_index = mem_realloc(px->send_index, mem_bytes(px->send_index_cap, sizeof(int), "halo send index"),
                                  "halo send index");
  }
  px->n_send = 0;
  for (long k = 0; k < px->n_cells_out; k++) {
    long c = px->cells_out[k], start = space_cell_first(s, c), count = space_cell_size(s, c);
    for (long j = 0; j < count; j++) px->send_index[px->n_send++] = (int)(start + j);
  }
  free_picks(px);
  build_picks(px);
}

/* Exchange one count per proxy: send[k] goes to proxy k, recv[k] comes from it. */
static void exchange_counts(struct halo *h, const long *send, long *recv, int tag) {
  MPI_Request *req = h->requests;
  for (int k = 0; k < h->n_proxies; k++) {
    MPI_Irecv(&recv[k], 1, MPI_LONG, h->proxies[k].rank, tag, h->comm, &req[2 * k]);
    MPI_Isend(&send[k], 1, MPI_LONG, h->proxies[k].rank, tag, h->comm, &req[2 * k + 1]);
  }
  MPI_Waitall(2 * h->n_proxies, req, MPI_STATUSES_IGNORE);
}

/* Post the exchange of send_buf (n_send_vals) / recv_buf (n_recv_vals) with every proxy; the
 * requests are h->requests[0..h->n_pending). */
static void post_buffers(struct halo *h, const long *n_send_vals, const long *n_recv_vals, int tag) {
  MPI_Request *req = h->requests;
  int nreq = 0;
  for (int k = 0; k < h->n_proxies; k++) {
    struct proxy *px = &h->proxies[k];
    if (n_recv_vals[k])
      MPI_Irecv(px->recv_buf, (int)n_recv_vals[k], MPI_DOUBLE, px->rank, tag, h->comm, &req[nreq++]);
    if (n_send_vals[k]) {
      MPI_Isend(px->send_buf, (int)n_send_vals[k], MPI_DOUBLE, px->rank, tag, h->comm, &req[nreq++]);
      h->n_messages++;
      h->n_bytes += n_send_vals[k] * (long)sizeof(double);
    }
  }
  h->n_pending = nreq;
}

/* Wait for the posted exchange. */
static void wait_buffers(struct halo *h) {
  MPI_Waitall(h->n_pending, h->requests, MPI_STATUSES_IGNORE);
  h->n_pending = 0;
}

/* Exchange send_buf (n_send_vals) / recv_buf (n_recv_vals) with every proxy and wait. */
static void exchange_buffers(struct halo *h, const long *n_send_vals, const long *n_recv_vals, int tag) {
  post_buffers(h, n_send_vals, n_recv_vals, tag);
  wait_buffers(h);
}

/* The columns of the fields of parts_fields that op carries. */
static void part_columns(struct parts *p, unsigned op, struct columns *c) {
  c->n = 0;
  for (const struct part_field *f = parts_fields; f < parts_fields + parts_n_fields; f++)
    if ((f->ops & op) && parts_has_field(p, f))
      for (int k = 0; k < parts_field_ncomp(p, f); k++) add_column(c, parts_field_array(p, f, k), f->type);
}

void halo_rebuild(struct halo *h, const struct space *s, struct parts *p) {
  int np = h->n_proxies;
  long *counts = zeroed_counts(h);
  long *n_send = counts, *n_recv = counts + np + 1;
  for (int k = 0; k < np; k++) {
    collect_send(&h->proxies[k], s);
    n_send[k] = h->proxies[k].n_send;
  }
  exchange_counts(h, n_send, n_recv, TAG_COUNT);
  long total = 0;
  for (int k = 0; k < np; k++) {
    struct proxy *px = &h->proxies[k];
    px->n_recv = n_recv[k];
    px->recv_first = p->n_owned + total;
    total += n_recv[k];
  }
  parts_reserve(p, p->n_owned + total);
  struct columns c;
  part_columns(p, PART_HALO, &c);
  post_columns(h, &c, 0, TAG_PARTS);
  wait_buffers(h);
  p->n_halo = total;
}

/* The columns of a halo update's fields, received in place; sent from the proxies' send buffers
 * (the owned slots may change while the update is under way), packed here field by field. */
static void update_columns(struct halo *h, double *const *fields, int n_fields, struct columns *c) {
  c->n = 0;
  for (int f = 0; f < n_fields; f++) add_column(c, fields[f], PART_DOUBLE);
  for (int k = 0; k < h->n_proxies; k++) {
    struct proxy *px = &h->proxies[k];
    reserve_buf(&px->send_buf, &px->send_cap, px->n_send * n_fields);
    for (int f = 0; f < n_fields; f++) {
      double *dst = px->send_buf + f * px->n_send;
      for (long i = 0; i < px->n_send; i++) dst[i] = fields[f][px->send_index[i]];
    }
  }
}

void halo_update_begin(struct halo *h, double *const *fields, int n_fields) {
  struct columns c;
  update_columns(h, fields, n_fields, &c);
  post_columns(h, &c, 1, TAG_FIELDS);
}

void halo_update_progress(struct halo *h) {
  int done;
  if (h->n_pending) MPI_Testall(h->n_pending, h->requests, &done, MPI_STATUSES_IGNORE);
}

void halo_update_end(struct halo *h) { wait_buffers(h); }

void halo_update(struct halo *h, double *const *fields, int n_fields) {
  halo_update_begin(h, fields, n_fields);
  halo_update_end(h);
}

/* The id of an owned particle whose new owner is neither this rank nor a neighbour, or -1. */
static int64_t first_lost(const struct halo *h, const struct space *s, const struct parts *p) {
  for (long i = 0; i < p->n_owned; i++) {
    int dest = space_cell_owner(s, p->cell[i]);
    if (dest != s->rank && h->proxy_of_rank[dest] < 0) return p->id[i];
  }
  return -1;
}

/* Pack the owned particles leaving for each proxy (all neighbours, see first_lost); compacts the
 * stayers. */
static void pack_strays(struct halo *h, const struct space *s, struct parts *p, long *n_out) {
  int w = parts_packed_size(p, PART_MIGRATE);
  for (long i = 0; i < p->n_owned; i++) {
    int dest = space_cell_owner(s, p->cell[i]);
    if (dest == s->rank) continue;
    int k = h->proxy_of_rank[dest];
    struct proxy *px = &h->proxies[k];
    reserve_buf(&px->send_buf, &px->send_cap, (n_out[k] + 1) * w);
    parts_pack(p, PART_MIGRATE, &i, 1, px->send_buf + n_out[k] * w);
    n_out[k]++;
  }
  space_keep_own(s, p);
}

int64_t halo_migrate(struct halo *h, const struct space *s, struct parts *p) {
  int np = h->n_proxies, w = parts_packed_size(p, PART_MIGRATE);
  long *counts = zeroed_counts(h);
  long *n_out = counts, *n_in = counts + np + 1, *vals_out = counts + 2 * (np + 1),
       *vals_in = counts + 3 * (np + 1);
  int64_t lost = first_lost(h, s, p), lost_any;
  MPI_Allreduce(&lost, &lost_any, 1, MPI_INT64_T, MPI_MAX, h->comm);
  if (lost_any >= 0) return lost_any;
  pack_strays(h, s, p, n_out);
  exchange_counts(h, n_out, n_in, TAG_MIGRATE_COUNT);
  long total = 0;
  for (int k = 0; k < np; k++) {
    vals_out[k] = n_out[k] * w;
    vals_in[k] = n_in[k] * w;
    reserve_buf(&h->proxies[k].recv_buf, &h->proxies[k].recv_cap, vals_in[k]);
    total += n_in[k];
  }
  exchange_buffers(h, vals_out, vals_in, TAG_MIGRATE);
  parts_reserve(p, p->n_owned + total);
  for (int k = 0; k < np; k++) {
    parts_unpack(p, PART_MIGRATE, p->n_owned, n_in[k], h->proxies[k].recv_buf);
    p->n_owned += n_in[k];
  }
  return -1;
}
