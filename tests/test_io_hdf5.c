/* test_io_hdf5.c — collective snapshots written by every rank (one rank owns nothing), read back
 * on rank 0 with the serial HDF5 API and checked value by value; safe replacement; XDMF index;
 * checkpoints written and read back collectively (a block of rows per rank), also empty ones.
 * Usage: mpirun -n 1|2|3 test_io_hdf5 [KEEPDIR]   (with KEEPDIR the output folders are kept:
 * KEEPDIR (2D, two snapshots), KEEPDIR/3d and KEEPDIR/empty, each with snapshots.xdmf). */
#include "check.h"
#include "io/io_hdf5.h"

#include <hdf5.h>
#include <mpi.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define HALO 2                              /* junk halo particles that must not be written */
static const char *const SUBDIRS[] = {"", "/3d", "/empty"};
static const char *const VERSION = "test-1.0";

/* Owned particles of `rank`: none on rank 1 (or everywhere when empty), else 3 + 2 rank. */
static long count_of(int rank, int empty) { return (empty || rank == 1) ? 0 : 3 + 2 * rank; }

/* Owned particles of ranks [0, nranks). */
static long count_below(int nranks, int empty) {
  long n = 0;
  for (int r = 0; r < nranks; r++) n += count_of(r, empty);
  return n;
}

/* Expected component k of double field `what` (x v r p m) for global row g of snapshot salt. */
static double value(char what, int k, long g, int salt) {
  switch (what) {
  case 'x': return 0.1 * (k == 0 ? g % 4 : k == 1 ? g / 4 : g % 3) + 0.01 * salt;
  case 'v': return (k % 2 ? -1.0 : 1.0) * (g + 0.5 * salt) + k;
  case 'r': return 1000.0 + g + salt;
  case 'p': return 10.0 * g - 5.0 + salt;
  default: return 0.5 + g + 0.01 * salt;
  }
}
static int phase_of(long g) { return (int)(g % 3) - 1; }                    /* -1 = wall */
static int64_t id_of(long g) { return INT64_C(5000000000) + 7 * (1000 - g); } /* > 2^32 */

static void *alloc(long n, size_t size) { return n ? calloc((size_t)n, size) : NULL; }

/* Fill this rank's particles by hand: owned rows then HALO junk rows (NULL arrays when empty). */
static void fill_parts(struct parts *p, int dim, int salt, int empty, MPI_Comm comm) {
  int rank;
  MPI_Comm_rank(comm, &rank);
  long n = count_of(rank, empty), first = count_below(rank, empty);
  long cap = n + (empty ? 0 : HALO);
  memset(p, 0, sizeof *p);
  p->dim = dim, p->n_owned = n, p->n_halo = cap - n, p->capacity = cap;
  for (int k = 0; k < dim; k++) p->x[k] = alloc(cap, sizeof(double));
  for (int k = 0; k < dim; k++) p->v[k] = alloc(cap, sizeof(double));
  p->rho = alloc(cap, sizeof(double)), p->p = alloc(cap, sizeof(double));
  p->m = alloc(cap, sizeof(double)), p->phase = alloc(cap, sizeof(int));
  p->id = alloc(cap, sizeof(int64_t));
  for (long i = 0; i < cap; i++) {
    long g = i < n ? first + i : -99; /* halo rows get values no owned row has */
    for (int k = 0; k < dim; k++) p->x[k][i] = value('x', k, g, salt);
    for (int k = 0; k < dim; k++) p->v[k][i] = value('v', k, g, salt);
    p->rho[i] = value('r', 0, g, salt), p->p[i] = value('p', 0, g, salt);
    p->m[i] = value('m', 0, g, salt), p->phase[i] = phase_of(g), p->id[i] = id_of(g);
  }
}

static void free_parts(struct parts *p) {
  for (int k = 0; k < 3; k++) free(p->x[k]), free(p->v[k]);
  free(p->rho), free(p->p), free(p->m), free(p->phase), free(p->id);
}

/* Collectively write snapshot `salt` of every rank's particles to path; returns the status. */
static int write_snap(const char *path, int dim, int salt, int empty, const char *yaml,
                      char *err, size_t len) {
  struct parts p;
  struct snapshot_info info = {.time = 0.25 * salt, .step = 10L * salt, .dimension = dim,
                               .case_yaml = yaml, .code_version = VERSION};
  fill_parts(&p, dim, salt, empty, MPI_COMM_WORLD);
  int st = hdf5_write_snapshot(path, &info, &p, MPI_COMM_WORLD, err, len);
  free_parts(&p);
  return st;
}

/* A case_yaml of about 100 kB (beyond the 64 kB compact attribute limit), with UTF-8. */
static char *make_yaml(void) {
  size_t cap = 120000, used = 0;
  char *s = malloc(cap);
  used += (size_t)snprintf(s, cap, "name: water–air tank\n");
  for (int i = 0; used + 64 < cap && i < 5000; i++)
    used += (size_t)snprintf(s + used, cap - used, "key_%05d: {value: %d, note: ok}\n", i, i);
  return s;
}

/* Read dataset /particles/name as mem_type after checking class, element size and shape. */
static void *read_field(hid_t f, const char *name, hid_t mem_type, H5T_class_t cls, size_t size,
                        long n, int ncomp) {
  char full[64];
  snprintf(full, sizeof full, "/particles/%s", name);
  hid_t d = H5Dopen2(f, full, H5P_DEFAULT);
  CHECK(d >= 0, "open %s", full);
  if (d < 0) return NULL;
  hid_t type = H5Dget_type(d), space = H5Dget_space(d);
  hsize_t dims[2] = {0, 0};
  int rank = H5Sget_simple_extent_dims(space, dims, NULL);
  CHECK(H5Tget_class(type) == cls && H5Tget_size(type) == size, "%s: type", full);
  CHECK(rank == (ncomp > 1 ? 2 : 1) && dims[0] == (hsize_t)n &&
            (ncomp == 1 || dims[1] == (hsize_t)ncomp),
        "%s: shape rank %d dims %llu x %llu, want %ld x %d", full, rank,
        (unsigned long long)dims[0], (unsigned long long)dims[1], n, ncomp);
  void *buf = malloc((size_t)(n ? n : 1) * (size_t)ncomp * size);
  CHECK(H5Dread(d, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf) >= 0, "%s: read", full);
  H5Tclose(type), H5Sclose(space), H5Dclose(d);
  return buf;
}

/* Check every value of every /particles dataset against the formulas. */
static void check_particles(hid_t f, int dim, long n, int salt) {
  static const struct { const char *name; char what; int vector; } doubles[] = {
      {"position", 'x', 1}, {"velocity", 'v', 1}, {"density", 'r', 0},
      {"pressure", 'p', 0}, {"mass", 'm', 0}};
  for (size_t j = 0; j < sizeof doubles / sizeof doubles[0]; j++) {
    int nc = doubles[j].vector ? dim : 1;
    double *a = read_field(f, doubles[j].name, H5T_NATIVE_DOUBLE, H5T_FLOAT, 8, n, nc);
    long bad = 0;
    for (long g = 0; a && g < n; g++)
      for (int k = 0; k < nc; k++) bad += a[g * nc + k] != value(doubles[j].what, k, g, salt);
    CHECK(a && bad == 0, "%s: %ld wrong values", doubles[j].name, bad);
    free(a);
  }
  int *phase = read_field(f, "phase", H5T_NATIVE_INT, H5T_INTEGER, 4, n, 1);
  int64_t *id = read_field(f, "id", H5T_NATIVE_INT64, H5T_INTEGER, 8, n, 1);
  long bad = 0;
  for (long g = 0; phase && id && g < n; g++) bad += phase[g] != phase_of(g) || id[g] != id_of(g);
  CHECK(phase && id && bad == 0, "phase/id: %ld wrong values", bad);
  free(phase), free(id);
}

/* Read a numeric /header attribute as mem_type; returns the HDF5 status. */
static herr_t read_attr(hid_t g, const char *name, hid_t mem_type, void *out) {
  hid_t a = H5Aopen(g, name, H5P_DEFAULT);
  herr_t st = a < 0 ? -1 : H5Aread(a, mem_type, out);
  if (a >= 0) H5Aclose(a);
  return st;
}

/* Check that string attribute `name` is a variable-length UTF-8 string equal to want. */
static void check_string_attr(hid_t g, const char *name, const char *want) {
  hid_t a = H5Aopen(g, name, H5P_DEFAULT), type = H5Aget_type(a);
  char *s = NULL;
  CHECK(H5Tis_variable_str(type) > 0 && H5Tget_cset(type) == H5T_CSET_UTF8, "%s: vlen utf8", name);
  CHECK(H5Aread(a, type, &s) >= 0 && s && strcmp(s, want) == 0, "%s: value differs", name);
  H5free_memory(s), H5Tclose(type), H5Aclose(a);
}

/* Check the /header attributes of snapshot salt. */
static void check_header(hid_t f, int dim, long n, int salt, const char *yaml) {
  hid_t g = H5Gopen2(f, "/header", H5P_DEFAULT);
  double time = -1;
  int64_t step = -1, np = -1;
  int d = -1;
  CHECK(read_attr(g, "time", H5T_NATIVE_DOUBLE, &time) >= 0 && time == 0.25 * salt, "time %g",
        time);
  CHECK(read_attr(g, "step", H5T_NATIVE_INT64, &step) >= 0 && step == 10 * salt, "step");
  CHECK(read_attr(g, "dimension", H5T_NATIVE_INT, &d) >= 0 && d == dim, "dimension %d", d);
  CHECK(read_attr(g, "n_particles", H5T_NATIVE_INT64, &np) >= 0 && np == n, "n_particles");
  check_string_attr(g, "code_version", VERSION);
  check_string_attr(g, "case_yaml", yaml);
  H5Gclose(g);
}

/* Rank 0: open path serially and check it holds snapshot salt of all nranks ranks. */
static void check_file(const char *path, int dim, int nranks, int salt, int empty,
                       const char *yaml) {
  long n = count_below(nranks, empty);
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  CHECK(f >= 0, "open %s", path);
  if (f < 0) return;
  check_header(f, dim, n, salt, yaml);
  check_particles(f, dim, n, salt);
  H5Fclose(f);
}

/* Rank 0: snapshots.xdmf is in place, its temporary is gone, and it names the last snapshot. */
static void check_xdmf(const char *dir, int nsnap) {
  char path[4200], text[65536] = "", want[64];
  snprintf(path, sizeof path, "%s/snapshots.xdmf.tmp", dir);
  CHECK(access(path, F_OK) != 0, "%s left behind", path);
  snprintf(path, sizeof path, "%s/snapshots.xdmf", dir);
  FILE *f = fopen(path, "r");
  CHECK(f != NULL, "open %s", path);
  if (f) text[fread(text, 1, sizeof text - 1, f)] = '\0', fclose(f);
  snprintf(want, sizeof want, "snap_%05d.h5:/particles/velocity", nsnap - 1);
  CHECK(strstr(text, "CollectionType=\"Temporal\"") && strstr(text, want), "%s content", path);
}

/* Write nsnap snapshots (snapshot i with salt i) in dir; rank 0 reads each back and checks it. */
static void test_folder(const char *dir, int dim, int empty, int nsnap, const char *yaml,
                        int nranks) {
  char path[4200], err[512];
  int rank;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  for (int s = 0; s < nsnap; s++) {
    snprintf(path, sizeof path, "%s/snap_%05d.h5", dir, s);
    int st = write_snap(path, dim, s, empty, yaml, err, sizeof err);
    CHECK(st == 0, "write %s: %s", path, err);
    if (rank == 0) check_file(path, dim, nranks, s, empty, yaml);
  }
}

/* A write whose path.tmp cannot be created must fail on every rank and leave the good file at
 * path untouched; once possible, a rewrite replaces it completely and leaves no .tmp. */
static void test_replace(const char *path, int dim, int old_salt, const char *yaml, int nranks) {
  char tmp[4300], err[512] = "";
  int rank;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  snprintf(tmp, sizeof tmp, "%s.tmp", path);
  if (rank == 0) CHECK(mkdir(tmp, 0700) == 0, "mkdir %s", tmp);
  MPI_Barrier(MPI_COMM_WORLD);
  int st = write_snap(path, dim, old_salt + 1, 0, yaml, err, sizeof err);
  CHECK(st == 3 && err[0], "blocked write returned %d", st);
  if (rank == 0) printf("expected failure: %s\n", err);
  if (rank == 0) check_file(path, dim, nranks, old_salt, 0, yaml);
  if (rank == 0) rmdir(tmp);
  MPI_Barrier(MPI_COMM_WORLD);
  st = write_snap(path, dim, old_salt + 1, 0, yaml, err, sizeof err);
  CHECK(st == 0, "rewrite %s: %s", path, err);
  if (rank == 0) check_file(path, dim, nranks, old_salt + 1, 0, yaml);
  if (rank == 0) CHECK(access(tmp, F_OK) != 0, "%s left behind", tmp);
}

/* Expected mirror component k and wall index of global row g (walls: phase -1). */
static double mirror_of(int k, long g) { return -0.5 * g - k; }
static int wall_of(long g) { return phase_of(g) == -1 ? (int)(g % 5) : -1; }

/* Write a checkpoint of snapshot salt with ghost geometry, run numbers and a snapshot series;
 * read it back on every rank and check this rank's block of rows and the run state. */
static void test_checkpoint(const char *path, int salt, int empty, const char *yaml) {
  char err[512] = "";
  int rank, size;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  struct parts p;
  fill_parts(&p, 2, salt, empty, MPI_COMM_WORLD);
  long first = count_below(rank, empty), total = count_below(size, empty);
  p.wall = calloc(p.capacity + 1, sizeof(int));   /* non-NULL: the particles have walls */
  for (int k = 0; k < 2; k++) p.mirror[k] = calloc(p.capacity + 1, sizeof(double));
  for (long i = 0; i < p.n_owned; i++) {
    p.wall[i] = wall_of(first + i);
    for (int k = 0; k < 2; k++) p.mirror[k][i] = mirror_of(k, first + i);
  }
  double dt = 1e-4 * salt, times[3] = {0, 0.5, 1.5}, dt_read = -1;
  long steps = 7, steps_read = -1, counts[3] = {total, total, total};
  struct hdf5_number numbers[] = {{"dt", &dt, NULL}, {"steps", NULL, &steps}};
  struct checkpoint_extra x = {2, numbers, 0, NULL, empty ? 0 : 3, times, counts};
  struct snapshot_info info = {.time = 0.25 * salt, .step = 10L * salt, .dimension = 2,
                               .case_yaml = yaml, .code_version = VERSION};
  CHECK(hdf5_write_checkpoint(path, &info, &p, &x, MPI_COMM_WORLD, err, sizeof err) == 0,
        "write checkpoint %s: %s", path, err);
  free_parts(&p);
  free(p.wall), free(p.mirror[0]), free(p.mirror[1]);

  struct snapshot_info got;
  CHECK(hdf5_read_header(path, &got, MPI_COMM_WORLD, err, sizeof err) == 0 && got.step == 10L * salt &&
            got.n_particles == total && strcmp(got.case_yaml, yaml) == 0, "read header: %s", err);
  hdf5_info_free(&got);
  struct hdf5_number back[] = {{"dt", &dt_read, NULL}, {"steps", NULL, &steps_read}};
  struct checkpoint_extra y = {2, back, 0, NULL, 0, NULL, NULL};
  parts_init(&p, 2, 1, 1);
  CHECK(hdf5_read_run(path, &y, MPI_COMM_WORLD, err, sizeof err) == 0 &&
            hdf5_read_particles(path, &p, MPI_COMM_WORLD, err, sizeof err) == 0,
        "read %s: %s", path, err);
  long lo = total * rank / size, bad = 0;
  CHECK(p.n_owned == total * (rank + 1) / size - lo, "rank %d: %ld rows", rank, p.n_owned);
  for (long i = 0; i < p.n_owned; i++) {
    long g = lo + i;
    for (int k = 0; k < 2; k++)
      bad += p.x[k][i] != value('x', k, g, salt) || p.v[k][i] != value('v', k, g, salt) ||
             p.mirror[k][i] != mirror_of(k, g);
    bad += p.rho[i] != value('r', 0, g, salt) || p.p[i] != value('p', 0, g, salt) ||
           p.m[i] != value('m', 0, g, salt) || p.phase[i] != phase_of(g) || p.id[i] != id_of(g) ||
           p.wall[i] != wall_of(g);
  }
  CHECK(bad == 0, "checkpoint rows: %ld wrong values", bad);
  CHECK(dt_read == dt && steps_read == steps && y.n_snapshots == x.n_snapshots &&
            (empty || (y.snapshot_times[2] == 1.5 && y.snapshot_counts[1] == total)),
        "run state: dt %g steps %ld, %d snapshots", dt_read, steps_read, y.n_snapshots);
  free(y.snapshot_times), free(y.snapshot_counts);
  parts_free(&p);
}

/* A snapshot is not a checkpoint: reading it as one fails on every rank with a reason. */
static void test_not_checkpoint(const char *path) {
  char err[512] = "";
  double dt;
  struct hdf5_number numbers[] = {{"dt", &dt, NULL}};
  struct checkpoint_extra y = {1, numbers, 0, NULL, 0, NULL, NULL};
  CHECK(hdf5_read_run(path, &y, MPI_COMM_WORLD, err, sizeof err) == 3 &&
            strstr(err, "not a checkpoint"), "snapshot read as a checkpoint: '%s'", err);
}

/* Rank 0: write dir/snapshots.xdmf for the snapshots with the given salts, and check it. */
static void write_xdmf(const char *dir, int dim, int empty, int nsnap, const int *salts,
                       int nranks) {
  double times[4];
  long counts[4];
  char err[512];
  for (int s = 0; s < nsnap; s++)
    times[s] = 0.25 * salts[s], counts[s] = count_below(nranks, empty);
  CHECK(xdmf_write_series(dir, nsnap, times, counts, dim, err, sizeof err) == 0, "xdmf: %s", err);
  check_xdmf(dir, nsnap);
}

/* Rank 0: an XDMF index that cannot be written gives 3 and a message naming the folder. */
static void test_xdmf_error(const char *dir) {
  char missing[4200], err[512] = "";
  double time = 0;
  long count = 1;
  snprintf(missing, sizeof missing, "%s/no/such/folder", dir);
  CHECK(xdmf_write_series(missing, 1, &time, &count, 2, err, sizeof err) == 3 &&
            strstr(err, missing), "xdmf into a missing folder: '%s'", err);
}

/* Rank 0 makes the output folders (KEEPDIR or a fresh temporary one) and tells the others. */
static void make_dirs(int argc, char **argv, char *dir, size_t len) {
  int rank;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) {
    snprintf(dir, len, "%s", argc > 1 ? argv[1] : "/tmp/test_io_hdf5_XXXXXX");
    CHECK(argc > 1 ? (mkdir(dir, 0755) == 0 || access(dir, W_OK) == 0) : mkdtemp(dir) != NULL,
          "cannot make %s", dir);
    for (size_t i = 1; i < sizeof SUBDIRS / sizeof SUBDIRS[0]; i++) {
      char sub[4200];
      snprintf(sub, sizeof sub, "%s%s", dir, SUBDIRS[i]);
      mkdir(sub, 0755);
    }
  }
  MPI_Bcast(dir, (int)len, MPI_CHAR, 0, MPI_COMM_WORLD);
}

/* Rank 0: remove everything the test wrote (when no KEEPDIR was given). */
static void remove_dirs(const char *dir) {
  static const char *const files[] = {"snap_00000.h5", "snap_00001.h5", "snapshots.xdmf",
                                      "checkpoint.h5"};
  char path[4300];
  for (int i = (int)(sizeof SUBDIRS / sizeof SUBDIRS[0]) - 1; i >= 0; i--) {
    for (size_t j = 0; j < sizeof files / sizeof files[0]; j++) {
      snprintf(path, sizeof path, "%s%s/%s", dir, SUBDIRS[i], files[j]);
      unlink(path);
    }
    snprintf(path, sizeof path, "%s%s", dir, SUBDIRS[i]);
    rmdir(path);
  }
}

int main(int argc, char **argv) {
  int rank, nranks, failures;
  char dir[4096], sub[4200];
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &nranks);
  make_dirs(argc, argv, dir, sizeof dir);
  char *yaml = make_yaml();
  const int salts_2d[] = {0, 2}, salt0[] = {0};

  test_folder(dir, 2, 0, 2, yaml, nranks);
  snprintf(sub, sizeof sub, "%s/snap_00001.h5", dir);
  test_replace(sub, 2, 1, yaml, nranks);
  if (rank == 0) write_xdmf(dir, 2, 0, 2, salts_2d, nranks);
  snprintf(sub, sizeof sub, "%s/3d", dir);
  test_folder(sub, 3, 0, 1, yaml, nranks);
  if (rank == 0) write_xdmf(sub, 3, 0, 1, salt0, nranks);
  snprintf(sub, sizeof sub, "%s/empty", dir);
  test_folder(sub, 2, 1, 1, yaml, nranks);
  if (rank == 0) write_xdmf(sub, 2, 1, 1, salt0, nranks);
  if (rank == 0) test_xdmf_error(dir);
  snprintf(sub, sizeof sub, "%s/checkpoint.h5", dir);
  test_checkpoint(sub, 3, 0, yaml);
  snprintf(sub, sizeof sub, "%s/empty/checkpoint.h5", dir);
  test_checkpoint(sub, 1, 1, yaml);
  snprintf(sub, sizeof sub, "%s/snap_00000.h5", dir);
  test_not_checkpoint(sub);

  MPI_Barrier(MPI_COMM_WORLD);
  if (rank == 0 && argc < 2) remove_dirs(dir);
  free(yaml);
  MPI_Allreduce(&check_failures, &failures, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  int rc = failures != 0;
  if (rank == 0) check_failures = failures, rc = check_report("test_io_hdf5");
  MPI_Finalize();
  return rc;
}
