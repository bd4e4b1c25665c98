/* kinds.c — the kind table as data (names, properties, load-balance work), from PART_KINDS, and
 * the assumptions the loops make about it. */
#include "base/kinds.h"

#define KIND_ROW_(unused, kind, name, properties, work) [kind] = {name, properties, work},
#define KIND_ONE_(unused, kind, name, properties, work) +1
const struct part_kind_info part_kinds[KIND_COUNT] = {PART_KINDS(KIND_ROW_, 0)};

_Static_assert(0 PART_KINDS(KIND_ONE_, 0) == KIND_COUNT, "one row of PART_KINDS per kind");
/* rk_update, the dual stepper, the checks and stats.csv read an integrated particle's phase */
_Static_assert(KINDS_WITH(KIND_INTEGRATED) == 1u << KIND_FLUID,
               "an integrated kind other than fluid has no phase: give it its own update");
/* the pair loops read the phase of every neighbour that is not a boundary particle */
_Static_assert(KINDS_WITH(KIND_BOUNDARY) == ((1u << KIND_COUNT) - 1u) - (1u << KIND_FLUID),
               "a kind other than fluid that is not a boundary neighbour: decide its role in the pair loops");
