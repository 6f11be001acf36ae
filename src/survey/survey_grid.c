/* survey_grid.c - close pairs from a uniform grid (see survey_index.h).
 *
 * Cells have side r (0.1 % more, so that rounding in x / side can never put
 * a pair closer than r two cells apart): such a pair lies in one cell or in
 * two neighbouring ones.  Each cell is paired with itself and with four of its
 * eight neighbours (east, and the three to the north), which visits every
 * neighbouring pair of cells exactly once.  Points are counting-sorted by
 * cell, their coordinates copied in that order, so the pair tests read memory
 * in a row.  Cells are numbered densely over the bounding box when it holds at
 * most a few cells per point (the usual case: one sea area), else through a
 * hash table of the occupied cells (a stray point far off costs nothing).
 * Either way building the grid is O(n) and the tests O(n + pairs within about
 * 2 r): linear in n at a bounded density.
 */
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "core/mem.h"
#include "survey/survey_index.h"

/* Bounding boxes up to this many cells per point are numbered densely. */
static const double kDenseCellsPerPoint = 4.0;

static bool grow(void **p, size_t sz, size_t n)
{
    void *q = realloc(*p, sz * n);
    if (q)
        *p = q;
    return q != NULL;
}

static int reserve_points(sv_grid *g, int n)
{
    if (n <= g->cap)
        return 0;
    size_t m = (size_t)(n > 2 * g->cap ? n : 2 * g->cap);
    if (!grow((void **)&g->px, sizeof *g->px, m) || !grow((void **)&g->py, sizeof *g->py, m) ||
        !grow((void **)&g->cell_of, sizeof *g->cell_of, m) ||
        !grow((void **)&g->order, sizeof *g->order, m) ||
        !grow((void **)&g->xs, sizeof *g->xs, m) || !grow((void **)&g->ys, sizeof *g->ys, m))
        return -1;
    g->cap = (int)m;
    return 0;
}

static int reserve_cells(sv_grid *g, int cells)
{
    if (cells > g->cell_cap) {
        size_t m = (size_t)(cells > 2 * g->cell_cap ? cells : 2 * g->cell_cap);
        if (!grow((void **)&g->count, sizeof *g->count, m) ||
            !grow((void **)&g->start, sizeof *g->start, m) ||
            !grow((void **)&g->cx, sizeof *g->cx, m) || !grow((void **)&g->cy, sizeof *g->cy, m))
            return -1;
        g->cell_cap = (int)m;
    }
    return 0;
}

/* Points u < v within [s, e) and [s2, e2) of the sorted arrays; fn gets the
 * input positions.  d2 is the same whichever point comes first (negation is
 * exact), so it equals sv_brute_pairs' to the bit. */
static inline void test_pair(const sv_grid *g, int u, int v, double r2, sv_pair_fn fn, void *ctx)
{
    double dx = g->xs[v] - g->xs[u], dy = g->ys[v] - g->ys[u];
    double d2 = dx * dx + dy * dy;
    if (d2 < r2)
        fn(ctx, g->order[u], g->order[v], d2);
}

static void within(const sv_grid *g, int c, double r2, sv_pair_fn fn, void *ctx)
{
    int s = g->start[c], e = s + g->count[c];
    for (int u = s; u < e; u++)
        for (int v = u + 1; v < e; v++)
            test_pair(g, u, v, r2, fn, ctx);
}

static void across(const sv_grid *g, int c, int d, double r2, sv_pair_fn fn, void *ctx)
{
    int s = g->start[c], e = s + g->count[c], s2 = g->start[d], e2 = s2 + g->count[d];
    for (int u = s; u < e; u++)
        for (int v = s2; v < e2; v++)
            test_pair(g, u, v, r2, fn, ctx);
}

/* Counting sort of the points by cell_of over ncell cells (count[] filled). */
static void sort_points(sv_grid *g, const double *x, const double *y, int n, int ncell)
{
    for (int c = 0, s = 0; c < ncell; c++) {
        g->start[c] = s;
        s += g->count[c];
    }
    /* start[] is the cursor, restored after */
    for (int i = 0; i < n; i++) {
        int k = g->start[g->cell_of[i]]++;
        g->order[k] = i;
        g->xs[k] = x[i];
        g->ys[k] = y[i];
    }
    for (int c = 0; c < ncell; c++)
        g->start[c] -= g->count[c];
}

static const int kNb[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};

static int dense_pairs(sv_grid *g, const double *x, const double *y, int n, double r2,
                       int64_t x0, int64_t y0, int w, int h, sv_pair_fn fn, void *ctx)
{
    int ncell = w * h;
    if (reserve_cells(g, ncell))
        return -1;
    memset(g->count, 0, sizeof *g->count * (size_t)ncell);
    for (int i = 0; i < n; i++) {
        int c = (int)(g->py[i] - y0) * w + (int)(g->px[i] - x0);
        g->cell_of[i] = c;
        g->count[c]++;
    }
    sort_points(g, x, y, n, ncell);
    for (int b = 0; b < h; b++)
        for (int a = 0; a < w; a++) {
            int c = b * w + a;
            if (!g->count[c])
                continue;
            within(g, c, r2, fn, ctx);
            for (int k = 0; k < 4; k++) {
                int na = a + kNb[k][0], nb = b + kNb[k][1];
                if (na >= 0 && na < w && nb < h)
                    across(g, c, nb * w + na, r2, fn, ctx);
            }
        }
    return 0;
}

static size_t cell_hash(int64_t x, int64_t y)
{
    uint64_t z = (uint64_t)x * 0x9e3779b97f4a7c15ULL ^ (uint64_t)y * 0xc2b2ae3d27d4eb4fULL;
    return (size_t)(z ^ (z >> 29));
}

/* The hashed cell (x, y): its index, -1 if absent (insert: a new one). */
static int hashed_cell(sv_grid *g, int64_t x, int64_t y, bool insert, int *ncell)
{
    size_t k = cell_hash(x, y) & (g->slot_cap - 1);
    for (; g->slot[k]; k = (k + 1) & (g->slot_cap - 1)) {
        int c = g->slot[k] - 1;
        if (g->cx[c] == x && g->cy[c] == y)
            return c;
    }
    if (!insert)
        return -1;
    int c = (*ncell)++;
    g->slot[k] = c + 1;
    g->cx[c] = x;
    g->cy[c] = y;
    g->count[c] = 0;
    return c;
}

static int hashed_pairs(sv_grid *g, const double *x, const double *y, int n, double r2,
                        sv_pair_fn fn, void *ctx)
{
    size_t want = 16;
    while (want < 2 * (size_t)n)
        want *= 2;
    if (want > g->slot_cap) {
        if (!grow((void **)&g->slot, sizeof *g->slot, want))
            return -1;
        g->slot_cap = want;
    }
    if (reserve_cells(g, n))
        return -1;
    memset(g->slot, 0, sizeof *g->slot * g->slot_cap);
    int ncell = 0;
    for (int i = 0; i < n; i++) {
        int c = hashed_cell(g, g->px[i], g->py[i], true, &ncell);
        g->cell_of[i] = c;
        g->count[c]++;
    }
    sort_points(g, x, y, n, ncell);
    for (int c = 0; c < ncell; c++) {
        within(g, c, r2, fn, ctx);
        for (int k = 0; k < 4; k++) {
            int d = hashed_cell(g, g->cx[c] + kNb[k][0], g->cy[c] + kNb[k][1], false, NULL);
            if (d >= 0)
                across(g, c, d, r2, fn, ctx);
        }
    }
    return 0;
}

int sv_grid_pairs(sv_grid *g, const double *x, const double *y, int n, double r, sv_pair_fn fn,
                  void *ctx)
{
    if (n < 2)
        return 0;
    if (reserve_points(g, n))
        return -1;
    const double side = 1.001 * r;
    int64_t x0 = INT64_MAX, x1 = INT64_MIN, y0 = INT64_MAX, y1 = INT64_MIN;
    for (int i = 0; i < n; i++) {
        int64_t a = (int64_t)floor(x[i] / side), b = (int64_t)floor(y[i] / side);
        g->px[i] = a;
        g->py[i] = b;
        x0 = a < x0 ? a : x0;
        x1 = a > x1 ? a : x1;
        y0 = b < y0 ? b : y0;
        y1 = b > y1 ? b : y1;
    }
    /* in doubles: the span of far-apart points overflows an int */
    double w = (double)x1 - (double)x0 + 1.0, h = (double)y1 - (double)y0 + 1.0;
    if (w * h <= kDenseCellsPerPoint * n + 64.0)
        return dense_pairs(g, x, y, n, r * r, x0, y0, (int)w, (int)h, fn, ctx);
    return hashed_pairs(g, x, y, n, r * r, fn, ctx);
}

void sv_brute_pairs(const double *x, const double *y, int n, double r, sv_pair_fn fn, void *ctx)
{
    const double r2 = r * r;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            double dx = x[j] - x[i], dy = y[j] - y[i];
            double d2 = dx * dx + dy * dy;
            if (d2 < r2)
                fn(ctx, i, j, d2);
        }
}

void sv_grid_free(sv_grid *g)
{
    fw_free_each(11, g->px, g->py, g->cell_of, g->order, g->xs, g->ys, g->count, g->start, g->cx,
                     g->cy, g->slot);
    memset(g, 0, sizeof *g);
}
