/* io_hdf5.c — collective parallel-HDF5 snapshots and checkpoints: /header attributes,
 * /particles datasets and, in checkpoints, the /run group; and reading them back.
 * Every rank writes (reads) its rows of each global dataset through a hyperslab, collectively. */
#include "io/io_hdf5.h"

#include <errno.h>
#include <hdf5.h>
#include <limits.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>
#include <unistd.h>
#include "io/io_mpiio.h"
#include "io/outdir.h"

#include "base/mem.h"

/* Bytes one rank hands to one H5Dwrite: MPI-IO counts are int, so stay well below 2 GiB.
 * Can be lowered at compile time to exercise the multi-call path. */
#ifndef MPSPH_IO_MAX_BYTES
#define MPSPH_IO_MAX_BYTES (1L << 30)
#endif

#define MAX_FIELDS PARTS_MAX_FIELDS   /* datasets of /particles in a checkpoint, at most */
#define MAX_FIELD_PATH 64              /* bytes of a dataset's path */

/* This rank's rows of a global dataset, and how many collective transfer calls each makes. */
struct layout {
  hsize_t total;     /* global row count */
  hsize_t offset;    /* first global row of this rank */
  hsize_t n;         /* rows of this rank */
  hsize_t per_call;  /* rows per H5Dwrite/H5Dread call */
  long calls;        /* calls per dataset, the same on every rank */
};

/* One dataset and the arrays its rows come from (go to); vectors (ncomp > 1) are double. */
struct field {
  char name[MAX_FIELD_PATH]; /* full path in the file */
  hid_t file_type, mem_type;
  size_t size;            /* bytes per component */
  int ncomp;              /* 1 for scalars, dim for vectors */
  void *comp[3];          /* component arrays */
};

/* H5Ewalk2 callback: keep the innermost (first, walking upward) error description. */
static herr_t innermost(unsigned n, const H5E_error2_t *e, void *reason) {
  if (n == 0 && e->desc) snprintf(reason, 256, "%s", e->desc);
  return 0;
}

/* Put a formatted message, followed by HDF5's innermost reason, into err; returns 3. */
static int fail(char *err, size_t len, const char *fmt, ...) {
  char what[512], reason[256] = "";
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(what, sizeof what, fmt, ap);
  va_end(ap);
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, innermost, reason);
  if (err && len)
    snprintf(err, len, "%s%s%s%s", what, reason[0] ? " (" : "", reason, reason[0] ? ")" : "");
  return 3;
}

/* Collective: 0 if every rank's status is 0, else 3 on every rank with the message of the
 * lowest failing rank copied into err. While a file is written, a failed write of this rank
 * (recorded by io_mpiio.c, hidden from HDF5) counts as a failure. Also serves as a barrier. */
static int agree(int status, MPI_Comm comm, char *err, size_t len) {
  int rank, who, first;
  char msg[768] = "";
  MPI_Comm_rank(comm, &rank);
  if (!status) status = mpiio_watch_failed(err, len);
  who = status ? rank : INT_MAX;
  MPI_Allreduce(&who, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == INT_MAX) return 0;
  if (rank == first && err && len) snprintf(msg, sizeof msg, "%s", err);
  MPI_Bcast(msg, (int)sizeof msg, MPI_CHAR, first, comm);
  if (err && len) snprintf(err, len, "%s", msg);
  return 3;
}

/* ---- layouts and fields ---- */

/* Rows per call for rows of row_bytes, and the common number of calls. */
static void layout_calls(struct layout *L, size_t row_bytes, MPI_Comm comm) {
  long calls;
  L->per_call = MPSPH_IO_MAX_BYTES / row_bytes;
  if (L->per_call == 0) L->per_call = 1;
  calls = (long)((L->n + L->per_call - 1) / L->per_call);
  MPI_Allreduce(&calls, &L->calls, 1, MPI_LONG, MPI_MAX, comm);
}

/* Writing: this rank's n rows follow those of the lower ranks (MPI_Exscan). */
static void write_layout(long n, size_t row_bytes, MPI_Comm comm, struct layout *L) {
  long long mine = n, before = 0, total = 0;
  int rank;
  MPI_Comm_rank(comm, &rank);
  MPI_Exscan(&mine, &before, 1, MPI_LONG_LONG, MPI_SUM, comm);
  if (rank == 0) before = 0; /* MPI_Exscan leaves rank 0's result undefined */
  MPI_Allreduce(&mine, &total, 1, MPI_LONG_LONG, MPI_SUM, comm);
  L->total = (hsize_t)total;
  L->offset = (hsize_t)before;
  L->n = (hsize_t)mine;
  layout_calls(L, row_bytes, comm);
}

/* Reading `total` rows: every rank all of them (whole), or a contiguous block of nearly equal
 * size per rank. */
static void read_layout(hsize_t total, int whole, size_t row_bytes, MPI_Comm comm,
                        struct layout *L) {
  int rank, size;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  L->total = total;
  L->offset = whole ? 0 : total * (hsize_t)rank / (hsize_t)size;
  L->n = whole ? total : total * (hsize_t)(rank + 1) / (hsize_t)size - L->offset;
  layout_calls(L, row_bytes, comm);
}

/* A one-component dataset name of file_type from the array a (mem_type, size bytes each). */
static struct field scalar_field(const char *name, hid_t file_type, hid_t mem_type, size_t size,
                                 void *a) {
  struct field f = {"", file_type, mem_type, size, 1, {a}};
  snprintf(f.name, sizeof f.name, "%s", name);
  return f;
}

static struct field real_field(const char *name, double *a) {
  return scalar_field(name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, sizeof(double), a);
}

static struct field long_field(const char *name, hid_t mem_type, void *a) {
  return scalar_field(name, H5T_STD_I64LE, mem_type, sizeof(int64_t), a);
}

/* The dataset /particles/<name> of the particle field pf of p (vectors: dim columns). */
static struct field table_field(const struct parts *p, const struct part_field *pf) {
  struct field f = pf->type == PART_INT
                       ? scalar_field("", H5T_STD_I32LE, H5T_NATIVE_INT, sizeof(int), NULL)
                   : pf->type == PART_INT64 ? long_field("", H5T_NATIVE_INT64, NULL)
                                            : real_field("", NULL);
  snprintf(f.name, sizeof f.name, "/particles/%s", pf->name);
  f.ncomp = parts_field_ncomp(p, pf);
  for (int k = 0; k < f.ncomp; k++) f.comp[k] = parts_field_array(p, pf, k);
  return f;
}

/* The /particles datasets of p, from parts_fields: the snapshot fields; with checkpoint, also the
 * checkpoint-only ones (walls-only fields only when p has walls). */
static int particle_fields(const struct parts *p, int checkpoint, struct field *f) {
  unsigned ops = PART_SNAPSHOT | (checkpoint ? PART_CHECKPOINT : 0);
  int n = 0;
  for (const struct part_field *pf = parts_fields; pf < parts_fields + parts_n_fields; pf++)
    if ((pf->ops & ops) && parts_has_field(p, pf)) f[n++] = table_field(p, pf);
  return n;
}

/* ---- transfers ---- */

/* Rows [first, first + rows) of f, row-major: scalars in place, vectors packed into buf. */
static void *rows_of(const struct field *f, hsize_t first, hsize_t rows, double *buf) {
  if (f->ncomp == 1) return rows ? (char *)f->comp[0] + first * f->size : (void *)buf;
  for (hsize_t i = 0; i < rows; i++)
    for (int k = 0; k < f->ncomp; k++)
      buf[i * (hsize_t)f->ncomp + k] = ((const double *)f->comp[k])[first + i];
  return buf;
}

/* After a read of a vector into buf: unpack rows [first, first + rows) into the components. */
static void unpack_rows(const struct field *f, hsize_t first, hsize_t rows, const double *buf) {
  if (f->ncomp == 1) return;
  for (hsize_t i = 0; i < rows; i++)
    for (int k = 0; k < f->ncomp; k++)
      ((double *)f->comp[k])[first + i] = buf[i * (hsize_t)f->ncomp + k];
}

/* Collective call number `call` on dataset dset: this rank's next slice, or nothing, written
 * from or read into f; 0 or 3. */
static int transfer_call(hid_t dset, const struct field *f, const struct layout *L, long call,
                         hid_t dxpl, double *buf, int reading, char *err, size_t len) {
  hsize_t first = (hsize_t)call * L->per_call;
  hsize_t rows = first < L->n ? L->n - first : 0;
  if (rows > L->per_call) rows = L->per_call;
  hsize_t start[2] = {L->offset + first, 0}, count[2] = {rows, (hsize_t)f->ncomp};
  hid_t fspace = H5Dget_space(dset);
  hid_t mspace = H5Screate_simple(f->ncomp > 1 ? 2 : 1, count, NULL);
  herr_t st = rows ? H5Sselect_hyperslab(fspace, H5S_SELECT_SET, start, NULL, count, NULL)
                   : H5Sselect_none(fspace);
  void *mem = reading && f->ncomp > 1 ? buf : rows_of(f, first, rows, buf);
  if (fspace < 0 || mspace < 0 || st < 0) st = -1;
  else if (reading) st = H5Dread(dset, f->mem_type, mspace, fspace, dxpl, mem);
  else st = H5Dwrite(dset, f->mem_type, mspace, fspace, dxpl, mem);
  if (reading && st >= 0) unpack_rows(f, first, rows, buf);
  int status = st < 0 ? fail(err, len, "cannot %s %s", reading ? "read" : "write", f->name) : 0;
  H5Sclose(mspace);
  H5Sclose(fspace);
  return status;
}

/* Every call of one dataset; a local failure does not stop the loop, so every rank makes the
 * same calls. Then closes dset. 0 or 3, the same on every rank. */
static int transfer_field(hid_t dset, const struct field *f, const struct layout *L, hid_t dxpl,
                          int reading, MPI_Comm comm, char *err, size_t len) {
  hsize_t rows = L->n < L->per_call ? L->n : L->per_call;
  double *buf = mem_calloc(rows ? rows : 1, (size_t)f->ncomp * sizeof(double), "HDF5 transfer buffer");
  int st = 0;
  for (long c = 0; c < L->calls; c++)
    st |= transfer_call(dset, f, L, c, dxpl, buf, reading, err, len);
  if (H5Dclose(dset) < 0 && !st) st = fail(err, len, "cannot close %s", f->name);
  free(buf);
  return agree(st, comm, err, len);
}

/* Create dataset f with L->total rows and write every rank's rows collectively; 0 or 3. */
static int write_field(hid_t file, const struct field *f, const struct layout *L, hid_t dxpl,
                       MPI_Comm comm, char *err, size_t len) {
  hsize_t dims[2] = {L->total, (hsize_t)f->ncomp};
  hid_t space = H5Screate_simple(f->ncomp > 1 ? 2 : 1, dims, NULL);
  hid_t dset = H5Dcreate2(file, f->name, f->file_type, space, H5P_DEFAULT, H5P_DEFAULT,
                          H5P_DEFAULT);
  H5Sclose(space);
  if (agree(dset < 0 ? fail(err, len, "cannot create %s", f->name) : 0, comm, err, len)) {
    if (dset >= 0) H5Dclose(dset);
    return 3;
  }
  return transfer_field(dset, f, L, dxpl, 0, comm, err, len);
}

/* Rows of dataset `name` (1-D, or 2-D with ncomp columns), or -1 with a message in err. */
static long dataset_rows(hid_t dset, const char *name, int ncomp, char *err, size_t len) {
  hsize_t dims[2] = {0, 0};
  hid_t space = H5Dget_space(dset);
  int rank = space < 0 ? -1 : H5Sget_simple_extent_ndims(space);
  if (rank == (ncomp > 1 ? 2 : 1) && rank > 0) H5Sget_simple_extent_dims(space, dims, NULL);
  if (space >= 0) H5Sclose(space);
  if (rank == (ncomp > 1 ? 2 : 1) && (ncomp == 1 || dims[1] == (hsize_t)ncomp)) return (long)dims[0];
  fail(err, len, "%s: expected %d column%s", name, ncomp, ncomp > 1 ? "s" : "");
  return -1;
}

/* Open dataset f and check its columns and that it has `total` rows (total < 0: any): the
 * dataset, its rows in *rows; or H5I_INVALID_HID with a message in err. */
static hid_t open_field(hid_t file, const struct field *f, long total, long *rows, char *err,
                        size_t len) {
  hid_t dset = H5Dopen2(file, f->name, H5P_DEFAULT);
  *rows = dset < 0 ? (fail(err, len, "no dataset %s", f->name), -1)
                   : dataset_rows(dset, f->name, f->ncomp, err, len);
  if (*rows >= 0 && total >= 0 && *rows != total)
    *rows = (fail(err, len, "%s has %ld rows, expected %ld", f->name, *rows, total), -1);
  if (*rows < 0 && dset >= 0) {
    H5Dclose(dset);
    dset = H5I_INVALID_HID;
  }
  return dset;
}

/* Open dataset f, check it has `total` rows (total < 0: any; then *rows_out gets them) and
 * read this rank's rows of layout L (set up here from the row count: a block per rank, or
 * every row when whole) into f's arrays. Collective; 0 or 3. */
static int read_field(hid_t file, const struct field *f, long total, int whole, hid_t dxpl,
                      long *rows_out, MPI_Comm comm, char *err, size_t len) {
  long rows;
  hid_t dset = open_field(file, f, total, &rows, err, len);
  if (agree(dset < 0, comm, err, len)) {
    if (dset >= 0) H5Dclose(dset);
    return 3;
  }
  struct layout L;
  read_layout((hsize_t)rows, whole, (size_t)f->ncomp * sizeof(double), comm, &L);
  if (rows_out) *rows_out = rows;
  return transfer_field(dset, f, &L, dxpl, 1, comm, err, len);
}

/* A collective data transfer property list; 0 or 3. */
static int collective_dxpl(hid_t *dxpl, char *err, size_t len) {
  *dxpl = H5Pcreate(H5P_DATASET_XFER);
  if (*dxpl >= 0 && H5Pset_dxpl_mpio(*dxpl, H5FD_MPIO_COLLECTIVE) >= 0) return 0;
  return fail(err, len, "cannot set up collective transfers");
}

/* ---- attributes ---- */

/* Write one scalar attribute (same value on every rank); 0 or 3. */
static int put_attr(hid_t loc, const char *name, hid_t file_type, hid_t mem_type, const void *value,
                    char *err, size_t len) {
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t attr = H5Acreate2(loc, name, file_type, space, H5P_DEFAULT, H5P_DEFAULT);
  int st = (attr < 0 || H5Awrite(attr, mem_type, value) < 0)
               ? fail(err, len, "cannot write attribute %s", name) : 0;
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  return st;
}

/* Read one scalar attribute as mem_type; 0 or 3. */
static int get_attr(hid_t loc, const char *name, hid_t mem_type, void *value, char *err,
                    size_t len) {
  hid_t attr = H5Aopen(loc, name, H5P_DEFAULT);
  int st = (attr < 0 || H5Aread(attr, mem_type, value) < 0)
               ? fail(err, len, "cannot read attribute %s", name) : 0;
  if (attr >= 0) H5Aclose(attr);
  return st;
}

/* The variable-length UTF-8 string type of the text attributes. */
static hid_t string_type(void) {
  hid_t type = H5Tcopy(H5T_C_S1);
  if (type >= 0 && (H5Tset_size(type, H5T_VARIABLE) < 0 || H5Tset_cset(type, H5T_CSET_UTF8) < 0)) {
    H5Tclose(type);
    return H5I_INVALID_HID;
  }
  return type;
}

/* Write a UTF-8 variable-length string attribute: its text lives in the global heap, so it has
 * no 64 kB attribute-size limit, and h5py reads it as str. NULL is written as "". */
static int put_string_attr(hid_t loc, const char *name, const char *value, char *err, size_t len) {
  const char *text = value ? value : "";
  hid_t type = string_type();
  int st = type < 0 ? fail(err, len, "cannot make string type for %s", name)
                    : put_attr(loc, name, type, type, &text, err, len);
  if (type >= 0) H5Tclose(type);
  return st;
}

/* Read a string attribute into a copy from mem.h (*out, NULL on failure); 0 or 3. */
static int get_string_attr(hid_t loc, const char *name, const char **out, char *err, size_t len) {
  char *text = NULL;
  hid_t type = string_type();
  int st = type < 0 ? fail(err, len, "cannot make string type for %s", name)
                    : get_attr(loc, name, type, &text, err, len);
  *out = !st && text ? mem_strndup(text, SIZE_MAX, "HDF5 string attribute") : NULL;
  if (!st && !*out) st = fail(err, len, "attribute %s is empty", name);
  if (text) H5free_memory(text);
  if (type >= 0) H5Tclose(type);
  return st;
}

/* ---- files ---- */

/* The collective-buffering buffer of an MPI-IO aggregator rank [bytes] (the MPI-IO hint
 * cb_buffer_size): MPI libraries default to 16 or 32 MB, which the aggregators add to their
 * peak memory at every snapshot; 4 MB keeps the writes in large pieces. */
#define IO_AGGREGATOR_BYTES "4194304"

/* File access list for collective MPI-IO by every rank of comm, metadata collective too. */
static hid_t mpio_fapl(MPI_Comm comm) {
  hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  MPI_Info info;
  MPI_Info_create(&info);
  MPI_Info_set(info, "cb_buffer_size", IO_AGGREGATOR_BYTES);
  if (fapl >= 0 && (H5Pset_fapl_mpio(fapl, comm, info) < 0 ||
                    H5Pset_coll_metadata_write(fapl, 1) < 0 ||
                    H5Pset_all_coll_metadata_ops(fapl, 1) < 0)) {
    H5Pclose(fapl);
    fapl = H5I_INVALID_HID;
  }
  MPI_Info_free(&info);
  return fapl;
}

/* Create (truncate) or open (read-only) path collectively; 0 or 3. */
static int open_file(const char *path, int create, MPI_Comm comm, hid_t *file, char *err,
                     size_t len) {
  hid_t fapl = mpio_fapl(comm);
  *file = H5I_INVALID_HID;
  if (fapl >= 0 && create) *file = H5Fcreate(path, H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  else if (fapl >= 0) *file = H5Fopen(path, H5F_ACC_RDONLY, fapl);
  int st = *file < 0 ? fail(err, len, "cannot %s %s", create ? "create" : "open", path) : 0;
  if (fapl >= 0) H5Pclose(fapl);
  return st;
}

/* Create /header with the contracted attributes; 0 or 3. */
static int write_header(hid_t file, const struct snapshot_info *info, hsize_t total, char *err,
                        size_t len) {
  int64_t step = info->step, n = (int64_t)total;
  hid_t g = H5Gcreate2(file, "header", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (g < 0) return fail(err, len, "cannot create group /header");
  int st = put_attr(g, "time", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &info->time, err, len) ||
           put_attr(g, "step", H5T_STD_I64LE, H5T_NATIVE_INT64, &step, err, len) ||
           put_attr(g, "dimension", H5T_STD_I32LE, H5T_NATIVE_INT, &info->dimension, err, len) ||
           put_attr(g, "n_particles", H5T_STD_I64LE, H5T_NATIVE_INT64, &n, err, len) ||
           put_string_attr(g, "code_version", info->code_version, err, len) ||
           put_string_attr(g, "case_yaml", info->case_yaml, err, len);
  H5Gclose(g);
  return st ? 3 : 0;
}

/* Read /header into info (strings allocated); 0 or 3. */
static int read_header(hid_t file, struct snapshot_info *info, char *err, size_t len) {
  int64_t step = 0, n = 0;
  hid_t g = H5Gopen2(file, "header", H5P_DEFAULT);
  if (g < 0) return fail(err, len, "no group /header");
  int st = get_attr(g, "time", H5T_NATIVE_DOUBLE, &info->time, err, len) ||
           get_attr(g, "step", H5T_NATIVE_INT64, &step, err, len) ||
           get_attr(g, "dimension", H5T_NATIVE_INT, &info->dimension, err, len) ||
           get_attr(g, "n_particles", H5T_NATIVE_INT64, &n, err, len) ||
           get_string_attr(g, "code_version", &info->code_version, err, len) ||
           get_string_attr(g, "case_yaml", &info->case_yaml, err, len);
  info->step = (long)step;
  info->n_particles = (long)n;
  H5Gclose(g);
  return st ? 3 : 0;
}

/* Write every dataset of fields[0..n) with layout L; 0 or 3 (same on every rank). */
static int write_fields(hid_t file, const struct field *fields, int n, const struct layout *L,
                        MPI_Comm comm, char *err, size_t len) {
  hid_t dxpl;
  int st = agree(collective_dxpl(&dxpl, err, len), comm, err, len);
  for (int k = 0; k < n && !st; k++) st = write_field(file, &fields[k], L, dxpl, comm, err, len);
  if (dxpl >= 0) H5Pclose(dxpl);
  return st;
}

/* The /run numbers of a checkpoint as attributes; 0 or 3. */
static int put_numbers(hid_t g, const struct checkpoint_extra *x, char *err, size_t len) {
  int st = 0;
  for (int k = 0; k < x->n_numbers && !st; k++) {
    const struct hdf5_number *v = &x->numbers[k];
    st = v->real ? put_attr(g, v->name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, v->real, err, len)
                 : put_attr(g, v->name, H5T_STD_I64LE, H5T_NATIVE_LONG, v->integer, err, len);
  }
  return st;
}

/* Read the /run numbers of a checkpoint; 0 or 3. */
static int get_numbers(hid_t g, const struct checkpoint_extra *x, char *err, size_t len) {
  int st = 0;
  for (int k = 0; k < x->n_numbers && !st; k++) {
    const struct hdf5_number *v = &x->numbers[k];
    st = v->real ? get_attr(g, v->name, H5T_NATIVE_DOUBLE, v->real, err, len)
                 : get_attr(g, v->name, H5T_NATIVE_LONG, v->integer, err, len);
  }
  return st;
}

/* The two datasets of the snapshot series. */
static void series_fields(const struct checkpoint_extra *x, struct field *f) {
  f[0] = real_field("/run/snapshot_times", x->snapshot_times);
  f[1] = long_field("/run/snapshot_particles", H5T_NATIVE_LONG, x->snapshot_counts);
}

/* The dataset /<group>/<name> of replicated array a. */
static struct field array_field(const char *group, const struct hdf5_array *a) {
  char name[MAX_FIELD_PATH];
  snprintf(name, sizeof name, "/%s/%s", group, a->name);
  return real_field(name, a->at);
}

/* The replicated arrays a[0, n) as datasets /<group>/<name> written by rank 0; 0 or 3. */
static int write_arrays(hid_t file, const char *group, const struct hdf5_array *a, int n, MPI_Comm comm, char *err,
                        size_t len) {
  int rank, st = 0;
  MPI_Comm_rank(comm, &rank);
  for (int k = 0; k < n && !st; k++) {
    struct layout L;
    struct field f = array_field(group, &a[k]);
    write_layout(rank == 0 ? a[k].n : 0, sizeof(double), comm, &L);
    st = write_fields(file, &f, 1, &L, comm, err, len);
  }
  return st;
}

/* Create /run: the numbers as attributes, and the snapshot series written by rank 0; 0 or 3. */
static int write_run(hid_t file, const struct checkpoint_extra *x, MPI_Comm comm, char *err,
                     size_t len) {
  int rank;
  MPI_Comm_rank(comm, &rank);
  hid_t g = H5Gcreate2(file, "run", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  int st = g < 0 ? fail(err, len, "cannot create group /run") : put_numbers(g, x, err, len);
  if (g >= 0) H5Gclose(g);
  if (agree(st, comm, err, len)) return 3;
  struct field f[2];
  struct layout L;
  series_fields(x, f);
  write_layout(rank == 0 ? x->n_snapshots : 0, sizeof(double), comm, &L);
  st = write_fields(file, f, 2, &L, comm, err, len);
  return st ? st : write_arrays(file, "run", x->arrays, x->n_arrays, comm, err, len);
}

/* Test hook, documented in doc/user-guide.md: with MPSPH_TEST_ABORT_IN_WRITE=NAME in the
 * environment, die by SIGKILL (as kill -9 would) while writing a file whose path contains NAME:
 * after its temporary file was filled, before it is closed and renamed. */
static void test_abort_hook(const char *tmp) {
  const char *name = getenv("MPSPH_TEST_ABORT_IN_WRITE");
  if (name && name[0] && strstr(tmp, name)) raise(SIGKILL);
}

/* Write the whole file (extra NULL: a snapshot) into tmp; 0 or 3, the same on every rank. */
static int write_file(const char *tmp, const struct snapshot_info *info, const struct parts *p,
                      const struct checkpoint_extra *extra, MPI_Comm comm, char *err,
                      size_t len) {
  struct field fields[MAX_FIELDS];
  struct layout L;
  hid_t file, g;
  int n = particle_fields(p, extra != NULL, fields);
  write_layout(p->n_owned, (size_t)p->dim * sizeof(double), comm, &L);
  int st = agree(open_file(tmp, 1, comm, &file, err, len), comm, err, len);
  if (st) return st;
  st = agree(write_header(file, info, L.total, err, len), comm, err, len);
  g = st ? H5I_INVALID_HID : H5Gcreate2(file, "particles", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (!st) st = agree(g < 0 ? fail(err, len, "cannot create group /particles") : 0, comm, err, len);
  if (g >= 0) H5Gclose(g);
  if (!st) st = write_fields(file, fields, n, &L, comm, err, len);
  if (!st && info->n_arrays) {
    g = H5Gcreate2(file, "solids", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    st = agree(g < 0 ? fail(err, len, "cannot create group /solids") : 0, comm, err, len);
    if (g >= 0) H5Gclose(g);
    if (!st) st = write_arrays(file, "solids", info->arrays, info->n_arrays, comm, err, len);
  }
  if (!st && extra) st = write_run(file, extra, comm, err, len);
  /* collective: the metadata out, then MPI_File_sync, so that a write the system reports late
   * (NFS, quotas) fails here, before the rename */
  if (!st && H5Fflush(file, H5F_SCOPE_GLOBAL) < 0) st = fail(err, len, "cannot flush %s", tmp);
  test_abort_hook(tmp);
  if (H5Fclose(file) < 0 && !st) st = fail(err, len, "cannot close %s", tmp);
  return agree(st, comm, err, len);
}

/* Rank 0, after every rank closed tmp: rename it to path on success, remove it on failure. */
static int publish(const char *tmp, const char *path, int status, MPI_Comm comm, char *err,
                   size_t len) {
  int rank, st = status;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0 && status) unlink(tmp);
  if (rank == 0 && !status && rename(tmp, path) != 0) {
    if (err && len) snprintf(err, len, "cannot rename %s to %s: %s", tmp, path, strerror(errno));
    st = 3;
  }
  return agree(st, comm, err, len);
}

/* status = call, with HDF5's automatic error printing off (errors are reported through err). */
#define QUIET_HDF5(status, call)                                  \
  do {                                                            \
    H5E_auto2_t old_func;                                         \
    void *old_data;                                               \
    H5Eget_auto2(H5E_DEFAULT, &old_func, &old_data);              \
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);                        \
    status = call;                                                \
    H5Eset_auto2(H5E_DEFAULT, old_func, old_data);                \
  } while (0)

#define METADATA_BYTES 65536.0   /* allowed for HDF5's metadata: a few kB per dataset */

/* The size of the file (extra NULL: a snapshot) of p on every rank of comm, about: its datasets,
 * text attributes and METADATA_BYTES. Collective. */
static double file_bytes(const struct snapshot_info *info, const struct parts *p,
                         const struct checkpoint_extra *extra, MPI_Comm comm) {
  struct field fields[MAX_FIELDS];
  double row = 0, rows = (double)p->n_owned, total;
  int n = particle_fields(p, extra != NULL, fields);
  for (int k = 0; k < n; k++) row += (double)fields[k].size * fields[k].ncomp;
  MPI_Allreduce(&rows, &total, 1, MPI_DOUBLE, MPI_SUM, comm);
  double text = (info->case_yaml ? strlen(info->case_yaml) : 0) +
                (info->code_version ? strlen(info->code_version) : 0);
  double arrays = 0;
  for (int k = 0; k < info->n_arrays; k++) arrays += 8.0 * (double)info->arrays[k].n;
  for (int k = 0; extra && k < extra->n_arrays; k++) arrays += 8.0 * (double)extra->arrays[k].n;
  return total * row + text + arrays + (extra ? 16.0 * extra->n_snapshots : 0) + METADATA_BYTES;
}

/* Collective: 0, or 3 on every rank when rank 0 finds less free space than `bytes` in the file
 * system of path (message: the sizes). A write into a file system with no room left fails
 * part-way, and Open MPI's own MPI-IO (ompio) can lose such a failure of its collective write
 * on 3 ranks or more and then hang in MPI_File_sync; this check keeps the common case, a disk
 * filled by the run's own snapshots, out of that. Skipped with MPSPH_TEST_NO_ROOM_CHECK=1 (a
 * test hook). */
static int room_for(const char *path, double bytes, MPI_Comm comm, char *err, size_t len) {
  int rank, st = 0;
  const char *skip = getenv("MPSPH_TEST_NO_ROOM_CHECK");
  MPI_Comm_rank(comm, &rank);
  if (rank == 0 && !(skip && !strcmp(skip, "1"))) st = outdir_room(path, bytes, err, len);
  return agree(st, comm, err, len);
}

/* Collective file (via path.tmp) of the owned particles, with extra for a checkpoint. */
static int write_via_tmp(const char *path, const struct snapshot_info *info,
                         const struct parts *p, const struct checkpoint_extra *extra,
                         MPI_Comm comm, char *err, size_t len) {
  char *tmp = NULL;
  int st;
  if (err && len) err[0] = '\0';
  if (p->dim < 1 || p->dim > 3 || p->dim != info->dimension)
    st = fail(err, len, "%s: particles have dimension %d, header %d", path, p->dim,
              info->dimension);
  else st = 0;
  st = agree(st, comm, err, len);
  if (!st) st = room_for(path, file_bytes(info, p, extra, comm), comm, err, len);
  if (!st) {
    tmp = mem_alloc(strlen(path) + sizeof ".tmp", "a file path");
    sprintf(tmp, "%s.tmp", path);
    mpiio_watch_begin(path, comm);
    st = write_file(tmp, info, p, extra, comm, err, len);
    mpiio_watch_end();
    st = publish(tmp, path, st, comm, err, len);
  }
  free(tmp);
  return st;
}

int hdf5_write_snapshot(const char *path, const struct snapshot_info *info,
                        const struct parts *p, MPI_Comm comm, char *err, size_t err_len) {
  int st;
  QUIET_HDF5(st, write_via_tmp(path, info, p, NULL, comm, err, err_len));
  return st;
}

int hdf5_write_checkpoint(const char *path, const struct snapshot_info *info,
                          const struct parts *p, const struct checkpoint_extra *extra,
                          MPI_Comm comm, char *err, size_t err_len) {
  int st;
  QUIET_HDF5(st, write_via_tmp(path, info, p, extra, comm, err, err_len));
  return st;
}

/* ---- reading ---- */

/* Open path, read its header, close; 0 or 3 (same on every rank). */
static int read_header_file(const char *path, struct snapshot_info *info, MPI_Comm comm,
                            char *err, size_t len) {
  hid_t file;
  memset(info, 0, sizeof *info);
  if (err && len) err[0] = '\0';
  int st = agree(open_file(path, 0, comm, &file, err, len), comm, err, len);
  if (st) return st;
  st = read_header(file, info, err, len);
  H5Fclose(file);
  return agree(st, comm, err, len);
}

int hdf5_read_header(const char *path, struct snapshot_info *info, MPI_Comm comm, char *err,
                     size_t err_len) {
  int st;
  QUIET_HDF5(st, read_header_file(path, info, comm, err, err_len));
  if (st) hdf5_info_free(info);
  return st;
}

void hdf5_info_free(struct snapshot_info *info) {
  free((char *)info->case_yaml);
  free((char *)info->code_version);
  info->case_yaml = info->code_version = NULL;
}

int io_agree(int failed, MPI_Comm comm, char *msg, size_t len) {
  return agree(failed, comm, msg, len) ? 1 : 0;
}

/* Collective: 0 if every dataset of fields[0..n) has `total` rows (and its columns), else 3 on
 * every rank with the first mismatch in err; nothing is read. */
static int check_rows(hid_t file, const struct field *fields, int n, long total, MPI_Comm comm,
                      char *err, size_t len) {
  int st = 0;
  for (int k = 0; k < n && !st; k++) {
    long rows;
    hid_t dset = open_field(file, &fields[k], total, &rows, err, len);
    st = dset < 0 ? 3 : 0;
    if (dset >= 0) H5Dclose(dset);
  }
  return agree(st, comm, err, len);
}

/* This rank's block of every /particles dataset into p; 0 or 3. */
static int read_particles(hid_t file, struct parts *p, hid_t dxpl, MPI_Comm comm, char *err,
                          size_t len) {
  struct field fields[MAX_FIELDS];
  struct layout L;
  int64_t total = 0;
  hid_t g = H5Gopen2(file, "header", H5P_DEFAULT);
  int st = g < 0 ? fail(err, len, "no group /header")
                 : get_attr(g, "n_particles", H5T_NATIVE_INT64, &total, err, len);
  if (!st && total < 0)
    st = fail(err, len, "/header/n_particles: got %lld, expected a row count >= 0",
              (long long)total);
  if (g >= 0) H5Gclose(g);
  if (agree(st, comm, err, len)) return 3;
  int n = particle_fields(p, 1, fields);
  if (check_rows(file, fields, n, (long)total, comm, err, len)) return 3;  /* before reserving */
  read_layout((hsize_t)total, 0, sizeof(double), comm, &L);
  parts_reserve(p, (long)L.n);
  p->n_owned = (long)L.n;
  p->n_halo = 0;
  particle_fields(p, 1, fields);   /* the arrays may have moved */
  for (int k = 0; k < n && !st; k++)
    st = read_field(file, &fields[k], (long)total, 0, dxpl, NULL, comm, err, len);
  return st;
}

/* The /run numbers and snapshot series of a checkpoint into x (series allocated); 0 or 3. */
static int read_run(hid_t file, struct checkpoint_extra *x, hid_t dxpl, MPI_Comm comm, char *err,
                    size_t len) {
  hid_t g = H5Gopen2(file, "run", H5P_DEFAULT);
  int st = g < 0 ? fail(err, len, "no group /run: not a checkpoint") : get_numbers(g, x, err, len);
  hid_t d = st ? H5I_INVALID_HID : H5Dopen2(g, "snapshot_times", H5P_DEFAULT);
  long n = d < 0 ? -1 : dataset_rows(d, "/run/snapshot_times", 1, err, len);
  if (!st && n < 0) st = fail(err, len, "no dataset /run/snapshot_times");
  if (!st && n > INT_MAX) st = fail(err, len, "/run/snapshot_times has %ld rows, more than %d", n,
                                    INT_MAX);
  if (d >= 0) H5Dclose(d);
  if (g >= 0) H5Gclose(g);
  if (agree(st, comm, err, len)) return 3;
  x->n_snapshots = (int)n;
  x->snapshot_times = mem_calloc((size_t)n, sizeof(double), "snapshot series");
  x->snapshot_counts = mem_calloc((size_t)n, sizeof(long), "snapshot series");
  struct field f[2];
  series_fields(x, f);
  st = read_field(file, &f[0], n, 1, dxpl, NULL, comm, err, len);
  if (!st) st = read_field(file, &f[1], n, 1, dxpl, NULL, comm, err, len);
  for (int k = 0; k < x->n_arrays && !st; k++) {
    f[0] = array_field("run", &x->arrays[k]);
    st = read_field(file, &f[0], x->arrays[k].n, 1, dxpl, NULL, comm, err, len);
  }
  return st;
}

/* Open path and read its run state (x not NULL: the /run group) or particles (p not NULL);
 * 0 or 3 (same on every rank). */
static int read_checkpoint_file(const char *path, struct parts *p, struct checkpoint_extra *x,
                                MPI_Comm comm, char *err, size_t len) {
  hid_t file, dxpl = H5I_INVALID_HID;
  if (err && len) err[0] = '\0';
  int st = agree(open_file(path, 0, comm, &file, err, len), comm, err, len);
  if (st) return st;
  st = agree(collective_dxpl(&dxpl, err, len), comm, err, len);
  if (!st && x) st = read_run(file, x, dxpl, comm, err, len);
  if (!st && p) st = read_particles(file, p, dxpl, comm, err, len);
  if (dxpl >= 0) H5Pclose(dxpl);
  H5Fclose(file);
  return agree(st, comm, err, len);
}

int hdf5_read_run(const char *path, struct checkpoint_extra *extra, MPI_Comm comm, char *err,
                  size_t err_len) {
  int st;
  QUIET_HDF5(st, read_checkpoint_file(path, NULL, extra, comm, err, err_len));
  return st;
}

int hdf5_read_particles(const char *path, struct parts *p, MPI_Comm comm, char *err,
                        size_t err_len) {
  int st;
  QUIET_HDF5(st, read_checkpoint_file(path, p, NULL, comm, err, err_len));
  return st;
}
