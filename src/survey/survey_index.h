/* survey_index.h - the survey's lookup structures (internal to src/survey).
 *
 *   sv_pairs  a pair of interned ids -> the index of its latest episode
 *   sv_grid   every pair of points closer than r, once, from a uniform grid of
 *             cells of side r (hashed, so the area needs no bounds)
 *
 * Open addressing with linear probing and power-of-two tables throughout;
 * nothing is ever deleted (ids and pairs live as long as the survey).
 * Functions that allocate return 0, or -1 when out of memory.
 */
#ifndef FW_SURVEY_INDEX_H
#define FW_SURVEY_INDEX_H

#include <stddef.h>
#include <stdint.h>

#include "core/idmap.h"

typedef struct sv_pairs {
    uint64_t *key;    /* 0 = empty (a real key has hi > 0) */
    int *val;
    size_t cap, n;
} sv_pairs;

/* The key of an unordered pair of distinct interned ids. */
static inline uint64_t sv_pair_key(int a, int b)
{
    uint64_t lo = (uint64_t)(a < b ? a : b), hi = (uint64_t)(a < b ? b : a);
    return lo << 32 | hi;
}
/* The value stored for key, -1 if none. */
int sv_pairs_get(const sv_pairs *p, uint64_t key);
int sv_pairs_put(sv_pairs *p, uint64_t key, int val);
void sv_pairs_free(sv_pairs *p);

/* Called once per close pair with its squared distance. */
typedef void (*sv_pair_fn)(void *ctx, int i, int j, double d2);

typedef struct sv_grid {
    /* scratch, grown as needed and reused from step to step */
    int64_t *px, *py;         /* per point: its cell's coordinates */
    int *cell_of, *order;     /* per point: its cell; points sorted by cell */
    double *xs, *ys;          /* coordinates in that order: pair tests read them in a row */
    int cap;                  /* points the per-point arrays hold */
    int *count, *start;       /* per cell: members, first in order[] */
    int64_t *cx, *cy;         /* per cell (hashed grid only) */
    int cell_cap;
    int *slot;                /* hashed grid: cell index + 1, 0 = empty */
    size_t slot_cap;
} sv_grid;

/* fn(ctx, i, j, d2) for every pair i != j with d2 = dx^2 + dy^2 < r^2, each
 * pair once, in no particular order.  Coordinates must be finite with
 * |x| / r, |y| / r well inside int64. */
int sv_grid_pairs(sv_grid *g, const double *x, const double *y, int n, double r, sv_pair_fn fn,
                  void *ctx);
/* The same by testing all n (n - 1) / 2 pairs: the reference for tests. */
void sv_brute_pairs(const double *x, const double *y, int n, double r, sv_pair_fn fn, void *ctx);
void sv_grid_free(sv_grid *g);

#endif
