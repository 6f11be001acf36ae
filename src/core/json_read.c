/* json_read.c - see json_read.h.  Jansson parses; this file checks and names. */
#include "core/json_read.h"

#include <errno.h>
#include <jansson.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct fw_jdoc {
    json_t *root;
    char name[256];
};

fw_status fw_jdoc_parse(const char *name, const char *text, size_t n, fw_jdoc **out, fw_error *err)
{
    *out = NULL;
    if (n > FW_JSON_MAX_BYTES)
        return fw_fail(err, FW_EINPUT, "%s: $: more than %u bytes, the most a JSON input may have", name,
                       FW_JSON_MAX_BYTES);
    /* a file of another kind is not quoted (Jansson's message shows the text
     * near the error: the first word of /etc/shadow, say) */
    size_t k = 0;
    int line = 1;
    for (; k < n && text[k] && strchr(" \t\r\n", text[k]); k++)
        line += text[k] == '\n';
    if (k == n || (text[k] != '{' && text[k] != '['))
        return fw_fail_at(err, name, line, "$",
                          "not JSON: %s (not the kind of file expected?)",
                          k == n ? "empty" : "it does not begin with '{' or '['");
    json_error_t je;
    json_t *root = json_loadb(text, n, JSON_REJECT_DUPLICATES, &je);
    if (!root)
        return fw_fail_at(err, name, je.line, "$", "invalid JSON: %s (column %d)", je.text, je.column);
    fw_jdoc *d = calloc(1, sizeof *d);
    if (!d) {
        json_decref(root);
        return fw_fail(err, FW_ERUN, "%s: out of memory", name);
    }
    d->root = root;
    snprintf(d->name, sizeof d->name, "%s", name);
    *out = d;
    return FW_OK;
}

fw_status fw_jdoc_load(const char *path, fw_jdoc **out, fw_error *err)
{
    *out = NULL;
    FILE *f = fopen(path, "rb");
    if (!f)
        return fw_fail(err, FW_EINPUT, "%s: cannot open: %s", path, strerror(errno));
    size_t cap = FW_JSON_MAX_BYTES + 1, n = 0;
    char *buf = malloc(cap);
    if (!buf) {
        fclose(f);
        return fw_fail(err, FW_ERUN, "%s: out of memory", path);
    }
    n = fread(buf, 1, cap, f);
    int bad = ferror(f) ? (errno ? errno : EIO) : 0;
    fclose(f);
    fw_status st = bad ? fw_fail(err, FW_EINPUT, "%s: cannot read: %s", path, strerror(bad))
                       : fw_jdoc_parse(path, buf, n, out, err);
    free(buf);
    return st;
}

void fw_jdoc_free(fw_jdoc *doc)
{
    if (!doc)
        return;
    json_decref(doc->root);
    free(doc);
}

fw_jnode fw_jdoc_root(const fw_jdoc *doc)
{
    fw_jnode n = {.doc = doc, .v = doc->root, .path = "$"};
    return n;
}

const char *fw_jdoc_name(const fw_jdoc *doc) { return doc->name; }

fw_jtype fw_jnode_type(const fw_jnode *n)
{
    const json_t *v = n->v;
    if (!v)
        return FW_J_ABSENT;
    switch (json_typeof(v)) {
    case JSON_OBJECT: return FW_J_OBJECT;
    case JSON_ARRAY: return FW_J_ARRAY;
    case JSON_STRING: return FW_J_STRING;
    case JSON_INTEGER:
    case JSON_REAL: return FW_J_NUMBER;
    case JSON_TRUE:
    case JSON_FALSE: return FW_J_BOOL;
    case JSON_NULL: break;
    }
    return FW_J_NULL;
}

const char *fw_jtype_name(fw_jtype t)
{
    static const char *const names[] = {"absent", "an object", "an array", "a string",
                                        "a number", "a boolean", "null"};
    return names[t];
}

fw_status fw_jfail(const fw_jnode *n, fw_error *err, const char *fmt, ...)
{
    char msg[384];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return fw_fail(err, FW_EINPUT, "%s: %s: %s", n->doc->name, n->path, msg);
}

static fw_status want(const fw_jnode *n, fw_jtype t, fw_error *err)
{
    fw_jtype have = fw_jnode_type(n);
    if (have == t)
        return FW_OK;
    if (have == FW_J_ABSENT)
        return fw_jfail(n, err, "missing: must be %s", fw_jtype_name(t));
    return fw_jfail(n, err, "must be %s, not %s", fw_jtype_name(t), fw_jtype_name(have));
}

fw_status fw_jobject(const fw_jnode *n, fw_error *err) { return want(n, FW_J_OBJECT, err); }

/* The child path: ".key" for a plain key, "['key']" (printable, cut) otherwise;
 * a path that does not fit ends in "...". */
static void child_path(char *dst, const char *parent, const char *key, long index)
{
    char part[96];
    if (!key) {
        snprintf(part, sizeof part, "[%ld]", index);
    } else {
        bool plain = key[0] != '\0' && strlen(key) < 64;
        for (const char *c = key; *c && plain; c++)
            plain = (*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') || (*c >= '0' && *c <= '9') || *c == '_';
        if (plain) {
            snprintf(part, sizeof part, ".%s", key);
        } else {
            size_t k = 0;
            part[k++] = '[', part[k++] = '\'';
            for (const char *c = key; *c && k < 60; c++)
                part[k++] = (*c >= 0x20 && *c < 0x7f && *c != '\'') ? *c : '?';
            part[k++] = '\'', part[k++] = ']', part[k] = '\0';
        }
    }
    size_t np = strlen(parent), nc = strlen(part);
    if (np + nc < FW_JSON_PATH_MAX) {
        memmove(dst, parent, np);
        memcpy(dst + np, part, nc + 1);
    } else {
        size_t keep = np < FW_JSON_PATH_MAX - 4 ? np : FW_JSON_PATH_MAX - 4;
        memmove(dst, parent, keep);
        memcpy(dst + keep, "...", 4);
    }
}

fw_status fw_jmember(const fw_jnode *obj, const char *key, bool required, fw_jnode *out, fw_error *err)
{
    fw_jnode m = {.doc = obj->doc}; /* out may be obj */
    child_path(m.path, obj->path, key, 0);
    fw_status st = fw_jobject(obj, err);
    if (st == FW_OK) {
        m.v = json_object_get(obj->v, key);
        if (!m.v && required)
            st = fw_jfail(&m, err, "missing");
    }
    *out = m;
    return st;
}

fw_status fw_jarray(const fw_jnode *n, size_t min_len, size_t *len, fw_error *err)
{
    fw_status st = want(n, FW_J_ARRAY, err);
    if (st)
        return st;
    *len = json_array_size(n->v);
    if (*len < min_len)
        return fw_jfail(n, err, "%zu elements, at least %zu needed", *len, min_len);
    return FW_OK;
}

fw_jnode fw_jelement(const fw_jnode *arr, size_t i)
{
    fw_jnode n = {.doc = arr->doc, .v = json_array_get(arr->v, i)};
    child_path(n.path, arr->path, NULL, (long)i);
    return n;
}

fw_status fw_jnumber(const fw_jnode *n, double lo, double hi, double *out, fw_error *err)
{
    fw_status st = want(n, FW_J_NUMBER, err);
    if (st)
        return st;
    double v = json_number_value(n->v);
    if (!isfinite(v) || v < lo || v > hi)
        return fw_jfail(n, err, "%g is not in [%g, %g]", v, lo, hi);
    *out = v;
    return FW_OK;
}

fw_status fw_jstring(const fw_jnode *n, const char **out, fw_error *err)
{
    fw_status st = want(n, FW_J_STRING, err);
    if (st)
        return st;
    if (strlen(json_string_value(n->v)) != json_string_length(n->v))
        return fw_jfail(n, err, "a string holding a NUL character");
    *out = json_string_value(n->v);
    return FW_OK;
}

fw_status fw_jbool(const fw_jnode *n, bool *out, fw_error *err)
{
    fw_status st = want(n, FW_J_BOOL, err);
    if (st)
        return st;
    *out = json_is_true((const json_t *)n->v);
    return FW_OK;
}

fw_status fw_jmember_number(const fw_jnode *obj, const char *key, bool required, double lo, double hi,
                            double *out, bool *present, fw_error *err)
{
    fw_jnode m;
    fw_status st = fw_jmember(obj, key, required, &m, err);
    if (present)
        *present = st == FW_OK && m.v != NULL;
    if (st || !m.v)
        return st;
    return fw_jnumber(&m, lo, hi, out, err);
}

fw_status fw_jmember_string(const fw_jnode *obj, const char *key, bool required, const char **out,
                            fw_error *err)
{
    fw_jnode m;
    fw_status st = fw_jmember(obj, key, required, &m, err);
    if (st || !m.v)
        return st;
    return fw_jstring(&m, out, err);
}

fw_status fw_jonly_keys(const fw_jnode *obj, const char *const *known, fw_error *err)
{
    fw_status st = fw_jobject(obj, err);
    if (st)
        return st;
    const char *key;
    json_t *v;
    json_object_foreach((json_t *)obj->v, key, v) {
        size_t i = 0;
        while (known[i] && strcmp(known[i], key) != 0)
            i++;
        if (!known[i]) {
            fw_jnode m = {.doc = obj->doc, .v = v};
            child_path(m.path, obj->path, key, 0);
            return fw_jfail(&m, err, "unknown key");
        }
    }
    return FW_OK;
}

fw_status fw_jkeys(const fw_jnode *obj, size_t *len, fw_error *err)
{
    fw_status st = fw_jobject(obj, err);
    if (st)
        return st;
    *len = json_object_size(obj->v);
    return FW_OK;
}

fw_jnode fw_jkey_at(const fw_jnode *obj, size_t i, const char **key)
{
    void *it = json_object_iter((json_t *)obj->v);
    for (size_t k = 0; k < i && it; k++)
        it = json_object_iter_next((json_t *)obj->v, it);
    fw_jnode n = {.doc = obj->doc, .v = it ? json_object_iter_value(it) : NULL};
    *key = it ? json_object_iter_key(it) : "";
    child_path(n.path, obj->path, *key, 0);
    return n;
}
