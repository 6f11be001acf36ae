#include "avoid/helm_search.h"

#include "avoid/clearance.h"
#include "core/mem.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/units.h"

struct fw_helm_ctx {
    const fw_ship *ship;
    fw_helm_def def;
    fw_own_state own;
    bool symmetric;  /* start on a straight course with the rudder amidships */
    int nh;
    fw_track *tracks; /* [side 0 = starboard, 1 = port][nh], then keep, then spare */
    bool *have;
    bool have_keep;
    int computed;
    /* per-decision scratch over the targets (grown on demand): the order in
     * which targets are checked, and each one's window of chunks that can
     * reach the domain of any candidate track */
    int cap;
    int *idx;
    short *jlo, *jhi;
    fw_prep_target *prep;
    double *paths;         /* the predicted targets' paths (clearance.h) */
    size_t paths_cap;      /* doubles */
    fw_chunk_boxes *boxes; /* per track slot, made with the track */
};

const char *fw_side_name(int side)
{
    return side == FW_SIDE_STARBOARD ? "starboard" : side == FW_SIDE_PORT ? "port" : "none";
}

fw_helm_def fw_default_helm_def(void)
{
    return (fw_helm_def){.min_helm_deg = 10.0,
                         .max_helm_deg = 35.0,
                         .step_deg = 1.0,
                         .overtake_side = 0,
                         .domain = fw_default_domain_def(),
                         .colregs = fw_default_colregs_def(),
                         .track = fw_default_track_def()};
}

void fw_helm_ctx_destroy(fw_helm_ctx *c)
{
    if (!c)
        return;
    if (c->tracks)
        for (int i = 0; i < 2 * c->nh + 2; i++)
            fw_track_free(&c->tracks[i]);
    fw_free_each(9, c->tracks, c->have, c->idx, c->jlo, c->jhi, c->prep, c->paths, c->boxes, c);
}

fw_status fw_helm_ctx_create(const fw_ship *ship, const fw_helm_def *def, fw_helm_ctx **out,
                             fw_error *err)
{
    *out = NULL;
    if (!(def->step_deg > 0.0) || !(def->min_helm_deg > 0.0) ||
        def->max_helm_deg < def->min_helm_deg)
        return fw_fail(err, FW_EINPUT, "helm search: need 0 < min_helm <= max_helm, step > 0");
    if (!(def->track.dt > 0.0) || !(def->track.horizon >= def->track.dt))
        return fw_fail(err, FW_EINPUT, "helm search: need 0 < dt <= horizon");
    if (!(def->domain.size > 0.0) || !(def->domain.fore_aft_ratio > 0.0))
        return fw_fail(err, FW_EINPUT, "helm search: the domain needs positive axes");
    if (!ship->nomoto.present)
        return fw_fail(err, FW_EINPUT,
                       "ship '%s' has no Nomoto knowledge base (nomoto:), which the avoidance "
                       "predicts its tracks with: make one with 'fairway identify --ship %s "
                       "--out FILE' and use FILE as the ship",
                       ship->name, ship->name);
    fw_helm_ctx *c = calloc(1, sizeof *c);
    if (!c)
        return fw_fail(err, FW_ERUN, "out of memory");
    c->ship = ship;
    c->def = *def;
    c->nh = (int)floor((def->max_helm_deg - def->min_helm_deg) / def->step_deg + 1e-9) + 1;
    int ntr = 2 * c->nh + 2;
    c->tracks = calloc((size_t)ntr, sizeof *c->tracks);
    c->have = calloc((size_t)(2 * c->nh), sizeof *c->have);
    c->boxes = calloc((size_t)ntr, sizeof *c->boxes);
    if (!c->tracks || !c->have || !c->boxes) {
        fw_helm_ctx_destroy(c);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    int ns = fw_track_samples(&def->track);
    for (int i = 0; i < ntr; i++) {
        fw_status st = fw_track_alloc(&c->tracks[i], ns, err);
        if (st) {
            fw_helm_ctx_destroy(c);
            return st;
        }
    }
    *out = c;
    return FW_OK;
}

void fw_helm_begin(fw_helm_ctx *c, const fw_own_state *own)
{
    c->own = *own;
    /* a port knowledge base of its own breaks the mirror image */
    c->symmetric = own->r == 0.0 && own->rdot == 0.0 && own->delta == 0.0 && own->beta == 0.0 &&
                   !c->ship->nomoto_port.present;
    for (int i = 0; i < 2 * c->nh; i++)
        c->have[i] = false;
    c->have_keep = false;
    c->computed = 0;
}

int fw_helm_count(const fw_helm_ctx *c) { return c->nh; }

double fw_helm_value(const fw_helm_ctx *c, int side, int i)
{
    double deg = c->def.min_helm_deg + i * c->def.step_deg;
    if (deg > c->def.max_helm_deg)
        deg = c->def.max_helm_deg;
    return (side == FW_SIDE_PORT ? -1.0 : 1.0) * fw_deg_to_rad(deg);
}

int fw_helm_tracks_computed(const fw_helm_ctx *c) { return c->computed; }

fw_status fw_helm_track(fw_helm_ctx *c, int side, int i, const fw_track **tr, fw_error *err)
{
    int s = side == FW_SIDE_PORT ? 1 : 0;
    int slot = s * c->nh + i;
    if (!c->have[slot]) {
        int other = (1 - s) * c->nh + i;
        if (c->symmetric && c->have[other]) {
            fw_track_mirror(&c->tracks[other], &c->own, &c->tracks[slot]);
        } else {
            fw_status st = fw_track_predict(c->ship, &c->def.track, &c->own,
                                            fw_helm_value(c, side, i), &c->tracks[slot], err);
            if (st)
                return st;
            c->computed++;
        }
        fw_track_boxes(&c->tracks[slot], &c->boxes[slot]);
        c->have[slot] = true;
    }
    *tr = &c->tracks[slot];
    return FW_OK;
}

fw_status fw_helm_keep_track(fw_helm_ctx *c, const fw_track **tr, fw_error *err)
{
    fw_track *k = &c->tracks[2 * c->nh];
    if (!c->have_keep) {
        fw_status st = fw_track_predict(c->ship, &c->def.track, &c->own, 0.0, k, err);
        if (st)
            return st;
        fw_track_boxes(k, &c->boxes[2 * c->nh]);
        c->have_keep = true;
        c->computed++;
    }
    *tr = k;
    return FW_OK;
}

fw_status fw_helm_precompute(fw_helm_ctx *c, fw_error *err)
{
    const fw_track *tr;
    fw_status st = fw_helm_keep_track(c, &tr, err);
    for (int s = 0; s < 2 && !st; s++)
        for (int i = 0; i < c->nh && !st; i++)
            st = fw_helm_track(c, s ? FW_SIDE_PORT : FW_SIDE_STARBOARD, i, &tr, err);
    return st;
}

/* Clearance of a candidate track over the prepared targets c->idx[0..m-1] in
 * that order (each within its chunk window if windows is set).  A target that
 * stops the scan is moved to the front: neighbouring helms fail on the same
 * target, so the next track finds it first. */
static double clearance_idx(fw_helm_ctx *c, const fw_track *tr, int m, bool windows,
                            double stop_below)
{
    const fw_chunk_boxes *cb = &c->boxes[tr - c->tracks];
    double best = INFINITY, stop2 = stop_below * stop_below;
    for (int p = 0; p < m; p++) {
        int i = c->idx[p];
        int j0 = windows ? c->jlo[i] : 0, j1 = windows ? c->jhi[i] : INT_MAX / FW_CHUNK;
        double m2 = fw_target_min2(&c->def.domain, tr, cb, &c->prep[i], j0, j1, stop2);
        if (m2 < best)
            best = m2;
        if (best < stop2) {
            memmove(c->idx + 1, c->idx, sizeof *c->idx * (size_t)p);
            c->idx[0] = i;
            break;
        }
    }
    return sqrt(best);
}

/* A path buffer for one predicted target: on the stack when it fits (the
 * default 600 s horizon at 5 s needs 484 doubles), else on the heap. */
enum { PATH_STACK = 2048 };

static double *path_buffer(const fw_track_def *tdef, double *stack)
{
    size_t len = (size_t)fw_prep_path_len(tdef);
    return len <= PATH_STACK ? stack : malloc(sizeof(double) * len);
}

double fw_track_clearance(const fw_helm_def *def, const fw_track *tr, const fw_target *t, int n,
                          double stop_below, int *limiting)
{
    fw_chunk_boxes cb;
    fw_track_boxes(tr, &cb);
    double best = INFINITY, stop2 = stop_below * stop_below, stack[PATH_STACK];
    int lim = -1;
    for (int i = 0; i < n; i++) {
        fw_prep_target g;
        double *path = t[i].pred ? path_buffer(&def->track, stack) : NULL;
        if (t[i].pred && !path) {
            /* no memory for its path: counted as inside, the safe verdict */
            best = 0.0, lim = i;
            break;
        }
        fw_prep_targets(&def->domain, &def->track, &t[i], 1, &g, path);
        double m2 = fw_target_min2(&def->domain, tr, &cb, &g, 0, INT_MAX / FW_CHUNK, stop2);
        if (path != stack)
            free(path);
        if (m2 < best) {
            best = m2;
            lim = i;
        }
        if (best < stop2)
            break;
    }
    if (limiting)
        *limiting = lim;
    return sqrt(best);
}

double fw_track_min_distance(const fw_track *tr, const fw_target *t, double *t_min)
{
    /* the target prepared over the track's own samples */
    fw_track_def tdef = {.dt = tr->dt, .horizon = (tr->n - 1) * tr->dt};
    fw_domain_def dom = fw_default_domain_def();
    double stack[PATH_STACK], *path = t->pred ? path_buffer(&tdef, stack) : NULL;
    fw_prep_target g;
    fw_prep_targets(&dom, &tdef, t, 1, &g, path);
    double best = INFINITY, tb = 0.0, px = 0.0, py = 0.0;
    for (int k = 0; k < tr->n; k++) {
        double tk = k * tr->dt, ge, gn;
        fw_prep_at(&g, k, tk, &ge, &gn);
        double dx = ge - tr->east[k], dy = gn - tr->north[k];
        if (k > 0) {
            double ex = dx - px, ey = dy - py, q = ex * ex + ey * ey;
            double s = q > 0.0 ? -(px * ex + py * ey) / q : 0.0;
            s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
            double d = hypot(px + s * ex, py + s * ey);
            if (d < best) {
                best = d;
                tb = (k - 1 + s) * tr->dt;
            }
        } else {
            best = hypot(dx, dy);
        }
        px = dx, py = dy;
    }
    if (path != stack)
        free(path);
    if (t_min)
        *t_min = tb;
    return best;
}

int fw_permitted_sides(const fw_helm_def *def, const fw_assessment *as, int n)
{
    int allowed = FW_ALLOW_EITHER;
    for (int i = 0; i < n; i++) {
        if (!as[i].enters_domain)
            continue;
        switch (as[i].situation) {
        case FW_SIT_HEAD_ON:
        case FW_SIT_GIVE_WAY:
            allowed &= FW_ALLOW_STARBOARD;
            break;
        case FW_SIT_OVERTAKING:
            if (def->overtake_side == FW_SIDE_STARBOARD)
                allowed &= FW_ALLOW_STARBOARD;
            else if (def->overtake_side == FW_SIDE_PORT)
                allowed &= FW_ALLOW_PORT;
            break;
        case FW_SIT_STAND_ON:
        case FW_SIT_OVERTAKEN:
            if (as[i].rel_bearing >= FW_PI) /* target on the own port side */
                allowed &= FW_ALLOW_STARBOARD;
            break;
        }
    }
    /* a port-only overtaking against a starboard-only threat: the rules for the
     * other threats win; starboard is never forbidden by them */
    return allowed ? allowed : FW_ALLOW_STARBOARD;
}

static fw_status ensure_scratch(fw_helm_ctx *c, int n, fw_error *err)
{
    if (n <= c->cap)
        return FW_OK;
    if (!fw_resize_each((size_t)n, 4, (void **)&c->idx, sizeof *c->idx,
                        (void **)&c->jlo, sizeof *c->jlo, (void **)&c->jhi, sizeof *c->jhi,
                        (void **)&c->prep, sizeof *c->prep))
        return fw_fail(err, FW_ERUN, "out of memory for %d targets", n);
    c->cap = n;
    return FW_OK;
}

/* Keeps in idx[0..*m-1] only the targets that can reach the domain of some
 * candidate track (those of the allowed sides, all computed by now), each
 * with its window of such chunks.  The test is the per-chunk culling test
 * against the union of the candidates' chunk boxes, so a dropped target would
 * have been culled on every candidate (its clearance is >= 1 on all of them)
 * and each window holds every chunk not culled on some candidate. */
static void prune_targets(fw_helm_ctx *c, int allowed, int *m)
{
    fw_chunk_boxes u;
    bool first = true;
    for (int s = 0; s < 2; s++) {
        if (!(allowed & (s ? FW_ALLOW_PORT : FW_ALLOW_STARBOARD)))
            continue;
        for (int i = 0; i < c->nh; i++) {
            const fw_chunk_boxes *cb = &c->boxes[s * c->nh + i];
            if (first)
                u = *cb;
            else
                fw_boxes_union(&u, cb);
            first = false;
        }
    }
    if (first || u.nch * FW_CHUNK < u.nseg)
        return; /* chunks without boxes: no pruning */
    int kept = 0;
    for (int p = 0; p < *m; p++) {
        int i = c->idx[p], lo = -1, hi = -1;
        for (int j = 0; j < u.nch; j++)
            if (!fw_chunk_misses(c->def.track.dt, &c->prep[i], j, u.nseg, u.b[j])) {
                if (lo < 0)
                    lo = j;
                hi = j + 1;
            }
        if (lo < 0)
            continue;
        c->jlo[i] = (short)lo;
        c->jhi[i] = (short)hi;
        c->idx[kept++] = i;
    }
    *m = kept;
}

fw_status fw_helm_search(fw_helm_ctx *c, const fw_target *t, int n, int allowed,
                         fw_helm_result *res, fw_error *err)
{
    const fw_track *tr;
    fw_status st = fw_helm_keep_track(c, &tr, err);
    if (st || (st = ensure_scratch(c, n, err)))
        return st;
    res->allowed = allowed;
    res->side_helm[0] = res->side_helm[1] = NAN;
    res->feasible = true;
    res->side = FW_SIDE_NONE;
    res->helm = 0.0;
    /* keep course, target by target: the threats (inside the domain on the
     * keep track) are checked first on the candidates, the likeliest to fail */
    size_t npred = 0, len = (size_t)fw_prep_path_len(&c->def.track);
    for (int i = 0; i < n; i++)
        npred += t[i].pred != NULL;
    if (npred * len > c->paths_cap) {
        if (!fw_resize((void **)&c->paths, sizeof *c->paths, npred * len))
            return fw_fail(err, FW_ERUN, "out of memory for %zu predicted paths", npred);
        c->paths_cap = npred * len;
    }
    fw_prep_targets(&c->def.domain, &c->def.track, t, n, c->prep, c->paths);
    const fw_chunk_boxes *kb = &c->boxes[2 * c->nh];
    double kbest = INFINITY;
    int nthreat = 0;
    res->limiting = -1;
    for (int i = 0; i < n; i++) {
        double m2 = fw_target_min2(&c->def.domain, tr, kb, &c->prep[i], 0, INT_MAX / FW_CHUNK, 0.0);
        if (m2 < kbest)
            kbest = m2, res->limiting = i;
        c->jlo[i] = m2 < 1.0; /* scratch: threat flag, the windows come later */
        nthreat += m2 < 1.0;
    }
    for (int i = 0, a = 0, b = nthreat; i < n; i++)
        c->idx[c->jlo[i] ? a++ : b++] = i;
    res->keep_clearance = sqrt(kbest);
    res->threat = res->keep_clearance < 1.0;
    res->clearance = res->keep_clearance;
    if (!res->threat)
        return FW_OK;
    static const int sides[2] = {FW_SIDE_STARBOARD, FW_SIDE_PORT};
    static const int masks[2] = {FW_ALLOW_STARBOARD, FW_ALLOW_PORT};
    int found[2] = {-1, -1};
    for (int s = 0; s < 2; s++) {
        if (!(allowed & masks[s]))
            continue;
        for (int i = 0; i < c->nh; i++) {
            if ((st = fw_helm_track(c, sides[s], i, &tr, err)))
                return st;
            if (clearance_idx(c, tr, n, false, 1.0) >= 1.0) {
                found[s] = i;
                res->side_helm[s] = fw_helm_value(c, sides[s], i);
                break;
            }
            /* the other side already cleared with less helm: no need to go on */
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
        /* nothing clears: the helm that keeps the nearest target farthest out.
         * Every candidate track exists now; only the targets that can reach
         * some candidate's domain can be the nearest (all nearest are < 1). */
        res->feasible = false;
        int m = n;
        prune_targets(c, allowed, &m);
        double best = -1.0;
        for (int s = 0; s < 2; s++) {
            if (!(allowed & masks[s]))
                continue;
            for (int i = 0; i < c->nh; i++) {
                if ((st = fw_helm_track(c, sides[s], i, &tr, err)))
                    return st;
                /* branch and bound: a track is abandoned as soon as some
                 * target comes closer than the best track's nearest one; the
                 * target that did it is tried first on the next track */
                double cl = clearance_idx(c, tr, m, true, best > 0.0 ? best : 0.0);
                if (cl > best + 1e-9)
                    best = cl, pick = i, side = s;
            }
        }
    }
    res->side = sides[side];
    res->helm = fw_helm_value(c, sides[side], pick);
    if ((st = fw_helm_track(c, sides[side], pick, &tr, err)))
        return st;
    res->clearance = fw_track_clearance(&c->def, tr, t, n, 0.0, &res->limiting);
    return FW_OK;
}

fw_status fw_helm_clears_after(fw_helm_ctx *c, const fw_target *t, int n, double helm,
                               double delay, bool *clears, fw_error *err)
{
    fw_track_def d = c->def.track;
    d.delay = delay;
    fw_track *spare = &c->tracks[2 * c->nh + 1];
    fw_status st = fw_track_predict(c->ship, &d, &c->own, helm, spare, err);
    if (st)
        return st;
    c->computed++;
    *clears = fw_track_clearance(&c->def, spare, t, n, 1.0, NULL) >= 1.0;
    return FW_OK;
}

/* Where target t is at the last sample k of a track and how it moves on from
 * there: its predictor's path (velocity from the last two samples) or
 * constant velocity. */
static void target_at_end(const fw_helm_ctx *c, const fw_target *t, int k, double *e, double *n,
                          double *ve, double *vn)
{
    double T = k * c->def.track.dt;
    fw_velocity(t->speed, t->course, ve, vn);
    *e = t->east + *ve * T;
    *n = t->north + *vn * T;
    double stack[PATH_STACK], *path = t->pred && k > 0 ? path_buffer(&c->def.track, stack) : NULL;
    if (!path)
        return;
    int ns = fw_prep_path_len(&c->def.track) / 4;
    fw_target_path(t, c->def.track.dt, ns, path, path + ns, path + 2 * ns);
    *e = path[k];
    *n = path[ns + k];
    *ve = (path[k] - path[k - 1]) / c->def.track.dt;
    *vn = (path[ns + k] - path[ns + k - 1]) / c->def.track.dt;
    if (path != stack)
        free(path);
}

/* The closest approach of every target after the track's end, the own ship
 * going on at its straight-course speed on the last heading. */
static double beyond_horizon(const fw_helm_ctx *c, const fw_track *tr, const fw_target *t, int n)
{
    int k = tr->n - 1;
    double U = c->own.U0 > 0.0 ? c->own.U0 : c->own.U, cl = INFINITY;
    double oe = U * tr->sin_psi[k], on = U * tr->cos_psi[k];
    for (int i = 0; i < n; i++) {
        double te, tn, ve, vn;
        target_at_end(c, &t[i], k, &te, &tn, &ve, &vn);
        double rx = te - tr->east[k], ry = tn - tr->north[k];
        double wx = ve - oe, wy = vn - on, tc, dc;
        fw_cpa(rx, ry, wx, wy, &tc, &dc);
        if (tc <= 0.0)
            continue; /* opening from there on */
        fw_target at = t[i];
        at.east = rx + wx * tc, at.north = ry + wy * tc;
        cl = fmin(cl, fw_domain_lambda(&c->def.domain, 0.0, 0.0, tr->psi[k], &at));
    }
    return cl;
}

fw_status fw_helm_steer_clearance(fw_helm_ctx *c, const fw_target *t, int n,
                                  const fw_steer_def *ap, bool beyond, double *clearance,
                                  fw_error *err)
{
    fw_track *tr = &c->tracks[2 * c->nh + 1];
    fw_status st = fw_track_predict_steer(c->ship, &c->def.track, &c->own, ap, tr, err);
    if (st)
        return st;
    c->computed++;
    double cl = fw_track_clearance(&c->def, tr, t, n, 0.0, NULL);
    if (beyond && tr->n > 0)
        cl = fmin(cl, beyond_horizon(c, tr, t, n));
    *clearance = cl;
    return FW_OK;
}
