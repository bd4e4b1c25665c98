/* parts.c — allocation and copying of the particle arrays. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "base/parts.h"
#include "base/mem.h"

/* Grow a particle array to bytes (out of memory ends the run, mem.h). */
static void *grow(void *ptr, size_t bytes) { return mem_realloc(ptr, bytes, "particle arrays"); }

void parts_init(struct parts *p, int dim, long capacity, int with_walls) {
  memset(p, 0, sizeof(*p));
  p->dim = dim;
  if (with_walls) p->wall = grow(NULL, sizeof(int));
  parts_reserve(p, capacity);
}

void parts_reserve(struct parts *p, long capacity) {
  if (capacity <= p->capacity) return;
  size_t n = (size_t)capacity, dsz = n * sizeof(double);
  for (int d = 0; d < p->dim; d++) {
    p->x[d] = grow(p->x[d], dsz);
    p->v[d] = grow(p->v[d], dsz);
    if (p->wall) p->mirror[d] = grow(p->mirror[d], dsz);
  }
  p->rho = grow(p->rho, dsz);
  p->p = grow(p->p, dsz);
  p->m = grow(p->m, dsz);
  p->phase = grow(p->phase, n * sizeof(int));
  p->id = grow(p->id, n * sizeof(int64_t));
  p->cell = grow(p->cell, n * sizeof(int));
  if (p->wall) p->wall = grow(p->wall, n * sizeof(int));
  p->capacity = capacity;
}

void parts_free(struct parts *p) {
  for (int d = 0; d < 3; d++) {
    free(p->x[d]);
    free(p->v[d]);
    free(p->mirror[d]);
  }
  free(p->rho);
  free(p->p);
  free(p->m);
  free(p->phase);
  free(p->id);
  free(p->cell);
  free(p->wall);
  memset(p, 0, sizeof(*p));
}

void parts_copy_one(struct parts *dst, long j, const struct parts *src, long i) {
  for (int d = 0; d < src->dim; d++) {
    dst->x[d][j] = src->x[d][i];
    dst->v[d][j] = src->v[d][i];
    if (src->wall) dst->mirror[d][j] = src->mirror[d][i];
  }
  dst->rho[j] = src->rho[i];
  dst->p[j] = src->p[i];
  dst->m[j] = src->m[i];
  dst->phase[j] = src->phase[i];
  dst->id[j] = src->id[i];
  dst->cell[j] = src->cell[i];
  if (src->wall) dst->wall[j] = src->wall[i];
}

long parts_bytes(const struct parts *p) {
  long doubles = 2 * p->dim + 3 + (p->wall ? p->dim : 0);
  long ints = 2 + (p->wall ? 1 : 0);
  return p->capacity * (doubles * (long)sizeof(double) + ints * (long)sizeof(int) + (long)sizeof(int64_t));
}
