/* energy_check.c — the energy instability check (exit status 2, time.energy_growth). The mechanical
 * energy of the fluid, E = sum_i m_i (|u_i|^2 / 2 + phi(x_i) + e(rho_i)), with phi = -g.x +
 * Omega^2 |x - r_c|^2 / 2 and e the specific internal energy of the phase's EOS, plus that of the
 * elastic solids (kinetic, strain, and phi of their particles), cannot grow in a closed tank with
 * fixed walls: every term of the schemes conserves or dissipates it, up to the discretisation
 * error. A run stops when E has grown by more than time.energy_growth times the
 * energy scale E_U = M U_max^2 / 2 (M the fluid mass, U_max physics.u_max) since the start of the
 * run (of this process, after a restart). Walls that move do work on the fluid: the check is off
 * then, as it is with time.energy_growth 0. E is summed in fixed point (integers, exact and
 * associative), so the value and the step that trips are the same on any number of ranks. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include "engine/engine.h"
#include "physics/eos.h"

#define ENERGY_FRACTION_BITS 24   /* one fixed-point unit: 2^-24 of a reference particle's E_U */

/* Specific internal energy [J/kg] of phase ph at density rho: the integral of p / rho^2 from rho0,
 * for the Tait EOS p = B((rho/rho0)^gamma - 1) + p_b. */
static double internal_energy(const struct phase *ph, double rho) {
  double b = ph->rho0 * ph->c0 * ph->c0 / ph->gamma, r = rho / ph->rho0;
  double stiff = ph->gamma == 1 ? log(r) : (pow(r, ph->gamma - 1) - 1) / (ph->gamma - 1);
  return b / ph->rho0 * stiff + (ph->p_background - b) * (1 / ph->rho0 - 1 / rho);
}

/* Potential of the body forces [J/kg] at x: gravity and the quadratic potential. */
static double body_potential(const struct case_def *c, const double *x) {
  double phi = 0, r2 = 0;
  for (int d = 0; d < c->dimension; d++) {
    phi -= c->gravity[d] * x[d];
    r2 += (x[d] - c->potential_centre[d]) * (x[d] - c->potential_centre[d]);
  }
  return phi + 0.5 * c->potential_omega * c->potential_omega * r2;
}

/* The fixed-point unit [J]: 2^-ENERGY_FRACTION_BITS of the kinetic energy at U_max of a particle
 * of the densest phase; the same on every rank (case constants only). */
static double energy_unit(const struct engine *e) {
  double rho_max = 0;
  for (int ph = 0; ph < e->c->n_phases; ph++) rho_max = fmax(rho_max, e->c->phases[ph].rho0);
  return 0.5 * rho_max * e->prm.vol0 * e->c->u_max * e->c->u_max * ldexp(1.0, -ENERGY_FRACTION_BITS);
}

/* Energy q [units of energy_unit] as the fixed-point integer, cut to +-limit (a runaway particle
 * cannot overflow the sum; the sum has tripped the check long before). */
static int64_t fixed_point(double q, double limit) {
  return (int64_t)llround(isfinite(q) ? fmax(-limit, fmin(limit, q)) : limit);
}

/* Owned fluid particle i's mechanical energy [units of energy_unit], cut to +-limit. */
static int64_t particle_energy(const struct engine *e, long i, double unit, double limit) {
  const struct parts *p = &e->p;
  double x[3] = {0, 0, 0}, u2 = 0;
  for (int d = 0; d < p->dim; d++) x[d] = p->x[d][i], u2 += p->v[d][i] * p->v[d][i];
  const struct phase *ph = &e->c->phases[p->phase[i]];
  return fixed_point(p->m[i] * (0.5 * u2 + body_potential(e->c, x) + internal_energy(ph, p->rho[i])) / unit, limit);
}

/* The elastic solids' mechanical energy [J] (2D: [J/m]): kinetic and strain energy, and the body
 * forces' potential of their particles. */
static double solids_energy(const struct engine *e) {
  double energy = 0;
  for (int k = 0; k < e->solids.n; k++) {
    const struct elastic_solid *s = &e->solids.run[k].s;
    energy += elastic_energy(s);
    for (int a = 0; a < s->n; a++) energy += s->mass * body_potential(e->c, s->x + (size_t)a * s->dim);
  }
  return energy;
}

/* Global E and M: E in energy units, M [kg] (in the same fixed point, scaled by u_max^2 / 2):
 * out[0] = sum of E, out[1] = sum of the particles' E_U. One reduction. The solids, which every
 * rank holds alike, count once, on rank 0. */
static void global_energy(const struct engine *e, int64_t out[2]) {
  double unit = e->energy_unit, limit = e->energy_limit, half_u2 = 0.5 * e->c->u_max * e->c->u_max;
  out[0] = out[1] = 0;
  if (e->rank == 0 && e->solids.n) out[0] += fixed_point(solids_energy(e) / unit, limit * (double)e->solids.view.n);
  for (long i = 0; i < e->p.n_owned; i++) {
    if (!part_has(e->p.phase[i], KIND_INTEGRATED)) continue;
    out[0] += particle_energy(e, i, unit, limit);
    out[1] += (int64_t)llround(e->p.m[i] * half_u2 / unit);
  }
  MPI_Allreduce(MPI_IN_PLACE, out, 2, MPI_INT64_T, MPI_SUM, e->comm);
}

int engine_energy_on(const struct engine *e) {
  return e->c->energy_growth > 0 && !case_walls_move(e->c);
}

void engine_energy_reference(struct engine *e) {
  if (!engine_energy_on(e)) return;
  long n = 0;
  for (long i = 0; i < e->p.n_owned; i++) n += part_has(e->p.phase[i], KIND_INTEGRATED);
  MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPI_LONG, MPI_SUM, e->comm);
  n += e->solids.view.n;   /* the solids' particles: their energy may take as many limits */
  e->energy_unit = energy_unit(e);
  e->energy_limit = ldexp(1.0, 62) / (double)(n > 0 ? n : 1);   /* |sum| < 2^62 */
  int64_t sums[2];
  global_energy(e, sums);
  e->energy_start = sums[0];
  e->energy_scale = (double)sums[1];
  e->energy_growth_peak = 0;
}

int engine_check_energy(struct engine *e) {
  if (!engine_energy_on(e)) return 0;
  int64_t sums[2];
  global_energy(e, sums);
  double growth = (double)(sums[0] - e->energy_start) / e->energy_scale;
  e->energy_growth_peak = fmax(e->energy_growth_peak, growth);
  if (!(growth > e->c->energy_growth) && isfinite(growth)) return 0;
  double u;
  long i = engine_largest_vector(e, e->p.v, &u);
  char what[256];
  snprintf(what, sizeof what, "the mechanical energy grew by %.4g M U_max^2/2 since the start, above "
           "time.energy_growth %g; this particle is the fastest, %.3g m/s", growth,
           e->c->energy_growth, u);
  if (i >= 0) engine_report_particle(e, i, what);
  return 2;
}
