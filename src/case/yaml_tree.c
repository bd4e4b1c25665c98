/* yaml_tree.c — build a node tree from libyaml parser events; apply key.path=value overrides. */
#include "case/yaml_tree.h"
#include "base/mem.h"

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

#define YTREE_MAX_DEPTH 64
#define YTREE_PATH_LEN 256

struct reader {
  yaml_parser_t parser;
  const char *source;
  int fixed_line;        /* > 0: every node and error gets this line */
  char *err;
  size_t err_len;
};

/* Write "<source>:<line>: [<path>: ]<message>" into err. */
static void say(char *err, size_t err_len, const char *source, int line, const char *path,
                const char *fmt, ...) {
  if (err_len == 0) return;
  int k = snprintf(err, err_len, "%s:%d: %s%s", source, line, path, path[0] ? ": " : "");
  if (k < 0 || (size_t)k >= err_len) return;
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(err + k, err_len - (size_t)k, fmt, ap);
  va_end(ap);
}

static struct ynode *node_new(enum ynode_kind kind, const char *source, int line) {
  struct ynode *n = mem_calloc(1, sizeof *n, "YAML node");
  n->kind = kind;
  n->source = mem_strndup(source, SIZE_MAX, "YAML source name");
  n->line = line;
  return n;
}

static struct yentry *append(struct ynode *n, char *key, int key_line, struct ynode *value) {
  if (n->n == n->cap) {
    n->cap = n->cap ? 2 * n->cap : 4;
    n->entries = mem_realloc(n->entries, mem_bytes((size_t)n->cap, sizeof *n->entries, "YAML map"), "YAML map");
  }
  n->entries[n->n] = (struct yentry){key, key_line, value};
  return &n->entries[n->n++];
}

/* Free a tree (NULL is allowed). */
void ytree_free(struct ynode *node) {
  if (!node) return;
  for (int i = 0; i < node->n; i++) {
    free(node->entries[i].key);
    ytree_free(node->entries[i].value);
  }
  free(node->entries);
  free(node->text);
  free(node->source);
  free(node);
}

/* The value of `key` in the mapping `map`, or NULL. */
const struct ynode *ytree_get(const struct ynode *map, const char *key) {
  if (!map || map->kind != YNODE_MAPPING) return NULL;
  for (int i = 0; i < map->n; i++)
    if (strcmp(map->entries[i].key, key) == 0) return map->entries[i].value;
  return NULL;
}

/* ---- reading libyaml events ---- */

static int event_line(const struct reader *rd, yaml_mark_t mark) {
  return rd->fixed_line > 0 ? rd->fixed_line : (int)mark.line + 1;
}

/* Read the next event; on a syntax error write the message and return 0. */
static int next_event(struct reader *rd, yaml_event_t *ev, const char *path) {
  if (yaml_parser_parse(&rd->parser, ev)) return 1;
  const yaml_parser_t *p = &rd->parser;
  say(rd->err, rd->err_len, rd->source, event_line(rd, p->problem_mark), path,
      "malformed YAML: %s%s%s, expected valid YAML", p->problem ? p->problem : "syntax error",
      p->context ? " " : "", p->context ? p->context : "");
  return 0;
}

static void child_path(char *out, const char *parent, const char *key) {
  int k = snprintf(out, YTREE_PATH_LEN, "%s%s%s", parent, parent[0] ? "." : "", key);
  if (k >= YTREE_PATH_LEN) out[YTREE_PATH_LEN - 1] = '\0';
}

/* Refuse an anchor (&name) or a tag (!!str, !x) on the node starting with event ev: an anchor is
 * only of use to an alias, which is refused, and a tag would be ignored. Returns 0, or 1 with a
 * message. */
static int decorated(struct reader *rd, const yaml_event_t *ev, const char *path, int line) {
  const yaml_char_t *anchor = ev->type == YAML_SCALAR_EVENT ? ev->data.scalar.anchor
                              : ev->type == YAML_SEQUENCE_START_EVENT ? ev->data.sequence_start.anchor
                              : ev->type == YAML_MAPPING_START_EVENT ? ev->data.mapping_start.anchor : NULL;
  const yaml_char_t *tag = ev->type == YAML_SCALAR_EVENT ? ev->data.scalar.tag
                           : ev->type == YAML_SEQUENCE_START_EVENT ? ev->data.sequence_start.tag
                           : ev->type == YAML_MAPPING_START_EVENT ? ev->data.mapping_start.tag : NULL;
  if (anchor)
    say(rd->err, rd->err_len, rd->source, line, path, "got the anchor &%s, expected none "
        "(anchors and aliases are not supported)", (const char *)anchor);
  else if (tag) {
    const char *name = (const char *)tag, *core = "tag:yaml.org,2002:";   /* written !!name */
    int is_core = strncmp(name, core, strlen(core)) == 0;
    say(rd->err, rd->err_len, rd->source, line, path, "got the tag %s%s, expected none "
        "(tags are not supported)", is_core ? "!!" : "", is_core ? name + strlen(core) : name);
  }
  return anchor || tag;
}

static struct ynode *parse_node(struct reader *rd, yaml_event_t *ev, const char *path, int depth);

static int read_item(struct reader *rd, struct ynode *seq, yaml_event_t *ev, const char *path,
                     int depth) {
  char index[16], cpath[YTREE_PATH_LEN];
  snprintf(index, sizeof index, "%d", seq->n);
  child_path(cpath, path, index);
  struct ynode *child = parse_node(rd, ev, cpath, depth + 1);
  if (child) append(seq, NULL, child->line, child);
  return child != NULL;
}

static int read_pair(struct reader *rd, struct ynode *map, yaml_event_t *ev, const char *path,
                     int depth) {
  int line = event_line(rd, ev->start_mark);
  if (ev->type != YAML_SCALAR_EVENT) {
    say(rd->err, rd->err_len, rd->source, line, path,
        "got a list or mapping as a key, expected plain keys");
    return 0;
  }
  const char *key = (const char *)ev->data.scalar.value;
  char cpath[YTREE_PATH_LEN];
  child_path(cpath, path, key);
  if (decorated(rd, ev, cpath, line)) return 0;
  if (ytree_get(map, key)) {
    say(rd->err, rd->err_len, rd->source, line, cpath, "duplicate key, expected each key once");
    return 0;
  }
  yaml_event_t vev;
  if (!next_event(rd, &vev, cpath)) return 0;
  struct ynode *child = parse_node(rd, &vev, cpath, depth + 1);
  yaml_event_delete(&vev);
  if (child) append(map, mem_strndup(key, SIZE_MAX, "YAML key"), line, child);
  return child != NULL;
}

/* Read the children of the list or mapping n up to its end event. */
static struct ynode *parse_children(struct reader *rd, struct ynode *n, const char *path,
                                    int depth) {
  if (depth > YTREE_MAX_DEPTH) {
    say(rd->err, rd->err_len, rd->source, n->line, path, "nested deeper than %d levels",
        YTREE_MAX_DEPTH);
    ytree_free(n);
    return NULL;
  }
  for (;;) {
    yaml_event_t ev;
    if (!next_event(rd, &ev, path)) break;
    int end = ev.type == YAML_SEQUENCE_END_EVENT || ev.type == YAML_MAPPING_END_EVENT;
    int ok = end || (n->kind == YNODE_MAPPING ? read_pair(rd, n, &ev, path, depth)
                                              : read_item(rd, n, &ev, path, depth));
    yaml_event_delete(&ev);
    if (end) return n;
    if (!ok) break;
  }
  ytree_free(n);
  return NULL;
}

/* Build the node that starts with event ev (the caller deletes ev). */
static struct ynode *parse_node(struct reader *rd, yaml_event_t *ev, const char *path, int depth) {
  int line = event_line(rd, ev->start_mark);
  struct ynode *n;
  if (decorated(rd, ev, path, line)) return NULL;
  switch (ev->type) {
  case YAML_SCALAR_EVENT:
    n = node_new(YNODE_SCALAR, rd->source, line);
    n->text = mem_strndup((const char *)ev->data.scalar.value, SIZE_MAX, "YAML scalar");
    n->plain = ev->data.scalar.style == YAML_PLAIN_SCALAR_STYLE;
    return n;
  case YAML_SEQUENCE_START_EVENT:
    return parse_children(rd, node_new(YNODE_SEQUENCE, rd->source, line), path, depth);
  case YAML_MAPPING_START_EVENT:
    return parse_children(rd, node_new(YNODE_MAPPING, rd->source, line), path, depth);
  case YAML_ALIAS_EVENT:
    say(rd->err, rd->err_len, rd->source, line, path,
        "got the alias *%s, expected a value written out (anchors and aliases are not supported)",
        (const char *)ev->data.alias.anchor);
    return NULL;
  default:
    say(rd->err, rd->err_len, rd->source, line, path, "unexpected YAML event %d", ev->type);
    return NULL;
  }
}

/* Handle one top-level event: -1 error, 0 go on, 1 end of stream. */
static int stream_event(struct reader *rd, yaml_event_t *ev, struct ynode **root, int *docs,
                        const char *path) {
  int line = event_line(rd, ev->start_mark);
  switch (ev->type) {
  case YAML_STREAM_START_EVENT:
  case YAML_DOCUMENT_END_EVENT:
    return 0;
  case YAML_DOCUMENT_START_EVENT:
    if (++*docs == 1) return 0;
    say(rd->err, rd->err_len, rd->source, line, path,
        "a second YAML document, expected a single document");
    return -1;
  case YAML_STREAM_END_EVENT:
    if (*root) return 1;
    say(rd->err, rd->err_len, rd->source, line, path, "no YAML content, expected a value");
    return -1;
  default:
    *root = parse_node(rd, ev, path, 0);
    return *root ? 0 : -1;
  }
}

/* Read the whole stream of an initialised parser; `path` names the text in messages. */
static struct ynode *read_stream(struct reader *rd, const char *path) {
  struct ynode *root = NULL;
  int docs = 0, status = 0;
  while (status == 0) {
    yaml_event_t ev;
    if (!next_event(rd, &ev, path)) {
      status = -1;
      break;
    }
    status = stream_event(rd, &ev, &root, &docs, path);
    yaml_event_delete(&ev);
  }
  if (status > 0) return root;
  ytree_free(root);
  return NULL;
}

/* The encoding, UTF-16 or UTF-32, whose byte-order mark text starts with, or NULL. libyaml would
 * read such text; without a mark it reads UTF-8 and refuses invalid sequences itself. */
static const char *foreign_bom(const char *text, size_t len) {
  static const struct { const char *bytes, *name; size_t n; } boms[] = {
      {"\xff\xfe\0\0", "UTF-32LE", 4}, {"\0\0\xfe\xff", "UTF-32BE", 4},
      {"\xff\xfe", "UTF-16LE", 2}, {"\xfe\xff", "UTF-16BE", 2}};
  for (size_t k = 0; k < sizeof boms / sizeof boms[0]; k++)
    if (len >= boms[k].n && memcmp(text, boms[k].bytes, boms[k].n) == 0) return boms[k].name;
  return NULL;
}

static struct ynode *parse_text(const char *text, size_t len, const char *source, int line,
                                const char *path, char *err, size_t err_len) {
  const char *bom = foreign_bom(text, len);
  if (bom) {
    say(err, err_len, source, line > 0 ? line : 1, path, "the text is %s (it starts with its "
        "byte-order mark), expected UTF-8", bom);
    return NULL;
  }
  struct reader rd = {.source = source, .fixed_line = line, .err = err, .err_len = err_len};
  if (!yaml_parser_initialize(&rd.parser)) mem_fail(0, "libyaml parser");
  yaml_parser_set_input_string(&rd.parser, (const unsigned char *)text, len);
  struct ynode *root = read_stream(&rd, path);
  yaml_parser_delete(&rd.parser);
  return root;
}

/* Parse len bytes of YAML text into a tree. */
struct ynode *ytree_parse(const char *text, size_t len, const char *source, int line, char *err,
                          size_t err_len) {
  return parse_text(text, len, source, line, "", err, err_len);
}

/* ---- overrides ---- */

/* The entry for key comp[0..len) of a mapping, appended (value NULL) when missing. */
static struct yentry *map_entry(struct ynode *map, const char *comp, size_t len, int line) {
  for (int i = 0; i < map->n; i++) {
    const char *key = map->entries[i].key;
    if (strlen(key) == len && strncmp(key, comp, len) == 0) return &map->entries[i];
  }
  return append(map, mem_strndup(comp, len, "YAML key"), line, NULL);
}

/* The entry at index comp[0..len) of a list (index n appends), or NULL if not an index. */
static struct yentry *list_entry(struct ynode *seq, const char *comp, size_t len, int line) {
  if (len == 0 || len > 9 || strspn(comp, "0123456789") < len) return NULL;
  long index = strtol(comp, NULL, 10);
  if (index > seq->n) return NULL;
  return index < seq->n ? &seq->entries[index] : append(seq, NULL, line, NULL);
}

/* Walk (and create) the path of an override; the last entry's value may be NULL. */
static struct yentry *walk(struct ynode *root, const char *path, int line, char *err,
                           size_t err_len) {
  struct ynode *cur = root;
  for (const char *comp = path;; comp += strcspn(comp, ".") + 1) {
    size_t len = strcspn(comp, ".");
    char prefix[YTREE_PATH_LEN];
    snprintf(prefix, sizeof prefix, "%.*s", (int)(comp + len - path), path);
    struct yentry *e = NULL;
    if (len == 0)
      say(err, err_len, "--set", line, path, "empty key in the path, expected key.path=value");
    else if (cur->kind == YNODE_MAPPING)
      e = map_entry(cur, comp, len, line);
    else if (cur->kind == YNODE_SEQUENCE) {
      if (!(e = list_entry(cur, comp, len, line)))
        say(err, err_len, "--set", line, prefix, "no such list item, expected an index 0 to %d",
            cur->n);
    } else
      say(err, err_len, "--set", line, prefix, "got a key inside the scalar '%s', expected a "
          "path through mappings and lists", cur->text);
    if (!e || comp[len] == '\0') return e;
    if (!e->value) e->value = node_new(YNODE_MAPPING, "--set", line);
    cur = e->value;
  }
}

/* Apply the override "a.b.c=value" to the tree. */
int ytree_set(struct ynode *root, const char *assignment, int line, char *err, size_t err_len) {
  const char *eq = strchr(assignment, '=');
  if (!eq) {
    say(err, err_len, "--set", line, assignment, "missing '=', expected key.path=value");
    return 1;
  }
  char *path = mem_strndup(assignment, (size_t)(eq - assignment), "--set key");
  struct ynode *value = parse_text(eq + 1, strlen(eq + 1), "--set", line, path, err, err_len);
  struct yentry *e = value ? walk(root, path, line, err, err_len) : NULL;
  if (e) {
    ytree_free(e->value);
    e->value = value;
    e->key_line = line;
  } else {
    ytree_free(value);
  }
  free(path);
  return e ? 0 : 1;
}
