/* yaml_tree.h — a small YAML node tree (scalars, lists, mappings) built from libyaml events,
 * each node remembering the source it came from and its line, plus --set style overrides. */
#ifndef MPSPH_YAML_TREE_H
#define MPSPH_YAML_TREE_H

#include <stddef.h>

enum ynode_kind { YNODE_SCALAR = 0, YNODE_SEQUENCE, YNODE_MAPPING };

struct ynode;

/** One child of a list (key NULL) or one key: value pair of a mapping. */
struct yentry {
  char *key;             /* mapping key; NULL in a list */
  int key_line;          /* line of the key (of the override that last set it) */
  struct ynode *value;
};

/** A node: a scalar with its text, or a list / mapping of n entries. */
struct ynode {
  enum ynode_kind kind;
  char *source;          /* file name, or "--set" for override text */
  int line;              /* 1-based line where the node starts (override number for --set) */
  char *text;            /* scalar text; NULL for lists and mappings */
  int plain;             /* scalar written unquoted (so it may be a number or a boolean) */
  int n, cap;
  struct yentry *entries;
};

/** Parse len bytes of YAML text (one document, block or flow; NUL bytes are errors) into a tree
 *  whose nodes name `source`. line 0: nodes get their line in the text; line > 0: every node gets
 *  that line. Returns NULL with a one-line message "<source>:<line>: ..." in err on malformed
 *  YAML, duplicate keys, aliases or more than one document. */
struct ynode *ytree_parse(const char *text, size_t len, const char *source, int line, char *err,
                          size_t err_len);

/** Free a tree (NULL is allowed). */
void ytree_free(struct ynode *node);

/** The value of `key` in the mapping `map`, or NULL when absent or map is not a mapping. */
const struct ynode *ytree_get(const struct ynode *map, const char *key);

/** Apply the override "a.b.c=value" to the tree: value is YAML flow text (e.g. `0.5`, `[0, 0]`,
 *  `{min: [0, 0], max: [1, 1]}`), path components are mapping keys or list indices
 *  (`fluids.1.box.max=[1, 2]`). A missing mapping key is added (with empty mappings on the way);
 *  index n of an n-item list appends. The new nodes have source "--set" and line `line` (the
 *  override's 1-based number). Returns 0, or 1 with "--set:<line>: <path>: ..." in err. */
int ytree_set(struct ynode *root, const char *assignment, int line, char *err, size_t err_len);

#endif
