/* test_parts.c — the particle field table (parts.h): it covers every member of struct parts
 * after the counts, each pointer once; in 2D and 3D, with and without walls, a pack of every
 * field (halo and migration) unpacked into other slots, parts_copy_one and growth by
 * parts_reserve keep every component's value bit for bit; parts_bytes counts every slot. The
 * kind table (kinds.h): every kind has a name and a work weight, each marker maps back to its
 * kind, the phase indices to the fluid and -1 to the wall ghost, and part_has (the folded sets)
 * answers what the table's rows say for every combination of properties. */
#include <string.h>
#include "check.h"
#include "base/parts.h"
#include "parallel/proxy.h"

/* The value stored for particle i in component k of the field number f (distinct, exact in a
 * double and in an int). */
static double value_of(int f, int k, long i) { return 1000.0 * (f + 1) + 100.0 * k + (double)i; }

/* Element i of component k of field f of p, as a double. */
static double get(const struct parts *p, const struct part_field *f, int k, long i) {
  const void *a = parts_field_array(p, f, k);
  return f->type == PART_DOUBLE ? ((const double *)a)[i]
         : f->type == PART_INT  ? ((const int *)a)[i]
                                : (double)((const int64_t *)a)[i];
}

/* Set element i of component k of field f of p to v. */
static void set(struct parts *p, const struct part_field *f, int k, long i, double v) {
  void *a = parts_field_array(p, f, k);
  if (f->type == PART_DOUBLE) ((double *)a)[i] = v;
  else if (f->type == PART_INT) ((int *)a)[i] = (int)v;
  else ((int64_t *)a)[i] = (int64_t)v;
}

/* Fill particles [0, n) of p with value_of. */
static void fill(struct parts *p, long n) {
  for (int f = 0; f < parts_n_fields; f++)
    if (parts_has_field(p, &parts_fields[f]))
      for (int k = 0; k < parts_field_ncomp(p, &parts_fields[f]); k++)
        for (long i = 0; i < n; i++) set(p, &parts_fields[f], k, i, value_of(f, k, i));
}

/* Count of the values of slots first..first+n of p differing from particles order[0..n). */
static int mismatches(const struct parts *p, long first, const long *order, long n) {
  int bad = 0;
  for (int f = 0; f < parts_n_fields; f++)
    if (parts_has_field(p, &parts_fields[f]))
      for (int k = 0; k < parts_field_ncomp(p, &parts_fields[f]); k++)
        for (long i = 0; i < n; i++)
          bad += get(p, &parts_fields[f], k, first + i) != value_of(f, k, order[i]);
  return bad;
}

/* Every pointer member of struct parts after the counts is one table slot, none twice; vectors
 * are double. */
static void check_covers_struct(void) {
  enum { SLOTS = (sizeof(struct parts) - offsetof(struct parts, x)) / sizeof(void *) };
  int seen[SLOTS] = {0};
  for (int f = 0; f < parts_n_fields; f++) {
    size_t first = (parts_fields[f].offset - offsetof(struct parts, x)) / sizeof(void *);
    for (int k = 0; k < (parts_fields[f].vector ? 3 : 1); k++) seen[first + k]++;
    CHECK(!parts_fields[f].vector || parts_fields[f].type == PART_DOUBLE, "%s: a vector of doubles",
          parts_fields[f].name);
  }
  for (int s = 0; s < SLOTS; s++) CHECK(seen[s] == 1, "pointer slot %d of struct parts: %d entries", s, seen[s]);
  CHECK((sizeof(struct parts) - offsetof(struct parts, x)) % sizeof(void *) == 0, "struct parts ends in pointers");
}

/* Pack n particles in reverse order with op, unpack them after the n particles, compare. */
static void check_round_trip(struct parts *p, long n, unsigned op, const char *what) {
  long order[8];
  double buf[8 * 64];
  for (long i = 0; i < n; i++) order[i] = n - 1 - i;
  CHECK(parts_packed_size(p, op) <= 64, "%s: packed size %d", what, parts_packed_size(p, op));
  parts_pack(p, op, order, n, buf);
  parts_reserve(p, 2 * n);
  parts_unpack(p, op, n, n, buf);
  CHECK(mismatches(p, n, order, n) == 0, "%s: unpacked values", what);
  CHECK(mismatches(p, 0, (long[]){0, 1, 2, 3, 4, 5, 6, 7}, n) == 0, "%s: kept after growth", what);
}

/* The table's operations in dim dimensions, with or without walls. */
static void check_parts(int dim, int walls) {
  const long n = 8;
  char what[64];
  struct parts p, q;
  parts_init(&p, dim, n, walls);
  fill(&p, n);
  snprintf(what, sizeof what, "%dD%s halo", dim, walls ? " walls" : "");
  check_round_trip(&p, n, PART_HALO, what);
  fill(&p, n);
  snprintf(what, sizeof what, "%dD%s migration", dim, walls ? " walls" : "");
  check_round_trip(&p, n, PART_MIGRATE, what);
  parts_init(&q, dim, n, walls);
  for (long i = 0; i < n; i++) parts_copy_one(&q, i, &p, n - 1 - i);
  long reversed[8] = {7, 6, 5, 4, 3, 2, 1, 0};
  CHECK(mismatches(&q, 0, reversed, n) == 0, "%dD walls %d: parts_copy_one", dim, walls);
  long per = 0;
  for (int f = 0; f < parts_n_fields; f++)
    if (parts_has_field(&q, &parts_fields[f]))
      per += parts_field_ncomp(&q, &parts_fields[f]) * (long)parts_field_size(&parts_fields[f]);
  CHECK(parts_bytes(&q) == n * per && parts_bytes(&p) == 2 * n * per,
        "%dD walls %d: parts_bytes %ld and %ld, %ld per particle", dim, walls, parts_bytes(&q),
        parts_bytes(&p), per);
  parts_free(&p);
  parts_free(&q);
}

/* The kind table and its marker. */
static void check_kinds(void) {
  for (int k = 0; k < KIND_COUNT; k++) {
    const char *name = part_kinds[k].name;
    CHECK(name && name[0], "kind %d has a name", k);
    for (int q = 0; q < k && name; q++) CHECK(strcmp(name, part_kinds[q].name), "kinds %d and %d: one name", q, k);
    CHECK(part_kinds[k].work > 0, "kind %d: work %d", k, part_kinds[k].work);
    if (k != KIND_FLUID)
      CHECK(kind_marker(k) < 0 && kind_of(kind_marker(k)) == (enum part_kind)k, "kind %d: marker %d maps back",
            k, kind_marker(k));
  }
  for (int ph = 0; ph < 8; ph++) CHECK(kind_of(ph) == KIND_FLUID, "phase %d is fluid", ph);
  CHECK(PHASE_WALL == -1 && kind_of(PHASE_WALL) == KIND_WALL, "the wall ghost's marker is -1 (the files' value)");
  int wrong = 0;
  for (unsigned props = 1; props < 32; props++)
    for (int phase = -(KIND_COUNT - 1); phase < 3; phase++)
      wrong += part_has(phase, props) != ((part_kinds[kind_of(phase)].properties & props) != 0);
  CHECK(wrong == 0, "part_has: %d answers differ from the table's rows", wrong);
}

int main(void) {
  check_covers_struct();
  check_kinds();
  for (int dim = 2; dim <= 3; dim++)
    for (int walls = 0; walls <= 1; walls++) check_parts(dim, walls);
  return check_report("test_parts");
}
