#include "yaml/yaml_tree.h"

#include <ctype.h>
#include <stdarg.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <yaml.h>

/* libyaml gives a stream of events; a small recursive builder turns one
 * document into nodes.  Aliases are refused: none of fairway's files needs
 * them and they would make "which line is wrong" ambiguous. */

typedef struct builder {
    yaml_parser_t parser;
    const char *file;
    fw_error *err;
    int depth; /* collections open around the node being built */
} builder;

static void node_free(yt_node *n)
{
    if (!n)
        return;
    free(n->str);
    for (size_t i = 0; i < n->n; i++) {
        if (n->keys)
            free(n->keys[i]);
        node_free(n->items[i]);
    }
    free(n->keys);
    free(n->key_lines);
    free(n->items);
    free(n);
}

static int next_event(builder *b, yaml_event_t *ev)
{
    if (!yaml_parser_parse(&b->parser, ev)) {
        fw_fail_at(b->err, b->file, (int)b->parser.problem_mark.line + 1, NULL,
                   "YAML syntax error: %s", b->parser.problem ? b->parser.problem : "unknown");
        return -1;
    }
    return 0;
}

static int grow(yt_node *n, bool with_keys)
{
    size_t cap = n->n + 1;
    yt_node **items = realloc(n->items, cap * sizeof *items);
    if (!items)
        return -1;
    n->items = items;
    if (with_keys) {
        char **keys = realloc(n->keys, cap * sizeof *keys);
        if (!keys)
            return -1;
        n->keys = keys;
        int *lines = realloc(n->key_lines, cap * sizeof *lines);
        if (!lines)
            return -1;
        n->key_lines = lines;
    }
    return 0;
}

static yt_node *build(builder *b, yaml_event_t *ev);

static yt_node *build_collection(builder *b, yt_node *n, yaml_event_type_t end_type)
{
    for (;;) {
        yaml_event_t ev;
        if (next_event(b, &ev))
            goto fail;
        if (ev.type == end_type) {
            yaml_event_delete(&ev);
            return n;
        }
        if (n->kind == YT_MAP) {
            int kline = (int)ev.start_mark.line + 1;
            if (ev.type != YAML_SCALAR_EVENT) {
                fw_fail_at(b->err, b->file, kline, NULL, "map keys must be plain scalars");
                yaml_event_delete(&ev);
                goto fail;
            }
            char *key = strdup((const char *)ev.data.scalar.value);
            yaml_event_delete(&ev);
            if (!key)
                goto oom;
            for (size_t i = 0; i < n->n; i++) {
                if (strcmp(n->keys[i], key) == 0) {
                    fw_fail_at(b->err, b->file, kline, key, "duplicate key (first at line %d)",
                               n->key_lines[i]);
                    free(key);
                    goto fail;
                }
            }
            yaml_event_t vev;
            if (next_event(b, &vev)) {
                free(key);
                goto fail;
            }
            yt_node *val = build(b, &vev);
            if (!val) {
                free(key);
                goto fail;
            }
            if (grow(n, true)) {
                free(key);
                node_free(val);
                goto oom;
            }
            n->keys[n->n] = key;
            n->key_lines[n->n] = kline;
            n->items[n->n++] = val;
        } else {
            yt_node *val = build(b, &ev);
            if (!val)
                goto fail;
            if (grow(n, false)) {
                node_free(val);
                goto oom;
            }
            n->items[n->n++] = val;
        }
    }
oom:
    fw_fail(b->err, FW_ERUN, "%s: out of memory", b->file);
fail:
    node_free(n);
    return NULL;
}

/* Consumes ev (deletes it) and everything that belongs to the node it opens. */
static yt_node *build(builder *b, yaml_event_t *ev)
{
    yt_node *n = calloc(1, sizeof *n);
    if (!n) {
        yaml_event_delete(ev);
        fw_fail(b->err, FW_ERUN, "%s: out of memory", b->file);
        return NULL;
    }
    n->line = (int)ev->start_mark.line + 1;
    switch (ev->type) {
    case YAML_SCALAR_EVENT:
        n->kind = YT_SCALAR;
        n->quoted = ev->data.scalar.style == YAML_SINGLE_QUOTED_SCALAR_STYLE ||
                    ev->data.scalar.style == YAML_DOUBLE_QUOTED_SCALAR_STYLE;
        n->str = strdup((const char *)ev->data.scalar.value);
        yaml_event_delete(ev);
        if (!n->str) {
            free(n);
            fw_fail(b->err, FW_ERUN, "%s: out of memory", b->file);
            return NULL;
        }
        return n;
    case YAML_MAPPING_START_EVENT:
    case YAML_SEQUENCE_START_EVENT:
        /* the builder recurses once per level: bound it, so a hostile file
         * gets an error instead of a stack overflow */
        if (b->depth >= YT_MAX_DEPTH) {
            fw_fail_at(b->err, b->file, n->line, NULL,
                       "nested deeper than %d levels", YT_MAX_DEPTH);
            break;
        }
        n->kind = ev->type == YAML_MAPPING_START_EVENT ? YT_MAP : YT_SEQ;
        yaml_event_delete(ev);
        b->depth++;
        yt_node *done = build_collection(
            b, n, n->kind == YT_MAP ? YAML_MAPPING_END_EVENT : YAML_SEQUENCE_END_EVENT);
        b->depth--;
        return done;
    case YAML_ALIAS_EVENT:
        fw_fail_at(b->err, b->file, n->line, NULL, "YAML aliases are not supported");
        break;
    default:
        fw_fail_at(b->err, b->file, n->line, NULL, "unexpected YAML structure");
        break;
    }
    yaml_event_delete(ev);
    free(n);
    return NULL;
}

static fw_status load(builder *b, const char *name, yt_doc **out)
{
    *out = NULL;
    yt_node *root = NULL;
    yaml_event_t ev;
    /* stream start, document start */
    for (;;) {
        if (next_event(b, &ev))
            return FW_EINPUT;
        yaml_event_type_t t = ev.type;
        if (t == YAML_STREAM_START_EVENT || t == YAML_DOCUMENT_START_EVENT) {
            yaml_event_delete(&ev);
            continue;
        }
        if (t == YAML_STREAM_END_EVENT) {
            yaml_event_delete(&ev);
            return fw_fail_at(b->err, name, 1, NULL, "file is empty");
        }
        root = build(b, &ev);
        if (!root)
            return b->err ? b->err->status : FW_EINPUT;
        break;
    }
    /* document end, then the stream must end: one document per file */
    for (;;) {
        if (next_event(b, &ev)) {
            node_free(root);
            return FW_EINPUT;
        }
        yaml_event_type_t t = ev.type;
        int line = (int)ev.start_mark.line + 1;
        yaml_event_delete(&ev);
        if (t == YAML_DOCUMENT_END_EVENT)
            continue;
        if (t == YAML_STREAM_END_EVENT)
            break;
        node_free(root);
        return fw_fail_at(b->err, name, line, NULL, "only one YAML document per file");
    }
    if (root->kind != YT_MAP) {
        int line = root->line;
        node_free(root);
        return fw_fail_at(b->err, name, line, NULL, "top level must be a mapping of fields");
    }
    yt_doc *doc = calloc(1, sizeof *doc);
    if (!doc || !(doc->file = strdup(name))) {
        free(doc);
        node_free(root);
        return fw_fail(b->err, FW_ERUN, "%s: out of memory", name);
    }
    doc->root = root;
    *out = doc;
    return FW_OK;
}

fw_status yt_load_file(const char *path, yt_doc **out, fw_error *err)
{
    *out = NULL;
    FILE *f = fopen(path, "rb");
    if (!f)
        return fw_fail(err, FW_EINPUT, "%s: cannot open: %s", path, strerror(errno));
    /* fopen succeeds on a directory and libyaml then says only "input error" */
    struct stat sb;
    if (fstat(fileno(f), &sb) == 0 && !S_ISREG(sb.st_mode)) {
        fclose(f);
        return fw_fail(err, FW_EINPUT, "%s: is %s, expected a YAML file", path,
                       S_ISDIR(sb.st_mode) ? "a directory" : "not a regular file");
    }
    builder b = {.file = path, .err = err};
    if (!yaml_parser_initialize(&b.parser)) {
        fclose(f);
        return fw_fail(err, FW_ERUN, "%s: cannot initialise YAML parser", path);
    }
    yaml_parser_set_input_file(&b.parser, f);
    fw_status st = load(&b, path, out);
    yaml_parser_delete(&b.parser);
    fclose(f);
    return st;
}

fw_status yt_load_string(const char *text, const char *name, yt_doc **out, fw_error *err)
{
    *out = NULL;
    builder b = {.file = name, .err = err};
    if (!yaml_parser_initialize(&b.parser))
        return fw_fail(err, FW_ERUN, "%s: cannot initialise YAML parser", name);
    yaml_parser_set_input_string(&b.parser, (const unsigned char *)text, strlen(text));
    fw_status st = load(&b, name, out);
    yaml_parser_delete(&b.parser);
    return st;
}

void yt_free(yt_doc *doc)
{
    if (!doc)
        return;
    node_free(doc->root);
    free(doc->file);
    free(doc);
}

const yt_node *yt_get(const yt_node *map, const char *key)
{
    if (!map || map->kind != YT_MAP)
        return NULL;
    for (size_t i = 0; i < map->n; i++)
        if (strcmp(map->keys[i], key) == 0)
            return map->items[i];
    return NULL;
}

int yt_key_line(const yt_node *map, const char *key)
{
    if (!map)
        return 0;
    if (map->kind == YT_MAP)
        for (size_t i = 0; i < map->n; i++)
            if (strcmp(map->keys[i], key) == 0)
                return map->key_lines[i];
    return map->line;
}

const char *yt_path(char *out, size_t outsz, const char *path, const char *key)
{
    if (path && path[0])
        snprintf(out, outsz, "%s.%s", path, key);
    else
        snprintf(out, outsz, "%s", key);
    return out;
}

/* A key that could be a misspelt field (letters, digits, '_', '-', at most
 * 40) is quoted in the message; anything else is not: a file that is not the
 * kind expected (a ship named /etc/shadow) must not have its lines printed. */
static bool field_like(const char *key)
{
    size_t n = 0;
    for (; key[n]; n++)
        if (n >= 40 || !(isalnum((unsigned char)key[n]) || key[n] == '_' || key[n] == '-'))
            return false;
    return n > 0;
}

fw_status yt_check_keys(const yt_doc *doc, const yt_node *map, const char *path,
                        const char *const *allowed, fw_error *err)
{
    char field[256];
    for (size_t i = 0; i < map->n; i++) {
        bool ok = false;
        for (const char *const *a = allowed; *a; a++)
            if (strcmp(*a, map->keys[i]) == 0) {
                ok = true;
                break;
            }
        if (!ok) {
            char known[256] = "";
            size_t used = 0;
            for (const char *const *a = allowed; *a && used + 1 < sizeof known; a++)
                used += (size_t)snprintf(known + used, sizeof known - used, "%s%s",
                                         a == allowed ? "" : ", ", *a);
            if (!field_like(map->keys[i]))
                return fw_fail_at(err, doc->file, map->key_lines[i], path,
                                  "a key that is no field name (not the kind of file "
                                  "expected? expected one of: %s)",
                                  known);
            return fw_fail_at(err, doc->file, map->key_lines[i],
                              yt_path(field, sizeof field, path, map->keys[i]),
                              "unknown field (expected one of: %s)", known);
        }
    }
    return FW_OK;
}

static bool is_null(const yt_node *n)
{
    return n->kind == YT_SCALAR && !n->quoted &&
           (n->str[0] == '\0' || strcmp(n->str, "~") == 0 || strcmp(n->str, "null") == 0);
}

fw_status yt_number(const yt_doc *doc, const yt_node *node, const char *field, double *out,
                    fw_error *err)
{
    if (node->kind != YT_SCALAR || node->quoted || is_null(node))
        return fw_fail_at(err, doc->file, node->line, field, "expected a number");
    const char *s = node->str;
    char *end = NULL;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end != '\0')
        return fw_fail_at(err, doc->file, node->line, field, "'%s' is not a number", s);
    if (!isfinite(v) || errno == ERANGE)
        return fw_fail_at(err, doc->file, node->line, field, "'%s' is not a finite number", s);
    *out = v;
    return FW_OK;
}

static fw_status missing(const yt_doc *doc, const yt_node *map, const char *field, fw_error *err)
{
    return fw_fail_at(err, doc->file, map->line, field, "required field is missing");
}

fw_status yt_opt_number(const yt_doc *doc, const yt_node *map, const char *path,
                        const char *key, double lo, double hi, double *out, fw_error *err)
{
    const yt_node *n = yt_get(map, key);
    if (!n)
        return FW_OK;
    char field[256];
    yt_path(field, sizeof field, path, key);
    double v = 0.0;
    fw_status st = yt_number(doc, n, field, &v, err);
    if (st)
        return st;
    if (v < lo || v > hi)
        /* the number as the file has it: %g rounds 80.000001 to "80" */
        return fw_fail_at(err, doc->file, n->line, field, "%s is out of range [%g, %g]", n->str,
                          lo, hi);
    *out = v;
    return FW_OK;
}

fw_status yt_req_number(const yt_doc *doc, const yt_node *map, const char *path,
                        const char *key, double lo, double hi, double *out, fw_error *err)
{
    char field[256];
    if (!yt_get(map, key))
        return missing(doc, map, yt_path(field, sizeof field, path, key), err);
    return yt_opt_number(doc, map, path, key, lo, hi, out, err);
}

fw_status yt_opt_int(const yt_doc *doc, const yt_node *map, const char *path, const char *key,
                     long lo, long hi, long *out, fw_error *err)
{
    const yt_node *n = yt_get(map, key);
    if (!n)
        return FW_OK;
    char field[256];
    yt_path(field, sizeof field, path, key);
    if (n->kind != YT_SCALAR || n->quoted)
        return fw_fail_at(err, doc->file, n->line, field, "expected an integer");
    char *end = NULL;
    errno = 0;
    long v = strtol(n->str, &end, 10);
    if (end == n->str || *end != '\0' || errno == ERANGE)
        return fw_fail_at(err, doc->file, n->line, field, "'%s' is not an integer", n->str);
    if (v < lo || v > hi)
        return fw_fail_at(err, doc->file, n->line, field, "%s is out of range [%ld, %ld]", n->str,
                          lo, hi);
    *out = v;
    return FW_OK;
}

fw_status yt_req_int(const yt_doc *doc, const yt_node *map, const char *path, const char *key,
                     long lo, long hi, long *out, fw_error *err)
{
    char field[256];
    if (!yt_get(map, key))
        return missing(doc, map, yt_path(field, sizeof field, path, key), err);
    return yt_opt_int(doc, map, path, key, lo, hi, out, err);
}

fw_status yt_opt_string(const yt_doc *doc, const yt_node *map, const char *path,
                        const char *key, char *out, size_t outsz, fw_error *err)
{
    const yt_node *n = yt_get(map, key);
    if (!n)
        return FW_OK;
    char field[256];
    yt_path(field, sizeof field, path, key);
    if (n->kind != YT_SCALAR || is_null(n))
        return fw_fail_at(err, doc->file, n->line, field, "expected a text value");
    if (strlen(n->str) >= outsz)
        return fw_fail_at(err, doc->file, n->line, field, "value is longer than %zu characters",
                          outsz - 1);
    strcpy(out, n->str);
    return FW_OK;
}

fw_status yt_req_string(const yt_doc *doc, const yt_node *map, const char *path,
                        const char *key, char *out, size_t outsz, fw_error *err)
{
    char field[256];
    if (!yt_get(map, key))
        return missing(doc, map, yt_path(field, sizeof field, path, key), err);
    return yt_opt_string(doc, map, path, key, out, outsz, err);
}

fw_status yt_opt_bool(const yt_doc *doc, const yt_node *map, const char *path, const char *key,
                      bool *out, fw_error *err)
{
    const yt_node *n = yt_get(map, key);
    if (!n)
        return FW_OK;
    char field[256];
    yt_path(field, sizeof field, path, key);
    if (n->kind == YT_SCALAR && !n->quoted) {
        if (!strcmp(n->str, "true") || !strcmp(n->str, "yes") || !strcmp(n->str, "on")) {
            *out = true;
            return FW_OK;
        }
        if (!strcmp(n->str, "false") || !strcmp(n->str, "no") || !strcmp(n->str, "off")) {
            *out = false;
            return FW_OK;
        }
    }
    return fw_fail_at(err, doc->file, n->line, field, "expected true or false");
}

fw_status yt_child(const yt_doc *doc, const yt_node *map, const char *path, const char *key,
                   yt_kind kind, bool required, const yt_node **out, fw_error *err)
{
    char field[256];
    yt_path(field, sizeof field, path, key);
    const yt_node *n = yt_get(map, key);
    *out = NULL;
    if (!n)
        return required ? missing(doc, map, field, err) : FW_OK;
    if (n->kind != kind)
        return fw_fail_at(err, doc->file, n->line, field, "expected a %s",
                          kind == YT_MAP ? "mapping of fields" : "list");
    *out = n;
    return FW_OK;
}

fw_status yt_top_map(const yt_doc *doc, const char *const *keys, const char *what, char *name,
                     size_t name_size, char *description, size_t description_size,
                     fw_error *err)
{
    const yt_node *root = doc->root;
    if (!root || root->kind != YT_MAP)
        return fw_fail_at(err, doc->file, root ? root->line : 1, "(top)", "expected a map with %s",
                          what);
    fw_status st;
    if ((st = yt_check_keys(doc, root, "", keys, err)) ||
        (st = yt_req_string(doc, root, "", "name", name, name_size, err)) ||
        (st = yt_opt_string(doc, root, "", "description", description, description_size, err)))
        return st;
    return FW_OK;
}

fw_status yt_fail_key(const yt_doc *doc, const yt_node *map, const char *path, const char *key,
                      fw_error *err, const char *fmt, ...)
{
    char field[256], msg[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return fw_fail_at(err, doc->file, yt_key_line(map, key), yt_path(field, sizeof field, path, key),
                      "%s", msg);
}

bool yt_name_ok(const char *v, size_t max, bool reserved, const char *use, char *msg, size_t n)
{
    size_t len = strlen(v);
    bool ctrl = false;
    for (size_t i = 0; i < len; i++)
        ctrl |= (unsigned char)v[i] < 0x20 || v[i] == 0x7f;
    if (len == 0)
        snprintf(msg, n, "is empty: use %s", use);
    else if (ctrl)
        snprintf(msg, n, "contains a line break or other control character: use %s", use);
    else if (strspn(v, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") != len ||
             len > max)
        snprintf(msg, n, "'%.*s%s': use %s", 64, v, len > 64 ? "..." : "", use);
    else if (reserved && strncmp(v, "fw_", 3) == 0)
        snprintf(msg, n, "'%s': names beginning 'fw_' are fairway's own (its SUMO objects: fw_own, "
                         "fw_t_ID)", v);
    else
        return true;
    return false;
}

static yt_node *new_node(yt_kind kind, int line)
{
    yt_node *n = calloc(1, sizeof *n);
    if (n) {
        n->kind = kind;
        n->line = line;
    }
    return n;
}

/* The value of `key` (n bytes) in map, made (an empty map) when absent.
 * NULL when out of memory. */
static yt_node **map_slot(yt_node *map, const char *key, size_t n)
{
    for (size_t i = 0; i < map->n; i++)
        if (strlen(map->keys[i]) == n && !memcmp(map->keys[i], key, n))
            return &map->items[i];
    int line = map->line;
    yt_node *child = new_node(YT_MAP, line);
    char *k = strndup(key, n);
    if (!child || !k || grow(map, true)) {
        free(child);
        free(k);
        return NULL;
    }
    map->keys[map->n] = k;
    map->key_lines[map->n] = line;
    map->items[map->n] = child;
    return &map->items[map->n++];
}

fw_status yt_set(yt_doc *doc, const char *key, const char *value, fw_error *err)
{
    if (!doc->root)
        doc->root = new_node(YT_MAP, 1);
    if (!doc->root)
        return fw_fail(err, FW_ERUN, "out of memory");
    yt_node **at = &doc->root;
    const char *p = key;
    for (;;) {
        const char *dot = strchr(p, '.');
        size_t n = dot ? (size_t)(dot - p) : strlen(p);
        if (n == 0)
            return fw_fail(err, FW_EINPUT, "'%s' is not a dotted key (an empty step)", key);
        if ((*at)->kind != YT_MAP) {
            int done = p > key ? (int)(p - key - 1) : 0;
            return fw_fail(err, FW_EINPUT, "%s:%d: %.*s%s is not a map, so '%s' names no place in it",
                           doc->file, (*at)->line, done, key, done ? "" : "the top", key);
        }
        at = map_slot(*at, p, n);
        if (!at)
            return fw_fail(err, FW_ERUN, "out of memory");
        if (!dot)
            break;
        p = dot + 1;
    }
    yt_node *leaf = new_node(YT_SCALAR, (*at)->line);
    char *s = strdup(value);
    if (!leaf || !s) {
        free(leaf);
        free(s);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    leaf->str = s;
    node_free(*at);
    *at = leaf;
    return FW_OK;
}
