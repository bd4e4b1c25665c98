/* io_xdmf.c — snapshots.xdmf: an XDMF 3 temporal collection of the snap_NNNNN.h5 files, for
 * ParaView and VisIt. Paths inside are relative to the output folder, so the folder can move. */
#include "io/io_hdf5.h"
#include "io/outdir.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Number type and precision of each /particles dataset as XDMF spells them. */
#define XDMF_DOUBLE "NumberType=\"Float\" Precision=\"8\""
#define XDMF_INT32 "NumberType=\"Int\" Precision=\"4\""
#define XDMF_INT64 "NumberType=\"Int\" Precision=\"8\""

/* A <DataItem> reading dataset /particles/<name> of snap with the given dimensions. */
static void hdf_item(FILE *f, const char *indent, const char *dims, const char *type,
                     const char *snap, const char *name) {
  fprintf(f, "%s<DataItem Dimensions=\"%s\" %s Format=\"HDF\">%s:/particles/%s</DataItem>\n",
          indent, dims, type, snap, name);
}

/* A node-centred attribute (Scalar or Vector) read straight from /particles/<name>.
 * 2D velocity is an N x 2 Vector read as it is. Checked with ParaView 5.11: its "XDMF Reader"
 * pads it to 3 components (z = 0), so glyphs and magnitude work; its "Xdmf3 Reader" gives a
 * 2-component array with the right values. The alternative, a JOIN Function of HyperSlabs
 * with a zero z column, works in the XDMF Reader only: the Xdmf3 readers skip Function and
 * HyperSlab items altogether (the array is missing), so plain datasets it is. */
static void attribute(FILE *f, const char *snap, const char *name, const char *kind,
                      const char *dims, const char *type) {
  fprintf(f, "        <Attribute Name=\"%s\" AttributeType=\"%s\" Center=\"Node\">\n", name, kind);
  hdf_item(f, "          ", dims, type, snap, name);
  fprintf(f, "        </Attribute>\n");
}

/* One Uniform grid for snapshot `index` at `time` with n particles. The Polyvertex topology
 * has no connectivity array: ParaView's "XDMF Reader" makes one vertex cell per particle (shown
 * by the default Surface representation); its Xdmf3 readers load the points and arrays but no
 * cells, so there the particles show with the "Point Gaussian" representation. */
static void grid(FILE *f, int index, double time, long n, int dim) {
  char snap[32], dims[48], count[32];
  snprintf(snap, sizeof snap, OUTDIR_SNAPSHOT_NAME, index);
  snprintf(dims, sizeof dims, "%ld %d", n, dim);
  snprintf(count, sizeof count, "%ld", n);
  fprintf(f, "      <Grid Name=\"snap_%05d\" GridType=\"Uniform\">\n", index);
  fprintf(f, "        <Time Value=\"%.17g\"/>\n", time);
  fprintf(f, "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"%ld\" "
             "NodesPerElement=\"1\"/>\n", n);
  fprintf(f, "        <Geometry GeometryType=\"%s\">\n", dim == 3 ? "XYZ" : "XY");
  hdf_item(f, "          ", dims, XDMF_DOUBLE, snap, "position");
  fprintf(f, "        </Geometry>\n");
  attribute(f, snap, "pressure", "Scalar", count, XDMF_DOUBLE);
  attribute(f, snap, "density", "Scalar", count, XDMF_DOUBLE);
  attribute(f, snap, "mass", "Scalar", count, XDMF_DOUBLE);
  attribute(f, snap, "phase", "Scalar", count, XDMF_INT32);
  attribute(f, snap, "id", "Scalar", count, XDMF_INT64);
  attribute(f, snap, "velocity", "Vector", dims, XDMF_DOUBLE);
  fprintf(f, "      </Grid>\n");
}

/* The whole document for n snapshots. */
static void document(FILE *f, int n, const double *times, const long *counts, int dim) {
  fprintf(f, "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
             "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
             "  <Domain>\n"
             "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n");
  for (int i = 0; i < n; i++) grid(f, i, times[i], counts[i], dim);
  fprintf(f, "    </Grid>\n  </Domain>\n</Xdmf>\n");
}

/* Write the document to path; 0 or the errno of the failure. */
static int write_text(const char *path, int n, const double *times, const long *counts, int dim) {
  FILE *f = fopen(path, "w");
  if (!f) return errno;
  document(f, n, times, counts, dim);
  int e = ferror(f) ? (errno ? errno : EIO) : 0;
  if (fclose(f) != 0 && !e) e = errno;
  return e;
}

/* Rank 0: write dir/snapshots.xdmf (via a .tmp and rename) for snapshots 0..n-1; 0 or 3. */
int xdmf_write_series(const char *dir, int n_snapshots, const double *times,
                      const long *n_particles, int dimension, char *err, size_t err_len) {
  char *tmp = outdir_path(dir, "snapshots.xdmf.tmp"), *path = outdir_path(dir, "snapshots.xdmf");
  int e = write_text(tmp, n_snapshots, times, n_particles, dimension);
  if (!e && rename(tmp, path) != 0) e = errno;
  if (e) unlink(tmp);
  if (e && err && err_len)
    snprintf(err, err_len, "cannot write %s/snapshots.xdmf: %s", dir, strerror(e));
  free(tmp);
  free(path);
  return e ? 3 : 0;
}
