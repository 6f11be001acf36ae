/* streams.c - a run's table of random streams (streams.h). */
#include "core/streams.h"

#include <stdlib.h>

#include "core/mem.h"

/* Streams live in blocks that never move, so the pointers handed out stay
 * valid as the table grows. */
enum { BLOCK = 32 };

typedef struct block {
    fw_rng s[BLOCK];
    struct block *next;
} block;

struct fw_streams {
    uint64_t seed;
    block *head, *tail;
    int n;            /* streams made */
    uint32_t *chain;  /* the re-keyings so far, in order */
    int n_chain, cap_chain;
};

fw_streams *fw_streams_create(uint64_t run_seed)
{
    fw_streams *t = calloc(1, sizeof *t);
    if (t)
        t->seed = run_seed;
    return t;
}

void fw_streams_free(fw_streams *t)
{
    if (!t)
        return;
    for (block *b = t->head, *next; b; b = next) {
        next = b->next;
        free(b);
    }
    free(t->chain);
    free(t);
}

static fw_rng *at(const fw_streams *t, int i)
{
    block *b = t->head;
    for (; i >= BLOCK; i -= BLOCK)
        b = b->next;
    return &b->s[i];
}

fw_rng *fw_streams_get(fw_streams *t, uint32_t vessel, fw_purpose purpose)
{
    uint32_t p = (uint32_t)purpose & 0x7fffffffu;
    /* a run has a few streams per ship: a scan is cheaper than a hash here,
     * and elements ask once and keep the pointer */
    for (int i = 0; i < t->n; i++) {
        fw_rng *s = at(t, i);
        if (s->vessel == vessel && s->purpose == p)
            return s;
    }
    if (t->n % BLOCK == 0) {
        block *nb = calloc(1, sizeof *nb);
        if (!nb)
            return NULL;
        if (t->tail)
            t->tail->next = nb;
        else
            t->head = nb;
        t->tail = nb;
    }
    fw_rng *s = &t->tail->s[t->n % BLOCK];
    *s = fw_rng_make(t->seed, vessel, purpose);
    for (int k = 0; k < t->n_chain; k++)
        *s = fw_rng_branch(s, t->chain[k]);
    t->n++;
    return s;
}

bool fw_streams_rekey(fw_streams *t, uint32_t branch)
{
    if (!fw_reserve((void **)&t->chain, sizeof *t->chain, &t->cap_chain, t->n_chain + 1))
        return false;
    t->chain[t->n_chain++] = branch;
    for (int i = 0; i < t->n; i++) {
        fw_rng *s = at(t, i);
        *s = fw_rng_branch(s, branch);
    }
    return true;
}

int fw_streams_count(const fw_streams *t) { return t->n; }
int fw_streams_rekeyed(const fw_streams *t) { return t->n_chain; }
