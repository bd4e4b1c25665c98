/* init.h — initial particles: fluid regions filled on the lattice, wall ghost layers, ids,
 * hydrostatic pressure and masses. */
#ifndef MPSPH_INIT_H
#define MPSPH_INIT_H

#include <stddef.h>
#include "case/case.h"
#include "case/geometry.h"
#include "base/parts.h"

/** Particle counts of a case (global). */
struct init_counts {
  long fluid[CASE_MAX_PHASES];   /* per phase */
  long n_fluid, n_wall;
};

/** Number of ghost layers (wall thickness / dx) needed for a kernel support of `support` m. */
int init_wall_layers(const struct case_def *c, double support);

/** The candidate nodes of the initial particles, in the order that numbers them: the fluid
 *  regions' lattices (in case order), then the walls' ghost-node lattices, each cut into rows
 *  along x (row iy + n[1] iz of a source, nodes by ix). A particle's id is the number of
 *  particles before it in this order, so that any rank can number the particles of a row once it
 *  knows how many the rows before hold. */
struct init_source {
  int wall;                /* -1: fluid region (source index); else the wall's index */
  int tank;                /* a box wall with the fluid inside: node coordinates from axis[] */
  int layers;              /* walls: ghost layers */
  struct lattice l;        /* the nodes when not a tank */
  double *axis[3];         /* tank: node coordinates along each axis */
  long n[3];               /* nodes per axis */
  long first_row;          /* global index of its first row */
};
struct init_rows {
  int n_sources;           /* fluid regions, then walls */
  struct init_source src[CASE_MAX_REGIONS + CASE_MAX_WALLS];
  long n_rows;
  double thickness;        /* wall ghost layers [m] */
};

/** Called for each particle of a row: its position [m], source and ordinal within the row. */
typedef void (*init_node_fn)(void *ctx, const double *x, int source, long ordinal);

/** Lay out the rows of case c for a kernel support of `support` m (no node visited). */
void init_rows_open(struct init_rows *r, const struct case_def *c, double support);

/** Free what init_rows_open allocated. */
void init_rows_close(struct init_rows *r);

/** The source of global row `row`. */
int init_row_source(const struct init_rows *r, long row);

/** The box [lo, hi] [m] holding source k's candidate nodes, and the box [in_lo, in_hi] strictly
 *  inside which it has none (a tank's interior; empty, in_lo > in_hi, for other sources);
 *  axes d < dim. */
void init_source_extent(const struct init_rows *r, int k, int dim, double *lo, double *hi, double *in_lo,
                        double *in_hi);

/** Count the particles of rows [first, end) into counts[row - first], calling fn (if not NULL)
 *  for each. Returns -1, or the row where bad input was found (overlapping fluid regions, wall
 *  layers leaving the domain) with a message naming the offending key. */
long init_count_rows(const struct case_def *c, const struct init_rows *r, long first, long end,
                     int *counts, init_node_fn fn, void *ctx, char *err, size_t len);

/** Call fn for the particles of row `row` among its first ix_end nodes (the row's ordinals count
 *  from its first node; the row was counted without error). Returns their number. */
long init_visit_row(const struct case_def *c, const struct init_rows *r, long row, long ix_end,
                    init_node_fn fn, void *ctx);

/** The node index ranges first[d]..last[d] (d < dim; 0 beyond) of source k within the box
 *  [lo, hi] [m]. Returns 0 when the box holds none of its nodes. */
int init_rows_in_box(const struct init_rows *r, int k, int dim, const double *lo, const double *hi,
                     long *first, long *last);

/** Store a fluid particle of region k at x with id `id` in the next owned slot of p: the initial
 *  velocity, pressure (background, plus hydrostatic when asked), density from it, mass. */
void init_add_fluid(const struct case_def *c, int k, const double *x, int64_t id, struct parts *p);

/** Store a ghost of wall w at x with id `id` in the next owned slot of p, with the offset 2 (q - x)
 *  to its mirror point across the wall boundary point q nearest to x (fixed in the wall's frame). */
void init_add_ghost(const struct case_def *c, int w, const double *x, int64_t id, struct parts *p);

/** 1 with a message when a case generates no fluid particle (n_fluid of them), else 0. */
int init_no_fluid(const struct case_def *c, long n_fluid, char *err, size_t err_len);

/** Generate every particle of case c into p, ids in row order (with p == NULL only count), on
 *  one process. Returns 0, or 1 with a message naming the offending key (overlapping fluid
 *  regions, wall layers leaving the domain, no particle at all). */
int init_particles(const struct case_def *c, double support, struct parts *p,
                   struct init_counts *counts, char *err, size_t err_len);

/** An upper bound on the lattice nodes init_particles visits (fluid regions and wall ghost
 *  candidates), hence on the particles it generates, computed without visiting them (infinity
 *  when beyond a double). */
double init_visit_count(const struct case_def *c, double support);

/** The wall ghost candidates' part of init_visit_count: a bound on the wall ghosts. */
double init_wall_visit_count(const struct case_def *c, double support);

/** Initial gauge pressure [Pa] at x balancing the body forces: with uniform gravity the exact
 *  weight of the fluid regions above x; with a potential or a linear initial velocity field,
 *  integrated along the direction of the balancing acceleration. */
double init_hydrostatic_pressure(const struct case_def *c, const double *x);

#endif
