/* test_case_load.c — case file loading: defaults, every kind of error message (file, line, key
 * path, allowed values), --set overrides, and the case_to_yaml -> case_load round trip. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "case/case_load.h"
#include "case/init.h"
#include "base/parts.h"
#include "check.h"

#define ERR_LEN 1024

static char dir[64];
static char path[128];
static char err[ERR_LEN];

/* The base case, one line per entry (line i + 1 of the file). */
static const char *const BASE[] = {
    "name: tank",
    "dimension: 2",
    "resolution: {dx: 0.02}",
    "time: {end: 1.0}",
    "domain: {min: [0, 0], max: [1, 1]}",
    "phases:",
    "  - {name: water, rho0: 1000, c0: 30, incompressible: true}",
    "  - {name: air, rho0: 1, c0: 340, gamma: 1.4}",
    "fluids:",
    "  - {phase: water, box: {min: [0, 0], max: [1, 0.5]}}",
    "probes:",
    "  - {name: p0, position: [0.5, 0]}",
    NULL};

/* The base case with line `line` (1-based; one past the end appends) replaced by text. */
static const char *variant(int line, const char *text) {
  static char buf[4096];
  buf[0] = '\0';
  int i = 0;
  for (; BASE[i]; i++) {
    strcat(buf, i + 1 == line ? text : BASE[i]);
    strcat(buf, "\n");
  }
  if (line == i + 1) {
    strcat(buf, text);
    strcat(buf, "\n");
  }
  return buf;
}

static void write_file(const char *file, const char *text) {
  FILE *f = fopen(file, "w");
  fputs(text, f);
  fclose(f);
}

/* Write text as <dir>/case.yaml and load it with the overrides. */
static int load(const char *text, int n_sets, const char *const *sets, struct case_def *c) {
  write_file(path, text);
  err[0] = '\0';
  return case_load(path, n_sets, (char *const *)sets, c, err, sizeof err);
}

/* The load fails with a one-line message containing where ("case.yaml:3: key.path: ") and
 * what (the allowed values). */
static void expect_error(const char *text, int n_sets, const char *const *sets, const char *where,
                         const char *what) {
  struct case_def c;
  CHECK(load(text, n_sets, sets, &c) == 1, "load should fail (%s)", where);
  CHECK(strstr(err, where) != NULL, "message '%s' should contain '%s'", err, where);
  CHECK(strstr(err, what) != NULL, "message '%s' should contain '%s'", err, what);
  CHECK(strchr(err, '\n') == NULL, "message '%s' should be one line", err);
}

static void test_defaults(void) {
  struct case_def c;
  CHECK(load(variant(0, ""), 0, NULL, &c) == 0, "base case loads: %s", err);
  CHECK(strcmp(c.name, "tank") == 0 && strcmp(c.description, "") == 0, "name, description");
  CHECK(strcmp(c.source_file, path) == 0, "source_file %s", c.source_file);
  CHECK(c.dimension == 2 && c.scheme == SCHEME_DELTA_PLUS && c.kernel == KERNEL_GAUSSIAN, "enums");
  CHECK_CLOSE(c.h_over_dx, 1.33, 0, "h_over_dx default (gaussian)");
  CHECK_CLOSE(c.cfl, 1.0, 0, "cfl default");
  CHECK_CLOSE(c.stats_interval, 0.01, 0, "stats_interval = end/100");
  CHECK_CLOSE(c.probes_interval, 0.01, 0, "probes_interval = stats_interval");
  CHECK_CLOSE(c.progress_interval, 10, 0, "progress_interval");
  CHECK(c.gravity[0] == 0 && c.gravity[1] == 0 && c.gravity[2] == 0, "gravity zero");
  CHECK(c.n_phases == 2 && c.phases[0].incompressible == 1 && c.phases[1].incompressible == 0,
        "phases");
  CHECK_CLOSE(c.phases[0].gamma, 7, 0, "gamma default");
  CHECK_CLOSE(c.phases[1].gamma, 1.4, 0, "gamma given");
  CHECK(c.n_fluids == 1 && c.fluids[0].phase == 0 && c.fluids[0].shape.kind == SHAPE_BOX, "fluid");
  CHECK(c.fluids[0].shape.max[2] == 0 && c.domain_max[2] == 0, "unused components are zero");
  CHECK(c.n_walls == 0 && c.n_probes == 1 && c.probes[0].kind == PROBE_PRESSURE, "walls, probes");
  CHECK_CLOSE(c.delta, 0.1, 0, "delta");
  CHECK_CLOSE(c.alpha, 0.1, 0, "artificial_viscosity");
  CHECK(c.acoustic_damper == 10 && c.shifting == SHIFTING_CONSISTENT, "physics defaults");
  CHECK(c.u_max == c.phases[0].c0 / 10, "u_max default: liquid c0 / 10 (%g)", c.u_max);
  CHECK(c.tensile_control == 1 && c.free_surface == FREE_SURFACE_AUTO && c.surface_band == 2 &&
        c.interface_mode == 4 && c.damper_form == DAMPER_OWN_PHASE && c.interface_sharpness == 0 &&
        c.limit_surface_shifting == 0 && c.potential_omega == 0 &&
        c.surface_tension == 0, "delta-plus defaults");
  CHECK(c.initial_pressure == INIT_PRESSURE_HYDROSTATIC, "initial pressure");
  CHECK_CLOSE(c.repartition_threshold, 0.1, 0, "repartition_threshold");
  CHECK(c.repartition_every == 0 && c.max_steps == 0, "counts");
  CHECK(c.phases[0].density_band[0] == 0.5 && c.phases[0].density_band[1] == 2.0,
        "liquid density band default");
  CHECK(c.phases[1].density_band[0] == 0.1 && c.phases[1].density_band[1] == 10.0,
        "gas density band default");
  CHECK_CLOSE(c.dt_min, 1e-6 * 1.0 * 1.33 * 0.02 / 340, 1e-22, "dt_min default: 1e-6 CFL h / max c0");
  CHECK(load(variant(13, "kernel: wendland-c2"), 0, NULL, &c) == 0, "wendland: %s", err);
  CHECK_CLOSE(c.h_over_dx, 2.0, 0, "h_over_dx default (wendland-c2)");
}

static void test_key_errors(void) {
  expect_error(variant(13, "colour: red"), 0, NULL, "case.yaml:13: colour: unknown key",
               "allowed keys: name, description, dimension");
  expect_error(variant(10, "  - {phase: water, boxx: {min: [0, 0], max: [1, 0.5]}}"), 0, NULL,
               "case.yaml:10: fluids.0.boxx: unknown key",
               "allowed keys: phase, box, circle, polygon, velocity");
  expect_error(variant(4, "time: {cfl: 0.5}"), 0, NULL, "case.yaml:4: time.end: missing required",
               "expected a number > 0");
  expect_error(variant(1, "description: no name"), 0, NULL, "case.yaml:1: name: missing required",
               "[A-Za-z0-9._-]");
  expect_error(variant(4, ""), 0, NULL, "case.yaml:1: time.end: missing required key",
               "expected a number > 0");
  expect_error(variant(13, "name: again"), 0, NULL, "case.yaml:13: name: duplicate key", "once");
}

static void test_value_errors(void) {
  expect_error(variant(3, "resolution: {dx: abc}"), 0, NULL, "case.yaml:3: resolution.dx: ",
               "got 'abc', expected a number > 0");
  expect_error(variant(3, "resolution: {dx: -0.1}"), 0, NULL, "case.yaml:3: resolution.dx: ",
               "got '-0.1', expected a number > 0");
  expect_error(variant(3, "resolution: {dx: \"0.1\"}"), 0, NULL, "case.yaml:3: resolution.dx: ",
               "got the string \"0.1\", expected a number > 0");
  expect_error(variant(3, "resolution: {dx: .inf}"), 0, NULL, "case.yaml:3: resolution.dx: ",
               "expected a number > 0");
  expect_error(variant(3, "resolution: {dx: 0.1, h_over_dx: 11}"), 0, NULL,
               "case.yaml:3: resolution.h_over_dx: ", "got '11', expected a number > 0 and <= 10");
  expect_error(variant(4, "time: {end: 1, cfl: 5}"), 0, NULL, "case.yaml:4: time.cfl: ",
               "got '5', expected a number > 0 and <= 2");
  expect_error(variant(4, "time: {end: 1, max_steps: 1.5}"), 0, NULL, "case.yaml:4: time.max_steps",
               "expected an integer >= 0");
  expect_error(variant(2, "dimension: 4"), 0, NULL, "case.yaml:2: dimension: ", "expected 2 or 3");
  expect_error(variant(13, "kernel: cubic"), 0, NULL, "case.yaml:13: kernel: got 'cubic'",
               "allowed values: gaussian, wendland-c2");
  expect_error(variant(7, "  - {name: water, rho0: 1000, c0: 30, incompressible: yes}"), 0, NULL,
               "case.yaml:7: phases.0.incompressible: ", "allowed values: false, true");
  expect_error(variant(1, "name: my tank"), 0, NULL, "case.yaml:1: name: got 'my tank'",
               "expected a name of 1 to 63 characters from [A-Za-z0-9._-]");
  expect_error(variant(13, "resolution: {dx: 0.1}"), 0, NULL, "case.yaml:13: resolution: duplicate",
               "expected each key once");
  expect_error(variant(8, "  - {name: air, rho0: 1, c0: 340, density_band: [1.2, 2]}"), 0, NULL,
               "case.yaml:8: phases.1.density_band: got [1.2, 2]",
               "expected a list [min_ratio, max_ratio] with 0 <= min_ratio < 1 < max_ratio");
  expect_error(variant(8, "  - {name: air, rho0: 1, c0: 340, density_band: 0.5}"), 0, NULL,
               "case.yaml:8: phases.1.density_band: got '0.5'", "[min_ratio, max_ratio]");
  expect_error(variant(4, "time: {end: 1, dt_min: 0}"), 0, NULL, "case.yaml:4: time.dt_min: got '0'",
               "expected a number > 0");
}

static void test_shape_errors(void) {
  expect_error(variant(5, "domain: {min: [0, 0, 0], max: [1, 1]}"), 0, NULL,
               "case.yaml:5: domain.min: got a list of 3 items", "expected a list of 2 numbers (one per dimension)");
  expect_error(variant(5, "domain: {min: [0, 0], max: [1, 0]}"), 0, NULL, "case.yaml:5: domain.max",
               "expected max > min in every component");
  expect_error(variant(10, "  - {phase: oil, box: {min: [0, 0], max: [1, 0.5]}}"), 0, NULL,
               "case.yaml:10: fluids.0.phase: unknown phase 'oil'", "known phases: water, air");
  expect_error(variant(12, "  - {name: p0, position: [2, 0.5]}"), 0, NULL,
               "case.yaml:12: probes.0.position: got [2, 0.5] outside the domain",
               "expected a point inside the domain min [0, 0] max [1, 1]");
  expect_error(variant(10, "  - {phase: water, circle: {centre: [0.5, 0.5], radius: 0.6}}"), 0,
               NULL, "case.yaml:10: fluids.0.circle: got bounding box", "inside the domain");
  expect_error(variant(10, "  - {phase: water, box: {min: [0, 0], max: [1, 1]}, circle: {}}"), 0,
               NULL, "case.yaml:10: fluids.0: got 2 shapes",
               "expected exactly one of: box, circle, polygon");
  expect_error(variant(10, "  - {phase: water, polygon: [[0, 0], [1, 0]]}"), 0, NULL,
               "case.yaml:10: fluids.0.polygon: got a list of 2 items", "3 to 64 [x, y] vertices");
  expect_error(variant(12, "  - {name: p0, position: [0.5, 0]}\n  - {name: p0, position: [0, 0]}"),
               0, NULL, "case.yaml:13: probes.1.name: got 'p0' a second time", "unique names");
  expect_error(variant(10, "  - {phase: water, polygon: [[0, 0], [1, 0.5], [1, 0], [0, 0.5]]}"), 0, NULL,
               "case.yaml:10: fluids.0.polygon: edges 0 ([0, 0] to [1, 0.5]) and 2 ([1, 0] to [0, 0.5]) "
               "cross or touch", "expected a simple polygon");
  expect_error(variant(10, "  - {phase: water, polygon: [[0, 0], [0.5, 0.25], [1, 0.5]]}"), 0, NULL,
               "case.yaml:10: fluids.0.polygon: edges 0 ([0, 0] to [0.5, 0.25]) and 2", "cross or touch");
  expect_error(variant(10, "  - {phase: water, polygon: [[0, 0], [1, 0], [1, 0.5], [0, 0]]}"), 0, NULL,
               "case.yaml:10: fluids.0.polygon: vertices 0 and 3 are the same point [0, 0]",
               "expected distinct vertices");
}

static void test_malformed(void) {
  expect_error(variant(4, "time: {end: 1.0"), 0, NULL, "case.yaml:5: time: malformed YAML",
               "expected valid YAML");
  expect_error(variant(13, "  bad: indent"), 0, NULL, "case.yaml:13: probes: malformed YAML", "YAML");
  expect_error(variant(13, "gravity: *g"), 0, NULL, "case.yaml:", "alias");
  expect_error(variant(13, "gravity: &g [0, -9.81]"), 0, NULL, "case.yaml:13: gravity: got the anchor &g",
               "expected none (anchors and aliases are not supported)");
  expect_error(variant(13, "&k gravity: [0, -9.81]"), 0, NULL, "case.yaml:13: gravity: got the anchor &k",
               "not supported");
  expect_error(variant(3, "resolution: !!map {dx: 0.02}"), 0, NULL, "case.yaml:3: resolution: got the tag !!map",
               "expected none (tags are not supported)");
  expect_error(variant(3, "resolution: {dx: !local 0.02}"), 0, NULL,
               "case.yaml:3: resolution.dx: got the tag !local", "not supported");
  const char *tagged[] = {"time.end=!!float 2"};
  expect_error(variant(0, ""), 1, tagged, "--set:1: time.end: got the tag !!float", "not supported");
  expect_error(variant(1, "name: \"two\\nlines\""), 0, NULL, "case.yaml:1: name: ",
               "got the string \"two\\nlines\", expected a name");
  struct case_def c;
  CHECK(case_load("/nonexistent/case.yaml", 0, NULL, &c, err, sizeof err) == 1 &&
            strstr(err, "/nonexistent/case.yaml: cannot open") != NULL, "missing file: %s", err);
  CHECK(case_load(dir, 0, NULL, &c, err, sizeof err) == 1 && strstr(err, "cannot read the file: it is a directory, expected a regular file"),
        "a directory: %s", err);
}

/* The same text loads from memory, named by its source; a NUL byte is malformed YAML. */
static void test_string(void) {
  struct case_def c;
  const char *text = variant(0, "");
  CHECK(case_load_string(text, strlen(text), "memory", 0, NULL, &c, err, sizeof err) == 0,
        "from memory: %s", err);
  CHECK(strcmp(c.source_file, "memory") == 0 && c.dx == 0.02, "source and content");
  CHECK(case_load_string(text, 4, "memory", 0, NULL, &c, err, sizeof err) == 1 &&
            strstr(err, "memory:") != NULL, "only the given length is read: %s", err);
  CHECK(case_load_string("name: a\0b\n", 11, "memory", 0, NULL, &c, err, sizeof err) == 1 &&
            strstr(err, "memory:1: malformed YAML") != NULL, "NUL byte: %s", err);
  const char utf16le[] = "\xff\xfen\0a\0m\0e\0:\0 \0a\0\n\0", utf32be[] = "\0\0\xfe\xff\0\0\0n";
  CHECK(case_load_string(utf16le, sizeof utf16le - 1, "memory", 0, NULL, &c, err, sizeof err) == 1 &&
            strstr(err, "memory:1: the text is UTF-16LE (it starts with its byte-order mark), expected UTF-8"),
        "UTF-16: %s", err);
  CHECK(case_load_string(utf32be, sizeof utf32be - 1, "memory", 0, NULL, &c, err, sizeof err) == 1 &&
            strstr(err, "memory:1: the text is UTF-32BE"), "UTF-32: %s", err);
  char bom8[4096];
  snprintf(bom8, sizeof bom8, "\xef\xbb\xbf%s", text);
  CHECK(case_load_string(bom8, strlen(bom8), "memory", 0, NULL, &c, err, sizeof err) == 0,
        "UTF-8 with its byte-order mark loads: %s", err);
  CHECK(case_load_string("name: caf\xe9\n", 10, "memory", 0, NULL, &c, err, sizeof err) == 1 &&
            strstr(err, "memory:1: name: malformed YAML"), "Latin-1: %s", err);
}

static void test_set(void) {
  struct case_def c;
  const char *sets[] = {"resolution.dx=0.005", "time.cfl=0.5", "fluids.0.box.max=[1, 0.25]",
                        "physics.delta=0.2", "time.max_steps=7",
                        "probes.1={name: p1, position: [0.25, 0.75]}", "name=renamed"};
  CHECK(load(variant(0, ""), 7, sets, &c) == 0, "overrides apply: %s", err);
  CHECK_CLOSE(c.dx, 0.005, 0, "existing scalar");
  CHECK_CLOSE(c.cfl, 0.5, 0, "nested key added to a flow mapping");
  CHECK(c.fluids[0].shape.max[0] == 1 && c.fluids[0].shape.max[1] == 0.25, "list item by index");
  CHECK_CLOSE(c.delta, 0.2, 0, "missing mapping added");
  CHECK(c.max_steps == 7, "missing key added");
  CHECK(c.n_probes == 2 && strcmp(c.probes[1].name, "p1") == 0 && c.probes[1].position[1] == 0.75,
        "list item appended");
  CHECK(strcmp(c.name, "renamed") == 0, "top-level string");
  const char *unknown[] = {"time.cfl=0.5", "physics.deltaa=1"};
  expect_error(variant(0, ""), 2, unknown, "--set:2: physics.deltaa: unknown key",
               "allowed keys: delta, artificial_viscosity");
  const char *typo[] = {"phyiscs.delta=1"};
  expect_error(variant(0, ""), 1, typo, "--set:1: phyiscs: unknown key", "allowed keys: name");
  const char *no_eq[] = {"resolution.dx"};
  expect_error(variant(0, ""), 1, no_eq, "--set:1: resolution.dx: missing '='",
               "expected key.path=value");
  const char *bad_flow[] = {"domain.min=[0, 0"};
  expect_error(variant(0, ""), 1, bad_flow, "--set:1: domain.min: malformed YAML", "expected");
  const char *bad_index[] = {"fluids.3.phase=air"};
  expect_error(variant(0, ""), 1, bad_index, "--set:1: fluids.3: no such list item",
               "expected an index 0 to 1");
  const char *in_scalar[] = {"name.first=x"};
  expect_error(variant(0, ""), 1, in_scalar, "--set:1: name.first: ", "inside the scalar");
  const char *bad_value[] = {"time.end=-1"};
  expect_error(variant(0, ""), 1, bad_value, "--set:1: time.end: got '-1'", "a number > 0");
}

static const char ROUND_TRIP[] =
    "name: rt-case_1.0\n"
    "description: \"Tank: \\\"quoted\\\" # not a comment\\tand a tab\"\n"
    "dimension: 2\n"
    "scheme: riemann\n"
    "kernel: wendland-c2\n"
    "resolution: {dx: 0.0033333333333333335, h_over_dx: 1.7}\n"
    "gravity: [0.1, -9.81]\n"
    "time: {end: 2.5, cfl: 0.3, max_steps: 12345, dt_min: 1e-7}\n"
    "output: {interval: 0.1, stats_interval: 0.003, probes_interval: 0.007, "
    "progress_interval: 2.5}\n"
    "domain: {min: [-0.1, -0.2], max: [3.2, 2.1]}\n"
    "phases:\n"
    "  - {name: water, rho0: 1000, c0: 31.3, p_background: 12.5, viscosity: 1e-3,"
    " incompressible: true}\n"
    "  - {name: air, rho0: 1.2, c0: 340, gamma: 1.4, density_band: [0, 1e6]}\n"
    "  - {name: oil, rho0: 870.5, c0: 45, viscosity: 0.05}\n"
    "fluids:\n"
    "  - {phase: water, box: {min: [0, 0], max: [1, 0.6]}, velocity: [0.5, -0.25]}\n"
    "  - {phase: oil, circle: {centre: [2, 1], radius: 0.3}}\n"
    "  - {phase: air, polygon: [[0, 0.6], [3, 0.6], [3, 2], [0, 2]]}\n"
    "walls:\n"
    "  - {box: {min: [0, 0], max: [3, 2]}, slip: no}\n"
    "  - {circle: {centre: [2, 0.5], radius: 0.1}, fluid_side: outside}\n"
    "  - {polygon: [[1.5, 0], [1.7, 0], [1.6, 0.2]], slip: free, fluid_side: outside}\n"
    "physics: {delta: 0.2, artificial_viscosity: 0.02, acoustic_damper: 10, shifting: consistent,"
    " u_max: 3.5}\n"
    "initial: {pressure: zero}\n"
    "probes:\n"
    "  - {name: p_bottom, position: [1.5, 0]}\n"
    "  - {name: p_top, kind: pressure, position: [1.5, 2.1]}\n"
    "parallel: {repartition_threshold: 0.25, repartition_every: 100}\n";

static void same_vec(const double *a, const double *b, int n, const char *what) {
  for (int i = 0; i < n; i++) CHECK(a[i] == b[i], "%s[%d]: %.17g vs %.17g", what, i, a[i], b[i]);
}

static void same_shape(const struct shape *a, const struct shape *b, const char *what) {
  CHECK(a->kind == b->kind && a->n_vertices == b->n_vertices, "%s kind", what);
  same_vec(a->min, b->min, 3, what);
  same_vec(a->max, b->max, 3, what);
  same_vec(a->centre, b->centre, 3, what);
  CHECK(a->radius == b->radius, "%s radius", what);
  CHECK(a->surface == b->surface && a->surface_level == b->surface_level &&
        a->surface_amplitude == b->surface_amplitude && a->surface_wavelength == b->surface_wavelength,
        "%s surface", what);
  for (int i = 0; i < a->n_vertices; i++) same_vec(a->vertex[i], b->vertex[i], 2, what);
}

static void same_lists(const struct case_def *a, const struct case_def *b) {
  CHECK(a->n_phases == b->n_phases && a->n_fluids == b->n_fluids && a->n_walls == b->n_walls &&
            a->n_probes == b->n_probes, "list lengths");
  for (int i = 0; i < a->n_phases; i++) {
    const struct phase *p = &a->phases[i], *q = &b->phases[i];
    CHECK(strcmp(p->name, q->name) == 0 && p->incompressible == q->incompressible, "phase %d", i);
    CHECK(p->rho0 == q->rho0 && p->c0 == q->c0 && p->gamma == q->gamma, "phase %d EOS", i);
    CHECK(p->p_background == q->p_background && p->viscosity == q->viscosity, "phase %d", i);
    same_vec(p->density_band, q->density_band, 2, "density_band");
  }
  for (int i = 0; i < a->n_fluids; i++) {
    CHECK(a->fluids[i].phase == b->fluids[i].phase, "fluid %d phase", i);
    same_shape(&a->fluids[i].shape, &b->fluids[i].shape, "fluid shape");
    same_vec(a->fluids[i].velocity, b->fluids[i].velocity, 3, "fluid velocity");
    CHECK(memcmp(&a->fluids[i].mode, &b->fluids[i].mode, sizeof(a->fluids[i].mode)) == 0,
          "fluid %d velocity_mode", i);
  }
  for (int i = 0; i < a->n_walls; i++) {
    same_shape(&a->walls[i].shape, &b->walls[i].shape, "wall shape");
    CHECK(a->walls[i].slip == b->walls[i].slip, "wall %d slip", i);
    CHECK(a->walls[i].fluid_side == b->walls[i].fluid_side, "wall %d side", i);
    CHECK(memcmp(&a->walls[i].motion, &b->walls[i].motion, sizeof(a->walls[i].motion)) == 0 &&
          a->walls[i].moving == b->walls[i].moving, "wall %d motion", i);
    CHECK(memcmp(&a->walls[i].body, &b->walls[i].body, sizeof(a->walls[i].body)) == 0, "wall %d body", i);
  }
  for (int i = 0; i < a->n_probes; i++) {
    CHECK(strcmp(a->probes[i].name, b->probes[i].name) == 0, "probe %d name", i);
    CHECK(a->probes[i].kind == b->probes[i].kind, "probe %d kind", i);
    same_vec(a->probes[i].position, b->probes[i].position, 3, "probe position");
    same_vec(a->probes[i].axis, b->probes[i].axis, 3, "probe axis");
    CHECK(a->probes[i].diameter == b->probes[i].diameter && a->probes[i].phase == b->probes[i].phase &&
          a->probes[i].interpolation == b->probes[i].interpolation, "probe %d keys", i);
  }
}

static void same_case(const struct case_def *a, const struct case_def *b) {
  CHECK(strcmp(a->name, b->name) == 0, "name %s vs %s", a->name, b->name);
  CHECK(strcmp(a->description, b->description) == 0, "description '%s'", b->description);
  CHECK(a->dimension == b->dimension && a->scheme == b->scheme && a->kernel == b->kernel, "enums");
  CHECK(a->dx == b->dx && a->h_over_dx == b->h_over_dx, "resolution");
  same_vec(a->gravity, b->gravity, 3, "gravity");
  CHECK(a->t_end == b->t_end && a->cfl == b->cfl && a->max_steps == b->max_steps, "time");
  CHECK(a->dt_min == b->dt_min, "dt_min");
  CHECK(a->output_interval == b->output_interval && a->stats_interval == b->stats_interval, "out");
  CHECK(a->probes_interval == b->probes_interval, "probes_interval");
  CHECK(a->progress_interval == b->progress_interval, "progress_interval");
  same_vec(a->domain_min, b->domain_min, 3, "domain_min");
  same_vec(a->domain_max, b->domain_max, 3, "domain_max");
  same_lists(a, b);
  CHECK(a->initial_pressure == b->initial_pressure && a->shifting == b->shifting, "enums");
  CHECK(a->delta == b->delta && a->alpha == b->alpha, "delta, alpha");
  CHECK(a->acoustic_damper == b->acoustic_damper && a->u_max == b->u_max, "damper, u_max");
  CHECK(a->repartition_threshold == b->repartition_threshold, "repartition_threshold");
  CHECK(a->repartition_every == b->repartition_every, "repartition_every");
}

/* case_load(case_to_yaml(c)) == c, and writing it again gives the same text. */
static void round_trip(const char *text) {
  struct case_def a, b;
  CHECK(load(text, 0, NULL, &a) == 0, "round-trip case loads: %s", err);
  char *yaml = case_to_yaml(&a);
  CHECK(load(yaml, 0, NULL, &b) == 0, "case_to_yaml output loads: %s\n%s", err, yaml);
  same_case(&a, &b);
  char *again = case_to_yaml(&b);
  CHECK(strcmp(yaml, again) == 0, "stable output");
  free(yaml);
  free(again);
}

static void test_round_trip(void) {
  struct case_def c;
  round_trip(ROUND_TRIP);
  CHECK(load(ROUND_TRIP, 0, NULL, &c) == 0, "loads: %s", err);
  CHECK(strcmp(c.description, "Tank: \"quoted\" # not a comment\tand a tab") == 0, "escapes");
  CHECK(c.fluids[1].phase == 2 && c.fluids[2].shape.n_vertices == 4, "fluid items");
  CHECK(c.walls[0].slip == SLIP_NO && c.walls[1].fluid_side == FLUID_OUTSIDE, "wall items");
  CHECK(c.dt_min == 1e-7 && c.phases[1].density_band[1] == 1e6, "checks given");
  char *yaml = case_to_yaml(&c);
  CHECK(strstr(yaml, "\ndomain:\n  min: [-0.1, -0.2]\n  max: [3.2, 2.1]\n") != NULL,
        "block style with flow vectors:\n%s", yaml);
  CHECK(strstr(yaml, "  - box:\n      min: [0, 0]\n") != NULL, "wall box in a list item");
  free(yaml);
  round_trip("name: ball\ndimension: 3\nresolution: {dx: 0.1}\ntime: {end: 1}\n"
             "gravity: [0, 0, -9.81]\ndomain: {min: [0, 0, 0], max: [1, 1, 1]}\n"
             "phases: [{name: w, rho0: 1000, c0: 20}]\n"
             "fluids: [{phase: w, circle: {centre: [0.5, 0.5, 0.5], radius: 0.25}}]\n");
  round_trip("name: u\ndimension: 2\nresolution: {dx: 0.1}\ntime: {end: 1}\n"
             "description: \"line\\u2028sep\\x85nel\\u2029par\\x80c1\\ufeffbom \\U0001F30A\"\n"
             "domain: {min: [0, 0], max: [1, 1]}\nphases: [{name: w, rho0: 1000, c0: 20}]\n");
  expect_error("name: t\ndimension: 2\nresolution: {dx: 1e-300}\ntime: {end: 1}\n"
               "domain: {min: [0, 0], max: [1, 1]}\nphases: [{name: w, rho0: 1, c0: 1e300}]\n", 0,
               NULL, "case.yaml:4: time.dt_min: got the default 0 computed from the other keys",
               "expected a number > 0: set the key");
  round_trip("name: rt\ndimension: 3\nresolution: {dx: 0.1}\ntime: {end: 1}\n"
             "domain: {min: [0, 0, 0], max: [1, 1, 4]}\nphases: [{name: w, rho0: 1, c0: 1}]\n"
             "fluids: [{phase: w, box: {min: [0, 0, 1.9], max: [1, 1, 4],\n"
             "          floor: {level: 2, amplitude: 0.05, wavelength: 1}}},\n"
             "         {phase: w, box: {min: [0, 0, 0], max: [1, 1, 2.1],\n"
             "          ceiling: {level: 2, amplitude: 0.05, wavelength: 1}}}]\n");
  expect_error("name: f\ndimension: 3\nresolution: {dx: 0.1}\ntime: {end: 1}\n"
               "domain: {min: [0, 0, 0], max: [1, 1, 1]}\nphases: [{name: w, rho0: 1, c0: 1}]\n"
               "walls: [{box: {min: [0, 0, 0], max: [1, 1, 1], floor: {level: 0.5, amplitude: 0.1, "
               "wavelength: 1}}}]\n", 0, NULL, "case.yaml:7: walls.0.box: got a box with a floor or ceiling in a wall",
               "expected a plain box");
  expect_error("name: p\ndimension: 3\nresolution: {dx: 0.1}\ntime: {end: 1}\n"
               "domain: {min: [0, 0, 0], max: [1, 1, 1]}\nphases: [{name: w, rho0: 1, c0: 1}]\n"
               "walls: [{polygon: [[0, 0], [1, 0], [0, 1]]}]\n", 0, NULL,
               "case.yaml:7: walls.0.polygon: got a polygon in 3D", "expected box or circle");
}

/* resolution.origin: one lattice for every fluid region. An air box whose lower corner is 0.015 dx
 * off the water's lattice loses its top row (it falls 0.485 dx from the lid, inside dx/2, and is
 * not filled); on the common lattice anchored at the tank's corner the row is there. */
static void test_lattice_origin(void) {
  const char *tank = "name: tank\ndimension: 2\nresolution: {dx: 0.02}\ntime: {end: 1.0}\n"
                     "domain: {min: [-0.1, -0.1], max: [1.1, 1.1]}\n"
                     "phases: [{name: water, rho0: 1000, c0: 30}, {name: air, rho0: 1, c0: 340}]\n"
                     "fluids: [{phase: water, box: {min: [0, 0], max: [1, 0.5]}},\n"
                     "         {phase: air, box: {min: [0, 0.5003], max: [1, 1]}}]\n"
                     "walls: [{box: {min: [0, 0], max: [1, 1]}}]\n";
  struct case_def c;
  struct init_counts own, common;
  char msg[256];
  CHECK(load(tank, 0, NULL, &c) == 0 && !c.has_lattice_origin, "loads: %s", err);
  CHECK(init_particles(&c, 0.04, NULL, &own, msg, sizeof msg) == 0, "counts: %s", msg);
  const char *set[] = {"resolution.origin=[0, 0]"};
  CHECK(load(tank, 1, set, &c) == 0 && c.has_lattice_origin, "loads with origin: %s", err);
  CHECK(init_particles(&c, 0.04, NULL, &common, msg, sizeof msg) == 0, "counts: %s", msg);
  CHECK(own.fluid[1] == 24 * 50 && common.fluid[1] == 25 * 50 && common.fluid[0] == 25 * 50,
        "air rows: %ld particles on its own lattice (1200 expected), %ld on the common one (1250)",
        own.fluid[1], common.fluid[1]);
  round_trip(variant(3, "resolution: {dx: 0.02, origin: [0, 0.01]}"));
  expect_error(variant(3, "resolution: {dx: 0.02, origin: [0]}"), 0, NULL,
               "case.yaml:3: resolution.origin: got a list of 1 item", "one per dimension");
}

/* fluids.N.velocity_mode: the interface mode's velocity on the lattice (both sides of a flat
 * interface at y0 = 0.5: the normal velocity continuous across it, the tangential one reversed,
 * the value V e^(-k|y - y0|) cos kx on each particle), its echo and its errors. */
static void test_velocity_mode(void) {
  const char *mode = "{amplitude: 0.02, wavelength: 0.5, interface: 0.5}";
  char text[1024];
  snprintf(text, sizeof text, "name: rt\ndimension: 2\nresolution: {dx: 0.05, origin: [0, 0]}\n"
           "time: {end: 1.0}\ndomain: {min: [-0.1, -0.1], max: [1.1, 1.1]}\n"
           "phases: [{name: heavy, rho0: 3, c0: 6}, {name: light, rho0: 1, c0: 6}]\n"
           "fluids: [{phase: heavy, box: {min: [0, 0.5], max: [1, 1]}, velocity_mode: %s},\n"
           "         {phase: light, box: {min: [0, 0], max: [1, 0.5]}, velocity_mode: %s}]\n", mode, mode);
  struct case_def c;
  struct parts p;
  struct init_counts n;
  char msg[256];
  CHECK(load(text, 0, NULL, &c) == 0 && c.fluids[1].mode.active, "loads: %s", err);
  parts_init(&p, 2, 16, 0);
  CHECK(init_particles(&c, 0.1, &p, &n, msg, sizeof msg) == 0 && p.n_owned == 400, "init: %s", msg);
  double k = 4 * acos(-1.0), worst = 0, jump_n = 0, jump_t = 0;
  for (long i = 0; i < p.n_owned; i++) {
    double x = p.x[0][i], dy = p.x[1][i] - 0.5, decay = 0.02 * exp(-k * fabs(dy));
    worst = fmax(worst, fabs(p.v[1][i] - decay * cos(k * x)));
    worst = fmax(worst, fabs(p.v[0][i] - (dy > 0 ? decay : -decay) * sin(k * x)));
    for (long j = 0; j < p.n_owned; j++)   /* the mirror particle across the interface */
      if (p.x[0][j] == x && fabs(p.x[1][j] - 0.5 + dy) < 1e-12) {
        jump_n = fmax(jump_n, fabs(p.v[1][j] - p.v[1][i]));
        jump_t = fmax(jump_t, fabs(p.v[0][j] + p.v[0][i]));
      }
  }
  CHECK(worst < 1e-15, "mode velocity off by %g m/s", worst);
  CHECK(jump_n < 1e-15 && jump_t < 1e-15, "mirror pairs: normal jump %g, tangential asymmetry %g",
        jump_n, jump_t);
  parts_free(&p);
  round_trip(text);
  expect_error(variant(10, "  - {phase: water, box: {min: [0, 0], max: [1, 0.5]}, "
                       "velocity_mode: {amplitude: 0.1, wavelength: 0, interface: 0.5}}"), 0, NULL,
               "case.yaml:10: fluids.0.velocity_mode.wavelength: got '0'", "a number > 0");
  expect_error(variant(10, "  - {phase: water, box: {min: [0, 0], max: [1, 0.5]}, "
                       "velocity_mode: {amplitude: 0.1, wavelength: 1}}"), 0, NULL,
               "fluids.0.velocity_mode.interface: missing required key", "a number");
  expect_error("name: t\ndimension: 3\nresolution: {dx: 0.1}\ntime: {end: 1}\n"
               "domain: {min: [0, 0, 0], max: [1, 1, 1]}\nphases: [{name: w, rho0: 1, c0: 1}]\n"
               "fluids: [{phase: w, box: {min: [0, 0, 0], max: [1, 1, 1]}, "
               "velocity_mode: {amplitude: 1, wavelength: 1, interface: 0.5}}]\n", 0, NULL,
               "case.yaml:7: fluids.0.velocity_mode: got velocity_mode in 3D", "2D only");
}

/* Wall motion: the laws, their defaults, the round trip and the required keys. */
static void test_motion(void) {
  const char *moving = "walls:\n  - box: {min: [0, 0], max: [1, 1]}\n    motion:\n"
                       "      translation: {amplitude: [0.01, 0], period: 0.83, phase: 3.141592653589793}\n"
                       "      rotation: {amplitude: 0.05, period: 2, centre: [0.5, 0.5], ramp: {shape: smooth, time: 3}}\n";
  struct case_def c;
  CHECK(load(variant(13, moving), 0, NULL, &c) == 0, "loads: %s", err);
  const struct wall_motion *m = &c.walls[0].motion;
  CHECK(c.walls[0].moving && m->translation.active && m->rotation.active, "both laws active");
  CHECK(m->translation.amplitude[0] == 0.01 && m->translation.period == 0.83 &&
        m->translation.ramp == RAMP_NONE, "translation law");
  CHECK(m->rotation.amplitude[0] == 0.05 && m->rotation.ramp == RAMP_SMOOTH && m->rotation.ramp_time == 3 &&
        m->centre[1] == 0.5 && m->rotation.phase == 0, "rotation law");
  round_trip(variant(13, moving));
  CHECK(load(variant(13, "walls: [{box: {min: [0, 0], max: [1, 1]}}]"), 0, NULL, &c) == 0 && !c.walls[0].moving,
        "a wall without motion is fixed");
  expect_error(variant(13, "walls: [{box: {min: [0, 0], max: [1, 1]}, motion: {translation: {amplitude: [0.01, 0]}}}]"),
               0, NULL, "case.yaml:13: walls.0.motion.translation.period: missing required key", "a number > 0");
  expect_error(variant(13, "walls: [{box: {min: [0, 0], max: [1, 1]}, motion: {rotation: {amplitude: 0.1, period: 1}}}]"),
               0, NULL, "walls.0.motion.rotation.centre: missing required key", "");
  expect_error(variant(13, "walls: [{box: {min: [0, 0], max: [1, 1]}, motion: {translation: {amplitude: [1, 0], "
                           "period: 1, ramp: {shape: cosine, time: 1}}}}]"),
               0, NULL, "walls.0.motion.translation.ramp.shape: got 'cosine'", "none, linear, smooth");
  expect_error(variant(13, "walls: [{box: {min: [0, 0], max: [1, 1]}, motion: {translation: {amplitude: [0.01, 0], "
                           "period: 1, phase: 1.5708}}}]"),
               0, NULL, "case.yaml:13: walls.0.motion: starts displaced (|d(0)| = 0.01 m", "zero displacement");
}

/* A 3D case whose line 7 is the walls given. */
static const char *case_3d(const char *walls) {
  static char buf[1024];
  snprintf(buf, sizeof buf, "name: t\ndimension: 3\nresolution: {dx: 0.1}\ntime: {end: 1}\n"
           "domain: {min: [-1, -1, -1], max: [2, 2, 2]}\nphases: [{name: w, rho0: 1000, c0: 20}]\n%s\n", walls);
  return buf;
}

/* The rotation axis: 3D only, kept as given and written back, z by default, the zero vector and
 * a motion-level axis beside a law refused. */
static void test_motion_axis(void) {
  const char *roll = "walls: [{box: {min: [0, 0, 0], max: [1, 1, 1]}, motion: {rotation: {amplitude: 0.1, "
                     "period: 1, centre: [0.5, 0.5, 0.5], axis: [2, 0, 0]}}}]";
  const char *table = "walls: [{box: {min: [0, 0, 0], max: [1, 1, 1]}, motion: {centre: [0.5, 0, 0.5], "
                      "axis: [0, -1, 0.5], table: [[0, 0, 0, 0, 0], [1, 0, 0, 0, 0.1]]}}]";
  struct case_def c;
  CHECK(load(case_3d(roll), 0, NULL, &c) == 0, "roll loads: %s", err);
  const double *a = c.walls[0].motion.axis;
  CHECK(a[0] == 2 && a[1] == 0 && a[2] == 0, "axis kept as given: [%g, %g, %g]", a[0], a[1], a[2]);
  round_trip(case_3d(roll));
  CHECK(load(case_3d(table), 0, NULL, &c) == 0, "table about an axis loads: %s", err);
  CHECK(a[1] == -1 && a[2] == 0.5 && c.walls[0].motion.n_rows == 2, "table axis");
  round_trip(case_3d(table));
  CHECK(load(case_3d("walls: [{box: {min: [0, 0, 0], max: [1, 1, 1]}, motion: {rotation: {amplitude: 0.1, "
                     "period: 1, centre: [0.5, 0.5, 0.5]}}}]"), 0, NULL, &c) == 0 &&
        a[0] == 0 && a[1] == 0 && a[2] == 1, "the default axis is z: %s", err);
  CHECK(load(variant(13, "walls: [{box: {min: [0, 0], max: [1, 1]}, motion: {translation: {amplitude: [0.1, 0], "
                         "period: 1}}}]"), 0, NULL, &c) == 0 && a[0] == 0 && a[1] == 0 && a[2] == 1,
        "2D: the axis is z: %s", err);
  static const struct { int dim; const char *walls, *where, *what; } refused[] = {
      {3, "walls: [{box: {min: [0, 0, 0], max: [1, 1, 1]}, motion: {rotation: {amplitude: 0.1, period: 1, "
          "centre: [0.5, 0.5, 0.5], axis: [0, 0, 0]}}}]",
       "case.yaml:7: walls.0.motion.rotation.axis: got a zero or overflowing vector", "a rotation axis of finite length"},
      {3, "walls: [{box: {min: [0, 0, 0], max: [1, 1, 1]}, motion: {rotation: {amplitude: 0.1, period: 1, "
          "centre: [0.5, 0.5, 0.5], axis: [1, 0]}}}]",
       "case.yaml:7: walls.0.motion.rotation.axis: got a list of 2 items", "a list of 3 numbers"},
      {3, "walls: [{box: {min: [0, 0, 0], max: [1, 1, 1]}, motion: {axis: [1, 0, 0], "
          "rotation: {amplitude: 0.1, period: 1, centre: [0.5, 0.5, 0.5]}}}]",
       "case.yaml:7: walls.0.motion.axis: got an axis without a table", "rotation.axis"},
      {2, "walls: [{box: {min: [0, 0], max: [1, 1]}, motion: {rotation: {amplitude: 0.1, period: 1, "
          "centre: [0.5, 0.5], axis: [0, 0, 1]}}}]",
       "case.yaml:13: walls.0.motion.rotation.axis: got an axis in 2D", "turns about z"},
      {2, "walls: [{box: {min: [0, 0], max: [1, 1]}, motion: {axis: [1, 0], table: [[0, 0, 0, 0], [1, 0, 0, 0.1]]}}]",
       "case.yaml:13: walls.0.motion.axis: got an axis in 2D", "turns about z"}};
  for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++)
    expect_error(refused[i].dim == 3 ? case_3d(refused[i].walls) : variant(13, refused[i].walls), 0, NULL,
                 refused[i].where, refused[i].what);
}

/* Probe kinds: their keys, the round trip, the keys of another kind, the sensor axis, the
 * probes.csv columns. */
static void test_probe_kinds(void) {
  const char *probes = "  - {name: p0, position: [0.5, 0], diameter: 0.1, axis: [2, 0], interpolation: mls}\n"
                       "  - {name: eta, kind: elevation, position: [0.3, 0.9], phase: water}\n"
                       "  - {name: w, kind: integral, phase: water}\n";
  char with_gravity[4096], col[128];
  snprintf(with_gravity, sizeof with_gravity, "gravity: [0, -9.81]\n%s", variant(12, probes));
  struct case_def c;
  CHECK(load(with_gravity, 0, NULL, &c) == 0, "loads: %s", err);
  CHECK(c.probes[0].diameter == 0.1 && c.probes[0].axis[0] == 2 && c.probes[0].interpolation == INTERP_MLS,
        "segment sensor");
  CHECK(c.probes[1].kind == PROBE_ELEVATION && c.probes[1].phase == 0, "gauge");
  CHECK(c.probes[2].kind == PROBE_INTEGRAL && c.probes[2].phase == 0, "integral");
  CHECK(case_probe_column(&c, 2, 4, col, sizeof col) == 5 && strcmp(col, "w_com_y") == 0, "column %s", col);
  CHECK(c.probes[0].interpolation == INTERP_MLS, "mls");
  round_trip(with_gravity);
  expect_error(variant(12, "  - {name: e, kind: elevation, position: [0.5, 0], phase: water}"), 0, NULL,
               "case.yaml:12: probes.0.kind: got an elevation probe with zero gravity", "expected a gravity");
  expect_error(variant(12, "  - {name: e, kind: integral, phase: water, position: [0.5, 0]}"), 0, NULL,
               "case.yaml:12: probes.0.position: not a key of kind integral", "its keys: name, kind, phase");
  expect_error(variant(12, "  - {name: e, position: [0.5, 0], diameter: 0.1}"), 0, NULL,
               "case.yaml:12: probes.0.axis: missing required key", "a list of 2 numbers");
  expect_error(variant(12, "  - {name: e, position: [0.5, 0], axis: [1, 0]}"), 0, NULL,
               "case.yaml:12: probes.0.axis: got an axis for a point sensor", "diameter > 0");
  expect_error(variant(12, "  - {name: e, position: [0.5, 0], diameter: 0.1, axis: [0, 0]}"), 0, NULL,
               "case.yaml:12: probes.0.axis: got a zero or overflowing vector", "a direction of finite length");
  expect_error(variant(12, "  - {name: e, position: [0.5, 0], diameter: 0.1, axis: [0, 1]}"), 0, NULL,
               "case.yaml:12: probes.0.diameter: got [0.5, -0.05] outside the domain", "inside the domain");
  expect_error(variant(12, "  - {name: e, position: [0.5, 0], interpolation: linear}"), 0, NULL,
               "case.yaml:12: probes.0.interpolation: got 'linear'", "shepard, mls");
  expect_error(variant(12, "  - {name: w_volume, position: [0.5, 0]}\n  - {name: w, kind: integral, phase: water}"),
               0, NULL, "case.yaml:13: probes.1.name: gives the probes.csv column 'w_volume'", "unique columns");
}

/* Wall motion by a table: the rows, the round trip, the errors. */
static void test_motion_table(void) {
  const char *table = "walls:\n  - box: {min: [0, 0], max: [1, 1]}\n    motion:\n      centre: [0.5, 0.2]\n"
                      "      table: [[0, 0, 0, 0], [0.5, 0.01, 0, 0.02], [1, 0, 0.003, 0]]\n";
  struct case_def c;
  CHECK(load(variant(13, table), 0, NULL, &c) == 0, "loads: %s", err);
  const struct wall_motion *m = &c.walls[0].motion;
  CHECK(c.walls[0].moving && m->n_rows == 3 && m->table[1][1] == 0.01 && m->table[1][4] == 0.02 &&
        m->table[2][2] == 0.003 && m->centre[0] == 0.5 && !m->translation.active, "table rows");
  round_trip(variant(13, table));
  expect_error(variant(13, "walls: [{box: {min: [0, 0], max: [1, 1]}, motion: {table: [[0, 0, 0, 0], [0, 1, 0, 0]]}}]"),
               0, NULL, "case.yaml:13: walls.0.motion.table.1: got time 0 after 0", "strictly increasing");
  expect_error(variant(13, "walls: [{box: {min: [0, 0], max: [1, 1]}, motion: {table: [[0, 0, 0, 0.1], [1, 0, 0, 0]]}}]"),
               0, NULL, "case.yaml:13: walls.0.motion: starts displaced (|d(0)| = 0 m, theta(0) = 0.1 rad)", "zero displacement");
  expect_error(variant(13, "walls: [{box: {min: [0, 0], max: [1, 1]}, motion: {table: [[0, 0, 0]]}}]"),
               0, NULL, "case.yaml:13: walls.0.motion.table: got a list of 1 item", "a list of 2 to 256");
  expect_error(variant(13, "walls: [{box: {min: [0, 0], max: [1, 1]}, motion: {table: [[0, 0, 0], [1, 0, 0]]}}]"),
               0, NULL, "case.yaml:13: walls.0.motion.table.0: got a list of 3 items", "a row of 4 numbers [t, dx, dy, theta]");
  expect_error(variant(13, "walls: [{box: {min: [0, 0], max: [1, 1]}, motion: {table: [[0, 0, 0, 0], [1, 0, 0, 0]], "
                           "translation: {amplitude: [1, 0], period: 1}}}]"),
               0, NULL, "case.yaml:13: walls.0.motion: got a table and a sinusoidal law", "one of them");
  expect_error(variant(13, "walls: [{box: {min: [0, 0], max: [1, 1]}, motion: {centre: [0, 0], "
                           "translation: {amplitude: [1, 0], period: 1}}}]"),
               0, NULL, "case.yaml:13: walls.0.motion.centre: got a centre without a table", "rotation.centre");
}

/* Rigid bodies: the defaults from the shape, the degrees of freedom, the round trip (2D and 3D)
 * and the refusals; prescribed degrees of freedom beside free ones. */
static void test_bodies(void) {
  const char *body2 = "walls: [{box: {min: [0, 0], max: [1, 1]}}, {box: {min: [0.2, 0.4], max: [0.6, 0.6]}, "
                      "fluid_side: outside, body: {mass: 12, velocity: [0, -1], fixed: [x, rotation]}}]";
  struct case_def c;
  CHECK(load(variant(13, body2), 0, NULL, &c) == 0, "body loads: %s", err);
  const struct body *b = &c.walls[1].body;
  CHECK(b->active && c.walls[1].moving && !c.walls[0].body.active, "wall 1 is a body, wall 0 is not");
  CHECK_CLOSE(b->centre[0], 0.4, 1e-15, "default centre: the box's");
  CHECK_CLOSE(b->inertia[2], 12 * (0.16 + 0.04) / 12, 1e-15, "default I_zz: the box's, M (a^2 + b^2)/12");
  CHECK(b->fixed == (BODY_DOF_X | BODY_DOF_RZ) && b->velocity[1] == -1, "fixed x and rotation, velocity");
  round_trip(variant(13, body2));
  round_trip(case_3d("walls: [{box: {min: [0, 0, 0], max: [0.2, 0.1, 0.3]}, fluid_side: outside, body: "
                     "{mass: 3, inertia: [1, 2, 3], angular_velocity: [0, 0, 1], fixed: [z, rx, ry]}}]"));
  static const char *const refused[][3] = {   /* walls (line 13), where, what is expected */
      {"walls: [{box: {min: [0, 0], max: [1, 1]}, body: {mass: 1, fixed: [rz]}}]",
       "case.yaml:13: walls.0.body.fixed.0: got 'rz'", "x, y, rotation"},
      {"walls: [{box: {min: [0, 0], max: [1, 1]}, body: {fixed: [x]}}]", "walls.0.body.mass: missing required key",
       "a number > 0"},
      {"walls: [{box: {min: [0, 0], max: [1, 1]}, body: {mass: 1}, motion: {translation: {amplitude: [0.01, 0], "
       "period: 1}}}]", "walls.0.motion: got a motion and a body without body.prescribed", "to name the degrees"},
      {"walls: [{box: {min: [0, 0], max: [1, 1]}, body: {mass: 1, prescribed: [y]}}]",
       "walls.0.body: got prescribed degrees of freedom and no motion", "walls.N.motion"},
      {"walls: [{box: {min: [0, 0], max: [1, 1]}, body: {mass: 1, fixed: [y], prescribed: [y]}, motion: "
       "{translation: {amplitude: [0, 0.1], period: 1}}}]", "walls.0.body: got a degree of freedom both fixed and "
       "prescribed", "each in one list"},
      {"walls: [{box: {min: [0, 0], max: [1, 1]}, body: {mass: 1, prescribed: [y]}, motion: "
       "{translation: {amplitude: [0.1, 0.1], period: 1}}}]", "walls.0.motion: moves a degree of freedom the body does "
       "not prescribe", "to be zero"},
      {"walls: [{box: {min: [0, 0], max: [1, 1]}, body: {mass: 1, prescribed: [rotation]}, motion: "
       "{rotation: {amplitude: 0.1, period: 1, centre: [0, 0]}}}]", "walls.0.motion: turns about (0, 0, 0)",
       "the body's centre of mass (0.5, 0.5, 0)"}};
  for (size_t k = 0; k < sizeof refused / sizeof refused[0]; k++)
    expect_error(variant(13, refused[k][0]), 0, NULL, refused[k][1], refused[k][2]);
  const char *heave = "walls: [{box: {min: [0, 0], max: [1, 1]}, body: {mass: 1, prescribed: [y, rotation]}, "
                      "motion: {table: [[0, 0, 0, 0], [1, 0, 0.1, 0.2]], centre: [0.5, 0.5]}}]";
  CHECK(load(variant(13, heave), 0, NULL, &c) == 0, "prescribed heave and roll load: %s", err);
  CHECK(c.walls[0].body.prescribed == (BODY_DOF_Y | BODY_DOF_RZ) && c.walls[0].motion.n_rows == 2,
        "y and rotation follow the table");
  round_trip(variant(13, heave));
  const char *spin = "walls: [{box: {min: [0, 0, 0], max: [1, 1, 1]}, body: {mass: 1, prescribed: [rx, ry, rz]}, "
                     "motion: {rotation: {amplitude: 0.1, period: 1, centre: [0.5, 0.5, 0.5], axis: [1, 1, 0]}}}]";
  round_trip(case_3d(spin));
  const char *carried = "  - {name: p0, position: [0.5, 0.4], wall: 1}\nwalls: [{box: {min: [0, 0], max: [1, 1]}}, "
                        "{box: {min: [0.4, 0.4], max: [0.6, 0.6]}, fluid_side: outside, body: {mass: 1}}]";
  CHECK(load(variant(12, carried), 0, NULL, &c) == 0 && c.probes[0].wall == 1, "a sensor the body carries: %s", err);
  round_trip(variant(12, carried));
  expect_error(variant(12, "  - {name: p0, position: [0.5, 0.4], wall: 0}\nwalls: [{box: {min: [0, 0], max: [1, 1]}}]"),
               0, NULL, "probes.0.wall: got wall 0", "the index of a moving wall");
  expect_error(case_3d("walls: [{box: {min: [0, 0, 0], max: [1, 1, 1]}, body: {mass: 1, prescribed: [rx]}, "
                       "motion: {rotation: {amplitude: 0.1, period: 1, centre: [0.5, 0.5, 0.5], axis: [1, 0, 0]}}}]"),
               0, NULL, "walls.0.body: got some of a 3D body's rotations prescribed", "rx, ry and rz together");
}

int main(void) {
  strcpy(dir, "/tmp/test_case_load.XXXXXX");
  if (!mkdtemp(dir)) return 1;
  snprintf(path, sizeof path, "%s/case.yaml", dir);
  test_defaults();
  test_key_errors();
  test_value_errors();
  test_shape_errors();
  test_malformed();
  test_string();
  test_set();
  test_round_trip();
  test_motion();
  test_probe_kinds();
  test_motion_table();
  test_motion_axis();
  test_bodies();
  test_lattice_origin();
  test_velocity_mode();
  unlink(path);
  rmdir(dir);
  return check_report("test_case_load");
}
