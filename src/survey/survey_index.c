/* survey_index.c - interned ship ids and the pair -> episode map (see survey_index.h). */
#include "survey/survey_index.h"

#include <stdlib.h>
#include <string.h>

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

/* splitmix64's finaliser: pair keys differ in few bits */
static uint64_t mix(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

static int ids_rehash(sv_ids *t, size_t cap)
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

int sv_ids_intern(sv_ids *t, const char *id, int *out)
{
    uint64_t h = hash_str(id);
    if (t->cap) {
        for (size_t k = (size_t)h & (t->cap - 1); t->slot[k]; k = (k + 1) & (t->cap - 1)) {
            int i = t->slot[k] - 1;
            if (t->hash[i] == h && strcmp(t->name[i], id) == 0) {
                *out = i;
                return 0;
            }
        }
    }
    /* new: keep the table at most half full */
    if ((size_t)(t->n + 1) * 2 > t->cap && ids_rehash(t, t->cap ? 2 * t->cap : 256))
        return -1;
    if (t->n == t->name_cap) {
        int cap = t->name_cap ? 2 * t->name_cap : 128;
        char **name = realloc(t->name, sizeof *name * (size_t)cap);
        if (!name)
            return -1;
        t->name = name;
        uint64_t *hash = realloc(t->hash, sizeof *hash * (size_t)cap);
        if (!hash)
            return -1;
        t->hash = hash;
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
    return 0;
}

void sv_ids_free(sv_ids *t)
{
    for (int i = 0; i < t->n; i++)
        free(t->name[i]);
    free(t->name);
    free(t->hash);
    free(t->slot);
    memset(t, 0, sizeof *t);
}

int sv_pairs_get(const sv_pairs *p, uint64_t key)
{
    if (!p->cap)
        return -1;
    for (size_t k = (size_t)mix(key) & (p->cap - 1); p->key[k]; k = (k + 1) & (p->cap - 1))
        if (p->key[k] == key)
            return p->val[k];
    return -1;
}

static void put_raw(uint64_t *keys, int *vals, size_t cap, uint64_t key, int val)
{
    size_t k = (size_t)mix(key) & (cap - 1);
    while (keys[k] && keys[k] != key)
        k = (k + 1) & (cap - 1);
    keys[k] = key;
    vals[k] = val;
}

int sv_pairs_put(sv_pairs *p, uint64_t key, int val)
{
    if ((p->n + 1) * 2 > p->cap) {
        size_t cap = p->cap ? 2 * p->cap : 256;
        uint64_t *keys = calloc(cap, sizeof *keys);
        int *vals = malloc(sizeof *vals * cap);
        if (!keys || !vals) {
            free(keys);
            free(vals);
            return -1;
        }
        for (size_t k = 0; k < p->cap; k++)
            if (p->key[k])
                put_raw(keys, vals, cap, p->key[k], p->val[k]);
        free(p->key);
        free(p->val);
        p->key = keys;
        p->val = vals;
        p->cap = cap;
    }
    if (sv_pairs_get(p, key) < 0)
        p->n++;
    put_raw(p->key, p->val, p->cap, key, val);
    return 0;
}

void sv_pairs_free(sv_pairs *p)
{
    free(p->key);
    free(p->val);
    memset(p, 0, sizeof *p);
}
