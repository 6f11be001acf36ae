/* yaml_edit.c - see yaml_edit.h. */
#include "yaml/yaml_edit.h"

#include <errno.h>
#include <limits.h>
#include <fcntl.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/files.h"
#include "yaml/yaml_tree.h"

struct fw_yaml_edit {
    char *name; /* file it was read from: messages, default target */
    char *text; /* NUL-terminated, no NUL inside */
    size_t len;
};

/* One line of the text: [start, start + len) without its break, brk bytes of
 * line break after it (0 only on a last line without one). */
typedef struct line {
    size_t start, len, brk;
} line;

typedef struct lines {
    line *v;
    size_t n;
} lines;

/* Length of the line break at s[i] as libyaml reads it (its IS_BREAK and
 * CRLF), 0 when there is none: LF, CRLF, CR, NEL, LS, PS. */
static size_t break_len(const char *s, size_t i, size_t n)
{
    const unsigned char *u = (const unsigned char *)s;
    if (u[i] == '\r')
        return i + 1 < n && u[i + 1] == '\n' ? 2 : 1;
    if (u[i] == '\n')
        return 1;
    if (u[i] == 0xC2 && i + 1 < n && u[i + 1] == 0x85)
        return 2;
    if (u[i] == 0xE2 && i + 2 < n && u[i + 1] == 0x80 && (u[i + 2] == 0xA8 || u[i + 2] == 0xA9))
        return 3;
    return 0;
}

static fw_status split(const fw_yaml_edit *ed, lines *l, fw_error *err)
{
    size_t cap = 1;
    for (size_t i = 0; i < ed->len; i++)
        cap += break_len(ed->text, i, ed->len) > 0;
    l->n = 0;
    l->v = malloc(cap * sizeof *l->v);
    if (!l->v)
        return fw_fail(err, FW_ERUN, "%s: out of memory", ed->name);
    size_t start = 0, i = 0;
    while (i < ed->len) {
        size_t b = break_len(ed->text, i, ed->len);
        if (!b) {
            i++;
            continue;
        }
        l->v[l->n++] = (line){start, i - start, b};
        i += b;
        start = i;
    }
    if (start < ed->len)
        l->v[l->n++] = (line){start, ed->len - start, 0};
    return FW_OK;
}

/* Does line L hold `key:` (plain or quoted) after its indentation?  *indent
 * gets the indentation's width. */
static bool line_has_key(const fw_yaml_edit *ed, const line *L, const char *key, size_t *indent)
{
    const char *s = ed->text + L->start;
    size_t n = L->len, i = 0;
    if (L->start == 0 && n >= 3 && memcmp(s, "\xEF\xBB\xBF", 3) == 0)
        i = 3; /* libyaml skips a byte-order mark */
    size_t lead = i;
    while (i < n && s[i] == ' ')
        i++;
    *indent = i - lead;
    size_t k = strlen(key);
    if (i < n && (s[i] == '"' || s[i] == '\'')) {
        char q = s[i++];
        if (i + k >= n || memcmp(s + i, key, k) != 0 || s[i + k] != q)
            return false;
        i += k + 1;
    } else {
        if (i + k > n || memcmp(s + i, key, k) != 0)
            return false;
        i += k;
    }
    while (i < n && (s[i] == ' ' || s[i] == '\t'))
        i++;
    return i < n && s[i] == ':';
}

static bool node_equal(const yt_node *a, const yt_node *b, const yt_node *skip_in,
                       const char *skip_key);

/* Deep equality of the trees, lines aside; in the map skip_in (of tree a)
 * the entry skip_key is not compared. */
static bool map_equal(const yt_node *a, const yt_node *b, const yt_node *skip_in,
                      const char *skip_key)
{
    size_t na = 0, nb = 0;
    for (size_t i = 0; i < a->n; i++) {
        if (a == skip_in && strcmp(a->keys[i], skip_key) == 0)
            continue;
        na++;
        const yt_node *bv = yt_get(b, a->keys[i]);
        if (!bv || !node_equal(a->items[i], bv, skip_in, skip_key))
            return false;
    }
    for (size_t i = 0; i < b->n; i++)
        nb += !(a == skip_in && strcmp(b->keys[i], skip_key) == 0);
    return na == nb;
}

static bool node_equal(const yt_node *a, const yt_node *b, const yt_node *skip_in,
                       const char *skip_key)
{
    if (a->kind != b->kind || (a->kind != YT_MAP && a->n != b->n))
        return false;
    switch (a->kind) {
    case YT_SCALAR:
        return a->quoted == b->quoted && strcmp(a->str, b->str) == 0;
    case YT_SEQ:
        for (size_t i = 0; i < a->n; i++)
            if (!node_equal(a->items[i], b->items[i], skip_in, skip_key))
                return false;
        return true;
    case YT_MAP:
        return map_equal(a, b, skip_in, skip_key);
    }
    return false;
}

/* The new text ed->text[0, lines a) + ins (its '\n' written as brk) +
 * ed->text[lines b, end). */
static char *splice(const fw_yaml_edit *ed, const lines *l, size_t a, const char *ins, size_t b,
                    const char *brk, size_t *out_len)
{
    size_t pa = a < l->n ? l->v[a].start : ed->len, pb = b < l->n ? l->v[b].start : ed->len;
    size_t nl = 0, bl = strlen(brk), il = strlen(ins);
    for (size_t i = 0; i < il; i++)
        nl += ins[i] == '\n';
    /* appending after a last line that has no break: give it one */
    bool lead = a > 0 && a == l->n && l->v[a - 1].brk == 0 && il > 0;
    size_t cap = pa + (lead ? bl : 0) + il + nl * bl + (ed->len - pb) + 1;
    char *t = malloc(cap), *p = t;
    if (!t)
        return NULL;
    memcpy(p, ed->text, pa);
    p += pa;
    if (lead)
        memcpy(p, brk, bl), p += bl;
    for (size_t i = 0; i < il; i++) {
        if (ins[i] == '\n')
            memcpy(p, brk, bl), p += bl;
        else
            *p++ = ins[i];
    }
    memcpy(p, ed->text + pb, ed->len - pb);
    p += ed->len - pb;
    *p = '\0';
    *out_len = (size_t)(p - t);
    return t;
}

/* The line break the file uses near line i (LF for a file without any). */
static void break_of(const fw_yaml_edit *ed, const lines *l, size_t i, char out[4])
{
    const line *L = NULL;
    if (i < l->n && l->v[i].brk)
        L = &l->v[i];
    for (size_t k = 0; !L && k < l->n; k++)
        if (l->v[k].brk)
            L = &l->v[k];
    if (!L) {
        strcpy(out, "\n");
        return;
    }
    memcpy(out, ed->text + L->start + L->len, L->brk);
    out[L->brk] = '\0';
}

typedef bool (*verify_fn)(const yt_doc *old, const yt_doc *new_doc, const void *ctx);

/* Replaces ed's text with t if t parses and verify accepts it; frees t. */
static fw_status adopt(fw_yaml_edit *ed, char *t, size_t n, const yt_doc *old, verify_fn verify,
                       const void *ctx, const char *what, fw_error *err)
{
    if (!t)
        return fw_fail(err, FW_ERUN, "%s: out of memory", ed->name);
    yt_doc *nd = NULL;
    fw_error perr = {0};
    bool ok = yt_load_string(t, ed->name, &nd, &perr) == FW_OK && verify(old, nd, ctx);
    yt_free(nd);
    if (!ok) {
        free(t);
        return fw_fail(err, FW_EINPUT,
                       "%s: cannot edit %s in place (the file's layout is not one fairway can "
                       "rewrite line by line); the file is unchanged",
                       ed->name, what);
    }
    free(ed->text);
    ed->text = t;
    ed->len = n;
    return FW_OK;
}

fw_status fw_yaml_edit_open_text(const char *text, size_t len, const char *name,
                                 fw_yaml_edit **out, fw_error *err)
{
    *out = NULL;
    if (memchr(text, '\0', len))
        return fw_fail(err, FW_EINPUT, "%s: contains a NUL byte, not a YAML file", name);
    fw_yaml_edit *ed = calloc(1, sizeof *ed);
    if (!ed || !(ed->name = strdup(name)) || !(ed->text = malloc(len + 1))) {
        fw_yaml_edit_free(ed);
        return fw_fail(err, FW_ERUN, "%s: out of memory", name);
    }
    memcpy(ed->text, text, len);
    ed->text[len] = '\0';
    ed->len = len;
    yt_doc *doc = NULL;
    fw_status st = yt_load_string(ed->text, name, &doc, err);
    yt_free(doc);
    if (st) {
        fw_yaml_edit_free(ed);
        return st;
    }
    *out = ed;
    return FW_OK;
}

fw_status fw_yaml_edit_open(const char *path, fw_yaml_edit **out, fw_error *err)
{
    *out = NULL;
    /* the tree loader's checks first: directories, syntax, with their lines */
    yt_doc *doc = NULL;
    fw_status st = yt_load_file(path, &doc, err);
    yt_free(doc);
    if (st)
        return st;
    FILE *f = fopen(path, "rb");
    if (!f)
        return fw_fail(err, FW_EINPUT, "%s: cannot open: %s", path, strerror(errno));
    char *buf = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&buf, &len);
    char chunk[8192];
    size_t k;
    while (m && (k = fread(chunk, 1, sizeof chunk, f)) > 0)
        fwrite(chunk, 1, k, m);
    bool bad = ferror(f) || !m;
    fclose(f);
    if (m)
        bad |= fclose(m) != 0;
    if (bad) {
        free(buf);
        return fw_fail(err, FW_EINPUT, "%s: cannot read: %s", path, strerror(errno));
    }
    st = fw_yaml_edit_open_text(buf, len, path, out, err);
    free(buf);
    return st;
}

void fw_yaml_edit_free(fw_yaml_edit *ed)
{
    if (!ed)
        return;
    free(ed->name);
    free(ed->text);
    free(ed);
}

const char *fw_yaml_edit_text(const fw_yaml_edit *ed, size_t *len)
{
    if (len)
        *len = ed->len;
    return ed->text;
}

typedef struct scalar_ctx {
    const yt_node *old_sec;
    const char *section, *key, *value;
} scalar_ctx;

static bool verify_scalar(const yt_doc *old, const yt_doc *nd, const void *vctx)
{
    const scalar_ctx *c = vctx;
    const yt_node *v = yt_get(yt_get(nd->root, c->section), c->key);
    return v && v->kind == YT_SCALAR && !v->quoted && strcmp(v->str, c->value) == 0 &&
           node_equal(old->root, nd->root, c->old_sec, c->key);
}

/* Finds section.key's line (0-based) for a single-line scalar edit. */
static fw_status scalar_line(const fw_yaml_edit *ed, const yt_doc *doc, const lines *l,
                             const char *section, const char *key, size_t *at, size_t *indent,
                             fw_error *err)
{
    const yt_node *sec = yt_get(doc->root, section);
    const yt_node *val = yt_get(sec, key);
    if (!sec || sec->kind != YT_MAP || !val || val->kind != YT_SCALAR)
        return fw_fail(err, FW_EINPUT, "%s: no scalar field %s.%s to set", ed->name, section,
                       key);
    int kl = yt_key_line(sec, key);
    if (kl < 1 || (size_t)kl > l->n || val->line != kl ||
        !line_has_key(ed, &l->v[kl - 1], key, indent))
        return fw_fail(err, FW_EINPUT,
                       "%s:%d: %s.%s: cannot edit in place (the value is not on the key's own "
                       "line); the file is unchanged",
                       ed->name, kl, section, key);
    *at = (size_t)kl - 1;
    return FW_OK;
}

fw_status fw_yaml_edit_scalar(fw_yaml_edit *ed, const char *section, const char *key,
                              const char *value, const char *comment, fw_error *err)
{
    yt_doc *doc = NULL;
    fw_status st = yt_load_string(ed->text, ed->name, &doc, err);
    if (st)
        return st;
    lines l = {0};
    size_t at = 0, indent = 0;
    if ((st = split(ed, &l, err)) ||
        (st = scalar_line(ed, doc, &l, section, key, &at, &indent, err)))
        goto out;
    size_t need = indent + strlen(key) + strlen(value) + (comment ? strlen(comment) : 0) + 16;
    char *text = malloc(need);
    if (!text) {
        st = fw_fail(err, FW_ERUN, "%s: out of memory", ed->name);
        goto out;
    }
    snprintf(text, need, "%*s%s: %s%s%s\n", (int)indent, "", key, value, comment ? "  # " : "",
             comment ? comment : "");
    char brk[4];
    break_of(ed, &l, at, brk);
    size_t n = 0;
    char *t = splice(ed, &l, at, text, at + 1, brk, &n);
    free(text);
    scalar_ctx c = {yt_get(doc->root, section), section, key, value};
    st = adopt(ed, t, n, doc, verify_scalar, &c, key, err);
out:
    free(l.v);
    yt_free(doc);
    return st;
}

static bool verify_same(const yt_doc *old, const yt_doc *nd, const void *ctx)
{
    (void)ctx;
    return node_equal(old->root, nd->root, NULL, "");
}

static bool starts_with(const fw_yaml_edit *ed, const line *L, const char *prefix)
{
    size_t k = strlen(prefix);
    return L->len >= k && memcmp(ed->text + L->start, prefix, k) == 0;
}

fw_status fw_yaml_edit_comment_block(fw_yaml_edit *ed, const char *tag, const char *text,
                                     fw_error *err)
{
    yt_doc *doc = NULL;
    fw_status st = yt_load_string(ed->text, ed->name, &doc, err);
    if (st)
        return st;
    lines l = {0};
    size_t tl = strlen(tag), need = strlen(text) + 2 * tl + 32;
    char *open_m = malloc(tl + 8), *close_m = malloc(tl + 8), *block = malloc(need);
    if (!open_m || !close_m || !block) {
        st = fw_fail(err, FW_ERUN, "%s: out of memory", ed->name);
        goto out;
    }
    snprintf(open_m, tl + 8, "# >>> %s", tag);
    snprintf(close_m, tl + 8, "# <<< %s", tag);
    if ((st = split(ed, &l, err)))
        goto out;
    size_t a = l.n, b = l.n;
    for (size_t i = 0; i < l.n; i++) {
        if (a == l.n && starts_with(ed, &l.v[i], open_m))
            a = i;
        else if (a != l.n && starts_with(ed, &l.v[i], close_m)) {
            b = i + 1;
            break;
        }
    }
    if (a == l.n || b == l.n) {
        /* not there yet: after the leading comment header */
        a = 0;
        while (a < l.n && l.v[a].len > 0 && ed->text[l.v[a].start] == '#')
            a++;
        b = a;
    }
    snprintf(block, need, "%s\n%s%s\n", open_m, text, close_m);
    char brk[4];
    break_of(ed, &l, a, brk);
    size_t n = 0;
    char *t = splice(ed, &l, a, block, b, brk, &n);
    st = adopt(ed, t, n, doc, verify_same, NULL, "the comment block", err);
out:
    free(open_m);
    free(close_m);
    free(block);
    free(l.v);
    yt_free(doc);
    return st;
}

typedef struct block_ctx {
    const char *key;
} block_ctx;

static bool verify_block(const yt_doc *old, const yt_doc *nd, const void *vctx)
{
    const block_ctx *c = vctx;
    return yt_get(nd->root, c->key) && node_equal(old->root, nd->root, old->root, c->key);
}

static bool block_line(const fw_yaml_edit *ed, const line *L)
{
    char c = L->len ? ed->text[L->start] : '\0';
    return L->len == 0 || c == ' ' || c == '\t';
}

fw_status fw_yaml_edit_block(fw_yaml_edit *ed, const char *key, const char *text, fw_error *err)
{
    yt_doc *doc = NULL;
    fw_status st = yt_load_string(ed->text, ed->name, &doc, err);
    if (st)
        return st;
    lines l = {0};
    if ((st = split(ed, &l, err)))
        goto out;
    bool present = yt_get(doc->root, key) != NULL;
    int kl = present ? yt_key_line(doc->root, key) : 0;
    size_t a = l.n, b = l.n, indent = 0;
    if (present) {
        if (kl < 1 || (size_t)kl > l.n || !line_has_key(ed, &l.v[kl - 1], key, &indent) ||
            indent != 0) {
            st = fw_fail(err, FW_EINPUT,
                         "%s:%d: %s: cannot replace the block in place; the file is unchanged",
                         ed->name, kl, key);
            goto out;
        }
        a = (size_t)kl - 1;
        while (a > 0 && starts_with(ed, &l.v[a - 1], "#"))
            a--;
        /* the block ends at the next line that starts in column 0 with a key
         * or a comment that belongs to the next key */
        b = (size_t)kl;
        while (b < l.n && block_line(ed, &l.v[b]))
            b++;
        /* keep a blank line separating it from what follows */
        while (b > (size_t)kl && l.v[b - 1].len == 0)
            b--;
    }
    char brk[4];
    break_of(ed, &l, present ? (size_t)kl - 1 : 0, brk);
    size_t n = 0;
    char *t = splice(ed, &l, a, text, b, brk, &n);
    block_ctx c = {key};
    st = adopt(ed, t, n, doc, verify_block, &c, key, err);
out:
    free(l.v);
    yt_free(doc);
    return st;
}

/* Written through core/files.h's one writer: an unpredictable temporary name
 * beside path, checked, then renamed (a stream such as /dev/stdout written as
 * it is). */
fw_status fw_yaml_edit_save(const fw_yaml_edit *ed, const char *path, fw_yaml_check check,
                            void *ctx, fw_error *err)
{
    if (!path)
        path = ed->name;
    struct stat sb;
    if (stat(path, &sb) == 0 && S_ISDIR(sb.st_mode))
        return fw_fail(err, FW_EINPUT, "%s: is a directory", path);
    char tmp[PATH_MAX + 32];
    FILE *f = fw_file_begin(path, tmp, sizeof tmp, err);
    if (!f)
        return err->status;
    fw_status st = FW_OK;
    if ((ed->len > 0 && fwrite(ed->text, 1, ed->len, f) != ed->len) || fflush(f) != 0)
        st = fw_fail(err, FW_ERUN, "%s: write failed: %s", path, strerror(errno));
    else if (check)
        st = check(tmp, ctx, err); /* the check's message says why */
    if (st) {
        fw_file_abort(f, tmp);
        return st;
    }
    return fw_file_commit(f, tmp, path, err);
}

fw_status fw_yaml_set_scalar(const char *path, const char *section, const char *key,
                             const char *value, const char *comment, fw_error *err)
{
    fw_yaml_edit *ed = NULL;
    fw_status st = fw_yaml_edit_open(path, &ed, err);
    if (!st && !(st = fw_yaml_edit_scalar(ed, section, key, value, comment, err)))
        st = fw_yaml_edit_save(ed, NULL, NULL, NULL, err);
    fw_yaml_edit_free(ed);
    return st;
}
