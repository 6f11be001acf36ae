/* candidates.c - the candidate tracks of one decision (see helm_ctx.h). */
#include "avoid/helm_ctx.h"

#include <math.h>
#include <string.h>

/* Samples [0, kk) of a slot, mirrored from its source's or predicted. */
static void cand_grow(fw_helm_ctx *c, int slot, int kk)
{
    fw_track *tr = &c->tracks[slot];
    if (kk > tr->n)
        kk = tr->n;
    if (kk <= c->ready[slot])
        return;
    int src = c->src[slot];
    if (src >= 0) {
        cand_grow(c, src, kk);
        fw_track_mirror_range(&c->tracks[src], &c->own, tr, c->ready[slot], kk);
    } else {
        fw_track_extend(&c->gen[slot], tr, kk);
        c->samples += kk - c->ready[slot];
    }
    c->ready[slot] = kk;
}

/* Samples and boxes of a slot through chunk j. */
void fw_cand_chunk(fw_helm_ctx *c, int slot, int j)
{
    fw_chunk_boxes *cb = &c->boxes[slot];
    int k1 = (j + 1) * FW_CHUNK < cb->nseg ? (j + 1) * FW_CHUNK : cb->nseg;
    cand_grow(c, slot, k1 + 1);
    for (; c->nbox[slot] <= j && c->nbox[slot] < cb->nch; c->nbox[slot]++)
        fw_track_box(&c->tracks[slot], cb, c->nbox[slot]);
}

/* m out of band b at (e, n): beyond the room on either side that has one */
static double band_out(const fw_helm_band *b, double e, double n)
{
    double x = (e - b->east) * cos(b->course) - (n - b->north) * sin(b->course), out = 0.0;
    if (b->room_starboard > 0.0 && x - b->room_starboard > out)
        out = x - b->room_starboard;
    if (b->room_port > 0.0 && -x - b->room_port > out)
        out = -x - b->room_port;
    return out;
}

/* m: where the track's last sample is carried on FW_BAND_AHEAD_S by its
 * last step's motion (one coordinate, x: the track's east or north) */
static double ahead(const fw_track *tr, const double *x)
{
    int k = tr->n - 1;
    return k < 1 ? x[0] : x[k] + (x[k] - x[k - 1]) * (FW_BAND_AHEAD_S / tr->dt);
}

double fw_track_band_excess(const fw_helm_band *b, const fw_track *tr)
{
    if (!b->on || tr->n < 1)
        return 0.0;
    double out0 = band_out(b, tr->east[0], tr->north[0]), worst = 0.0;
    for (int k = 1; k <= tr->n; k++) {
        double d = band_out(b, k < tr->n ? tr->east[k] : ahead(tr, tr->east),
                            k < tr->n ? tr->north[k] : ahead(tr, tr->north)) - out0;
        if (d > worst)
            worst = d;
    }
    return worst;
}

void fw_helm_set_band(fw_helm_ctx *c, const fw_helm_band *band)
{
    c->band = band ? *band : (fw_helm_band){.on = false};
}

/* Chunk by chunk, the track predicted only as far as needed: most
 * candidates in a channel leave it within minutes. */
bool fw_cand_leaves_band(fw_helm_ctx *c, int slot)
{
    if (!c->band.on)
        return false;
    const fw_track *tr = &c->tracks[slot];
    fw_cand_chunk(c, slot, 0);
    double out0 = band_out(&c->band, tr->east[0], tr->north[0]);
    for (int j = 0, k = 1; j < c->nchunks; j++) {
        fw_cand_chunk(c, slot, j);
        for (; k < c->ready[slot]; k++)
            if (band_out(&c->band, tr->east[k], tr->north[k]) - out0 > FW_BAND_SLACK_M)
                return true;
    }
    return band_out(&c->band, ahead(tr, tr->east), ahead(tr, tr->north)) - out0 >
           FW_BAND_SLACK_M;
}

/* Starts candidate (side, i) if this decision has not: mirrored from the
 * other side's when the start is symmetric and that one is started. */
fw_status fw_cand_open(fw_helm_ctx *c, int side, int i, int *slot, fw_error *err)
{
    int s = side == FW_SIDE_PORT ? 1 : 0;
    *slot = s * c->nh + i;
    if (c->have[*slot])
        return FW_OK;
    int other = (1 - s) * c->nh + i;
    fw_track *tr = &c->tracks[*slot];
    if (c->symmetric && c->have[other]) {
        c->src[*slot] = other;
        fw_track_mirror_range(&c->tracks[other], &c->own, tr, 0, 0); /* n, dt, helm */
    } else {
        fw_status st = fw_track_start_from(c->ship, &c->def.track, &c->own,
                                           fw_helm_value(c, side, i), tr, &c->gen[*slot],
                                           c->origin, err);
        if (st)
            return st;
        c->computed++;
    }
    fw_track_boxes_init(tr, &c->boxes[*slot]);
    c->have[*slot] = true;
    c->opened = true;
    return FW_OK;
}

/* fw_target_min2_cap of target i over chunk j of slot, that is INFINITY
 * when the box test misses: made here first, inlined. */
static inline double chunk_min2(fw_helm_ctx *c, int slot, int i, int j, double stop2,
                                double cap2)
{
    const fw_chunk_boxes *cb = &c->boxes[slot];
    const fw_prep_target *g = &c->prep[i];
    if (j < cb->nch && j * FW_CHUNK < cb->nseg &&
        fw_chunk_misses_in(c->def.track.dt, g, j, cb->nseg, cb->b[j]))
        return INFINITY;
    return fw_target_min2_cap(&c->def.domain, &c->tracks[slot], cb, g, j, j + 1, stop2, cap2);
}

/* A value v met for target i lowers the smallest so far (*best, met for
 * *lim): as chosen_clearance in helm_search.c finds it, the lowest index of
 * the targets that meet it (a value equal to the cap is tested exactly, so a
 * tie is seen). */
static inline void lower_to(double *best, int *lim, double v, int i)
{
    if (v < *best || (v == *best && i < *lim))
        *best = v, *lim = i;
}

/* Does some target come inside the domain (lambda^2 < stop2) along
 * candidate slot?  Chunk by chunk in time, the track predicted only as far as
 * the scan has come, so a failing candidate is predicted only up to its first
 * failure, noted in c->fail[slot] with the smallest value of that chunk in
 * c->ub2[slot] (>= the candidate's minimum).  Over the chunks each target's reach window holds:
 * the others are culled on every track.  The target that stops the scan goes
 * to the front of its chunk's list: neighbouring helms fail on the same one.
 * Returns that value, or (none below stop2) some value >= stop2. */
double fw_cand_fails(fw_helm_ctx *c, int slot, double stop2)
{
    for (int j = 0; j < c->nchunks; j++) {
        int na = c->nact[j], *a = c->act + (size_t)j * (size_t)c->cap;
        if (na == 0)
            continue;
        fw_cand_chunk(c, slot, j);
        for (int p = 0; p < na; p++) {
            /* values above stop2 do not matter */
            double m2 = chunk_min2(c, slot, a[p], j, stop2, stop2);
            if (m2 < stop2) {
                int i = a[p], lim = i;
                /* the rest of the chunk too, for the fallback: its bound is
                 * then the chunk's smallest value (the targets before gave
                 * none below stop2), and it goes on from the next chunk */
                for (int q = p + 1; q < na; q++) {
                    double v = chunk_min2(c, slot, a[q], j, 0.0, m2);
                    lower_to(&m2, &lim, v, a[q]);
                }
                memmove(a + 1, a, sizeof *a * (size_t)p);
                a[0] = i;
                c->fail[slot] = j;
                c->ub2[slot] = m2;
                c->lim[slot] = lim;
                return m2;
            }
        }
    }
    return INFINITY;
}

/* Scans slot on from where it was left (chunk next[slot], target nextp[slot]
 * in that chunk's list) until its bound ub2[slot] falls below `below` or
 * every chunk is scanned.  The smallest value found so far bounds the exact
 * tests, so ub2 is always a value met along the candidate, and once every
 * chunk is scanned its exact minimum (of what the reference search
 * computes, from the chunk after the failing one on; see fallback_cl). */
static void scan_on(fw_helm_ctx *c, int slot, double below)
{
    double best = c->ub2[slot];
    int j = c->next[slot], p = c->nextp[slot], lim = c->lim[slot];
    while (j < c->nchunks && !(best < below)) {
        int na = c->nact[j];
        const int *a = c->act + (size_t)j * (size_t)c->cap;
        if (p < na)
            fw_cand_chunk(c, slot, j);
        for (; p < na && !(best < below); p++) {
            double m2 = chunk_min2(c, slot, a[p], j, 0.0, best);
            lower_to(&best, &lim, m2, a[p]);
        }
        if (p >= na)
            j++, p = 0;
    }
    c->ub2[slot] = best;
    c->lim[slot] = lim;
    c->next[slot] = j;
    c->nextp[slot] = p;
}

/* Clearance of a candidate in the fallback, or a value below stop, scanning
 * on from where the fallback left it: every candidate failed the clearing
 * check at chunk fail[slot], all its earlier chunks keeping every target out
 * (lambda >= 1), so its minimum (below 1) lies from there on, and so does
 * anything below stop (< 1); ub2 starts at that chunk's smallest value.
 * Exact once every chunk is scanned. */
static double fallback_cl(fw_helm_ctx *c, int slot, double stop)
{
    scan_on(c, slot, stop * stop);
    return sqrt(c->ub2[slot]);
}

/* The reference search's branch and bound over the candidates ord[0..m-1]
 * in its order: the pick is the first whose clearance beats the best so far
 * by 1e-9, the best so far bounding each scan.  A candidate whose upper bound
 * (ub2) cannot beat it needs no scan.  With theta > 0 (at most the largest
 * clearance) the best starts out as "somewhere below theta": a candidate
 * below theta is then scanned only that far and skipped (whatever it did
 * there is overtaken by the first one above theta + 1e-9, which beats any
 * best below theta); one in [theta, theta + 1e-9) could go either way and
 * gives *pick = -1. */
static void replay(fw_helm_ctx *c, const int *ord, int m, double theta, int *pick)
{
    double best = -1.0;
    bool known = !(theta > 0.0);
    *pick = -1;
    for (int q = 0; q < m; q++) {
        int slot = ord[q];
        double bar = known ? best + 1e-9 : theta, ub = sqrt(c->ub2[slot]);
        if (ub < bar || (known && ub <= bar))
            continue; /* cannot beat it */
        double cl = fallback_cl(c, slot, known ? (best > 0.0 ? best : 0.0) : theta);
        if (!known) {
            if (cl < theta)
                continue;
            if (cl < theta + 1e-9) {
                *pick = -1;
                return;
            }
            known = true, best = cl, *pick = slot;
        } else if (cl > best + 1e-9) {
            best = cl, *pick = slot;
        }
    }
}

/* Max-heap of candidate slots by ub2 (ties: the first in the reference
 * order, pos[] gives it). */
static bool heap_above(const fw_helm_ctx *c, const int *pos, int a, int b)
{
    return c->ub2[a] > c->ub2[b] || (c->ub2[a] == c->ub2[b] && pos[a] < pos[b]);
}

static void heap_down(const fw_helm_ctx *c, const int *pos, int *h, int m, int q)
{
    for (;;) {
        int l = 2 * q + 1, r = l + 1, top = q;
        if (l < m && heap_above(c, pos, h[l], h[top]))
            top = l;
        if (r < m && heap_above(c, pos, h[r], h[top]))
            top = r;
        if (top == q)
            return;
        int t = h[q];
        h[q] = h[top], h[top] = t;
        q = top;
    }
}

/* Nothing clears: the helm that keeps the nearest target farthest out, as
 * the reference search picks it (its branch and bound over the candidates in
 * order, starboard then port by helm).  First the largest clearance, best
 * first: the candidate whose bound (the smallest value met along it) is
 * highest is scanned on until it is no longer the highest, until the highest
 * is one scanned to the end, exact, and so the largest.  Each candidate is then scanned (and
 * predicted) only until it falls below that.  Then the reference order is
 * replayed from just below it. */
fw_status fw_cand_best_available(fw_helm_ctx *c, int allowed, int *pick, int *side, fw_error *err)
{
    int *ord = c->ord, *heap = c->ord + 2 * c->nh, *pos = c->ord + 4 * c->nh, m = 0;
    static const int sides[2] = {FW_SIDE_STARBOARD, FW_SIDE_PORT};
    for (int s = 0; s < 2; s++)
        for (int i = 0; i < c->nh && (allowed & (s ? FW_ALLOW_PORT : FW_ALLOW_STARBOARD)); i++) {
            int slot;
            fw_status st = fw_cand_open(c, sides[s], i, &slot, err);
            if (st)
                return st;
            if (fw_cand_leaves_band(c, slot))
                continue;
            pos[slot] = m;
            ord[m] = heap[m] = slot;
            c->next[slot] = c->fail[slot] + 1; /* its chunk is done */
            c->nextp[slot] = 0;
            m++;
        }
    if (m == 0 && !(allowed & FW_ALLOW_EITHER))
        return fw_fail(err, FW_EINPUT, "helm search: no side allowed");
    if (m == 0) {
        *pick = -1, *side = 0; /* every candidate leaves the band */
        return FW_OK;
    }
    for (int q = m / 2 - 1; q >= 0; q--)
        heap_down(c, pos, heap, m, q);
    double M;
    for (;;) {
        int top = heap[0];
        if (c->next[top] >= c->nchunks) {
            M = sqrt(c->ub2[top]);
            break;
        }
        /* on until it is no longer the highest */
        double second = -1.0;
        for (int q = 1; q <= 2 && q < m; q++)
            second = c->ub2[heap[q]] > second ? c->ub2[heap[q]] : second;
        scan_on(c, top, second);
        heap_down(c, pos, heap, m, 0);
    }
    replay(c, ord, m, M - 1e-7, pick);
    if (*pick < 0)
        replay(c, ord, m, 0.0, pick);
    *side = *pick >= c->nh;
    *pick -= *side * c->nh;
    return FW_OK;
}

