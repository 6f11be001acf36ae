/* json_read.h - reading JSON files with every field checked (Jansson underneath).
 *
 * The JSON formats fairway reads (DNV's maritime-schema traffic situations)
 * come from other programs, so every value read is checked and a problem is
 * named by its JSON path:
 *
 *     FILE: $.targetShips[1].waypoints[0].position.lat: 95 is not in [-90, 90]
 *
 * with FW_EINPUT (exit 2).  Text that is not JSON is named by line and column
 * ("FILE:LINE: $: invalid JSON: ... (column C)").  A file over
 * FW_JSON_MAX_BYTES is refused before it is parsed, and nesting deeper than
 * Jansson's parser depth (2048) is refused by the parser: neither can exhaust
 * memory or the stack.  Duplicate keys in an object are refused.
 *
 * A document (fw_jdoc) owns the parsed tree; a node (fw_jnode) is a small value
 * naming one place in it (its JSON path and the value there, NULL when an
 * optional member is absent).  Nodes live as long as their document.
 */
#ifndef FW_JSON_READ_H
#define FW_JSON_READ_H

#include <stdbool.h>
#include <stddef.h>

#include "core/error.h"

/* A traffic situation is a few kB; 8 MB is far beyond any real one. */
#define FW_JSON_MAX_BYTES (8u * 1024u * 1024u)
#define FW_JSON_PATH_MAX 200

typedef struct fw_jdoc fw_jdoc;

typedef struct fw_jnode {
    const fw_jdoc *doc;
    const void *v; /* the Jansson value; NULL: an absent optional member */
    char path[FW_JSON_PATH_MAX];
} fw_jnode;

typedef enum fw_jtype {
    FW_J_ABSENT,
    FW_J_OBJECT,
    FW_J_ARRAY,
    FW_J_STRING,
    FW_J_NUMBER,
    FW_J_BOOL,
    FW_J_NULL
} fw_jtype;

/* Reads and parses the file at path. */
fw_status fw_jdoc_load(const char *path, fw_jdoc **out, fw_error *err);
/* Parses n bytes of text; name is the file named in messages. */
fw_status fw_jdoc_parse(const char *name, const char *text, size_t n, fw_jdoc **out, fw_error *err);
void fw_jdoc_free(fw_jdoc *doc);

/* The document's top value, path "$". */
fw_jnode fw_jdoc_root(const fw_jdoc *doc);
const char *fw_jdoc_name(const fw_jdoc *doc);

fw_jtype fw_jnode_type(const fw_jnode *n);
/* The name of the type, for messages ("an object", "a number" ...). */
const char *fw_jtype_name(fw_jtype t);

/* "FILE: PATH: message" as FW_EINPUT. */
fw_status fw_jfail(const fw_jnode *n, fw_error *err, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* n must be an object. */
fw_status fw_jobject(const fw_jnode *n, fw_error *err);
/* Member key of object obj; with required false, an absent member gives a node
 * whose type is FW_J_ABSENT.  obj must be an object. */
fw_status fw_jmember(const fw_jnode *obj, const char *key, bool required, fw_jnode *out, fw_error *err);
/* n must be an array of at least min_len elements; *len its length. */
fw_status fw_jarray(const fw_jnode *n, size_t min_len, size_t *len, fw_error *err);
/* Element i of array arr (i < its length). */
fw_jnode fw_jelement(const fw_jnode *arr, size_t i);

/* n must be a number in [lo, hi]. */
fw_status fw_jnumber(const fw_jnode *n, double lo, double hi, double *out, fw_error *err);
/* n must be a string (UTF-8, no NUL); *out lives as long as the document. */
fw_status fw_jstring(const fw_jnode *n, const char **out, fw_error *err);
fw_status fw_jbool(const fw_jnode *n, bool *out, fw_error *err);

/* Member key as a number in [lo, hi]; when absent and not required, *out keeps
 * its value and *present (may be NULL) is false. */
fw_status fw_jmember_number(const fw_jnode *obj, const char *key, bool required, double lo, double hi,
                            double *out, bool *present, fw_error *err);
/* Member key as a string; absent and not required: *out keeps its value. */
fw_status fw_jmember_string(const fw_jnode *obj, const char *key, bool required, const char **out,
                            fw_error *err);

/* Every key of object obj must be one of known (NULL-terminated). */
fw_status fw_jonly_keys(const fw_jnode *obj, const char *const *known, fw_error *err);

/* Keys of object obj in file order: the key and value at position i < *len. */
fw_status fw_jkeys(const fw_jnode *obj, size_t *len, fw_error *err);
fw_jnode fw_jkey_at(const fw_jnode *obj, size_t i, const char **key);

#endif
