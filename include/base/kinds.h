/* kinds.h — the particle kinds (fluid, wall ghost, elastic solid): the table of what each kind is to the loops,
 * and the marker that maps a particle to its kind. */
#ifndef MPSPH_KINDS_H
#define MPSPH_KINDS_H

/** The kinds of particle. A fluid particle holds its phase index (>= 0) in `phase`; a particle
 *  of any other kind holds the kind's marker, -kind, so that the stored phase values (snapshots,
 *  checkpoints) keep their meaning as kinds are added. */
enum part_kind { KIND_FLUID, KIND_WALL, KIND_SOLID, KIND_COUNT };

#define PHASE_WALL (-KIND_WALL)   /* the marker of a wall ghost (-1, as written to the files) */
#define PHASE_SOLID (-KIND_SOLID) /* the marker of an elastic solid's particle (-2) */

/** What the loops ask of a particle's kind: one bit each. */
enum {
  KIND_INTEGRATED = 1,   /* advanced in time from its right-hand sides and its phase's EOS (so it holds
                            a phase index): rk_update and the dual stepper, the checks and time-step
                            maxima over the moving fluid, the wall guard, stats.csv */
  KIND_LISTED = 2,       /* has a neighbour list of its own (nlist_build), and pass_for_each_owned
                            calls the pass's particle function for it (else the pass's other one) */
  KIND_BOUNDARY = 4,     /* as a neighbour in a pair loop: a boundary particle (it stands for the
                            fluid beside it; no phase of its own), not a fluid particle of its phase */
  KIND_MIRRORED = 8,     /* its values are interpolated at its mirror point (pass_wall_ghosts,
                            wall_mirror_point); checkpoints bound its mirror offset */
  KIND_ON_WALL = 16      /* belongs to the wall `wall` holds: moves with it (engine_moving_ghost);
                            exists only in a case with walls (the walls-only fields) */
};

/* The kind table, one row per kind in enum order: X(kind, name, properties, work), with work the
 * load-balance weight of one particle (a fluid particle's pair passes cost about four times a
 * ghost's interpolation). The compile-time property sets below come from it, so a hot loop's
 * question costs what the test of one marker does. */
#define PART_KINDS(X, A) \
  X(A, KIND_FLUID, "fluid", KIND_INTEGRATED | KIND_LISTED, 8) \
  X(A, KIND_WALL, "wall ghost", KIND_BOUNDARY | KIND_MIRRORED | KIND_ON_WALL, 2) \
  X(A, KIND_SOLID, "solid", KIND_BOUNDARY, 2)

/** One row of the kind table. */
struct part_kind_info {
  const char *name;
  unsigned properties;   /* KIND_* bits */
  int work;              /* load-balance work units of one particle */
};

/** The kind table as data, indexed by enum part_kind. */
extern const struct part_kind_info part_kinds[KIND_COUNT];

/* The set of kinds (bit k for kind k) whose properties include prop, a constant expression. */
#define KIND_BIT_IF_(prop, kind, name, properties, work) | (((properties) & (prop)) ? 1u << (kind) : 0u)
#define KINDS_WITH(prop) (0u PART_KINDS(KIND_BIT_IF_, prop))

/** The kind of a particle with this phase value (a valid one: a phase index or a marker). */
static inline enum part_kind kind_of(int phase) {
  return phase >= 0 ? KIND_FLUID : (enum part_kind)-phase;
}

/** The phase value that marks kind k (not KIND_FLUID, whose particles hold their phase index). */
static inline int kind_marker(enum part_kind k) { return -(int)k; }

/** 1 if the particle with this (valid) phase value is of a kind with property prop (a KIND_* bit,
 *  a constant, so that the set folds: the fluid alone is phase >= 0, one other kind alone the
 *  compare with its marker, as cheap in the pair loops as the marker test written out; other
 *  sets shift the set by the kind). */
static inline int part_has(int phase, unsigned prop) {
  const unsigned set = KINDS_WITH(prop), others = set & ~(1u << KIND_FLUID);
  if (others == 0) return set != 0 && phase >= 0;
  if (set == others && (others & (others - 1)) == 0)
    return phase == kind_marker((enum part_kind)__builtin_ctz(others));
  return (int)((set >> kind_of(phase)) & 1u);
}

#endif
