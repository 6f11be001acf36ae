/* survey_index.c - interned ship ids and the pair -> episode map (see survey_index.h). */
#include "survey/survey_index.h"

#include <stdlib.h>
#include <string.h>

/* splitmix64's finaliser: pair keys differ in few bits */
static uint64_t mix(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
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
