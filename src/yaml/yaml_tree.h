/* yaml_tree.h - YAML files as a small tree that remembers line numbers.
 *
 * fairway's data files (ships, scenarios, studies) are YAML.  Every error in
 * them must name the file, line and field, so this module keeps the line of
 * every node and key, and offers typed readers that check presence, type,
 * finiteness and range in one call and report "FILE:LINE: FIELD: problem".
 * Built on libyaml's event parser (Debian's libyaml-dev).
 */
#ifndef FW_YAML_TREE_H
#define FW_YAML_TREE_H

#include <stdbool.h>
#include <stddef.h>

#include "core/error.h"

/* Deepest nesting of maps and sequences accepted (fairway's files use 4). */
#define YT_MAX_DEPTH 64

typedef enum yt_kind { YT_SCALAR, YT_MAP, YT_SEQ } yt_kind;

typedef struct yt_node {
    yt_kind kind;
    int line; /* 1-based */
    char *str;   /* scalar text (NULL for maps and sequences) */
    bool quoted; /* scalar was quoted: never a number or null */
    size_t n;             /* entries of a map or sequence */
    char **keys;          /* map keys */
    int *key_lines;       /* line of each map key */
    struct yt_node **items; /* map values or sequence items */
} yt_node;

typedef struct yt_doc {
    char *file; /* name used in messages */
    yt_node *root;
} yt_doc;

fw_status yt_load_file(const char *path, yt_doc **out, fw_error *err);
fw_status yt_load_string(const char *text, const char *name, yt_doc **out, fw_error *err);
void yt_free(yt_doc *doc);

/* Value of key in a map, or NULL (also when node is not a map). */
const yt_node *yt_get(const yt_node *map, const char *key);
/* Line of key in map, or the map's own line when the key is absent. */
int yt_key_line(const yt_node *map, const char *key);

/* Rejects keys of map that are not in allowed (NULL-terminated).  path is the
 * map's dotted field path ("" for the root) used in messages. */
fw_status yt_check_keys(const yt_doc *doc, const yt_node *map, const char *path,
                        const char *const *allowed, fw_error *err);

/* Typed readers.  path is the dotted path of map; key is looked up in it.
 * yt_req_* fail when the key is missing; yt_opt_* leave *out untouched then.
 * Numbers must be finite and within [lo, hi]. */
fw_status yt_req_number(const yt_doc *doc, const yt_node *map, const char *path,
                        const char *key, double lo, double hi, double *out, fw_error *err);
fw_status yt_opt_number(const yt_doc *doc, const yt_node *map, const char *path,
                        const char *key, double lo, double hi, double *out, fw_error *err);
fw_status yt_req_int(const yt_doc *doc, const yt_node *map, const char *path, const char *key,
                     long lo, long hi, long *out, fw_error *err);
fw_status yt_opt_int(const yt_doc *doc, const yt_node *map, const char *path, const char *key,
                     long lo, long hi, long *out, fw_error *err);
/* Copies a scalar string into out (size outsz); fails if it does not fit. */
fw_status yt_req_string(const yt_doc *doc, const yt_node *map, const char *path,
                        const char *key, char *out, size_t outsz, fw_error *err);
fw_status yt_opt_string(const yt_doc *doc, const yt_node *map, const char *path,
                        const char *key, char *out, size_t outsz, fw_error *err);
fw_status yt_opt_bool(const yt_doc *doc, const yt_node *map, const char *path, const char *key,
                      bool *out, fw_error *err);
/* Fetches a child map or sequence, failing with a located error when it is
 * missing (req) or of the wrong kind. */
fw_status yt_child(const yt_doc *doc, const yt_node *map, const char *path, const char *key,
                   yt_kind kind, bool required, const yt_node **out, fw_error *err);
#define yt_req_map(doc, map, path, key, out, err) \
    yt_child(doc, map, path, key, YT_MAP, true, out, err)
#define yt_opt_map(doc, map, path, key, out, err) \
    yt_child(doc, map, path, key, YT_MAP, false, out, err)
#define yt_req_seq(doc, map, path, key, out, err) \
    yt_child(doc, map, path, key, YT_SEQ, true, out, err)
#define yt_opt_seq(doc, map, path, key, out, err) \
    yt_child(doc, map, path, key, YT_SEQ, false, out, err)

/* Sets the scalar at dotted path `key` ("sensing.visibility_nm") to `value`
 * (read as an unquoted YAML scalar: "1" is a number, "ais" a word), making
 * the maps along the path that the document does not have, and replacing
 * whatever was there.  The new scalar keeps the line of what it replaces (a
 * new map, that of the map it is made in), so that a reader's message about
 * it points where the key is, or would be, in the file.  FW_EINPUT when a step of the path is a scalar or a sequence
 * in the document (the key cannot name a place in it) or the key is empty;
 * the message says which step.  Used by a study's axes (study.h) to make a
 * scenario of each setting from one file. */
fw_status yt_set(yt_doc *doc, const char *key, const char *value, fw_error *err);

/* Parses a scalar node as a finite number; fails with a located error. */
fw_status yt_number(const yt_doc *doc, const yt_node *node, const char *field, double *out,
                    fw_error *err);

/* Joins a dotted path: out = path + "." + key (or key when path is empty). */
const char *yt_path(char *out, size_t outsz, const char *path, const char *key);

/* The top of a document that is a map of these keys with a name and an
 * optional description (scenarios, studies): checked, and the two read.
 * FW_EINPUT "FILE:LINE: (top): expected a map with WHAT" when it is not a
 * map. */
fw_status yt_top_map(const yt_doc *doc, const char *const *keys, const char *what, char *name,
                     size_t name_size, char *description, size_t description_size,
                     fw_error *err);

/* FW_EINPUT located at the key of map: "FILE:LINE: PATH.KEY: message". */
fw_status yt_fail_key(const yt_doc *doc, const yt_node *map, const char *path, const char *key,
                      fw_error *err, const char *fmt, ...) __attribute__((format(printf, 6, 7)));

/* A name the file gives that names things (a scenario, a study, a target's
 * id): true when it is 1 to max characters of letters, digits, '-' and '_'
 * and, with reserved, does not begin "fw_" (the prefix of fairway's own SUMO
 * objects: fw_own, fw_t_ID, fw_placed_ID).  Else false and the problem in
 * msg: "is empty", a line break or control character (said, not quoted: it
 * would break the one-line message), too long, a reserved id, or "'V': use
 * " followed by `use` (what to write instead). */
bool yt_name_ok(const char *v, size_t max, bool reserved, const char *use, char *msg, size_t n);

#endif
