#include "yaml/yaml_edit.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "yaml/yaml_tree.h"

typedef struct lines {
    char **v;
    size_t n;
} lines;

static void lines_free(lines *l)
{
    for (size_t i = 0; i < l->n; i++)
        free(l->v[i]);
    free(l->v);
    l->v = NULL;
    l->n = 0;
}

static fw_status lines_read(const char *path, lines *l, fw_error *err)
{
    l->v = NULL;
    l->n = 0;
    FILE *f = fopen(path, "r");
    if (!f)
        return fw_fail(err, FW_EINPUT, "%s: cannot open: %s", path, strerror(errno));
    char *buf = NULL;
    size_t cap = 0;
    ssize_t len;
    while ((len = getline(&buf, &cap, f)) >= 0) {
        char **v = realloc(l->v, (l->n + 1) * sizeof *v);
        char *copy = strdup(buf);
        if (!v || !copy) {
            free(v ? NULL : copy);
            if (v)
                l->v = v;
            free(buf);
            fclose(f);
            lines_free(l);
            return fw_fail(err, FW_ERUN, "out of memory");
        }
        l->v = v;
        l->v[l->n++] = copy;
    }
    free(buf);
    fclose(f);
    return FW_OK;
}

/* Writes lines [0, a) + text + lines [b, n) to path via a temporary file. */
static fw_status lines_write(const char *path, const lines *l, size_t a, const char *text,
                             size_t b, fw_error *err)
{
    char tmp[1100];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    FILE *f = fopen(tmp, "w");
    if (!f)
        return fw_fail(err, FW_ERUN, "%s: cannot write: %s", tmp, strerror(errno));
    for (size_t i = 0; i < a; i++)
        fputs(l->v[i], f);
    if (text)
        fputs(text, f);
    for (size_t i = b; i < l->n; i++)
        fputs(l->v[i], f);
    int bad = ferror(f);
    bad |= fclose(f);
    if (bad || rename(tmp, path)) {
        remove(tmp);
        return fw_fail(err, FW_ERUN, "%s: write failed", path);
    }
    return FW_OK;
}

fw_status fw_yaml_set_scalar(const char *path, const char *section, const char *key,
                             const char *value, const char *comment, fw_error *err)
{
    yt_doc *doc;
    fw_status st = yt_load_file(path, &doc, err);
    if (st)
        return st;
    const yt_node *sec = yt_get(doc->root, section);
    const yt_node *val = yt_get(sec, key);
    if (!sec || !val || val->kind != YT_SCALAR) {
        yt_free(doc);
        return fw_fail(err, FW_EINPUT, "%s: no scalar field %s.%s to set", path, section, key);
    }
    int line = yt_key_line(sec, key);
    yt_free(doc);
    lines l;
    if ((st = lines_read(path, &l, err)))
        return st;
    if (line < 1 || (size_t)line > l.n) {
        lines_free(&l);
        return fw_fail(err, FW_ERUN, "%s: line %d out of range", path, line);
    }
    const char *old = l.v[line - 1];
    int indent = 0;
    while (old[indent] == ' ')
        indent++;
    char text[1024];
    if (comment)
        snprintf(text, sizeof text, "%*s%s: %s  # %s\n", indent, "", key, value, comment);
    else
        snprintf(text, sizeof text, "%*s%s: %s\n", indent, "", key, value);
    st = lines_write(path, &l, (size_t)line - 1, text, (size_t)line, err);
    lines_free(&l);
    return st;
}

fw_status fw_yaml_set_comment_block(const char *path, const char *tag, const char *text,
                                    fw_error *err)
{
    lines l;
    fw_status st = lines_read(path, &l, err);
    if (st)
        return st;
    char open_m[128], close_m[128];
    snprintf(open_m, sizeof open_m, "# >>> %s", tag);
    snprintf(close_m, sizeof close_m, "# <<< %s", tag);
    size_t a = l.n, b = l.n;
    for (size_t i = 0; i < l.n; i++) {
        if (a == l.n && strncmp(l.v[i], open_m, strlen(open_m)) == 0)
            a = i;
        else if (a != l.n && strncmp(l.v[i], close_m, strlen(close_m)) == 0) {
            b = i + 1;
            break;
        }
    }
    if (a == l.n || b == l.n) {
        /* not there yet: after the leading comment header */
        a = 0;
        while (a < l.n && l.v[a][0] == '#')
            a++;
        b = a;
    }
    size_t need = strlen(text) + 2 * sizeof open_m + 4;
    char *block = malloc(need);
    if (!block) {
        lines_free(&l);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    snprintf(block, need, "%s\n%s%s\n", open_m, text, close_m);
    st = lines_write(path, &l, a, block, b, err);
    free(block);
    lines_free(&l);
    return st;
}

fw_status fw_yaml_replace_block(const char *path, const char *key, const char *text,
                                fw_error *err)
{
    yt_doc *doc;
    fw_status st = yt_load_file(path, &doc, err);
    if (st)
        return st;
    bool present = yt_get(doc->root, key) != NULL;
    int line = present ? yt_key_line(doc->root, key) : 0;
    yt_free(doc);
    lines l;
    if ((st = lines_read(path, &l, err)))
        return st;
    size_t a = l.n, b = l.n;
    if (present) {
        a = (size_t)line - 1;
        while (a > 0 && l.v[a - 1][0] == '#')
            a--;
        b = (size_t)line;
        /* the block ends at the next line that starts in column 0 with a key
         * or a comment that belongs to the next key */
        while (b < l.n && (l.v[b][0] == ' ' || l.v[b][0] == '\n' || l.v[b][0] == '\t'))
            b++;
        /* keep a blank line separating it from what follows */
        while (b > (size_t)line && l.v[b - 1][0] == '\n')
            b--;
    }
    st = lines_write(path, &l, a, text, b, err);
    lines_free(&l);
    return st;
}
