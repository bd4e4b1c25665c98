/* case_load.c — read a YAML case file (plus --set overrides) into struct case_def, validating
 * every key with one-line messages "<file>:<line>: <key.path>: <what is wrong>, <expected>",
 * and write a resolved case back as YAML. The keys of the top level, its sections and the phases
 * are tables (CASE_KEYS, PHASE_ITEM_KEYS) that drive the reading, the allowed keys, the writing
 * and the reference of `mpsph keys`; fluids, walls and probes have readers of their own. */
#include "case/case_load.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "case/geometry.h"
#include "base/mem.h"
#include "case/yaml_tree.h"

#define PATH_LEN 256
#define LIST_LEN 512
#define REQUIRED NAN   /* the default of a required number */
#define CASE_MAX_FILE_BYTES (1 << 20)   /* largest case file read [bytes] */

/* Enumeration spellings, in the order of the enums of case.h. */
#define SCHEME_SPELLING(value, spelling) spelling,
static const char *const SCHEME_NAMES[] = {SCHEME_LIST(SCHEME_SPELLING) NULL};
#undef SCHEME_SPELLING
static const char *const KERNEL_NAMES[] = {"gaussian", "wendland-c2", NULL};
static const char *const SHAPE_NAMES[] = {"box", "circle", "polygon", NULL};
static const char *const SLIP_NAMES[] = {"free", "no", NULL};
static const char *const SIDE_NAMES[] = {"inside", "outside", NULL};
static const char *const SHIFTING_NAMES[] = {"none", "consistent", "position", NULL};
static const char *const PROBE_KIND_NAMES[] = {"pressure", "elevation", "integral", NULL};
static const char *const INTERP_NAMES[] = {"shepard", "mls", NULL};
static const char *const PRESSURE_NAMES[] = {"hydrostatic", "zero", NULL};
static const char *const BOOL_NAMES[] = {"false", "true", NULL};
static const char *const FREE_SURFACE_NAMES[] = {"auto", "on", "off", NULL};
static const char *const DAMPER_NAMES[] = {"difference", "symmetric", "own-phase", NULL};
static const char *const IFACE_P_NAMES[] = {"sum", "density-weighted", NULL};
static const char *const IFACE_VISC_NAMES[] = {"none", "harmonic", NULL};
static const char *const SPC_MODEL_NAMES[] = {"present", "conventional", NULL};
static const char *const DISSIPATION_NAMES[] = {"consistent", "printed", NULL};
static const char *const BALANCE_NAMES[] = {"time", "work", NULL};
static const char *const RAMP_NAMES[] = {"none", "linear", "smooth", NULL};
static const char *const SOLID_MODEL_NAMES[] = {"saint-venant-kirchhoff", "neo-hookean", NULL};   /* elastic_model_name's */
static const char *const SOLID_CORRECTION_NAMES[] = {"linear", "quadratic", NULL};

/* The keys allowed in the mappings that a list reader of its own reads (the others follow from
 * the key tables). */
static const char *const BOX_KEYS[] = {"min", "max", "floor", "ceiling", NULL};
static const char *const SURFACE_KEYS[] = {"level", "amplitude", "wavelength", NULL};
static const char *const CIRCLE_KEYS[] = {"centre", "radius", "inner_radius", NULL};
static const char *const FLUID_KEYS[] = {"phase", "box", "circle", "polygon", "velocity",
                                         "velocity_gradient", "velocity_mode", NULL};
static const char *const MODE_KEYS[] = {"amplitude", "wavelength", "interface", NULL};
static const char *const WALL_KEYS[] = {"box", "circle", "polygon", "slip", "fluid_side", "motion", "body", NULL};
static const char *const BODY_KEYS[] = {"mass", "centre", "inertia", "velocity", "angular_velocity", "fixed",
                                        "prescribed", NULL};
/* The degrees of freedom a body's `fixed` and `prescribed` may name, in the order of the BODY_DOF_* bits, per
 * dimension. */
static const char *const DOF_NAMES_2D[] = {"x", "y", "", "", "", "rotation", NULL};
static const char *const DOF_NAMES_3D[] = {"x", "y", "z", "rx", "ry", "rz", NULL};
static const char *const MOTION_KEYS[] = {"translation", "rotation", "table", "centre", "axis", NULL};
static const char *const TRANSLATION_KEYS[] = {"amplitude", "period", "phase", "ramp", NULL};
static const char *const ROTATION_KEYS[] = {"amplitude", "period", "phase", "ramp", "centre", "axis", NULL};
static const char *const RAMP_KEYS[] = {"shape", "time", NULL};
static const char *const PROBE_KEYS[] = {"name", "kind", "position", "diameter", "axis",
                                         "interpolation", "phase", "wall", NULL};

static const char *const ALNUM = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
static const char *const NAME_PUNCT = "._-";   /* case and phase names (a directory name) */
static const char *const PROBE_PUNCT = "_";    /* probe names (a CSV column) */

/* The values a number may take. */
struct rule {
  const char *expected;
  double lo;
  int lo_open;          /* lo itself excluded */
  double hi;
  int integer;
};
static const struct rule R_ANY = {"a number", -HUGE_VAL, 0, HUGE_VAL, 0};
static const struct rule R_POSITIVE = {"a number > 0", 0, 1, HUGE_VAL, 0};
static const struct rule R_NONNEGATIVE = {"a number >= 0", 0, 0, HUGE_VAL, 0};
static const struct rule R_CFL = {"a number > 0 and <= 2", 0, 1, 2, 0};
static const struct rule R_COUNT = {"an integer >= 0", 0, 0, 1e18, 1};
static const struct rule R_TOP_CELLS = {"an integer from 1 to 1048576", 1, 0, 1048576, 1};
static const struct rule R_DIMENSION = {"2 or 3", 2, 0, 3, 1};
static const struct rule R_MODE = {"an integer from 1 to 4", 1, 0, 4, 1};
static const struct rule R_H_OVER_DX = {"a number > 0 and <= 10", 0, 1, 10, 0};
static const struct rule R_DX_RATIO = {"1 or 2", 1, 0, 2, 1};
static const struct rule R_POISSON = {"a number > -1 and < 0.5", -1, 1, 0.5, 0};   /* 0.5 itself: poisson_below_half */

/* Default density bands [min, max] / rho0 of the instability check: a liquid, a gas. */
static const double LIQUID_BAND[2] = {0.5, 2.0}, GAS_BAND[2] = {0.1, 10.0};
#define ENERGY_GROWTH 1.0       /* default time.energy_growth [M U_max^2 / 2] */
#define DT_MIN_FRACTION 1e-6   /* default time.dt_min / the acoustic step CFL h / max c0 */
#define WALL_GUARD_DX 0.25     /* default physics.wall_guard [dx] */

/* Loader state: where messages go and the dimension read so far. */
struct ld {
  char *err;
  size_t err_len;
  int dim;
};

/* A mapping being read; node NULL when absent (every key then takes its default). */
struct map {
  struct ld *ld;
  const struct ynode *node;
  const struct ynode *at;    /* node, or the nearest present ancestor: where missing keys are */
  char path[PATH_LEN];
};


/* ---- the key tables: what a key holds ---- */

/* The value of a key and the member it fills. */
enum key_type {
  KEY_NUMBER,    /* double, within rule */
  KEY_INTEGER,   /* int, within an integer rule */
  KEY_COUNT,     /* long, within an integer rule */
  KEY_CHOICE,    /* an enum (int): the index of the word in names */
  KEY_BOOL,      /* int: false or true */
  KEY_TEXT,      /* char[size]: a name of letters, digits and punct, or (punct NULL) any string */
  KEY_VECTOR,    /* double[3]: one number per dimension (zeros when absent and not required) */
  KEY_BAND,      /* double[2]: a density band [min_ratio, max_ratio] */
  KEY_LIST       /* a list of mappings: the count (int) at offset, the items per list */
};

enum key_flags {
  KEY_REQUIRED = 1,   /* no default: missing is an error */
  KEY_LATE = 2,       /* read after every other key (its default needs the lists) */
  KEY_GIVEN = 4       /* the int at `given` says whether the key was given; written only then */
};

typedef int (*item_reader)(const struct map *item, struct case_def *c, int i);
typedef void (*item_writer)(FILE *f, const struct case_def *c, int i);

/* One key of a mapping: where it is, what it holds, its default and its one-line doc. The
 * tables below drive reading and validation, the allowed keys of each mapping, the resolved-case
 * writer and `mpsph keys`. */
struct case_key {
  const char *section;       /* the mapping holding it ("" : the root, or the list item) */
  const char *key;
  enum key_type type;
  size_t offset;             /* of the member in struct case_def, or in the list's item */
  int flags;                 /* enum key_flags */
  const struct rule *rule;   /* KEY_NUMBER, KEY_INTEGER, KEY_COUNT */
  const char *const *names;  /* KEY_CHOICE */
  const char *punct;         /* KEY_TEXT: the punctuation a name may hold (NULL: any string) */
  size_t size;               /* KEY_TEXT: the member's size */
  double def[2];             /* the default: number, word index, band (text: ""; vector: zeros) */
  void (*computed)(const struct case_def *c, const void *item, double *out);   /* or from the
                                                               keys read before it */
  const char *def_doc;       /* the default as the reference shows it, when computed */
  size_t given;              /* KEY_GIVEN */
  int (*written)(const struct case_def *c);   /* NULL: always written */
  int (*check)(const struct map *m, const struct case_def *c, int i);   /* after reading it */
  const struct list_def *list;   /* KEY_LIST */
  const char *doc;           /* what it means, with its unit */
};

/* A list of mappings: its size, and its items' keys (a key table, or a reader and writer of
 * its own with the allowed keys). */
struct list_def {
  const char *what;          /* the items, plural */
  int lo, hi;                /* item count range */
  size_t items, item_size;   /* keys: offset of the item array in struct case_def, item size */
  const struct case_key *keys;
  int n_keys;
  const char *const *allowed;
  item_reader read;
  item_writer put;
};
/* ---- messages ---- */

static int vfail(struct ld *ld, const char *source, int line, const char *path, const char *fmt,
                 va_list ap) {
  if (ld->err_len == 0) return 1;
  int k = snprintf(ld->err, ld->err_len, "%s:%d: %s%s", source, line, path, path[0] ? ": " : "");
  if (k >= 0 && (size_t)k < ld->err_len) vsnprintf(ld->err + k, ld->err_len - (size_t)k, fmt, ap);
  return 1;
}

/* Report an error at node `at`; returns 1. */
static int fail(struct ld *ld, const struct ynode *at, const char *path, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  vfail(ld, at->source, at->line, path, fmt, ap);
  va_end(ap);
  return 1;
}

/* Report an error at an explicit source and line; returns 1. */
static int fail_at(struct ld *ld, const char *source, int line, const char *path, const char *fmt,
                   ...) {
  va_list ap;
  va_start(ap, fmt);
  vfail(ld, source, line, path, fmt, ap);
  va_end(ap);
  return 1;
}

static const char *names_list(const char *const *names, char *buf) {
  buf[0] = '\0';
  for (int i = 0; names[i]; i++) {
    size_t k = strlen(buf);
    snprintf(buf + k, LIST_LEN - k, "%s%s", i ? ", " : "", names[i]);
  }
  return buf;
}

/* How a node looks in a message: 'text', the string "text", a list of n items, a mapping. */
static const char *shown(const struct ynode *v, char *buf, size_t len) {
  if (v->kind == YNODE_MAPPING) return "a mapping";
  if (v->kind == YNODE_SEQUENCE)
    snprintf(buf, len, "a list of %d item%s", v->n, v->n == 1 ? "" : "s");
  else
    snprintf(buf, len, v->plain ? "'%.60s'" : "the string \"%.60s\"", v->text);
  return buf;
}

static int fail_got(struct ld *ld, const struct ynode *v, const char *path, const char *expected) {
  char buf[96];
  return fail(ld, v, path, "got %s, expected %s", shown(v, buf, sizeof buf), expected);
}

static const char *fmt_vec(char *buf, size_t len, const double *v, int n) {
  int k = snprintf(buf, len, "[");
  for (int i = 0; i < n && k > 0 && (size_t)k < len; i++)
    k += snprintf(buf + k, len - (size_t)k, "%s%g", i ? ", " : "", v[i]);
  if (k > 0 && (size_t)k < len) snprintf(buf + k, len - (size_t)k, "]");
  return buf;
}

/* ---- paths and lookups ---- */

static void join(char *out, const char *parent, const char *key) {
  if (snprintf(out, PATH_LEN, "%s%s%s", parent, parent[0] ? "." : "", key) >= PATH_LEN)
    out[PATH_LEN - 1] = '\0';
}

static void join_index(char *out, const char *parent, int i) {
  char index[16];
  snprintf(index, sizeof index, "%d", i);
  join(out, parent, index);
}

/* The value of key in m (NULL if absent); its path goes to path. */
static const struct ynode *get(const struct map *m, const char *key, char *path) {
  join(path, m->path, key);
  return ytree_get(m->node, key);
}

static int missing(const struct map *m, const char *path, const char *expected) {
  return fail(m->ld, m->at, path, "missing required key, expected %s", expected);
}

static int check_keys(const struct map *m, const char *const *allowed) {
  for (int i = 0; i < m->node->n; i++) {
    const struct yentry *e = &m->node->entries[i];
    int known = 0;
    for (int k = 0; allowed[k]; k++) known |= strcmp(e->key, allowed[k]) == 0;
    if (known) continue;
    char path[PATH_LEN], names[LIST_LEN];
    join(path, m->path, e->key);
    return fail_at(m->ld, e->value->source, e->key_line, path, "unknown key, allowed keys: %s",
                   names_list(allowed, names));
  }
  return 0;
}

/* Start reading mapping v (may be NULL) at path, with the given allowed keys. */
static int open_map(struct ld *ld, const struct ynode *v, const struct ynode *at, const char *path,
                    const char *const *allowed, struct map *m) {
  m->ld = ld;
  m->node = v;
  m->at = v ? v : at;
  snprintf(m->path, sizeof m->path, "%s", path);
  if (!v) return 0;
  if (v->kind != YNODE_MAPPING) {
    char expected[LIST_LEN + 32], names[LIST_LEN];
    snprintf(expected, sizeof expected, "a mapping with keys: %s", names_list(allowed, names));
    return fail_got(ld, v, path, expected);
  }
  return check_keys(m, allowed);
}

/* Start reading the mapping under key of parent. */
static int sub(const struct map *parent, const char *key, const char *const *allowed,
               struct map *m) {
  char path[PATH_LEN];
  const struct ynode *v = get(parent, key, path);
  return open_map(parent->ld, v, parent->at, path, allowed, m);
}

/* ---- scalar getters ---- */

/* 1 if x is a value the rule allows. */
static int allowed(const struct rule *r, double x) {
  return isfinite(x) && (r->lo_open ? x > r->lo : x >= r->lo) && x <= r->hi &&
         (!r->integer || x == floor(x));
}

static int number_of(struct ld *ld, const struct ynode *v, const char *path, const struct rule *r,
                     double *out) {
  char *end = NULL;
  double x = 0;
  if (v->kind == YNODE_SCALAR && v->plain && v->text[0]) x = strtod(v->text, &end);
  if (!end || *end != '\0' || !allowed(r, x)) return fail_got(ld, v, path, r->expected);
  *out = x;
  return 0;
}

/* The number under key (def when absent; def REQUIRED makes it required). */
static int num(const struct map *m, const char *key, const struct rule *r, double def,
               double *out) {
  char path[PATH_LEN];
  const struct ynode *v = get(m, key, path);
  if (v) return number_of(m->ld, v, path, r, out);
  if (isnan(def)) return missing(m, path, r->expected);
  if (!allowed(r, def))   /* a default computed from other keys, e.g. an underflow to 0 */
    return fail(m->ld, m->at, path, "got the default %g computed from the other keys, expected %s: "
                "set the key", def, r->expected);
  *out = def;
  return 0;
}

static int lnum(const struct map *m, const char *key, const struct rule *r, double def,
                long *out) {
  double x;
  if (num(m, key, r, def, &x)) return 1;
  *out = (long)x;
  return 0;
}

/* The index of the value of key in names (def when absent). */
static int choice(const struct map *m, const char *key, const char *const *names, int def,
                  int *out) {
  char path[PATH_LEN], list[LIST_LEN], buf[96];
  const struct ynode *v = get(m, key, path);
  *out = def;
  if (!v) return 0;
  for (int i = 0; names[i]; i++)
    if (v->kind == YNODE_SCALAR && strcmp(v->text, names[i]) == 0) {
      *out = i;
      return 0;
    }
  return fail(m->ld, v, path, "got %s, allowed values: %s", shown(v, buf, sizeof buf),
              names_list(names, list));
}

static int text_ok(const char *s, const char *punct, size_t cap) {
  size_t n = strlen(s);
  if (n >= cap) return 0;
  if (!punct) return 1;
  for (size_t i = 0; i < n; i++)
    if (!strchr(ALNUM, s[i]) && !strchr(punct, s[i])) return 0;
  return n > 0 && strspn(s, ".") < n;
}

/* What a text of at most cap - 1 characters may be; punct as for text(). */
static const char *text_expected(char *buf, size_t len, const char *punct, size_t cap) {
  if (punct)
    snprintf(buf, len, "a name of 1 to %zu characters from [A-Za-z0-9%s]%s", cap - 1, punct,
             strchr(punct, '.') ? ", not only dots" : "");
  else
    snprintf(buf, len, "a string of at most %zu characters", cap - 1);
  return buf;
}

/* The string under key, shorter than cap; punct non-NULL: a name of letters, digits and punct.
 * def NULL makes it required. */
static int text(const struct map *m, const char *key, const char *punct, const char *def,
                size_t cap, char *out) {
  char path[PATH_LEN], expected[128];
  const struct ynode *v = get(m, key, path);
  text_expected(expected, sizeof expected, punct, cap);
  if (!v && !def) return missing(m, path, expected);
  if (v && (v->kind != YNODE_SCALAR || !text_ok(v->text, punct, cap)))
    return fail_got(m->ld, v, path, expected);
  snprintf(out, cap, "%s", v ? v->text : def);
  return 0;
}

/* ---- vectors, lists and shapes ---- */

/* The n numbers of the list v into out[0..n-1]; expected describes such a list. */
static int vec_of(struct ld *ld, const struct ynode *v, const char *path, int n,
                  const char *expected, double *out) {
  char ipath[PATH_LEN];
  if (v->kind != YNODE_SEQUENCE || v->n != n) return fail_got(ld, v, path, expected);
  for (int i = 0; i < n; i++) {
    join_index(ipath, path, i);
    if (number_of(ld, v->entries[i].value, ipath, &R_ANY, &out[i])) return 1;
  }
  return 0;
}

/* The dimension-long vector under key; left as it is (zero) when absent and not required. */
static int vec(const struct map *m, const char *key, int required, double *out) {
  char path[PATH_LEN], expected[64];
  const struct ynode *v = get(m, key, path);
  snprintf(expected, sizeof expected, "a list of %d numbers (one per dimension)", m->ld->dim);
  if (v) return vec_of(m->ld, v, path, m->ld->dim, expected, out);
  return required ? missing(m, path, expected) : 0;
}

#define BAND_EXPECTED "a list [min_ratio, max_ratio] with 0 <= min_ratio < 1 < max_ratio"

/* The density band [min_ratio, max_ratio] under key, 0 <= min_ratio < 1 < max_ratio; def when
 * absent. */
static int band(const struct map *m, const char *key, const double *def, double *out) {
  static const char *expected = BAND_EXPECTED;
  char path[PATH_LEN], got[128];
  const struct ynode *v = get(m, key, path);
  out[0] = def[0];
  out[1] = def[1];
  if (!v) return 0;
  if (vec_of(m->ld, v, path, 2, expected, out)) return 1;
  if (out[0] >= 0 && out[0] < 1 && out[1] > 1) return 0;
  return fail(m->ld, v, path, "got %s, expected %s", fmt_vec(got, sizeof got, out, 2), expected);
}

/* The dimension x dimension matrix under key (list of rows); left zero when absent. */
static int matrix(const struct map *m, const char *key, double out[3][3]) {
  char path[PATH_LEN], rpath[PATH_LEN], expected[96];
  const struct ynode *v = get(m, key, path);
  int dim = m->ld->dim;
  snprintf(expected, sizeof expected, "a list of %d rows of %d numbers", dim, dim);
  if (!v) return 0;
  if (v->kind != YNODE_SEQUENCE || v->n != dim) return fail_got(m->ld, v, path, expected);
  for (int i = 0; i < dim; i++) {
    join_index(rpath, path, i);
    if (vec_of(m->ld, v->entries[i].value, rpath, dim, expected, out[i])) return 1;
  }
  return 0;
}

/* What a list of lo..hi items may be. */
static const char *list_expected(char *buf, size_t len, int lo, int hi, const char *what) {
  snprintf(buf, len, "a list of %d to %d %s", lo, hi, what);
  return buf;
}

/* The list under key, of lo..hi items (*seq NULL when absent and lo == 0). */
static int list(const struct map *m, const char *key, int lo, int hi, const char *what,
                const struct ynode **seq, char *path) {
  char expected[128];
  list_expected(expected, sizeof expected, lo, hi, what);
  *seq = get(m, key, path);
  if (!*seq) return lo > 0 ? missing(m, path, expected) : 0;
  if ((*seq)->kind != YNODE_SEQUENCE || (*seq)->n < lo || (*seq)->n > hi)
    return fail_got(m->ld, *seq, path, expected);
  return 0;
}

/* max > min in every component, else an error at key max of box mapping m. */
static int ordered(const struct map *m, const double *lo, const double *hi) {
  for (int d = 0; d < m->ld->dim; d++) {
    if (hi[d] > lo[d]) continue;
    char path[PATH_LEN], a[128], b[128];
    const struct ynode *v = get(m, "max", path);
    return fail(m->ld, v, path, "got max %s not above min %s, expected max > min in every "
                "component", fmt_vec(a, sizeof a, hi, m->ld->dim),
                fmt_vec(b, sizeof b, lo, m->ld->dim));
  }
  return 0;
}

/* min and max of a box mapping, max > min in every component. */
static int corners(const struct map *m, double *lo, double *hi) {
  return vec(m, "min", 1, lo) || vec(m, "max", 1, hi) || ordered(m, lo, hi);
}
/* The optional floor or ceiling of a box: its lower or upper face (last axis) becomes the surface
 * z = level + amplitude * sum over the other axes of cos(2 pi x_d / wavelength), e.g. a perturbed
 * interface between a region above (floor) and one below (ceiling). */
static int box_surface(const struct map *m, struct shape *s) {
  struct map fm, cm;
  if (sub(m, "floor", SURFACE_KEYS, &fm) || sub(m, "ceiling", SURFACE_KEYS, &cm)) return 1;
  if (fm.node && cm.node) {
    char path[PATH_LEN];
    return fail(m->ld, get(m, "ceiling", path), path, "got a floor and a ceiling, expected at most one");
  }
  s->surface = fm.node ? SURFACE_FLOOR : cm.node ? SURFACE_CEILING : SURFACE_NONE;
  if (s->surface == SURFACE_NONE) return 0;
  const struct map *sm = fm.node ? &fm : &cm;
  return num(sm, "level", &R_ANY, REQUIRED, &s->surface_level) ||
         num(sm, "amplitude", &R_ANY, REQUIRED, &s->surface_amplitude) ||
         num(sm, "wavelength", &R_POSITIVE, REQUIRED, &s->surface_wavelength);
}

/* The polygon s read from the list seq at path is simple and encloses an area (a crossing,
 * touching or degenerate one has no well-defined inside). */
static int polygon_simple(struct ld *ld, const struct ynode *seq, const char *path, const struct shape *s) {
  int a, b;
  char pa[128], pb[128], qa[128], qb[128];
  const double (*v)[2] = s->vertex;
  int n = s->n_vertices;
  switch (polygon_fault(s, &a, &b)) {
  case POLYGON_REPEATED_VERTEX:
    return fail(ld, seq, path, "vertices %d and %d are the same point %s, expected distinct "
                "vertices", a, b, fmt_vec(pa, sizeof pa, v[a], 2));
  case POLYGON_EDGES_MEET:
    return fail(ld, seq, path, "edges %d (%s to %s) and %d (%s to %s) cross or touch, expected a "
                "simple polygon (edge k joins vertices k and k + 1)", a, fmt_vec(pa, sizeof pa, v[a], 2),
                fmt_vec(pb, sizeof pb, v[(a + 1) % n], 2), b, fmt_vec(qa, sizeof qa, v[b], 2),
                fmt_vec(qb, sizeof qb, v[(b + 1) % n], 2));
  case POLYGON_NO_AREA:
    return fail(ld, seq, path, "encloses no area, expected a simple polygon with an inside");
  default:
    return 0;
  }
}

static int polygon(const struct map *m, struct shape *s) {
  char path[PATH_LEN], ipath[PATH_LEN];
  const struct ynode *seq;
  if (m->ld->dim != 2)
    return fail(m->ld, get(m, "polygon", path), path,
                "got a polygon in 3D, expected box or circle (polygons are 2D only)");
  if (list(m, "polygon", 3, CASE_MAX_VERTICES, "[x, y] vertices", &seq, path)) return 1;
  s->n_vertices = seq->n;
  for (int i = 0; i < seq->n; i++) {
    join_index(ipath, path, i);
    if (vec_of(m->ld, seq->entries[i].value, ipath, 2, "an [x, y] pair", s->vertex[i])) return 1;
  }
  return polygon_simple(m->ld, seq, path, s);
}

/* The one shape (box, circle or polygon) of a fluid or wall item. */
static int shape(const struct map *m, struct shape *s) {
  char names[LIST_LEN];
  struct map sm;
  int count = 0;
  for (int k = 0; SHAPE_NAMES[k]; k++)
    if (ytree_get(m->node, SHAPE_NAMES[k])) {
      s->kind = (enum shape_kind)k;
      count++;
    }
  if (count != 1)
    return fail(m->ld, m->at, m->path, "got %d shapes, expected exactly one of: %s", count,
                names_list(SHAPE_NAMES, names));
  switch (s->kind) {
  case SHAPE_BOX:
    return sub(m, "box", BOX_KEYS, &sm) || corners(&sm, s->min, s->max) || box_surface(&sm, s);
  case SHAPE_CIRCLE:
    if (sub(m, "circle", CIRCLE_KEYS, &sm) || vec(&sm, "centre", 1, s->centre) ||
        num(&sm, "radius", &R_POSITIVE, REQUIRED, &s->radius) ||
        num(&sm, "inner_radius", &R_NONNEGATIVE, 0, &s->inner_radius))
      return 1;
    if (s->inner_radius < s->radius) return 0;
    char path[PATH_LEN];
    return fail(m->ld, ytree_get(sm.node, "inner_radius"), strcat(strcpy(path, sm.path), ".inner_radius"),
                "got %g, expected a number below radius (%g)", s->inner_radius, s->radius);
  default:
    return polygon(m, s);
  }
}

static void bbox(const struct shape *s, double *lo, double *hi) {
  for (int d = 0; d < 3; d++) {
    lo[d] = s->kind == SHAPE_BOX ? s->min[d] : s->centre[d] - s->radius;
    hi[d] = s->kind == SHAPE_BOX ? s->max[d] : s->centre[d] + s->radius;
  }
  if (s->kind != SHAPE_POLYGON) return;
  for (int d = 0; d < 2; d++) {
    lo[d] = hi[d] = s->vertex[0][d];
    for (int i = 1; i < s->n_vertices; i++) {
      lo[d] = fmin(lo[d], s->vertex[i][d]);
      hi[d] = fmax(hi[d], s->vertex[i][d]);
    }
  }
}

/* The point (lo == hi) or bounding box lo..hi given under key lies inside the domain. */
static int inside(const struct map *m, const char *key, const double *lo, const double *hi,
                  const struct case_def *c) {
  int dim = m->ld->dim, point = memcmp(lo, hi, (size_t)dim * sizeof *lo) == 0;
  for (int d = 0; d < dim; d++) {
    if (lo[d] >= c->domain_min[d] && hi[d] <= c->domain_max[d]) continue;
    char path[PATH_LEN], a[128], b[128], dmin[128], dmax[128];
    const struct ynode *v = get(m, key, path);
    fmt_vec(a, sizeof a, lo, dim);
    fmt_vec(b, sizeof b, hi, dim);
    return fail(m->ld, v, path, "got %s%s%s%s outside the domain, expected %s inside the domain "
                "min %s max %s", point ? "" : "bounding box min ", a, point ? "" : " max ",
                point ? "" : b, point ? "a point" : "a shape",
                fmt_vec(dmin, sizeof dmin, c->domain_min, dim),
                fmt_vec(dmax, sizeof dmax, c->domain_max, dim));
  }
  return 0;
}

/* The name under "name" of item i of an array (first, stride) differs from the earlier ones. */
static int unique_name(const struct map *m, const char *first, size_t stride, int i) {
  const char *name = first + (size_t)i * stride;
  char path[PATH_LEN];
  for (int j = 0; j < i; j++)
    if (strcmp(first + (size_t)j * stride, name) == 0)
      return fail(m->ld, get(m, "name", path), path, "got '%s' a second time, expected unique "
                  "names", name);
  return 0;
}


/* ---- the items of the lists with readers of their own ---- */

static int phase_index(const struct map *m, const struct case_def *c, int *out) {
  char name[CASE_MAX_NAME], path[PATH_LEN], known[LIST_LEN] = "";
  if (text(m, "phase", NULL, NULL, sizeof name, name)) return 1;
  for (int i = 0; i < c->n_phases; i++) {
    if (strcmp(c->phases[i].name, name) == 0) {
      *out = i;
      return 0;
    }
    size_t k = strlen(known);
    snprintf(known + k, sizeof known - k, "%s%s", i ? ", " : "", c->phases[i].name);
  }
  return fail(m->ld, get(m, "phase", path), path, "unknown phase '%s', known phases: %s", name,
              known);
}

static int shape_inside(const struct map *m, const struct shape *s, const struct case_def *c) {
  double lo[3], hi[3];
  bbox(s, lo, hi);
  return inside(m, SHAPE_NAMES[s->kind], lo, hi, c);
}

/* The interface mode {amplitude: m/s, wavelength: m, interface: y [m]} of a region (2D only);
 * inactive when the key is absent. */
static int read_velocity_mode(const struct map *fluid, struct velocity_mode *mode) {
  char path[PATH_LEN];
  struct map m;
  if (sub(fluid, "velocity_mode", MODE_KEYS, &m)) return 1;
  mode->active = m.node != NULL;
  if (!mode->active) return 0;
  if (fluid->ld->dim != 2)
    return fail(fluid->ld, get(fluid, "velocity_mode", path), path,
                "got velocity_mode in 3D (the interface mode is 2D only)");
  return num(&m, "amplitude", &R_ANY, REQUIRED, &mode->amplitude) ||
         num(&m, "wavelength", &R_POSITIVE, REQUIRED, &mode->wavelength) ||
         num(&m, "interface", &R_ANY, REQUIRED, &mode->interface);
}

static int read_fluid(const struct map *m, struct case_def *c, int i) {
  struct fluid_region *f = &c->fluids[i];
  return phase_index(m, c, &f->phase) || shape(m, &f->shape) || shape_inside(m, &f->shape, c) ||
         vec(m, "velocity", 0, f->velocity) || matrix(m, "velocity_gradient", f->velocity_gradient) ||
         read_velocity_mode(m, &f->mode);
}

/* The ramp of a motion law: {shape: none | linear | smooth, time: seconds}. */
static int read_ramp(const struct map *law, struct motion_law *l) {
  struct map m;
  int kind;
  if (sub(law, "ramp", RAMP_KEYS, &m) || choice(&m, "shape", RAMP_NAMES, RAMP_NONE, &kind)) return 1;
  l->ramp = (enum ramp_kind)kind;
  return num(&m, "time", &R_POSITIVE, kind == RAMP_NONE ? 1.0 : REQUIRED, &l->ramp_time);
}

/* A translation (vector amplitude [m]) or rotation (angle amplitude [rad]) law under key; the
 * law stays inactive when the key is absent. */
static int read_law(const struct map *motion, const char *key, const char *const *keys, int vector,
                    struct motion_law *l, struct map *m) {
  if (sub(motion, key, keys, m)) return 1;
  l->active = m->node != NULL;
  if (!l->active) return 0;
  return (vector ? vec(m, "amplitude", 1, l->amplitude) : num(m, "amplitude", &R_ANY, REQUIRED, l->amplitude)) ||
         num(m, "period", &R_POSITIVE, REQUIRED, &l->period) || num(m, "phase", &R_ANY, 0, &l->phase) ||
         read_ramp(m, l);
}

/* The rows of the motion table under key: [t, dx, dy, theta] in 2D, [t, dx, dy, dz, theta] in
 * 3D, 2 to MOTION_MAX_ROWS of them at strictly increasing times. */
static int read_table(const struct map *m, struct wall_motion *w) {
  char path[PATH_LEN], ipath[PATH_LEN], expected[96];
  const struct ynode *seq;
  int dim = m->ld->dim, n = dim + 2;
  double row[MOTION_TABLE_COLUMNS];
  if (list(m, "table", 2, MOTION_MAX_ROWS, "rows [t, displacement..., theta]", &seq, path)) return 1;
  snprintf(expected, sizeof expected, "a row of %d numbers [t, %s, theta]", n,
           dim == 2 ? "dx, dy" : "dx, dy, dz");
  w->n_rows = seq->n;
  for (int i = 0; i < seq->n; i++) {
    join_index(ipath, path, i);
    if (vec_of(m->ld, seq->entries[i].value, ipath, n, expected, row)) return 1;
    double *t = w->table[i];
    t[0] = row[0], t[1] = row[1], t[2] = row[2], t[3] = dim == 3 ? row[3] : 0, t[4] = row[n - 1];
    if (i > 0 && !(t[0] > w->table[i - 1][0]))
      return fail(m->ld, seq->entries[i].value, ipath, "got time %g after %g, expected strictly "
                  "increasing times", t[0], w->table[i - 1][0]);
  }
  return 0;
}

/* The rotation axis under m's key axis (3D only; any length but 0, kept as given), [0, 0, 1] when
 * absent: 2D cases turn about z. */
static int read_axis(const struct map *m, struct wall_motion *w) {
  char path[PATH_LEN];
  const struct ynode *axis = get(m, "axis", path);
  w->axis[0] = w->axis[1] = 0, w->axis[2] = 1;
  if (!axis) return 0;
  if (m->ld->dim != 3)
    return fail(m->ld, axis, path, "got an axis in 2D, expected none: a 2D wall turns about z");
  if (vec(m, "axis", 1, w->axis)) return 1;
  double len = w->axis[0] * w->axis[0] + w->axis[1] * w->axis[1] + w->axis[2] * w->axis[2];
  if (len == 0 || !isfinite(len))
    return fail(m->ld, axis, path, "got a zero or overflowing vector, expected a rotation axis of finite length");
  return 0;
}

/* A table motion: the table, its rotation centre (default the origin) and axis; no law beside it. */
static int read_table_motion(const struct map *m, struct wall_motion *w) {
  const struct ynode *law = ytree_get(m->node, "translation") ? ytree_get(m->node, "translation")
                                                              : ytree_get(m->node, "rotation");
  if (law)
    return fail(m->ld, law, m->path, "got a table and a sinusoidal law, expected one of them");
  return read_table(m, w) || vec(m, "centre", 0, w->centre) || read_axis(m, w);
}

/* The case's geometry is the wall at t = 0: a motion must start there (zero displacement and
 * angle at t = 0; a sinusoid without a ramp and with sin(phase) != 0 does not). */
static int check_motion_start(const struct map *m, const struct wall_motion *w) {
  struct frame f;
  motion_frame(w, 0.0, &f);
  double d0 = sqrt(f.d[0] * f.d[0] + f.d[1] * f.d[1] + f.d[2] * f.d[2]);
  if (d0 <= 1e-12 && fabs(f.theta) <= 1e-12) return 0;
  return fail(m->ld, m->node, m->path, "starts displaced (|d(0)| = %g m, theta(0) = %g rad), "
              "expected zero displacement and angle at t = 0: the walls of the case are their "
              "place at t = 0 (use a ramp, a phase of 0 or pi, or a table whose first row is zero)",
              d0, f.theta);
}

/* The prescribed motion of a wall (absent: the wall is fixed). */
static int read_motion(const struct map *wall, struct wall *w) {
  struct map m, translation, rotation;
  char path[PATH_LEN];
  if (sub(wall, "motion", MOTION_KEYS, &m)) return 1;
  w->moving = m.node != NULL;
  if (!w->moving) return 0;
  if (ytree_get(m.node, "table")) return read_table_motion(&m, &w->motion) || check_motion_start(&m, &w->motion);
  for (const char *const *key = (const char *const[]){"centre", "axis", NULL}; *key; key++) {
    const struct ynode *table_key = get(&m, *key, path);
    if (table_key)
      return fail(m.ld, table_key, path, "got %s %s without a table, expected rotation.%s for a "
                  "rotation law (motion.%s is the table's)", **key == 'a' ? "an" : "a", *key, *key, *key);
  }
  return read_law(&m, "translation", TRANSLATION_KEYS, 1, &w->motion.translation, &translation) ||
         read_law(&m, "rotation", ROTATION_KEYS, 0, &w->motion.rotation, &rotation) ||
         (w->motion.rotation.active && vec(&rotation, "centre", 1, w->motion.centre)) ||
         read_axis(&rotation, &w->motion) || check_motion_start(&m, &w->motion);
}

/* A list of a body's degrees of freedom under key (names from the dimension's DOF names) as
 * BODY_DOF_* bits. */
static int read_dofs(const struct map *m, const char *key, unsigned *dofs) {
  char path[PATH_LEN], ipath[PATH_LEN], names[LIST_LEN] = "", expected[LIST_LEN + 32];
  const char *const *dof = m->ld->dim == 2 ? DOF_NAMES_2D : DOF_NAMES_3D;
  const struct ynode *seq;
  for (int k = 0; dof[k]; k++)
    if (dof[k][0]) snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s", names[0] ? ", " : "", dof[k]);
  snprintf(expected, sizeof expected, "a degree of freedom: %s", names);
  *dofs = 0;
  if (list(m, key, 0, 6, "degrees of freedom", &seq, path)) return 1;
  for (int i = 0; seq && i < seq->n; i++) {
    const struct ynode *v = seq->entries[i].value;
    int k = 0;
    while (dof[k] && !(v->kind == YNODE_SCALAR && dof[k][0] && strcmp(v->text, dof[k]) == 0)) k++;
    join_index(ipath, path, i);
    if (!dof[k]) return fail_got(m->ld, v, ipath, expected);
    *dofs |= 1u << k;
  }
  return 0;
}

/* The degrees of freedom motion m moves (BODY_DOF_* bits): a translation component of nonzero
 * amplitude or table column, and the rotations (all three in 3D) of a rotation law or a table's
 * nonzero angle column. */
static unsigned motion_dofs(const struct wall_motion *m, int dim) {
  unsigned dofs = 0;
  for (int c = 0; c < 4; c++) {
    int moves = c < 3 ? m->translation.active && m->translation.amplitude[c] != 0 : m->rotation.active;
    for (int row = 0; row < m->n_rows; row++) moves |= m->table[row][1 + c] != 0;
    if (moves) dofs |= c < 3 ? BODY_DOF_X << c : dim == 2 ? BODY_DOF_RZ : BODY_DOF_RX | BODY_DOF_RY | BODY_DOF_RZ;
  }
  return dofs;
}

/* A body's prescribed degrees of freedom: a wall motion for them and no other, none of them
 * fixed, a 3D body's rotations all prescribed or none, and a prescribed rotation about the body's
 * centre of mass. */
static int check_prescribed(const struct map *wall, const struct map *m, const struct wall *w) {
  const struct body *b = &w->body;
  const unsigned rotations = BODY_DOF_RX | BODY_DOF_RY | BODY_DOF_RZ, turning = b->prescribed & rotations;
  char path[PATH_LEN];
  const struct ynode *motion = get(wall, "motion", path);
  if (!motion && b->prescribed)
    return fail(m->ld, m->node, m->path, "got prescribed degrees of freedom and no motion, expected "
                "walls.N.motion giving their law");
  if (!motion) return 0;
  if (!b->prescribed)
    return fail(m->ld, motion, path, "got a motion and a body without body.prescribed, expected body.prescribed "
                "to name the degrees of freedom the motion sets (a body's others move as the flow drives them)");
  if (b->prescribed & b->fixed)
    return fail(m->ld, m->node, m->path, "got a degree of freedom both fixed and prescribed, expected each in one list");
  if (m->ld->dim == 3 && turning && turning != rotations)
    return fail(m->ld, m->node, m->path, "got some of a 3D body's rotations prescribed, expected rx, ry and rz "
                "together or none of them");
  if (motion_dofs(&w->motion, m->ld->dim) & ~b->prescribed)
    return fail(m->ld, motion, path, "moves a degree of freedom the body does not prescribe, expected the "
                "motion's other translations, and its rotation unless prescribed, to be zero");
  double off = 0;
  for (int d = 0; d < m->ld->dim; d++) off += fabs(w->motion.centre[d] - b->centre[d]);
  if (turning && off > 1e-12 * (1 + fabs(b->centre[0]) + fabs(b->centre[1]) + fabs(b->centre[2])))
    return fail(m->ld, motion, path, "turns about (%g, %g, %g), expected the body's centre of mass (%g, %g, %g): "
                "a prescribed rotation turns the body about it", w->motion.centre[0], w->motion.centre[1],
                w->motion.centre[2], b->centre[0], b->centre[1], b->centre[2]);
  return 0;
}

/* A rotation rate or moment under key: a number (about z) in 2D, a vector in 3D, into out[2] or
 * out[0..2]. */
static int per_rotation(const struct map *m, const char *key, const struct rule *r, double *out) {
  if (m->ld->dim == 3) return vec(m, key, 0, out);
  return num(m, key, r, out[2], &out[2]);
}

/* The rigid body of wall w (absent: the wall is not a body): mass, and centre of mass and inertia
 * by default those of the wall's shape filled uniformly. */
static int read_body(const struct map *wall, struct wall *w) {
  struct map m;
  struct body *b = &w->body;
  if (sub(wall, "body", BODY_KEYS, &m)) return 1;
  b->active = m.node != NULL;
  if (!b->active) return 0;
  double per_mass[3];
  shape_mass_properties(&w->shape, m.ld->dim, b->centre, per_mass);
  if (num(&m, "mass", &R_POSITIVE, REQUIRED, &b->mass)) return 1;
  for (int d = 0; d < 3; d++) b->inertia[d] = b->mass * per_mass[d];
  if (vec(&m, "centre", 0, b->centre) || per_rotation(&m, "inertia", &R_POSITIVE, b->inertia) ||
      vec(&m, "velocity", 0, b->velocity) || per_rotation(&m, "angular_velocity", &R_ANY, b->angular_velocity) ||
      read_dofs(&m, "fixed", &b->fixed) || read_dofs(&m, "prescribed", &b->prescribed) ||
      check_prescribed(wall, &m, w))
    return 1;
  for (int d = 0; d < 3; d++)
    if (!(b->inertia[d] > 0) && (m.ld->dim == 3 || d == 2))
      return fail(m.ld, m.node, m.path, "got a moment of inertia of %g, expected > 0 (set body.inertia)", b->inertia[d]);
  w->moving = 1;
  return 0;
}

static int read_wall(const struct map *m, struct case_def *c, int i) {
  struct wall *w = &c->walls[i];
  int slip, side;
  char path[PATH_LEN];
  if (shape(m, &w->shape)) return 1;
  if (w->shape.surface != SURFACE_NONE)
    return fail(m->ld, get(m, "box", path), path, "got a box with a floor or ceiling in a wall, expected a "
                "plain box (a cosine surface shapes fluid regions only)");
  if (choice(m, "slip", SLIP_NAMES, SLIP_FREE, &slip) ||
      choice(m, "fluid_side", SIDE_NAMES, FLUID_INSIDE, &side) || read_motion(m, w) || read_body(m, w))
    return 1;
  w->slip = (enum slip_kind)slip;
  w->fluid_side = (enum fluid_side)side;
  return 0;
}

/* The keys of a probe item each kind reads (name and kind aside). */
static const char *const PROBE_KIND_KEYS[][6] = {
    {"position", "diameter", "axis", "interpolation", "wall", NULL},   /* pressure */
    {"position", "phase", NULL},                                       /* elevation */
    {"phase", NULL}};                                                  /* integral */

/* Every key of probe item m is one its kind reads. */
static int probe_keys(const struct map *m, enum probe_kind kind) {
  for (int i = 0; i < m->node->n; i++) {
    const struct yentry *e = &m->node->entries[i];
    int known = strcmp(e->key, "name") == 0 || strcmp(e->key, "kind") == 0;
    for (int k = 0; PROBE_KIND_KEYS[kind][k]; k++) known |= strcmp(e->key, PROBE_KIND_KEYS[kind][k]) == 0;
    if (known) continue;
    char path[PATH_LEN], names[LIST_LEN];
    join(path, m->path, e->key);
    return fail_at(m->ld, e->value->source, e->key_line, path, "not a key of kind %s, its keys: "
                   "name, kind, %s", PROBE_KIND_NAMES[kind], names_list(PROBE_KIND_KEYS[kind], names));
  }
  return 0;
}

/* The face of a pressure sensor: diameter (0, a point, by default) and, when above 0 (2D
 * only), the direction axis of the segment (any length but 0); both ends inside the domain. */
static int sensor_face(const struct map *m, struct probe *p, const struct case_def *c) {
  char path[PATH_LEN];
  double len = 0, lo[3], hi[3];
  if (num(m, "diameter", &R_NONNEGATIVE, 0, &p->diameter)) return 1;
  const struct ynode *axis = get(m, "axis", path);
  if (p->diameter == 0 && axis)
    return fail(m->ld, axis, path, "got an axis for a point sensor, expected it only with a diameter > 0");
  if (p->diameter == 0) return 0;
  if (m->ld->dim != 2)
    return fail(m->ld, get(m, "diameter", path), path, "got a diameter in 3D, expected 0 "
                "(segment sensors are 2D only)");
  if (vec(m, "axis", 1, p->axis)) return 1;
  for (int d = 0; d < 2; d++) len += p->axis[d] * p->axis[d];
  if (len == 0 || !isfinite(len)) return fail(m->ld, axis, path, "got a zero or overflowing vector, expected a direction of finite length");
  for (int d = 0; d < 2; d++) {   /* the axis stays as given (the round trip); its unit vector: */
    lo[d] = p->position[d] - 0.5 * p->diameter * p->axis[d] / sqrt(len);
    hi[d] = p->position[d] + 0.5 * p->diameter * p->axis[d] / sqrt(len);
  }
  return inside(m, "diameter", lo, lo, c) || inside(m, "diameter", hi, hi, c);
}

/* The moving wall that carries pressure sensor p (key wall; absent: fixed in space, -1). */
static int sensor_wall(const struct map *m, struct probe *p, const struct case_def *c) {
  char path[PATH_LEN];
  double w = -1;
  const struct ynode *v = get(m, "wall", path);
  if (v && num(m, "wall", &R_COUNT, 0, &w)) return 1;
  p->wall = (int)w;
  if (v && (p->wall >= c->n_walls || !c->walls[p->wall].moving))
    return fail(m->ld, v, path, "got wall %d, expected the index of a moving wall (one with a motion or a body)",
                p->wall);
  return 0;
}

/* A wave gauge needs a vertical: gravity not zero. */
static int gravity_axis(const struct map *m, const struct case_def *c) {
  char path[PATH_LEN];
  for (int d = 0; d < c->dimension; d++)
    if (c->gravity[d] != 0) return 0;
  return fail(m->ld, get(m, "kind", path), path, "got an elevation probe with zero gravity, expected "
              "a gravity (its direction is the gauge's vertical)");
}

/* The keys of probe p of the kind read. */
static int probe_body(const struct map *m, struct probe *p, const struct case_def *c) {
  int interp;
  if (probe_keys(m, p->kind)) return 1;
  if (p->kind == PROBE_INTEGRAL) return phase_index(m, c, &p->phase);
  if (vec(m, "position", 1, p->position) || inside(m, "position", p->position, p->position, c))
    return 1;
  if (p->kind == PROBE_ELEVATION) return phase_index(m, c, &p->phase) || gravity_axis(m, c);
  if (choice(m, "interpolation", INTERP_NAMES, INTERP_SHEPARD, &interp)) return 1;
  p->interpolation = (enum probe_interpolation)interp;
  return sensor_face(m, p, c) || sensor_wall(m, p, c);
}

/* The probes.csv columns of probe i differ from those of the earlier probes. */
static int unique_columns(const struct map *m, const struct case_def *c, int i) {
  char a[2 * CASE_MAX_NAME], b[2 * CASE_MAX_NAME], path[PATH_LEN];
  for (int k = 0; k < case_probe_column(c, i, 0, NULL, 0); k++)
    for (int j = 0; j < i; j++)
      for (int l = 0; l < case_probe_column(c, j, 0, NULL, 0); l++) {
        case_probe_column(c, i, k, a, sizeof a);
        case_probe_column(c, j, l, b, sizeof b);
        if (strcmp(a, b) == 0)
          return fail(m->ld, get(m, "name", path), path, "gives the probes.csv column '%s' of "
                      "probe %d a second time, expected unique columns", a, j);
      }
  return 0;
}

static int read_probe(const struct map *m, struct case_def *c, int i) {
  struct probe *p = &c->probes[i];
  int kind;
  if (text(m, "name", PROBE_PUNCT, NULL, sizeof p->name, p->name) ||
      unique_name(m, c->probes[0].name, sizeof c->probes[0], i) ||
      choice(m, "kind", PROBE_KIND_NAMES, PROBE_PRESSURE, &kind))
    return 1;
  p->kind = (enum probe_kind)kind;
  p->wall = -1;
  return probe_body(m, p, c) || unique_columns(m, c, i);
}

/* ---- writing ---- */

/* The shortest of %.15g, %.16g, %.17g that reads back as x exactly. */
static const char *fmt_num(char *buf, size_t len, double x) {
  for (int digits = 15; digits <= 17; digits++) {
    snprintf(buf, len, "%.*g", digits, x);
    if (strtod(buf, NULL) == x) break;
  }
  return buf;
}

static void put_num(FILE *f, const char *indent, const char *key, double x) {
  char buf[32];
  fprintf(f, "%s%s: %s\n", indent, key, fmt_num(buf, sizeof buf, x));
}

static void put_word(FILE *f, const char *indent, const char *key, const char *word) {
  fprintf(f, "%s%s: %s\n", indent, key, word);
}

static void put_long(FILE *f, const char *indent, const char *key, long x) {
  fprintf(f, "%s%s: %ld\n", indent, key, x);
}

static void put_flow_vec(FILE *f, const double *v, int n) {
  char buf[32];
  fputc('[', f);
  for (int i = 0; i < n; i++) fprintf(f, "%s%s", i ? ", " : "", fmt_num(buf, sizeof buf, v[i]));
  fputc(']', f);
}

static void put_vec(FILE *f, const char *indent, const char *key, const double *v, int n) {
  fprintf(f, "%s%s: ", indent, key);
  put_flow_vec(f, v, n);
  fputc('\n', f);
}

/* A fluid region's interface mode, when it has one. */
static void put_velocity_mode(FILE *f, const struct velocity_mode *mode) {
  if (!mode->active) return;
  fputs("    velocity_mode:\n", f);
  put_num(f, "      ", "amplitude", mode->amplitude);
  put_num(f, "      ", "wavelength", mode->wavelength);
  put_num(f, "      ", "interface", mode->interface);
}

/* The code point of the UTF-8 sequence at s and its length in *n; a malformed sequence reads as
 * the one byte U+FFFD. */
static unsigned long utf8_at(const unsigned char *s, int *n) {
  *n = s[0] < 0xc0 ? 1 : s[0] < 0xe0 ? 2 : s[0] < 0xf0 ? 3 : 4;
  if (*n == 1) return s[0] < 0x80 ? s[0] : 0xfffd;
  unsigned long cp = s[0] & (0x7fu >> *n);
  for (int i = 1; i < *n; i++) {
    if ((s[i] & 0xc0) != 0x80) return *n = 1, 0xfffd;
    cp = (cp << 6) | (s[i] & 0x3fu);
  }
  return cp;
}

/* 1 if a double-quoted YAML scalar may hold code point cp as it is: printable, not a quote, a
 * backslash or a line break (NEL, LS and PS would fold into spaces when read again). */
static int yaml_verbatim(unsigned long cp) {
  if (cp == '"' || cp == '\\') return 0;
  return (cp >= 0x20 && cp <= 0x7e) || (cp >= 0xa0 && cp <= 0xd7ff && cp != 0x2028 && cp != 0x2029) ||
         (cp >= 0xe000 && cp <= 0xfffd && cp != 0xfeff) || (cp >= 0x10000 && cp <= 0x10ffff);
}

/* A double-quoted YAML string; characters it may not hold as they are are escaped. */
static void put_str(FILE *f, const char *indent, const char *key, const char *s) {
  fprintf(f, "%s%s: \"", indent, key);
  const unsigned char *c = (const unsigned char *)s;
  for (int n; *c; c += n) {
    unsigned long cp = utf8_at(c, &n);
    if (yaml_verbatim(cp))
      fwrite(c, 1, (size_t)n, f);
    else if (cp == '"' || cp == '\\')
      fprintf(f, "\\%c", (int)cp);
    else
      fprintf(f, cp < 0x100 ? "\\x%02lx" : cp < 0x10000 ? "\\u%04lx" : "\\U%08lx", cp);
  }
  fputs("\"\n", f);
}

/* The cosine floor or ceiling of a box under its keys' indent. */
static void put_surface(FILE *f, const char *inner, const struct shape *s) {
  char deeper[32];
  snprintf(deeper, sizeof deeper, "%s  ", inner);
  fprintf(f, "%s%s:\n", inner, s->surface == SURFACE_FLOOR ? "floor" : "ceiling");
  put_num(f, deeper, "level", s->surface_level);
  put_num(f, deeper, "amplitude", s->surface_amplitude);
  put_num(f, deeper, "wavelength", s->surface_wavelength);
}

/* A shape key at indent, its mapping entries at inner. */
static void put_shape(FILE *f, const char *indent, const char *inner, const struct shape *s,
                      int dim) {
  fprintf(f, "%s%s:", indent, SHAPE_NAMES[s->kind]);
  if (s->kind == SHAPE_POLYGON) {
    fputs(" [", f);
    for (int i = 0; i < s->n_vertices; i++) {
      fputs(i ? ", " : "", f);
      put_flow_vec(f, s->vertex[i], 2);
    }
    fputs("]\n", f);
    return;
  }
  fputc('\n', f);
  put_vec(f, inner, s->kind == SHAPE_BOX ? "min" : "centre", s->kind == SHAPE_BOX ? s->min :
          s->centre, dim);
  if (s->kind == SHAPE_BOX) {
    put_vec(f, inner, "max", s->max, dim);
    if (s->surface != SURFACE_NONE) put_surface(f, inner, s);
  } else {
    put_num(f, inner, "radius", s->radius);
    put_num(f, inner, "inner_radius", s->inner_radius);
  }
}

static void put_list_key(FILE *f, const char *key, int n) {
  fprintf(f, "%s:%s\n", key, n ? "" : " []");
}
/* One motion law under key (nothing when inactive). */
static void put_law(FILE *f, const char *key, const struct motion_law *l, int vector, int dim) {
  if (!l->active) return;
  fprintf(f, "      %s:\n", key);
  if (vector) put_vec(f, "        ", "amplitude", l->amplitude, dim);
  else put_num(f, "        ", "amplitude", l->amplitude[0]);
  put_num(f, "        ", "period", l->period);
  put_num(f, "        ", "phase", l->phase);
  fputs("        ramp:\n", f);
  put_word(f, "          ", "shape", RAMP_NAMES[l->ramp]);
  put_num(f, "          ", "time", l->ramp_time);
}

/* The rows of a motion table, one flow list per line. */
static void put_table(FILE *f, const struct wall_motion *m, int dim) {
  fputs("      table:\n", f);
  for (int i = 0; i < m->n_rows; i++) {
    double row[MOTION_TABLE_COLUMNS] = {m->table[i][0], m->table[i][1], m->table[i][2]};
    row[3] = dim == 3 ? m->table[i][3] : m->table[i][4];
    row[4] = m->table[i][4];
    fputs("        - ", f);
    put_flow_vec(f, row, dim + 2);
    fputc('\n', f);
  }
  put_vec(f, "      ", "centre", m->centre, dim);
  if (dim == 3) put_vec(f, "      ", "axis", m->axis, dim);
}

static void put_motion(FILE *f, const struct wall_motion *m, int dim) {
  fputs("    motion:\n", f);
  if (m->n_rows > 0) {
    put_table(f, m, dim);
    return;
  }
  put_law(f, "translation", &m->translation, 1, dim);
  put_law(f, "rotation", &m->rotation, 0, dim);
  if (m->rotation.active) put_vec(f, "        ", "centre", m->centre, dim);
  if (m->rotation.active && dim == 3) put_vec(f, "        ", "axis", m->axis, dim);
}


/* A rotation rate or moment: a number (about z) in 2D, a vector in 3D. */
static void put_per_rotation(FILE *f, const char *key, const double *v, int dim) {
  if (dim == 3) put_vec(f, "      ", key, v, 3);
  else put_num(f, "      ", key, v[2]);
}

/* A list of degrees of freedom (BODY_DOF_* bits dofs) under key. */
static void put_dofs(FILE *f, const char *key, unsigned dofs, int dim) {
  const char *const *dof = dim == 2 ? DOF_NAMES_2D : DOF_NAMES_3D;
  fprintf(f, "      %s: [", key);
  for (int k = 0, n = 0; dof[k]; k++)
    if (dofs & (1u << k)) fprintf(f, "%s%s", n++ ? ", " : "", dof[k]);
  fputs("]\n", f);
}

static void put_body(FILE *f, const struct body *b, int dim) {
  fputs("    body:\n", f);
  put_num(f, "      ", "mass", b->mass);
  put_vec(f, "      ", "centre", b->centre, dim);
  put_per_rotation(f, "inertia", b->inertia, dim);
  put_vec(f, "      ", "velocity", b->velocity, dim);
  put_per_rotation(f, "angular_velocity", b->angular_velocity, dim);
  put_dofs(f, "fixed", b->fixed, dim);
  put_dofs(f, "prescribed", b->prescribed, dim);
}

/* Fluid region i (the list's own writer). */
static void put_fluid(FILE *f, const struct case_def *c, int i) {
  const struct fluid_region *r = &c->fluids[i];
  put_str(f, "  - ", "phase", c->phases[r->phase].name);
  put_shape(f, "    ", "      ", &r->shape, c->dimension);
  put_vec(f, "    ", "velocity", r->velocity, c->dimension);
  fputs("    velocity_gradient: [", f);
  for (int a = 0; a < c->dimension; a++) {
    fputs(a ? ", " : "", f);
    put_flow_vec(f, r->velocity_gradient[a], c->dimension);
  }
  fputs("]\n", f);
  put_velocity_mode(f, &r->mode);
}

/* Wall i (the list's own writer). */
static void put_wall(FILE *f, const struct case_def *c, int i) {
  const struct wall *w = &c->walls[i];
  put_shape(f, "  - ", "      ", &w->shape, c->dimension);
  put_word(f, "    ", "slip", SLIP_NAMES[w->slip]);
  put_word(f, "    ", "fluid_side", SIDE_NAMES[w->fluid_side]);
  if (w->body.active) put_body(f, &w->body, c->dimension);
  if (w->moving && (!w->body.active || w->body.prescribed)) put_motion(f, &w->motion, c->dimension);
}

/* Probe i (the list's own writer): its name, kind and the keys of its kind. */
static void put_probe(FILE *f, const struct case_def *c, int i) {
  const struct probe *p = &c->probes[i];
  put_str(f, "  - ", "name", p->name);
  put_word(f, "    ", "kind", PROBE_KIND_NAMES[p->kind]);
  if (p->kind != PROBE_INTEGRAL) put_vec(f, "    ", "position", p->position, c->dimension);
  if (p->kind != PROBE_PRESSURE) {
    put_str(f, "    ", "phase", c->phases[p->phase].name);
    return;
  }
  put_word(f, "    ", "interpolation", INTERP_NAMES[p->interpolation]);
  put_num(f, "    ", "diameter", p->diameter);
  if (p->diameter > 0) put_vec(f, "    ", "axis", p->axis, c->dimension);
  if (p->wall >= 0) put_long(f, "    ", "wall", p->wall);
}

/* ---- defaults computed from the keys read before ---- */

static int is_gd(const struct case_def *c) { return c->scheme == SCHEME_GENERALIZED_DISSIPATION; }
static int is_plus(const struct case_def *c) { return c->scheme == SCHEME_DELTA_PLUS; }

/* resolution.h_over_dx: by kernel; paper 004 (generalized-dissipation): h = 1.1 dx. */
static void h_over_dx_default(const struct case_def *c, const void *item, double *out) {
  (void)item;
  out[0] = c->kernel == KERNEL_GAUSSIAN ? (is_gd(c) ? 1.1 : 1.33) : 2.0;
}

/* time.cfl: paper 004's dt = 0.25 h / (c + |u|). */
static void cfl_default(const struct case_def *c, const void *item, double *out) {
  (void)item;
  out[0] = is_gd(c) ? 0.25 : 1.0;
}

/* time.dt_min: a fraction of the acoustic step CFL h / max c0 (needs the phases). */
static void dt_min_default(const struct case_def *c, const void *item, double *out) {
  double c_max = 0;
  (void)item;
  for (int i = 0; i < c->n_phases; i++) c_max = fmax(c_max, c->phases[i].c0);
  out[0] = DT_MIN_FRACTION * c->cfl * c->h_over_dx * c->dx / c_max;
}

static void stats_interval_default(const struct case_def *c, const void *item, double *out) {
  (void)item;
  out[0] = c->t_end / 100;
}

static void probes_interval_default(const struct case_def *c, const void *item, double *out) {
  (void)item;
  out[0] = c->stats_interval;
}

/* physics.delta: paper 004 uses 0.5. */
static void delta_default(const struct case_def *c, const void *item, double *out) {
  (void)item;
  out[0] = is_gd(c) ? 0.5 : 0.1;
}

/* physics.artificial_viscosity: paper 004 physical viscosity only, paper 003 alpha_w = 0.05. */
static void alpha_default(const struct case_def *c, const void *item, double *out) {
  (void)item;
  out[0] = is_gd(c) ? 0.0 : c->scheme == SCHEME_SAME_PHASE_CONTINUITY ? 0.05 : 0.1;
}

/* The terms of paper 000 that the other schemes (papers 001-004) do without: the acoustic
 * damper, consistent shifting, tensile control. */
static void damper_default(const struct case_def *c, const void *item, double *out) {
  (void)item;
  out[0] = is_plus(c) ? 10 : 0;
}

static void shifting_default(const struct case_def *c, const void *item, double *out) {
  (void)item;
  out[0] = is_plus(c) ? SHIFTING_CONSISTENT : SHIFTING_NONE;
}

static void tensile_default(const struct case_def *c, const void *item, double *out) {
  (void)item;
  out[0] = is_plus(c);
}

/* physics.u_max: the c0 = 10 U_max rule of paper 000 read backwards, from the largest sound
 * speed of the liquids (of all phases when there is no liquid). */
static void u_max_default(const struct case_def *c, const void *item, double *out) {
  double c_liquid = 0, c_any = 0;
  (void)item;
  for (int i = 0; i < c->n_phases; i++) {
    c_any = fmax(c_any, c->phases[i].c0);
    if (c->phases[i].incompressible) c_liquid = fmax(c_liquid, c->phases[i].c0);
  }
  out[0] = (c_liquid > 0 ? c_liquid : c_any) / 10.0;
}

/* physics.interface_viscosity: harmonic across the phases in papers 002-004 (004 Eq. 10, 002
 * Eqs. 6-9, 003 Eq. 21). */
static void interface_viscosity_default(const struct case_def *c, const void *item, double *out) {
  (void)item;
  out[0] = is_gd(c) || c->scheme == SCHEME_SAME_PHASE_CONTINUITY || c->scheme == SCHEME_RIEMANN
               ? IFACE_VISC_HARMONIC : IFACE_VISC_NONE;
}

/* phases.N.density_band: by the phase's incompressible, read before it. */
static void band_default(const struct case_def *c, const void *item, double *out) {
  const struct phase *p = item;
  (void)c;
  out[0] = p->incompressible ? LIQUID_BAND[0] : GAS_BAND[0];
  out[1] = p->incompressible ? LIQUID_BAND[1] : GAS_BAND[1];
}

/* physics.dissipation_form is written for its scheme only (the other schemes' files stay as
 * they were before the key existed). */
static int dissipation_written(const struct case_def *c) { return is_gd(c); }

/* The vectors after dimension have its length. */
static int dimension_read(const struct map *m, const struct case_def *c, int i) {
  (void)i;
  m->ld->dim = c->dimension;
  return 0;
}

/* domain.max > domain.min. */
static int domain_ordered(const struct map *m, const struct case_def *c, int i) {
  (void)i;
  return ordered(m, c->domain_min, c->domain_max);
}

/* phases.N.name differs from the earlier phases' names. */
static int phase_name_unique(const struct map *m, const struct case_def *c, int i) {
  return unique_name(m, c->phases[0].name, sizeof c->phases[0], i);
}

/* solids.N (read to clamp_max): max above min, a whole number of dx apart; the clamp box, when given, whole (both corners, max above min). */
static int solid_boxes(const struct map *m, const struct case_def *c, int i) {
  const struct solid_def *s = &c->solids[i];
  char path[PATH_LEN], lo_path[PATH_LEN];
  if (ordered(m, s->min, s->max)) return 1;
  const struct ynode *lo = get(m, "clamp_min", lo_path), *hi = get(m, "clamp_max", path);
  if ((lo == NULL) != (hi == NULL))
    return fail(m->ld, lo ? lo : hi, lo ? lo_path : path, "got one corner of the clamp box, expected both "
                "clamp_min and clamp_max");
  for (int d = 0; d < m->ld->dim; d++) {
    double layers = (s->max[d] - s->min[d]) / c->dx;
    if (fabs(layers - round(layers)) > 1e-6 * layers)
      return fail(m->ld, get(m, "max", path), path, "got a box %.6g particle spacings wide along axis %d, expected a "
                  "whole number of resolution.dx (the particles fill it at min + (i + 1/2) dx)", layers, d);
  }
  for (int d = 0; lo && d < m->ld->dim; d++)
    if (!(s->clamp_max[d] > s->clamp_min[d]))
      return fail(m->ld, hi, path, "got clamp_max not above clamp_min, expected clamp_max > clamp_min in every "
                  "component");
  return 0;
}

/* solids.N.poisson_ratio below 1/2 (an incompressible solid has no finite sound speed). */
static int poisson_below_half(const struct map *m, const struct case_def *c, int i) {
  char path[PATH_LEN];
  if (c->solids[i].poisson < 0.5) return 0;
  return fail(m->ld, get(m, "poisson_ratio", path), path, "got 0.5, expected a number > -1 and < 0.5");
}

/* solids.N.probe inside the solid's box. */
static int probe_in_solid(const struct map *m, const struct case_def *c, int i) {
  const struct solid_def *s = &c->solids[i];
  char path[PATH_LEN];
  for (int d = 0; d < m->ld->dim; d++)
    if (!(s->probe[d] >= s->min[d] && s->probe[d] <= s->max[d]))
      return fail(m->ld, get(m, "probe", path), path, "got a point outside the solid's box, expected a point of "
                  "the solid (between min and max)");
  return 0;
}

/* ---- the key tables ---- */

#define CASE_KEY(sec, name, kind, member, ...)                                                    \
  {.section = sec, .key = name, .type = kind, .offset = offsetof(struct case_def, member), __VA_ARGS__}
#define PHASE_KEY(name, kind, member, ...)                                                        \
  {.section = "", .key = name, .type = kind, .offset = offsetof(struct phase, member), __VA_ARGS__}
#define TEXT_SIZE(type, member) (sizeof ((type *)0)->member)
_Static_assert(sizeof(enum scheme_kind) == sizeof(int), "choices are read and written as int");

/* The keys of a phase, in the order they are read and written. */
static const struct case_key PHASE_ITEM_KEYS[] = {
    PHASE_KEY("name", KEY_TEXT, name, .flags = KEY_REQUIRED, .punct = NAME_PUNCT,
              .size = TEXT_SIZE(struct phase, name), .check = phase_name_unique,
              .doc = "phase name, unique; `fluids.N.phase` refers to it, `stats.csv` columns are named after it"),
    PHASE_KEY("rho0", KEY_NUMBER, rho0, .flags = KEY_REQUIRED, .rule = &R_POSITIVE,
              .doc = "reference density ρ0 [kg/m³]"),
    PHASE_KEY("c0", KEY_NUMBER, c0, .flags = KEY_REQUIRED, .rule = &R_POSITIVE,
              .doc = "numerical sound speed c0 [m/s]"),
    PHASE_KEY("gamma", KEY_NUMBER, gamma, .rule = &R_POSITIVE, .def = {7},
              .doc = "exponent γ of the Tait equation p = ρ0c0²/γ [(ρ/ρ0)^γ − 1] + p_b [-]"),
    PHASE_KEY("p_background", KEY_NUMBER, p_background, .rule = &R_ANY,
              .doc = "background pressure p_b [Pa]"),
    PHASE_KEY("viscosity", KEY_NUMBER, viscosity, .rule = &R_NONNEGATIVE,
              .doc = "dynamic viscosity μ [Pa s], a laminar term added to the artificial viscosity"),
    PHASE_KEY("incompressible", KEY_BOOL, incompressible,
              .doc = "`true`: a liquid (it gets the acoustic damper; its c0 sets the default `u_max`), `false`: a gas"),
    PHASE_KEY("density_band", KEY_BAND, density_band, .computed = band_default,
              .def_doc = "`[0.5, 2]` for a liquid, `[0.1, 10]` for a gas",
              .doc = "a fluid particle of the phase whose ρ/ρ0 leaves the band stops the run as unstable (status 2) [-]"),
    PHASE_KEY("dx_ratio", KEY_INTEGER, dx_ratio, .rule = &R_DX_RATIO, .def = {1},
              .doc = "the phase's particle spacing and smoothing length in units of `resolution.dx` and h: `2` puts a "
              "light phase at twice the spacing (multi-resolution, paper 002 §3.5; scheme riemann only)"),
};

#define SOLID_KEY(name, kind, member, ...)                                                        \
  {.section = "", .key = name, .type = kind, .offset = offsetof(struct solid_def, member), __VA_ARGS__}

/* The keys of a solid, in the order they are read and written. */
static const struct case_key SOLID_ITEM_KEYS[] = {
    SOLID_KEY("min", KEY_VECTOR, min, .flags = KEY_REQUIRED, .doc = "lower corner of the box the solid fills at t = 0 [m]"),
    SOLID_KEY("max", KEY_VECTOR, max, .flags = KEY_REQUIRED,
              .doc = "upper corner of the box; the particles sit at min + (i + ½)Δx [m]"),
    SOLID_KEY("clamp_min", KEY_VECTOR, clamp_min, .flags = KEY_GIVEN, .given = offsetof(struct solid_def, has_clamp),
              .def_doc = "absent", .doc = "lower corner of the clamp box: the solid's particles inside it are held [m]"),
    SOLID_KEY("clamp_max", KEY_VECTOR, clamp_max, .flags = KEY_GIVEN, .given = offsetof(struct solid_def, has_clamp),
              .check = solid_boxes, .def_doc = "absent", .doc = "upper corner of the clamp box [m]"),
    SOLID_KEY("rho0", KEY_NUMBER, rho0, .flags = KEY_REQUIRED, .rule = &R_POSITIVE, .doc = "density [kg/m³]"),
    SOLID_KEY("youngs_modulus", KEY_NUMBER, young, .flags = KEY_REQUIRED, .rule = &R_POSITIVE,
              .doc = "Young's modulus E [Pa]"),
    SOLID_KEY("poisson_ratio", KEY_NUMBER, poisson, .flags = KEY_REQUIRED, .rule = &R_POISSON,
              .check = poisson_below_half, .doc = "Poisson's ratio ν [-]"),
    SOLID_KEY("damping", KEY_NUMBER, damping, .rule = &R_NONNEGATIVE, .def = {0.25},
              .doc = "Kelvin–Voigt pair damping coefficient (doc/theory.md §13); `0`: none [-]"),
    SOLID_KEY("model", KEY_CHOICE, model, .names = SOLID_MODEL_NAMES, .def = {SOLID_SVK},
              .doc = "strain energy: Saint Venant–Kirchhoff (paper 002) or compressible neo-Hookean; plane strain in 2D"),
    SOLID_KEY("correction", KEY_CHOICE, correction, .names = SOLID_CORRECTION_NAMES, .def = {SOLID_QUADRATIC},
              .doc = "the deformation gradient's weights: paper 002's linear correction, or mpsph's quadratic one "
              "(accurate at 4–6 particles through a thickness; doc/theory.md §13)"),
    SOLID_KEY("probe", KEY_VECTOR, probe, .flags = KEY_REQUIRED, .check = probe_in_solid,
              .doc = "a point of the solid at t = 0: `solids.csv` records the displacement of its nearest particle [m]"),
};

static const struct list_def PHASES = {
    .what = "phases", .lo = 1, .hi = CASE_MAX_PHASES, .items = offsetof(struct case_def, phases),
    .item_size = sizeof(struct phase), .keys = PHASE_ITEM_KEYS,
    .n_keys = sizeof PHASE_ITEM_KEYS / sizeof PHASE_ITEM_KEYS[0]};
static const struct list_def FLUIDS = {.what = "fluid regions", .hi = CASE_MAX_REGIONS,
                                       .allowed = FLUID_KEYS, .read = read_fluid, .put = put_fluid};
static const struct list_def WALLS = {.what = "walls", .hi = CASE_MAX_WALLS, .allowed = WALL_KEYS,
                                      .read = read_wall, .put = put_wall};
static const struct list_def SOLIDS = {
    .what = "solids", .hi = CASE_MAX_SOLIDS, .items = offsetof(struct case_def, solids),
    .item_size = sizeof(struct solid_def), .keys = SOLID_ITEM_KEYS,
    .n_keys = sizeof SOLID_ITEM_KEYS / sizeof SOLID_ITEM_KEYS[0]};
static const struct list_def PROBES = {.what = "probes", .hi = CASE_MAX_PROBES, .allowed = PROBE_KEYS,
                                       .read = read_probe, .put = put_probe};

/* The keys of a case, in the order they are written (and read, KEY_LATE aside); the allowed
 * keys of the root and of each section follow from it. */
static const struct case_key CASE_KEYS[] = {
    CASE_KEY("", "name", KEY_TEXT, name, .flags = KEY_REQUIRED, .punct = NAME_PUNCT,
             .size = TEXT_SIZE(struct case_def, name),
             .doc = "case name; the default output folder is `runs/<name>`"),
    CASE_KEY("", "description", KEY_TEXT, description, .size = TEXT_SIZE(struct case_def, description),
             .doc = "free text, copied into `config.yaml` and the snapshots"),
    CASE_KEY("", "dimension", KEY_INTEGER, dimension, .flags = KEY_REQUIRED, .rule = &R_DIMENSION,
             .check = dimension_read, .doc = "spatial dimension"),
    CASE_KEY("", "scheme", KEY_CHOICE, scheme, .names = SCHEME_NAMES, .def = {SCHEME_DELTA_PLUS},
             .doc = "the scheme (see below)"),
    CASE_KEY("", "kernel", KEY_CHOICE, kernel, .names = KERNEL_NAMES, .def = {KERNEL_GAUSSIAN},
             .doc = "Gaussian cut at 3h, or Wendland C2 with support 2h"),
    CASE_KEY("resolution", "dx", KEY_NUMBER, dx, .flags = KEY_REQUIRED, .rule = &R_POSITIVE,
             .doc = "initial particle spacing Δx [m]"),
    CASE_KEY("resolution", "h_over_dx", KEY_NUMBER, h_over_dx, .rule = &R_H_OVER_DX,
             .computed = h_over_dx_default,
             .def_doc = "`1.33` (gaussian; `1.1` with generalized-dissipation), `2.0` (wendland-c2)",
             .doc = "smoothing length h / Δx [-]"),
    CASE_KEY("resolution", "origin", KEY_VECTOR, lattice_origin, .flags = KEY_GIVEN,
             .given = offsetof(struct case_def, has_lattice_origin), .def_doc = "absent",
             .doc = "one lattice for every fluid region, nodes at origin + (i + ½)Δx (see below) [m]"),
    CASE_KEY("", "gravity", KEY_VECTOR, gravity, .doc = "gravity, e.g. `[0, -9.81]` [m/s²]"),
    CASE_KEY("potential", "omega", KEY_NUMBER, potential_omega, .rule = &R_NONNEGATIVE,
             .doc = "Ω of the quadratic potential ½Ω²\\|r − r_c\\|² (body force −Ω²(r − r_c)); `0`: none [1/s]"),
    CASE_KEY("potential", "centre", KEY_VECTOR, potential_centre, .doc = "centre r_c of the potential [m]"),
    CASE_KEY("time", "end", KEY_NUMBER, t_end, .flags = KEY_REQUIRED, .rule = &R_POSITIVE,
             .doc = "end time [s]"),
    CASE_KEY("time", "cfl", KEY_NUMBER, cfl, .rule = &R_CFL, .computed = cfl_default,
             .def_doc = "`1.0` (`0.25` with generalized-dissipation)",
             .doc = "factor of the time-step limits (section 5) [-]"),
    CASE_KEY("time", "max_steps", KEY_COUNT, max_steps, .rule = &R_COUNT,
             .doc = "stop after this many steps; `0`: no limit"),
    CASE_KEY("time", "dt_min", KEY_NUMBER, dt_min, .flags = KEY_LATE, .rule = &R_POSITIVE,
             .computed = dt_min_default, .def_doc = "10⁻⁶ · CFL · h / max c0",
             .doc = "a time step below this stops the run as unstable (status 2) [s]"),
    CASE_KEY("time", "energy_growth", KEY_NUMBER, energy_growth, .rule = &R_NONNEGATIVE,
             .def = {ENERGY_GROWTH}, .doc = "a growth of the fluid's mechanical energy beyond this "
             "times M U_max²/2 stops the run as unstable (status 2; see below); `0`: off, for flows "
             "that gain energy [-]"),
    CASE_KEY("output", "interval", KEY_NUMBER, output_interval, .rule = &R_NONNEGATIVE,
             .doc = "snapshot interval; `0`: the first and last snapshots only [s]"),
    CASE_KEY("output", "stats_interval", KEY_NUMBER, stats_interval, .rule = &R_POSITIVE,
             .computed = stats_interval_default, .def_doc = "`time.end` / 100",
             .doc = "`stats.csv` interval [s]"),
    CASE_KEY("output", "probes_interval", KEY_NUMBER, probes_interval, .rule = &R_POSITIVE,
             .computed = probes_interval_default, .def_doc = "`output.stats_interval`",
             .doc = "`probes.csv` interval [s]"),
    CASE_KEY("output", "progress_interval", KEY_NUMBER, progress_interval, .rule = &R_POSITIVE,
             .def = {10}, .doc = "wall-clock time between progress lines [s]"),
    CASE_KEY("output", "checkpoint_interval", KEY_NUMBER, checkpoint_interval, .rule = &R_NONNEGATIVE,
             .doc = "simulated time between checkpoints (section 4.4); `0`: at the end of the run (and on a stop signal) only [s]"),
    CASE_KEY("domain", "min", KEY_VECTOR, domain_min, .flags = KEY_REQUIRED,
             .doc = "lower corner of the box of the cell grid [m]"),
    CASE_KEY("domain", "max", KEY_VECTOR, domain_max, .flags = KEY_REQUIRED, .check = domain_ordered,
             .doc = "upper corner of the box of the cell grid, above `min` in every component [m]"),
    CASE_KEY("", "phases", KEY_LIST, n_phases, .flags = KEY_REQUIRED, .list = &PHASES,
             .doc = "the fluids"),
    CASE_KEY("", "fluids", KEY_LIST, n_fluids, .list = &FLUIDS,
             .doc = "regions filled with particles, in this order (section 2.2)"),
    CASE_KEY("", "walls", KEY_LIST, n_walls, .list = &WALLS, .doc = "walls of ghost particles (section 2.2)"),
    CASE_KEY("", "solids", KEY_LIST, n_solids, .list = &SOLIDS,
             .doc = "elastic solids, schemes riemann and delta-plus (section 2.2)"),
    CASE_KEY("physics", "delta", KEY_NUMBER, delta, .rule = &R_NONNEGATIVE, .computed = delta_default,
             .def_doc = "`0.1` (`0.5` with generalized-dissipation)", .doc = "δ of the density diffusion [-]"),
    CASE_KEY("physics", "artificial_viscosity", KEY_NUMBER, alpha, .rule = &R_NONNEGATIVE,
             .computed = alpha_default,
             .def_doc = "`0.1` (`0.05` with same-phase-continuity, `0` with generalized-dissipation)",
             .doc = "α of the artificial viscosity [-]"),
    CASE_KEY("physics", "acoustic_damper", KEY_NUMBER, acoustic_damper, .rule = &R_NONNEGATIVE,
             .computed = damper_default, .def_doc = "`10` with delta-plus, else `0`",
             .doc = "α2 of the acoustic damper (liquids only) [-]"),
    CASE_KEY("physics", "shifting", KEY_CHOICE, shifting, .names = SHIFTING_NAMES,
             .computed = shifting_default, .def_doc = "`consistent` with delta-plus, else `none`",
             .doc = "particle shifting (see below)"),
    CASE_KEY("physics", "u_max", KEY_NUMBER, u_max, .rule = &R_POSITIVE, .computed = u_max_default,
             .def_doc = "largest c0 of the liquids (of all phases without a liquid) / 10",
             .doc = "maximum expected velocity U_max of the shifting limit (riemann: its reference speed) [m/s]"),
    CASE_KEY("physics", "tensile_control", KEY_BOOL, tensile_control, .computed = tensile_default,
             .def_doc = "`true` with delta-plus, else `false`",
             .doc = "tensile instability control: p_j − p_i for p_i < 0 outside the free-surface region (paper 000 Eq. 9)"),
    CASE_KEY("physics", "free_surface", KEY_CHOICE, free_surface, .names = FREE_SURFACE_NAMES,
             .def = {FREE_SURFACE_AUTO}, .doc = "free-surface detection (see below)"),
    CASE_KEY("physics", "surface_band", KEY_NUMBER, surface_band, .rule = &R_NONNEGATIVE, .def = {2.0},
             .doc = "the free-surface region: the detected particles and every fluid particle within this many h of one [-]"),
    CASE_KEY("physics", "interface_mode", KEY_INTEGER, interface_mode, .rule = &R_MODE, .def = {4},
             .doc = "ε/φ/κ strategies of the shifting terms at interfaces and walls (see below)"),
    CASE_KEY("physics", "damper_form", KEY_CHOICE, damper_form, .names = DAMPER_NAMES,
             .def = {DAMPER_OWN_PHASE}, .doc = "form of the acoustic damper term (see below)"),
    CASE_KEY("physics", "interface_sharpness", KEY_NUMBER, interface_sharpness, .rule = &R_NONNEGATIVE,
             .doc = "χ of the repulsive interface force between phases (paper 000 Eq. 20); `0`: off [-]"),
    CASE_KEY("physics", "limit_surface_shifting", KEY_BOOL, limit_surface_shifting,
             .doc = "also apply the limit \\|δu\\| ≤ 0.5 U_max in the free-surface region (paper 000 exempts it)"),
    CASE_KEY("physics", "interface_pressure", KEY_CHOICE, interface_pressure, .names = IFACE_P_NAMES,
             .def = {IFACE_P_SUM}, .doc = "the other-phase pressure in the momentum pair sum (see below)"),
    CASE_KEY("physics", "interface_viscosity", KEY_CHOICE, interface_viscosity, .names = IFACE_VISC_NAMES,
             .computed = interface_viscosity_default,
             .def_doc = "`harmonic` with generalized-dissipation, riemann and same-phase-continuity, else `none`",
             .doc = "the laminar viscosity between phases (see below)"),
    CASE_KEY("physics", "surface_tension", KEY_NUMBER, surface_tension, .rule = &R_NONNEGATIVE,
             .doc = "σ between the fluid phases (see below); `0`: off [N/m]"),
    CASE_KEY("physics", "light_penalty", KEY_NUMBER, light_penalty, .rule = &R_NONNEGATIVE,
             .doc = "scheme riemann: the prefactor of paper 002's penalty force that keeps light-phase particles off "
             "walls and solids (doc/theory.md §14); the paper's is `0.01`; `0`: off (the default, as the riemann "
             "studies were measured) [-]"),
    CASE_KEY("physics", "wall_guard", KEY_NUMBER, wall_guard, .rule = &R_NONNEGATIVE, .def = {WALL_GUARD_DX},
             .doc = "distance from a wall within which velocity into it is removed (see below); `0`: off [Δx]"),
    CASE_KEY("physics", "spc_model", KEY_CHOICE, spc_model, .names = SPC_MODEL_NAMES, .def = {SPC_PRESENT},
             .doc = "scheme same-phase-continuity only: paper 003's model, or its conventional baseline (see below)"),
    CASE_KEY("physics", "dissipation_form", KEY_CHOICE, dissipation_form, .names = DISSIPATION_NAMES,
             .def = {DISSIPATION_CONSISTENT}, .written = dissipation_written,
             .doc = "scheme generalized-dissipation only: paper 004's Eq. 46 or its Eq. 49 as printed (see below)"),
    CASE_KEY("initial", "pressure", KEY_CHOICE, initial_pressure, .names = PRESSURE_NAMES,
             .def = {INIT_PRESSURE_HYDROSTATIC}, .doc = "initial pressure (see below)"),
    CASE_KEY("", "probes", KEY_LIST, n_probes, .list = &PROBES,
             .doc = "sensors recorded in `probes.csv` (section 2.2, section 4.3)"),
    CASE_KEY("parallel", "repartition_threshold", KEY_NUMBER, repartition_threshold, .rule = &R_POSITIVE,
             .def = {0.1}, .doc = "re-partition when the compute-time imbalance max/mean − 1 exceeds this (section 6.3) [-]"),
    CASE_KEY("parallel", "repartition_every", KEY_COUNT, repartition_every, .rule = &R_COUNT,
             .doc = "re-partition every N steps; `0`: only on imbalance"),
    CASE_KEY("parallel", "balance", KEY_CHOICE, balance, .names = BALANCE_NAMES, .def = {BALANCE_TIME},
             .doc = "what a re-partition balances: the measured compute time, or the particle work alone, "
             "which gives the same partition on every run (section 6.3)"),
    CASE_KEY("parallel", "top_cells_per_rank", KEY_COUNT, top_cells_per_rank, .rule = &R_TOP_CELLS,
             .def = {256}, .doc = "the top cells METIS partitions are the largest blocks of cells that leave at "
             "least this many per rank (section 6.1); fewer: larger blocks, a smaller METIS graph, a coarser balance"),
};
#define N_CASE_KEYS ((int)(sizeof CASE_KEYS / sizeof CASE_KEYS[0]))

/* ---- reading by the tables ---- */

#define MAX_SECTION_KEYS N_CASE_KEYS   /* no mapping has more keys than the largest table */
_Static_assert(sizeof PHASE_ITEM_KEYS / sizeof PHASE_ITEM_KEYS[0] <= MAX_SECTION_KEYS, "room for a phase's keys");

/* The allowed keys of mapping `section` of table t ("": the root, whose keys are the
 * top-level keys and the sections) into out, NULL-terminated. */
static const char *const *section_keys(const struct case_key *t, int n, const char *section,
                                       const char **out) {
  int k = 0;
  for (int i = 0; i < n; i++) {
    const char *name = section[0] ? t[i].key : t[i].section[0] ? t[i].section : t[i].key;
    int seen = strcmp(t[i].section, section) != 0 && section[0];
    for (int j = 0; j < k && !seen; j++) seen = strcmp(out[j], name) == 0;
    if (!seen) out[k++] = name;
  }
  out[k] = NULL;
  return out;
}

/* The mapping of key k's section under m (m itself for the root or a list item). */
static int section_of(const struct map *m, const struct case_key *t, int n, const struct case_key *k,
                      struct map *out) {
  const char *allowed[MAX_SECTION_KEYS + 1];
  if (!k->section[0]) return *out = *m, 0;
  return sub(m, k->section, section_keys(t, n, k->section, allowed), out);
}

static int read_list(const struct map *root, const struct case_key *k, struct case_def *c);

/* Key k of mapping m into the member of base (the case, or list item i); its default from
 * the keys read before. */
static int read_key(const struct map *m, const struct case_key *k, struct case_def *c, void *base, int i) {
  char *at = (char *)base + k->offset;
  double def[2] = {k->def[0], k->def[1]}, x;
  if (k->computed) k->computed(c, base, def);
  if (k->flags & KEY_REQUIRED) def[0] = REQUIRED;
  int rc = 0, required = (k->flags & KEY_REQUIRED) != 0;
  char path[PATH_LEN];
  switch (k->type) {
  case KEY_NUMBER: rc = num(m, k->key, k->rule, def[0], (double *)at); break;
  case KEY_INTEGER:
    rc = num(m, k->key, k->rule, def[0], &x);
    if (!rc) *(int *)at = (int)x;
    break;
  case KEY_COUNT: rc = lnum(m, k->key, k->rule, def[0], (long *)at); break;
  case KEY_CHOICE: rc = choice(m, k->key, k->names, (int)def[0], (int *)at); break;
  case KEY_BOOL: rc = choice(m, k->key, BOOL_NAMES, (int)def[0], (int *)at); break;
  case KEY_TEXT: rc = text(m, k->key, k->punct, required ? NULL : "", k->size, at); break;
  case KEY_VECTOR:
    if (k->flags & KEY_GIVEN) *(int *)((char *)base + k->given) = get(m, k->key, path) != NULL;
    rc = vec(m, k->key, required, (double *)at);
    break;
  case KEY_BAND: rc = band(m, k->key, def, (double *)at); break;
  case KEY_LIST: rc = read_list(m, k, c); break;
  }
  return rc || (k->check && k->check(m, c, i));
}

/* The keys of table t with (late) or without KEY_LATE from mapping m into base. */
static int read_keys(const struct map *m, const struct case_key *t, int n, int late, struct case_def *c,
                     void *base, int i) {
  struct map s;
  for (int j = 0; j < n; j++)
    if (((t[j].flags & KEY_LATE) != 0) == late &&
        (section_of(m, t, n, &t[j], &s) || read_key(&s, &t[j], c, base, i)))
      return 1;
  return 0;
}

/* The list of key k: each item by the list's key table or by its own reader; the count goes to
 * the member of k. */
static int read_list(const struct map *root, const struct case_key *k, struct case_def *c) {
  const struct list_def *l = k->list;
  const char *allowed[MAX_SECTION_KEYS + 1];
  char path[PATH_LEN], ipath[PATH_LEN];
  const struct ynode *seq;
  int *n = (int *)((char *)c + k->offset);
  struct map m;
  if (list(root, k->key, l->lo, l->hi, l->what, &seq, path)) return 1;
  *n = seq ? seq->n : 0;
  for (int i = 0; i < *n; i++) {
    void *item = (char *)c + l->items + (size_t)i * l->item_size;
    join_index(ipath, path, i);
    if (open_map(root->ld, seq->entries[i].value, NULL, ipath,
                 l->keys ? section_keys(l->keys, l->n_keys, "", allowed) : l->allowed, &m) ||
        (l->keys ? read_keys(&m, l->keys, l->n_keys, 0, c, item, i) : l->read(&m, c, i)))
      return 1;
  }
  return 0;
}

static int read_case(const struct ynode *root, struct case_def *c, char *err, size_t err_len) {
  struct ld ld = {err, err_len, 2};
  const char *allowed[MAX_SECTION_KEYS + 1];
  struct map m;
  return open_map(&ld, root, root, "", section_keys(CASE_KEYS, N_CASE_KEYS, "", allowed), &m) ||
         read_keys(&m, CASE_KEYS, N_CASE_KEYS, 0, c, c, 0) || read_keys(&m, CASE_KEYS, N_CASE_KEYS, 1, c, c, 0);
}

/* Rewrite the message in err on one printable line: control characters (a newline inside a
 * value or key shown in it) become \n, \t or \xNN; the end is cut at err_len. */
static void one_line(char *err, size_t err_len) {
  char buf[4096];
  size_t k = 0;
  for (const unsigned char *c = (const unsigned char *)err; *c && k + 5 < sizeof buf; c++) {
    if (*c >= 0x20 && *c != 0x7f)
      buf[k++] = (char)*c;
    else
      k += (size_t)snprintf(buf + k, 5, *c == '\n' ? "\\n" : *c == '\t' ? "\\t" : "\\x%02x", *c);
  }
  buf[k] = '\0';
  snprintf(err, err_len, "%s", buf);
}

/* Load, override, validate and resolve the case text into c. */
int case_load_string(const char *text, size_t len, const char *source, int n_sets,
                     char *const *sets, struct case_def *c, char *err, size_t err_len) {
  memset(c, 0, sizeof *c);
  if (strlen(source) >= sizeof c->source_file) {
    if (err_len) snprintf(err, err_len, "%s: path too long, expected at most %zu characters",
                          source, sizeof c->source_file - 1);
    return 1;
  }
  snprintf(c->source_file, sizeof c->source_file, "%s", source);
  struct ynode *root = ytree_parse(text, len, source, 0, err, err_len);
  int rc = root ? 0 : 1;
  for (int i = 0; rc == 0 && i < n_sets; i++) rc = ytree_set(root, sets[i], i + 1, err, err_len);
  if (rc == 0) rc = read_case(root, c, err, err_len);
  ytree_free(root);
  if (rc && err_len) one_line(err, err_len);
  return rc;
}

/* What a file of mode st_mode is when it is not a regular file ("a directory"), or NULL. */
static const char *not_regular(mode_t mode) {
  return S_ISREG(mode) ? NULL : S_ISDIR(mode) ? "a directory" : S_ISFIFO(mode) ? "a FIFO (named pipe)"
         : S_ISCHR(mode) ? "a character device" : S_ISBLK(mode) ? "a block device"
         : S_ISSOCK(mode) ? "a socket" : "not a regular file";
}

const char *case_file_not_regular(const char *path) {
  struct stat st;
  return stat(path, &st) == 0 ? not_regular(st.st_mode) : NULL;
}

/* The regular file at path opened for reading, or NULL with a message. Its type is asked before
 * it is opened, and again of the open file (which may have been replaced in between): opening a
 * FIFO would wait for a writer, reading a device might never end. */
static FILE *open_regular(const char *path, char *err, size_t err_len) {
  struct stat st;
  const char *kind = NULL;
  int fd = -1;
  if (stat(path, &st) == 0 && !(kind = not_regular(st.st_mode)) &&
      (fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC)) >= 0 && fstat(fd, &st) == 0)
    kind = not_regular(st.st_mode);
  FILE *f = fd >= 0 && !kind ? fdopen(fd, "rb") : NULL;
  if (f) return f;
  if (kind) snprintf(err, err_len, "%s: cannot read the file: it is %s, expected a regular file", path, kind);
  else snprintf(err, err_len, "%s: cannot open the file: %s", path, strerror(errno));
  if (fd >= 0) close(fd);
  return NULL;
}

/* The whole file at path (at most CASE_MAX_FILE_BYTES) in a new buffer, its size in *len; NULL
 * with a message on failure. */
static char *read_file(const char *path, size_t *len, char *err, size_t err_len) {
  FILE *f = open_regular(path, err, err_len);
  if (!f) return NULL;
  char *text = mem_alloc(CASE_MAX_FILE_BYTES + 1, "the case file's text");
  *len = fread(text, 1, CASE_MAX_FILE_BYTES + 1, f);
  if (ferror(f))
    snprintf(err, err_len, "%s: cannot read the file: %s", path, strerror(errno));
  else if (*len > CASE_MAX_FILE_BYTES)
    snprintf(err, err_len, "%s: larger than %d bytes, expected a case file of at most that size",
             path, CASE_MAX_FILE_BYTES);
  int ok = !ferror(f) && *len <= CASE_MAX_FILE_BYTES;
  fclose(f);
  if (ok) return text;
  free(text);
  return NULL;
}

/* Load, override, validate and resolve a case file into c. */
int case_load(const char *path, int n_sets, char *const *sets, struct case_def *c, char *err,
              size_t err_len) {
  size_t len = 0;
  char *text = read_file(path, &len, err, err_len);
  memset(c, 0, sizeof *c);
  if (!text && err_len) one_line(err, err_len);
  if (!text) return 1;
  int rc = case_load_string(text, len, path, n_sets, sets, c, err, err_len);
  free(text);
  return rc;
}

/* Column suffixes of an integral probe. */
static const char *const INTEGRAL_COLUMNS[] = {"volume", "kinetic", "potential", "com_x", "com_y", "com_z"};

int case_probe_column(const struct case_def *c, int k, int col, char *buf, size_t len) {
  const struct probe *p = &c->probes[k];
  int n = p->kind == PROBE_INTEGRAL ? 3 + c->dimension : 1;
  if (buf && p->kind == PROBE_INTEGRAL) snprintf(buf, len, "%s_%s", p->name, INTEGRAL_COLUMNS[col]);
  else if (buf) snprintf(buf, len, "%s", p->name);
  return n;
}


/* ---- writing by the tables ---- */

/* Key k of base (the case, or a list item) at indent, when it is written. */
static void put_key(FILE *f, const char *indent, const struct case_key *k, const struct case_def *c,
                    const void *base) {
  const char *at = (const char *)base + k->offset;
  if (k->written && !k->written(c)) return;
  switch (k->type) {
  case KEY_NUMBER: put_num(f, indent, k->key, *(const double *)at); break;
  case KEY_INTEGER: put_long(f, indent, k->key, *(const int *)at); break;
  case KEY_COUNT: put_long(f, indent, k->key, *(const long *)at); break;
  case KEY_CHOICE: put_word(f, indent, k->key, k->names[*(const int *)at]); break;
  case KEY_BOOL: put_word(f, indent, k->key, BOOL_NAMES[*(const int *)at != 0]); break;
  case KEY_TEXT: put_str(f, indent, k->key, at); break;
  case KEY_VECTOR:
    if (!(k->flags & KEY_GIVEN) || *(const int *)((const char *)base + k->given))
      put_vec(f, indent, k->key, (const double *)at, c->dimension);
    break;
  case KEY_BAND: put_vec(f, indent, k->key, (const double *)at, 2); break;
  case KEY_LIST: {
    const struct list_def *l = k->list;
    int n = *(const int *)at;
    put_list_key(f, k->key, n);
    for (int i = 0; i < n; i++) {
      const char *item = (const char *)c + l->items + (size_t)i * l->item_size;
      for (int j = 0; l->keys && j < l->n_keys; j++) put_key(f, j ? "    " : "  - ", &l->keys[j], c, item);
      if (!l->keys) l->put(f, c, i);
    }
    break;
  }
  }
}

/* The resolved case as YAML text, every key written; NULL if out of memory. Caller frees. */
char *case_to_yaml(const struct case_def *c) {
  char *buf = NULL;
  size_t size = 0;
  FILE *f = open_memstream(&buf, &size);
  if (!f) return NULL;
  for (int i = 0; i < N_CASE_KEYS; i++) {
    const char *section = CASE_KEYS[i].section;
    if (section[0] && (i == 0 || strcmp(section, CASE_KEYS[i - 1].section) != 0)) fprintf(f, "%s:\n", section);
    put_key(f, section[0] ? "  " : "", &CASE_KEYS[i], c, c);
  }
  fclose(f);
  return buf;
}

/* ---- the key reference ---- */

static const char *const TYPE_NAMES[] = {"number", "integer", "integer", "word", "boolean", "name",
                                         "vector", "[min, max]", "list"};

/* The default of key k as the reference shows it. */
static const char *shown_default(const struct case_key *k, char *buf, size_t len) {
  char num_buf[32];
  if (k->flags & KEY_REQUIRED) return "required";
  if (k->def_doc) return k->def_doc;
  switch (k->type) {
  case KEY_NUMBER: snprintf(buf, len, "`%s`", fmt_num(num_buf, sizeof num_buf, k->def[0])); break;
  case KEY_INTEGER: case KEY_COUNT: snprintf(buf, len, "`%ld`", (long)k->def[0]); break;
  case KEY_CHOICE: snprintf(buf, len, "`%s`", k->names[(int)k->def[0]]); break;
  case KEY_BOOL: snprintf(buf, len, "`%s`", BOOL_NAMES[(int)k->def[0]]); break;
  case KEY_TEXT: snprintf(buf, len, "`\"\"`"); break;
  case KEY_VECTOR: snprintf(buf, len, "zeros"); break;
  default: snprintf(buf, len, "empty"); break;
  }
  return buf;
}

/* The values key k allows, as the reference shows them (the words of the error messages). */
static const char *shown_allowed(const struct case_key *k, char *buf, size_t len) {
  switch (k->type) {
  case KEY_NUMBER: case KEY_INTEGER: case KEY_COUNT: return k->rule->expected;
  case KEY_CHOICE: case KEY_BOOL: {
    const char *const *names = k->type == KEY_BOOL ? BOOL_NAMES : k->names;
    buf[0] = '\0';
    for (int i = 0; names[i]; i++) {
      size_t n = strlen(buf);
      snprintf(buf + n, len - n, "%s`%s`", i ? ", " : "", names[i]);
    }
    return buf;
  }
  case KEY_TEXT: return text_expected(buf, len, k->punct, k->size);
  case KEY_VECTOR: return "a list of one number per dimension";
  case KEY_BAND: return BAND_EXPECTED;
  default: return list_expected(buf, len, k->list->lo, k->list->hi, k->list->what);
  }
}

/* One row of the reference: key k at path prefix (its section, or the list's "name.N."). */
static void key_row(FILE *f, const char *prefix, const struct case_key *k) {
  char def[LIST_LEN], allowed[LIST_LEN];
  const char *type = k->type == KEY_TEXT && !k->punct ? "string" : TYPE_NAMES[k->type];
  fprintf(f, "| `%s%s%s%s` | %s | %s | %s | %s |\n", prefix, k->section, k->section[0] ? "." : "", k->key,
          type, shown_default(k, def, sizeof def), shown_allowed(k, allowed, sizeof allowed), k->doc);
}

/* Print the case key reference (a markdown table of CASE_KEYS, the list items' keys after
 * their list) to f. */
void case_keys_markdown(FILE *f) {
  char prefix[PATH_LEN];
  fputs("| key path | type | default | allowed | meaning |\n|---|---|---|---|---|\n", f);
  for (int i = 0; i < N_CASE_KEYS; i++) {
    const struct case_key *k = &CASE_KEYS[i];
    key_row(f, "", k);
    snprintf(prefix, sizeof prefix, "%s.N.", k->key);
    for (int j = 0; k->type == KEY_LIST && k->list->keys && j < k->list->n_keys; j++)
      key_row(f, prefix, &k->list->keys[j]);
  }
}
