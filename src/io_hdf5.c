/* io_hdf5.c — collective parallel-HDF5 snapshots: /header attributes and /particles datasets.
 * Every rank writes its owned rows of each global dataset through a hyperslab, collectively. */
#include "io_hdf5.h"

#include <errno.h>
#include <hdf5.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Bytes one rank hands to one H5Dwrite: MPI-IO counts are int, so stay well below 2 GiB.
 * Can be lowered at compile time to exercise the multi-call path. */
#ifndef MPSPH_IO_MAX_BYTES
#define MPSPH_IO_MAX_BYTES (1L << 30)
#endif

/* This rank's rows of the global datasets, and how many collective H5Dwrite calls each makes. */
struct layout {
  hsize_t total;     /* global particle count */
  hsize_t offset;    /* first global row of this rank */
  hsize_t n;         /* rows owned by this rank */
  hsize_t per_call;  /* rows per H5Dwrite call */
  long calls;        /* H5Dwrite calls per dataset, the same on every rank */
};

/* One dataset of /particles and the arrays it comes from; vectors (ncomp > 1) are double. */
struct field {
  const char *name;
  hid_t file_type, mem_type;
  size_t size;            /* bytes per component */
  int ncomp;              /* 1 for scalars, dim for vectors */
  const void *comp[3];    /* component arrays */
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
 * lowest failing rank copied into err. Also serves as a barrier. */
static int agree(int status, MPI_Comm comm, char *err, size_t len) {
  int rank, who, first;
  char msg[768] = "";
  MPI_Comm_rank(comm, &rank);
  who = status ? rank : INT_MAX;
  MPI_Allreduce(&who, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == INT_MAX) return 0;
  if (rank == first && err && len) snprintf(msg, sizeof msg, "%s", err);
  MPI_Bcast(msg, (int)sizeof msg, MPI_CHAR, first, comm);
  if (err && len) snprintf(err, len, "%s", msg);
  return 3;
}

/* Global count, this rank's offset (MPI_Exscan) and the common number of write calls. */
static void make_layout(const struct parts *p, MPI_Comm comm, struct layout *L) {
  long long n = p->n_owned, before = 0, total = 0;
  long calls;
  int rank;
  MPI_Comm_rank(comm, &rank);
  MPI_Exscan(&n, &before, 1, MPI_LONG_LONG, MPI_SUM, comm);
  if (rank == 0) before = 0; /* MPI_Exscan leaves rank 0's result undefined */
  MPI_Allreduce(&n, &total, 1, MPI_LONG_LONG, MPI_SUM, comm);
  L->total = (hsize_t)total;
  L->offset = (hsize_t)before;
  L->n = (hsize_t)n;
  L->per_call = MPSPH_IO_MAX_BYTES / ((size_t)p->dim * sizeof(double));
  if (L->per_call == 0) L->per_call = 1;
  calls = (long)((L->n + L->per_call - 1) / L->per_call);
  MPI_Allreduce(&calls, &L->calls, 1, MPI_LONG, MPI_MAX, comm);
}

/* Create (truncate) path for collective MPI-IO access by every rank of comm; 0 or 3. */
static int create_file(const char *path, MPI_Comm comm, hid_t *file, char *err, size_t len) {
  hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  *file = H5I_INVALID_HID;
  if (fapl >= 0 && H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL) >= 0 &&
      H5Pset_coll_metadata_write(fapl, 1) >= 0) /* metadata too goes out collectively */
    *file = H5Fcreate(path, H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  int st = *file < 0 ? fail(err, len, "cannot create %s", path) : 0;
  H5Pclose(fapl);
  return st;
}

/* Write one scalar attribute (same value on every rank); 0 or 3. */
static int put_attr(hid_t loc, const char *name, hid_t file_type, hid_t mem_type, const void *value,
                    char *err, size_t len) {
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t attr = H5Acreate2(loc, name, file_type, space, H5P_DEFAULT, H5P_DEFAULT);
  int st = (attr < 0 || H5Awrite(attr, mem_type, value) < 0)
               ? fail(err, len, "cannot write attribute /header/%s", name) : 0;
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  return st;
}

/* Write a UTF-8 variable-length string attribute: its text lives in the global heap, so it has
 * no 64 kB attribute-size limit, and h5py reads it as str. NULL is written as "". */
static int put_string_attr(hid_t loc, const char *name, const char *value, char *err, size_t len) {
  const char *text = value ? value : "";
  hid_t type = H5Tcopy(H5T_C_S1);
  int st = (H5Tset_size(type, H5T_VARIABLE) < 0 || H5Tset_cset(type, H5T_CSET_UTF8) < 0)
               ? fail(err, len, "cannot make string type for /header/%s", name)
               : put_attr(loc, name, type, type, &text, err, len);
  H5Tclose(type);
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

/* Rows [first, first + rows) of f, row-major: scalars in place, vectors packed into buf. */
static const void *rows_of(const struct field *f, hsize_t first, hsize_t rows, double *buf) {
  if (f->ncomp == 1) return rows ? (const char *)f->comp[0] + first * f->size : (const void *)buf;
  for (hsize_t i = 0; i < rows; i++)
    for (int k = 0; k < f->ncomp; k++)
      buf[i * (hsize_t)f->ncomp + k] = ((const double *)f->comp[k])[first + i];
  return buf;
}

/* Collective call number `call` for dataset dset: this rank's next slice, or nothing; 0 or 3. */
static int write_call(hid_t dset, const struct field *f, const struct layout *L, long call,
                      hid_t dxpl, double *buf, char *err, size_t len) {
  hsize_t first = (hsize_t)call * L->per_call;
  hsize_t rows = first < L->n ? L->n - first : 0;
  if (rows > L->per_call) rows = L->per_call;
  hsize_t start[2] = {L->offset + first, 0}, count[2] = {rows, (hsize_t)f->ncomp};
  hid_t fspace = H5Dget_space(dset);
  hid_t mspace = H5Screate_simple(f->ncomp > 1 ? 2 : 1, count, NULL);
  herr_t st = rows ? H5Sselect_hyperslab(fspace, H5S_SELECT_SET, start, NULL, count, NULL)
                   : H5Sselect_none(fspace);
  if (fspace < 0 || mspace < 0 || st < 0) st = -1;
  else st = H5Dwrite(dset, f->mem_type, mspace, fspace, dxpl, rows_of(f, first, rows, buf));
  int status = st < 0 ? fail(err, len, "cannot write /particles/%s", f->name) : 0;
  H5Sclose(mspace);
  H5Sclose(fspace);
  return status;
}

/* Create /particles/<f->name> with global size and write every rank's rows collectively.
 * A local write failure does not stop the loop, so every rank makes the same calls. */
static int write_field(hid_t group, const struct field *f, const struct layout *L, hid_t dxpl,
                       double *buf, MPI_Comm comm, char *err, size_t len) {
  hsize_t dims[2] = {L->total, (hsize_t)f->ncomp};
  hid_t space = H5Screate_simple(f->ncomp > 1 ? 2 : 1, dims, NULL);
  hid_t dset = H5Dcreate2(group, f->name, f->file_type, space, H5P_DEFAULT, H5P_DEFAULT,
                          H5P_DEFAULT);
  int st = agree(dset < 0 ? fail(err, len, "cannot create /particles/%s", f->name) : 0, comm,
                 err, len);
  long calls = st ? 0 : L->calls;
  for (long c = 0; c < calls; c++) st |= write_call(dset, f, L, c, dxpl, buf, err, len);
  if (dset >= 0 && H5Dclose(dset) < 0 && !st) st = fail(err, len, "cannot close %s", f->name);
  H5Sclose(space);
  return agree(st, comm, err, len);
}

/* Create /particles and write every contracted field; 0 or 3 (same on every rank). */
static int write_particles(hid_t file, const struct parts *p, const struct layout *L,
                           MPI_Comm comm, char *err, size_t len) {
  const struct field fields[] = {
      {"position", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, sizeof(double), p->dim,
       {p->x[0], p->x[1], p->x[2]}},
      {"velocity", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, sizeof(double), p->dim,
       {p->v[0], p->v[1], p->v[2]}},
      {"density", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, sizeof(double), 1, {p->rho}},
      {"pressure", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, sizeof(double), 1, {p->p}},
      {"mass", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, sizeof(double), 1, {p->m}},
      {"phase", H5T_STD_I32LE, H5T_NATIVE_INT, sizeof(int), 1, {p->phase}},
      {"id", H5T_STD_I64LE, H5T_NATIVE_INT64, sizeof(int64_t), 1, {p->id}},
  };
  hsize_t rows = L->n < L->per_call ? L->n : L->per_call;
  double *buf = malloc((rows ? rows : 1) * (size_t)p->dim * sizeof(double));
  hid_t g = H5Gcreate2(file, "particles", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  hid_t dxpl = H5Pcreate(H5P_DATASET_XFER);
  int st = (!buf || g < 0 || dxpl < 0 || H5Pset_dxpl_mpio(dxpl, H5FD_MPIO_COLLECTIVE) < 0)
               ? fail(err, len, "cannot prepare /particles for writing") : 0;
  st = agree(st, comm, err, len);
  for (size_t k = 0; k < sizeof fields / sizeof fields[0] && !st; k++)
    st = write_field(g, &fields[k], L, dxpl, buf, comm, err, len);
  if (dxpl >= 0) H5Pclose(dxpl);
  if (g >= 0) H5Gclose(g);
  free(buf);
  return st;
}

/* Write the whole snapshot into tmp; 0 or 3, the same on every rank. */
static int write_file(const char *tmp, const struct snapshot_info *info, const struct parts *p,
                      MPI_Comm comm, char *err, size_t len) {
  struct layout L;
  make_layout(p, comm, &L);
  hid_t file;
  int st = agree(create_file(tmp, comm, &file, err, len), comm, err, len);
  if (st) return st;
  st = agree(write_header(file, info, L.total, err, len), comm, err, len);
  if (!st) st = write_particles(file, p, &L, comm, err, len);
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

/* Collective snapshot of the owned particles to path (via path.tmp); 0, or 3 with err set. */
int hdf5_write_snapshot(const char *path, const struct snapshot_info *info,
                        const struct parts *p, MPI_Comm comm, char *err, size_t err_len) {
  H5E_auto2_t old_func;
  void *old_data;
  size_t n = strlen(path) + sizeof ".tmp";
  char *tmp = malloc(n);
  int st;
  if (err && err_len) err[0] = '\0';
  H5Eget_auto2(H5E_DEFAULT, &old_func, &old_data);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  if (!tmp) st = fail(err, err_len, "out of memory for %s", path);
  else if (p->dim < 1 || p->dim > 3 || p->dim != info->dimension)
    st = fail(err, err_len, "%s: particles have dimension %d, header %d", path, p->dim,
              info->dimension);
  else st = 0;
  st = agree(st, comm, err, err_len);
  if (!st) {
    snprintf(tmp, n, "%s.tmp", path);
    st = publish(tmp, path, write_file(tmp, info, p, comm, err, err_len), comm, err, err_len);
  }
  H5Eset_auto2(H5E_DEFAULT, old_func, old_data);
  free(tmp);
  return st;
}
