/* idmap.c - see idmap.h. */
#include "core/idmap.h"

#include <assert.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "core/mem.h"

/* FNV-1a: ids are short strings like "east.123" */
static uint64_t hash_str(const char *s)
{
    uint64_t h = 1469598103934665603ULL;
    for (; *s; s++) {
        h ^= (unsigned char)*s;
        h *= 1099511628211ULL;
    }
    return h;
}

static int rehash(fw_idmap *t, size_t cap)
{
    int *slot = calloc(cap, sizeof *slot);
    if (!slot)
        return -1;
    for (int i = 0; i < t->n; i++) {
        size_t k = (size_t)t->hash[i] & (cap - 1);
        while (slot[k])
            k = (k + 1) & (cap - 1);
        slot[k] = i + 1;
    }
    free(t->slot);
    t->slot = slot;
    t->cap = cap;
    return 0;
}

static int find(const fw_idmap *t, const char *id, uint64_t h)
{
    if (!t->cap)
        return -1;
    for (size_t k = (size_t)h & (t->cap - 1); t->slot[k]; k = (k + 1) & (t->cap - 1)) {
        int i = t->slot[k] - 1;
        if (t->hash[i] == h && strcmp(t->name[i], id) == 0)
            return i;
    }
    return -1;
}

int fw_idmap_find(const fw_idmap *t, const char *id) { return find(t, id, hash_str(id)); }

/* fw_idmap_intern; *made: it was new. */
static int intern(fw_idmap *t, const char *id, int *out, bool *made)
{
    uint64_t h = hash_str(id);
    int found = find(t, id, h);
    *made = false;
    if (found >= 0) {
        *out = found;
        return 0;
    }
    /* new: keep the table at most half full */
    if ((size_t)(t->n + 1) * 2 > t->cap && rehash(t, t->cap ? 2 * t->cap : 256))
        return -1;
    if (t->n == t->name_cap) {
        int cap = t->name_cap ? 2 * t->name_cap : 128;
        if (!fw_resize_each((size_t)cap, 2, (void **)&t->name, sizeof *t->name,
                            (void **)&t->hash, sizeof *t->hash))
            return -1;
        t->name_cap = cap;
    }
    char *copy = strdup(id);
    if (!copy)
        return -1;
    int i = t->n++;
    t->name[i] = copy;
    t->hash[i] = h;
    size_t k = (size_t)h & (t->cap - 1);
    while (t->slot[k])
        k = (k + 1) & (t->cap - 1);
    t->slot[k] = i + 1;
    *out = i;
    *made = true;
    return 0;
}

int fw_idmap_intern(fw_idmap *t, const char *id, int *out)
{
    bool made;
    if (intern(t, id, out, &made))
        return -1;
    t->keyless += made;
    return 0;
}

/* The index key stands for, -1 if not seen (or key 0). */
static int by_key(const fw_idmap *t, int key, const char *id)
{
    if (key <= 0 || key > t->key_cap || !t->by_key[key - 1])
        return -1;
    int i = t->by_key[key - 1] - 1;
    assert(strcmp(t->name[i], id) == 0); /* one key, one id */
    (void)id;
    return i;
}

int fw_idmap_find_keyed(const fw_idmap *t, int key, const char *id)
{
    int i = by_key(t, key, id);
    if (i >= 0 || (key > 0 && t->keyless == 0))
        return i; /* (a key stands for one id: had it been interned, its key would map) */
    return fw_idmap_find(t, id);
}

int fw_idmap_intern_keyed(fw_idmap *t, int key, const char *id, int *out)
{
    int i = by_key(t, key, id);
    if (i >= 0) {
        *out = i;
        return 0;
    }
    /* room first: out of memory leaves the map as it was */
    int had = t->key_cap;
    if (key > 0 && !fw_reserve((void **)&t->by_key, sizeof *t->by_key, &t->key_cap, key))
        return -1;
    if (t->key_cap > had)
        memset(t->by_key + had, 0, sizeof *t->by_key * (size_t)(t->key_cap - had));
    bool made;
    if (intern(t, id, &i, &made))
        return -1;
    if (key > 0)
        t->by_key[key - 1] = i + 1;
    else
        t->keyless += made;
    *out = i;
    return 0;
}

void fw_idmap_free(fw_idmap *t)
{
    free(t->by_key);
    for (int i = 0; i < t->n; i++)
        free(t->name[i]);
    free(t->name);
    free(t->hash);
    free(t->slot);
    memset(t, 0, sizeof *t);
}

