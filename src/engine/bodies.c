/* bodies.c — the rigid bodies of a run (engine/bodies.h): loads summed in a fixed order, the
 * Runge-Kutta update of their state, their frames, bodies.csv and checkpoint numbers. */
#include <stdlib.h>
#include <string.h>
#include "engine/bodies.h"
#include "engine/engine.h"
#include "base/mem.h"

/* Impose the prescribed degrees of freedom of body r at time t [s] on its state (and, with rates,
 * on its rates and accelerations); nothing for a body that prescribes none. */
static void prescribe(const struct engine *e, struct body_run *r, double t, int rates) {
  const struct wall *w = &e->c->walls[r->wall];
  if (!w->body.prescribed) return;
  struct frame law;
  motion_frame(&w->motion, t, &law);
  rigid_prescribe(&w->body, e->c->dimension, &law, r->y, rates ? r->rate : NULL, r->acc, r->ang_acc);
}

void bodies_init(struct engine *e) {
  struct bodies *B = &e->bodies;
  memset(B, 0, sizeof *B);
  e->prm.body_walls = 0;
  for (int w = 0; w < e->c->n_walls; w++) {
    const struct body *b = &e->c->walls[w].body;
    if (!b->active) continue;
    struct body_run *r = &B->run[B->n++];
    r->wall = w;
    rigid_initial(b, r->y);
    prescribe(e, r, e->time, 0);
    memcpy(r->y0, r->y, sizeof r->y);
    e->prm.body_walls |= 1u << w;
  }
  if (!B->n) return;
  load_gather_init(&B->gather, e->n_ranks);
}

void bodies_frames(const struct engine *e, struct frame *f) {
  for (int k = 0; k < e->bodies.n; k++) {
    const struct body_run *r = &e->bodies.run[k];
    rigid_frame(&e->c->walls[r->wall].body, e->p.dim, r->y, r->acc, r->ang_acc, &f[r->wall]);
  }
}

/* Force and torque about the centre of mass c from the sorted loads l[0, n). */
static void sum_loads(const struct body_load *l, long n, const double *c, double *force, double *torque) {
  memset(force, 0, 3 * sizeof *force);
  memset(torque, 0, 3 * sizeof *torque);
  for (long k = 0; k < n; k++) {
    double arm[3] = {l[k].x[0] - c[0], l[k].x[1] - c[1], l[k].x[2] - c[2]};
    const double *f = l[k].force;
    for (int d = 0; d < 3; d++) force[d] += f[d];
    torque[0] += arm[1] * f[2] - arm[2] * f[1];
    torque[1] += arm[2] * f[0] - arm[0] * f[2];
    torque[2] += arm[0] * f[1] - arm[1] * f[0];
  }
}

/* Gather the loads and sum them per body k (about its centre of mass) into force[k], torque[k]. */
static void sum_bodies(struct engine *e, double (*force)[3], double (*torque)[3]) {
  struct bodies *B = &e->bodies;
  long total = load_gather_all(&B->gather, &B->loads, e->comm), first = 0;
  const struct body_load *all = B->gather.all;
  for (int k = 0; k < B->n; k++) {
    long end = first;
    while (end < total && all[end].wall == B->run[k].wall) end++;
    sum_loads(all + first, end - first, &B->run[k].y[RB_X], force[k], torque[k]);
    first = end;
  }
}

void bodies_apply_impulses(struct engine *e) {
  struct bodies *B = &e->bodies;
  double impulse[CASE_MAX_WALLS][3], angular[CASE_MAX_WALLS][3];
  sum_bodies(e, impulse, angular);
  for (int k = 0; k < B->n; k++)
    rigid_impulse(&e->c->walls[B->run[k].wall].body, e->p.dim, impulse[k], angular[k], B->run[k].y);
}

void bodies_evaluate(struct engine *e) {
  struct bodies *B = &e->bodies;
  double force[CASE_MAX_WALLS][3], torque[CASE_MAX_WALLS][3];
  sum_bodies(e, force, torque);
  for (int k = 0; k < B->n; k++) {
    struct body_run *r = &B->run[k];
    memcpy(r->force, force[k], sizeof r->force);
    memcpy(r->torque, torque[k], sizeof r->torque);
    rigid_rates(&e->c->walls[r->wall].body, e->p.dim, r->y, r->force, r->torque, e->c->gravity, r->rate, r->acc,
                r->ang_acc);
    prescribe(e, r, e->stage_time, 1);
  }
}

void bodies_save(struct engine *e) {
  for (int k = 0; k < e->bodies.n; k++) memcpy(e->bodies.run[k].y0, e->bodies.run[k].y, sizeof e->bodies.run[k].y);
}

void bodies_rk_update(struct engine *e, int s, double ws, double step, int last, double t_next) {
  for (int k = 0; k < e->bodies.n; k++) {
    struct body_run *r = &e->bodies.run[k];
    for (int j = 0; j < RB_STATE; j++) {
      r->sum[j] = (s ? r->sum[j] : 0) + ws * r->rate[j];
      r->y[j] = r->y0[j] + step * (!last ? r->rate[j] : r->sum[j]);
    }
    if (last) rigid_normalise(e->p.dim, r->y);
    prescribe(e, r, t_next, 0);
  }
}

/* The columns of a body in bodies.csv: the state's, then force and torque (2D: x, y, theta, vx,
 * vy, omega, fx, fy, torque). */
static const char *const COLUMNS_2D[] = {"x", "y", "theta", "vx", "vy", "omega", "fx", "fy", "torque", NULL};
static const char *const COLUMNS_3D[] = {"x", "y", "z", "qw", "qx", "qy", "qz", "vx", "vy", "vz", "wx", "wy",
                                         "wz", "fx", "fy", "fz", "tx", "ty", "tz", NULL};

void bodies_csv_header(const struct engine *e, FILE *f) {
  const char *const *col = e->p.dim == 2 ? COLUMNS_2D : COLUMNS_3D;
  fputs("step,time", f);
  for (int k = 0; k < e->bodies.n; k++)
    for (int j = 0; col[j]; j++) fprintf(f, ",body%d_%s", e->bodies.run[k].wall, col[j]);
  fputc('\n', f);
}

/* Body r's values in the order of its columns. */
static int row_values(const struct body_run *r, int dim, double *v) {
  int n = 0;
  for (int d = 0; d < dim; d++) v[n++] = r->y[RB_X + d];
  if (dim == 2) v[n++] = r->y[RB_THETA];
  else
    for (int j = 0; j < 4; j++) v[n++] = r->y[RB_Q + j];
  for (int d = 0; d < dim; d++) v[n++] = r->y[RB_V + d];
  for (int d = 3 - (dim == 2 ? 1 : 3); d < 3; d++) v[n++] = r->y[RB_W + d];
  for (int d = 0; d < dim; d++) v[n++] = r->force[d];
  for (int d = 3 - (dim == 2 ? 1 : 3); d < 3; d++) v[n++] = r->torque[d];
  return n;
}

void bodies_csv_row(const struct engine *e, FILE *f) {
  fprintf(f, "%ld,%.10g", e->step, e->time);
  for (int k = 0; k < e->bodies.n; k++) {
    double v[32];
    for (int j = 0, n = row_values(&e->bodies.run[k], e->p.dim, v); j < n; j++) fprintf(f, ",%.12g", v[j]);
  }
  fputc('\n', f);
}

int bodies_numbers(struct engine *e, struct hdf5_number *v) {
  int n = 0;
  for (int k = 0; k < e->bodies.n; k++) {
    struct body_run *r = &e->bodies.run[k];
    for (int j = 0; j < BODY_NUMBERS; j++) {
      double *at = j < RB_STATE ? &r->y[j] : j < RB_STATE + 3 ? &r->acc[j - RB_STATE] : &r->ang_acc[j - RB_STATE - 3];
      snprintf(r->names[j], sizeof r->names[j], "body%d_%s%d", r->wall,
               j < RB_STATE ? "state" : j < RB_STATE + 3 ? "acc" : "ang_acc", j < RB_STATE ? j : (j - RB_STATE) % 3);
      v[n++] = (struct hdf5_number){r->names[j], at, NULL};
    }
  }
  return n;
}

void bodies_free(struct bodies *B) {
  free(B->loads.at);
  load_gather_free(&B->gather);
  memset(B, 0, sizeof *B);
}
