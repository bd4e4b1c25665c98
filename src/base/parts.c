/* parts.c — the particle field table, allocation and copying of the particle arrays. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "base/parts.h"
#include "base/mem.h"

#define FIELD(name, type, vector, member, walls_only, ops) \
  {name, type, vector, offsetof(struct parts, member), walls_only, ops}
#define MOVES (PART_HALO | PART_MIGRATE)
#define WRITTEN (PART_SNAPSHOT | PART_CHECKPOINT)

const struct part_field parts_fields[] = {
    FIELD("position", PART_DOUBLE, 1, x, 0, MOVES | WRITTEN),
    FIELD("velocity", PART_DOUBLE, 1, v, 0, MOVES | WRITTEN),
    FIELD("density", PART_DOUBLE, 0, rho, 0, MOVES | WRITTEN),
    FIELD("pressure", PART_DOUBLE, 0, p, 0, MOVES | WRITTEN),
    FIELD("mass", PART_DOUBLE, 0, m, 0, MOVES | WRITTEN),
    FIELD("phase", PART_INT, 0, phase, 0, MOVES | WRITTEN),
    FIELD("id", PART_INT64, 0, id, 0, MOVES | WRITTEN),
    FIELD("cell", PART_INT, 0, cell, 0, MOVES),
    FIELD("mirror", PART_DOUBLE, 1, mirror, 1, MOVES | PART_CHECKPOINT),
    FIELD("wall", PART_INT, 0, wall, 1, MOVES | PART_CHECKPOINT),
};
const int parts_n_fields = (int)(sizeof parts_fields / sizeof parts_fields[0]);
_Static_assert(sizeof parts_fields / sizeof parts_fields[0] <= PARTS_MAX_FIELDS,
               "parts_fields has more entries than PARTS_MAX_FIELDS");

int parts_has_field(const struct parts *p, const struct part_field *f) {
  return !f->walls_only || p->wall != NULL;
}

int parts_field_ncomp(const struct parts *p, const struct part_field *f) {
  return f->vector ? p->dim : 1;
}

size_t parts_field_size(const struct part_field *f) {
  return f->type == PART_INT ? sizeof(int) : f->type == PART_INT64 ? sizeof(int64_t) : sizeof(double);
}

/* The address of the pointer to component k of f in p (pointers are read and written through
 * memcpy: the members have different pointer types). */
static char *slot_of(const struct parts *p, const struct part_field *f, int k) {
  return (char *)p + f->offset + (size_t)k * sizeof(void *);
}

void *parts_field_array(const struct parts *p, const struct part_field *f, int k) {
  void *a;
  memcpy(&a, slot_of(p, f, k), sizeof a);
  return a;
}

/* Point component k of f in p to a. */
static void set_array(struct parts *p, const struct part_field *f, int k, void *a) {
  memcpy(slot_of(p, f, k), &a, sizeof a);
}

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
  for (const struct part_field *f = parts_fields; f < parts_fields + parts_n_fields; f++) {
    if (!parts_has_field(p, f)) continue;
    size_t bytes = (size_t)capacity * parts_field_size(f);
    for (int k = 0; k < parts_field_ncomp(p, f); k++)
      set_array(p, f, k, grow(parts_field_array(p, f, k), bytes));
  }
  p->capacity = capacity;
}

void parts_free(struct parts *p) {
  for (const struct part_field *f = parts_fields; f < parts_fields + parts_n_fields; f++)
    for (int k = 0; k < (f->vector ? 3 : 1); k++) free(parts_field_array(p, f, k));
  memset(p, 0, sizeof(*p));
}

void parts_copy_one(struct parts *dst, long j, const struct parts *src, long i) {
  for (const struct part_field *f = parts_fields; f < parts_fields + parts_n_fields; f++) {
    if (!parts_has_field(src, f)) continue;
    size_t size = parts_field_size(f);
    for (int k = 0; k < parts_field_ncomp(src, f); k++) {
      char *to = (char *)parts_field_array(dst, f, k) + (size_t)j * size;
      const char *from = (const char *)parts_field_array(src, f, k) + (size_t)i * size;
      if (size == 8) memcpy(to, from, 8);   /* constant sizes: a load and a store */
      else memcpy(to, from, 4);
    }
  }
}

long parts_bytes(const struct parts *p) {
  long per_particle = 0;
  for (const struct part_field *f = parts_fields; f < parts_fields + parts_n_fields; f++)
    if (parts_has_field(p, f)) per_particle += parts_field_ncomp(p, f) * (long)parts_field_size(f);
  return p->capacity * per_particle;
}
