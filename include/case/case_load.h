/* case_load.h — read a YAML case file, apply --set overrides, validate, fill struct case_def. */
#ifndef MPSPH_CASE_LOAD_H
#define MPSPH_CASE_LOAD_H

#include <stddef.h>
#include <stdio.h>
#include "case/case.h"

/** Load `path`, apply the overrides `sets[0..n_sets-1]` ("key.path=value", value in YAML flow
 *  syntax), validate and fill `c` with every default resolved. Returns 0 on success, 1 on bad
 *  input with a one-line message in err naming the file, the line, the key path and the allowed
 *  values (e.g. "case.yaml:12: physics.delta: expected a number >= 0, got 'abc'"). */
int case_load(const char *path, int n_sets, char *const *sets, struct case_def *c,
              char *err, size_t err_len);

/** case_load on the len bytes of YAML text instead of a file; `source` names the text in
 *  messages and in c->source_file. */
int case_load_string(const char *text, size_t len, const char *source, int n_sets,
                     char *const *sets, struct case_def *c, char *err, size_t err_len);

/** The resolved case as YAML text (every key, defaults filled). Caller frees. Loading this
 *  text again gives the same case. */
char *case_to_yaml(const struct case_def *c);

/** Print the reference of the case keys read by a table (every key but those of the fluid, wall
 *  and probe items) as a markdown table to f: path, type, default, allowed values, meaning. */
void case_keys_markdown(FILE *f);

/** The number of probes.csv columns of probe k of c (1, or 3 + dimension for an integral) and,
 *  if buf is not NULL, the name of column col (< that number) in buf. */
int case_probe_column(const struct case_def *c, int k, int col, char *buf, size_t len);

/** What the file at path is when it exists but is not a regular file ("a directory", "a FIFO
 *  (named pipe)", "a character device", ...), or NULL: a regular file, or none (opening it then
 *  says why). Input files are refused unless regular: opening a FIFO waits for a writer. */
const char *case_file_not_regular(const char *path);

#endif
