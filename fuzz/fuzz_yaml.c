/* libFuzzer target: the YAML layer.  Any text is parsed into a tree (never a
 * crash, at any nesting), every typed reader is run on every field, and the
 * in-place editor is tried on the first fields it finds.  An edit must either
 * fail cleanly or give text that parses with the new value and every other
 * field unchanged (checked here independently of the editor's own check). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "yaml/yaml_edit.h"
#include "yaml/yaml_tree.h"

static void read_all(const yt_doc *doc, const yt_node *map, int depth)
{
    if (!map || map->kind != YT_MAP || depth > 8)
        return;
    fw_error err = {0};
    const char *allowed[3] = {map->n ? map->keys[0] : NULL, NULL, NULL};
    if (allowed[0])
        yt_check_keys(doc, map, "p", allowed, &err);
    for (size_t i = 0; i < map->n; i++) {
        const char *k = map->keys[i];
        double d = 0;
        long l = 0;
        bool b = false;
        char s[16];
        const yt_node *c = NULL;
        yt_opt_number(doc, map, "p", k, -1e9, 1e9, &d, &err);
        yt_opt_int(doc, map, "p", k, -5, 5, &l, &err);
        yt_opt_string(doc, map, "p", k, s, sizeof s, &err);
        yt_opt_bool(doc, map, "p", k, &b, &err);
        yt_opt_seq(doc, map, "p", k, &c, &err);
        yt_req_map(doc, map, "p", k, &c, &err);
        yt_key_line(map, k);
        read_all(doc, map->items[i], depth + 1);
    }
}

static bool same_except(const yt_node *a, const yt_node *b, const yt_node *skip_in,
                        const char *skip_key)
{
    if (a->kind != b->kind)
        return false;
    if (a->kind == YT_SCALAR)
        return a->quoted == b->quoted && strcmp(a->str, b->str) == 0;
    if (a->kind == YT_SEQ) {
        if (a->n != b->n)
            return false;
        for (size_t i = 0; i < a->n; i++)
            if (!same_except(a->items[i], b->items[i], skip_in, skip_key))
                return false;
        return true;
    }
    size_t na = 0, nb = 0;
    for (size_t i = 0; i < a->n; i++) {
        if (a == skip_in && strcmp(a->keys[i], skip_key) == 0)
            continue;
        na++;
        const yt_node *v = yt_get(b, a->keys[i]);
        if (!v || !same_except(a->items[i], v, skip_in, skip_key))
            return false;
    }
    for (size_t i = 0; i < b->n; i++)
        nb += !(a == skip_in && strcmp(b->keys[i], skip_key) == 0);
    return na == nb;
}

static yt_doc *reparse(const fw_yaml_edit *ed)
{
    size_t n;
    const char *t = fw_yaml_edit_text(ed, &n);
    yt_doc *doc = NULL;
    fw_error err = {0};
    if (strlen(t) != n || yt_load_string(t, "edited", &doc, &err) != FW_OK)
        __builtin_trap(); /* an accepted edit must give a parsable file */
    return doc;
}

/* The first scalar directly under a top-level mapping. */
static bool find_scalar(const yt_node *root, const char **sec, const char **key)
{
    for (size_t i = 0; i < root->n; i++) {
        const yt_node *m = root->items[i];
        if (m->kind != YT_MAP)
            continue;
        for (size_t j = 0; j < m->n; j++)
            if (m->items[j]->kind == YT_SCALAR) {
                *sec = root->keys[i];
                *key = m->keys[j];
                return true;
            }
    }
    return false;
}

static void try_edits(const char *text, size_t len, const yt_doc *doc, unsigned ops)
{
    fw_yaml_edit *ed = NULL;
    fw_error err = {0};
    if (fw_yaml_edit_open_text(text, len, "in.yaml", &ed, &err) != FW_OK)
        __builtin_trap(); /* it parsed as a tree */
    const char *sec, *key;
    if ((ops & 1) && find_scalar(doc->root, &sec, &key) &&
        fw_yaml_edit_scalar(ed, sec, key, "-0.0123", (ops & 2) ? "was: x # y" : NULL, &err) ==
            FW_OK) {
        yt_doc *nd = reparse(ed);
        const yt_node *v = yt_get(yt_get(nd->root, sec), key);
        if (!v || v->kind != YT_SCALAR || strcmp(v->str, "-0.0123") != 0 ||
            !same_except(doc->root, nd->root, yt_get(doc->root, sec), key))
            __builtin_trap();
        yt_free(nd);
    }
    yt_doc *cur = reparse(ed);
    if ((ops & 4) && fw_yaml_edit_comment_block(ed, "t", "# a\n# b\n", &err) == FW_OK) {
        yt_doc *nd = reparse(ed);
        if (!same_except(cur->root, nd->root, NULL, ""))
            __builtin_trap();
        yt_free(cur);
        cur = nd;
    }
    const char *bkey = cur->root->n ? cur->root->keys[(ops >> 3) % cur->root->n] : "zz";
    if ((ops & 64) && fw_yaml_edit_block(ed, bkey, "# new\nzz_new:\n  a: 1\n", &err) == FW_OK) {
        yt_doc *nd = reparse(ed);
        if (!yt_get(nd->root, "zz_new") || !same_except(cur->root, nd->root, cur->root, bkey))
            __builtin_trap();
        yt_free(nd);
    }
    yt_free(cur);
    fw_yaml_edit_free(ed);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    unsigned ops = data[0];
    char *text = malloc(size);
    if (!text)
        return 0;
    memcpy(text, data + 1, size - 1);
    text[size - 1] = '\0';
    size_t len = strlen(text);
    yt_doc *doc = NULL;
    fw_error err = {0};
    if (yt_load_string(text, "in.yaml", &doc, &err) == FW_OK) {
        read_all(doc, doc->root, 0);
        try_edits(text, len, doc, ops);
        yt_free(doc);
    } else if (!strstr(err.msg, "in.yaml:")) {
        __builtin_trap(); /* every refusal names the file and line */
    }
    free(text);
    return 0;
}
