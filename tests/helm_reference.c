/* helm_reference.c - see helm_reference.h. */
#include "helm_reference.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "avoid/clearance.h"
#include "core/mem.h"

struct fw_helm_ref {
    fw_helm_def def;
    int nh, cap;
    int *idx;
    short *jlo, *jhi;
    fw_prep_target *prep;
    double *paths;
    size_t paths_cap;
    fw_chunk_boxes *boxes; /* [side][nh], then keep */
    bool *have;
    fw_helm_band band;
};

void fw_helm_ref_set_band(fw_helm_ref *r, const fw_helm_band *band)
{
    r->band = band ? *band : (fw_helm_band){.on = false};
}

/* Does tr go more than FW_BAND_SLACK_M farther out of the band than its
 * first sample is?  Out: across the band's line beyond the room on a side
 * that has one. */
static bool leaves_band(const fw_helm_ref *r, const fw_track *tr)
{
    const fw_helm_band *b = &r->band;
    if (!b->on)
        return false;
    double to_stbd_e = cos(b->course), to_stbd_n = -sin(b->course), first = 0.0;
    for (int k = 0; k < tr->n; k++) {
        double x = (tr->east[k] - b->east) * to_stbd_e + (tr->north[k] - b->north) * to_stbd_n;
        double out = 0.0;
        if (b->room_starboard > 0.0 && x - b->room_starboard > out)
            out = x - b->room_starboard;
        if (b->room_port > 0.0 && -x - b->room_port > out)
            out = -x - b->room_port;
        if (k == 0)
            first = out;
        else if (out - first > FW_BAND_SLACK_M)
            return true;
    }
    if (tr->n < 2)
        return false;
    /* and the end, carried on FW_BAND_AHEAD_S by the last step's motion */
    int k = tr->n - 1;
    double f = FW_BAND_AHEAD_S / tr->dt;
    double e = tr->east[k] + (tr->east[k] - tr->east[k - 1]) * f;
    double n = tr->north[k] + (tr->north[k] - tr->north[k - 1]) * f;
    double x = (e - b->east) * to_stbd_e + (n - b->north) * to_stbd_n, out = 0.0;
    if (b->room_starboard > 0.0 && x - b->room_starboard > out)
        out = x - b->room_starboard;
    if (b->room_port > 0.0 && -x - b->room_port > out)
        out = -x - b->room_port;
    return out - first > FW_BAND_SLACK_M;
}

fw_status fw_helm_ref_create(const fw_helm_def *def, int nh, fw_helm_ref **out, fw_error *err)
{
    fw_helm_ref *r = calloc(1, sizeof *r);
    if (r) {
        r->boxes = calloc((size_t)(2 * nh + 1), sizeof *r->boxes);
        r->have = calloc((size_t)(2 * nh + 1), sizeof *r->have);
    }
    if (!r || !r->boxes || !r->have) {
        fw_helm_ref_destroy(r);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    r->def = *def;
    r->nh = nh;
    *out = r;
    return FW_OK;
}

void fw_helm_ref_destroy(fw_helm_ref *r)
{
    if (r)
        fw_free_each(8, r->idx, r->jlo, r->jhi, r->prep, r->paths, r->boxes, r->have, r);
}

/* The candidate (side s: 0 starboard, 1 port; i) or, with s = 2, the keep
 * track, and its chunk boxes, made once per search as the context did. */
static fw_status track_of(fw_helm_ref *r, fw_helm_ctx *c, int s, int i, const fw_track **tr,
                          const fw_chunk_boxes **cb, fw_error *err)
{
    int slot = s == 2 ? 2 * r->nh : s * r->nh + i;
    fw_status st = s == 2 ? fw_helm_keep_track(c, tr, err)
                          : fw_helm_track(c, s ? FW_SIDE_PORT : FW_SIDE_STARBOARD, i, tr, err);
    if (st)
        return st;
    if (!r->have[slot])
        fw_track_boxes(*tr, &r->boxes[slot]);
    r->have[slot] = true;
    *cb = &r->boxes[slot];
    return FW_OK;
}

static double clearance_idx(fw_helm_ref *r, const fw_track *tr, const fw_chunk_boxes *cb, int m,
                            bool windows, double stop_below)
{
    double best = INFINITY, stop2 = stop_below * stop_below;
    for (int p = 0; p < m; p++) {
        int i = r->idx[p];
        int j0 = windows ? r->jlo[i] : 0, j1 = windows ? r->jhi[i] : INT_MAX / FW_CHUNK;
        double m2 = fw_target_min2(&r->def.domain, tr, cb, &r->prep[i], j0, j1, stop2);
        if (m2 < best)
            best = m2;
        if (best < stop2) {
            memmove(r->idx + 1, r->idx, sizeof *r->idx * (size_t)p);
            r->idx[0] = i;
            break;
        }
    }
    return sqrt(best);
}

static void prune_targets(fw_helm_ref *r, int allowed, int *m)
{
    fw_chunk_boxes u;
    bool first = true;
    for (int s = 0; s < 2; s++) {
        if (!(allowed & (s ? FW_ALLOW_PORT : FW_ALLOW_STARBOARD)))
            continue;
        for (int i = 0; i < r->nh; i++) {
            const fw_chunk_boxes *cb = &r->boxes[s * r->nh + i];
            if (first)
                u = *cb;
            else
                fw_boxes_union(&u, cb);
            first = false;
        }
    }
    if (first || u.nch * FW_CHUNK < u.nseg) {
        /* no pruning: every chunk.  (f49b4df returned here with the windows
         * unset, holding the threat flags and earlier decisions' values: a
         * horizon beyond FW_MAX_CHUNKS chunks, 2560 s at 5 s, got a wrong
         * fallback; fixed here, the search never had it since) */
        for (int p = 0; p < *m; p++)
            r->jlo[r->idx[p]] = 0, r->jhi[r->idx[p]] = SHRT_MAX;
        return;
    }
    int kept = 0;
    for (int p = 0; p < *m; p++) {
        int i = r->idx[p], lo = -1, hi = -1;
        for (int j = 0; j < u.nch; j++)
            if (!fw_chunk_misses(r->def.track.dt, &r->prep[i], j, u.nseg, u.b[j])) {
                if (lo < 0)
                    lo = j;
                hi = j + 1;
            }
        if (lo < 0)
            continue;
        r->jlo[i] = (short)lo;
        r->jhi[i] = (short)hi;
        r->idx[kept++] = i;
    }
    *m = kept;
}

static fw_status prepare(fw_helm_ref *r, const fw_target *t, int n, fw_error *err)
{
    if (n > r->cap) {
        if (!fw_resize_each((size_t)n, 4, (void **)&r->idx, sizeof *r->idx, (void **)&r->jlo,
                            sizeof *r->jlo, (void **)&r->jhi, sizeof *r->jhi,
                            (void **)&r->prep, sizeof *r->prep))
            return fw_fail(err, FW_ERUN, "out of memory for %d targets", n);
        r->cap = n;
    }
    size_t npred = 0, len = (size_t)fw_prep_path_len(&r->def.track);
    for (int i = 0; i < n; i++)
        npred += t[i].pred != NULL;
    if (npred * len > r->paths_cap) {
        if (!fw_resize((void **)&r->paths, sizeof *r->paths, npred * len))
            return fw_fail(err, FW_ERUN, "out of memory for %zu predicted paths", npred);
        r->paths_cap = npred * len;
    }
    fw_prep_targets(&r->def.domain, &r->def.track, t, n, r->prep, r->paths);
    for (int i = 0; i < 2 * r->nh + 1; i++)
        r->have[i] = false;
    return FW_OK;
}

/* The fallback: the helm whose nearest target is farthest out, of those
 * that keep within the band (*pick stays -1 if none does). */
static fw_status best_available(fw_helm_ref *r, fw_helm_ctx *c, int n, int allowed, int *pick,
                                int *side, fw_error *err)
{
    int m = n;
    prune_targets(r, allowed, &m);
    double best = -1.0;
    for (int s = 0; s < 2; s++) {
        if (!(allowed & (s ? FW_ALLOW_PORT : FW_ALLOW_STARBOARD)))
            continue;
        for (int i = 0; i < r->nh; i++) {
            const fw_track *tr;
            const fw_chunk_boxes *cb;
            fw_status st = track_of(r, c, s, i, &tr, &cb, err);
            if (st)
                return st;
            if (leaves_band(r, tr))
                continue;
            double cl = clearance_idx(r, tr, cb, m, true, best > 0.0 ? best : 0.0);
            if (cl > best + 1e-9)
                best = cl, *pick = i, *side = s;
        }
    }
    return FW_OK;
}

fw_status fw_helm_search_reference(fw_helm_ref *r, fw_helm_ctx *c, const fw_target *t, int n,
                                   int allowed, fw_helm_result *res, fw_error *err)
{
    const fw_track *tr;
    const fw_chunk_boxes *kb, *cb;
    fw_status st = prepare(r, t, n, err);
    if (st || (st = track_of(r, c, 2, 0, &tr, &kb, err)))
        return st;
    res->allowed = allowed;
    res->side_helm[0] = res->side_helm[1] = NAN;
    res->feasible = true;
    res->band_left = false;
    res->side = FW_SIDE_NONE;
    res->helm = 0.0;
    double kbest = INFINITY;
    int nthreat = 0;
    res->limiting = -1;
    for (int i = 0; i < n; i++) {
        double m2 = fw_target_min2(&r->def.domain, tr, kb, &r->prep[i], 0, INT_MAX / FW_CHUNK, 0.0);
        if (m2 < kbest)
            kbest = m2, res->limiting = i;
        r->jlo[i] = m2 < 1.0;
        nthreat += m2 < 1.0;
    }
    for (int i = 0, a = 0, b = nthreat; i < n; i++)
        r->idx[r->jlo[i] ? a++ : b++] = i;
    res->keep_clearance = sqrt(kbest);
    res->threat = res->keep_clearance < 1.0;
    res->clearance = res->keep_clearance;
    if (!res->threat)
        return FW_OK;
    static const int sides[2] = {FW_SIDE_STARBOARD, FW_SIDE_PORT};
    int found[2] = {-1, -1};
    for (int s = 0; s < 2; s++) {
        if (!(allowed & (s ? FW_ALLOW_PORT : FW_ALLOW_STARBOARD)))
            continue;
        for (int i = 0; i < r->nh; i++) {
            if ((st = track_of(r, c, s, i, &tr, &cb, err)))
                return st;
            if (clearance_idx(r, tr, cb, n, false, 1.0) >= 1.0 && !leaves_band(r, tr)) {
                found[s] = i;
                res->side_helm[s] = fw_helm_value(c, sides[s], i);
                break;
            }
            if (s == 1 && found[0] >= 0 && i >= found[0])
                break;
        }
    }
    int pick = -1, side = -1;
    if (found[0] >= 0 && (found[1] < 0 || found[0] <= found[1]))
        pick = found[0], side = 0;
    else if (found[1] >= 0)
        pick = found[1], side = 1;
    if (pick < 0) {
        res->feasible = false;
        if ((st = best_available(r, c, n, allowed, &pick, &side, err)))
            return st;
        if (pick < 0) {
            res->band_left = true;
            return FW_OK;
        }
    }
    res->side = sides[side];
    res->helm = fw_helm_value(c, sides[side], pick);
    if ((st = fw_helm_track(c, sides[side], pick, &tr, err)))
        return st;
    res->clearance = fw_track_clearance(&r->def, tr, t, n, 0.0, &res->limiting);
    return FW_OK;
}
