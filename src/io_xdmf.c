/* io_xdmf.c — snapshots.xdmf: an XDMF 3 temporal collection of the snap_NNNNN.h5 files, for
 * ParaView and VisIt. Paths inside are relative to the output folder, so the folder can move. */
#include "io_hdf5.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

/* A node-centred scalar attribute read straight from /particles/<name>. */
static void scalar(FILE *f, const char *snap, long n, const char *name, const char *type) {
  char dims[32];
  snprintf(dims, sizeof dims, "%ld", n);
  fprintf(f, "        <Attribute Name=\"%s\" AttributeType=\"Scalar\" Center=\"Node\">\n", name);
  hdf_item(f, "          ", dims, type, snap, name);
  fprintf(f, "        </Attribute>\n");
}

/* Velocity as a 3-component Vector attribute. In 3D the dataset is read as it is. In 2D the
 * N x 2 dataset cannot be declared a Vector: ParaView's Xdmf3 reader always reads a Vector as
 * 3 components per tuple, so N x 2 data comes out as 2N/3 scrambled tuples. Instead a JOIN
 * Function interleaves the two columns (HyperSlabs of the dataset) with a zero z column,
 * giving an N x 3 vector that ParaView can colour by, take the magnitude of and use for glyphs. */
static void velocity(FILE *f, const char *snap, long n, int dim) {
  char dims[48], col[48];
  snprintf(dims, sizeof dims, "%ld %d", n, dim);
  fprintf(f, "        <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n");
  if (dim == 3) {
    hdf_item(f, "          ", dims, XDMF_DOUBLE, snap, "velocity");
  } else {
    snprintf(col, sizeof col, "%ld 1", n);
    fprintf(f, "          <DataItem ItemType=\"Function\" Function=\"JOIN($0, $1, 0 * $0)\" "
               "Dimensions=\"%ld 3\">\n", n);
    for (int k = 0; k < 2; k++) {
      fprintf(f, "            <DataItem ItemType=\"HyperSlab\" Dimensions=\"%s\" Type=\"HyperSlab\">\n"
                 "              <DataItem Dimensions=\"3 2\" Format=\"XML\">0 %d 1 1 %s</DataItem>\n",
              col, k, col);
      hdf_item(f, "              ", dims, XDMF_DOUBLE, snap, "velocity");
      fprintf(f, "            </DataItem>\n");
    }
    fprintf(f, "          </DataItem>\n");
  }
  fprintf(f, "        </Attribute>\n");
}

/* One Uniform Polyvertex grid for snapshot `index` at `time` with n particles. */
static void grid(FILE *f, int index, double time, long n, int dim) {
  char snap[32], dims[48];
  snprintf(snap, sizeof snap, "snap_%05d.h5", index);
  snprintf(dims, sizeof dims, "%ld %d", n, dim);
  fprintf(f, "      <Grid Name=\"snap_%05d\" GridType=\"Uniform\">\n", index);
  fprintf(f, "        <Time Value=\"%.17g\"/>\n", time);
  fprintf(f, "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"%ld\" "
             "NodesPerElement=\"1\"/>\n", n);
  fprintf(f, "        <Geometry GeometryType=\"%s\">\n", dim == 3 ? "XYZ" : "XY");
  hdf_item(f, "          ", dims, XDMF_DOUBLE, snap, "position");
  fprintf(f, "        </Geometry>\n");
  scalar(f, snap, n, "pressure", XDMF_DOUBLE);
  scalar(f, snap, n, "density", XDMF_DOUBLE);
  scalar(f, snap, n, "mass", XDMF_DOUBLE);
  scalar(f, snap, n, "phase", XDMF_INT32);
  scalar(f, snap, n, "id", XDMF_INT64);
  velocity(f, snap, n, dim);
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

/* Rank 0: write dir/snapshots.xdmf (via a .tmp and rename) for snapshots 0..n-1; 0 or 3. */
int xdmf_write_series(const char *dir, int n_snapshots, const double *times,
                      const long *n_particles, int dimension, char *err, size_t err_len) {
  size_t len = strlen(dir) + sizeof "/snapshots.xdmf.tmp";
  char *tmp = malloc(len), *path = malloc(len);
  FILE *f = NULL;
  int st = 3;
  if (tmp && path) {
    snprintf(tmp, len, "%s/snapshots.xdmf.tmp", dir);
    snprintf(path, len, "%s/snapshots.xdmf", dir);
    f = fopen(tmp, "w");
  }
  if (f) {
    document(f, n_snapshots, times, n_particles, dimension);
    st = ferror(f) ? 3 : 0;
    st = (fclose(f) != 0 || st || rename(tmp, path) != 0) ? 3 : 0;
    if (st) remove(tmp);
  }
  if (st && err && err_len)
    snprintf(err, err_len, "cannot write %s/snapshots.xdmf: %s", dir, strerror(errno));
  free(tmp);
  free(path);
  return st;
}
