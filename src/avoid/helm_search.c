#include "avoid/helm_search.h"

#include "avoid/helm_ctx.h"
#include "core/mem.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/units.h"

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
    fw_free_each(23, c->tracks, c->have, c->gen, c->ready, c->nbox, c->src, c->fail, c->ub2,
                 c->lim, c->next, c->nextp, c->ord, c->boxes, c->idx, c->jlo, c->jhi, c->act,
                 c->nact, c->prep, c->memo, c->paths, c->pbox, c);
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
    int ntr = 2 * c->nh + 2, ns = fw_track_samples(&def->track);
    c->nchunks = (ns - 1 + FW_CHUNK - 1) / FW_CHUNK;
    c->opened = true; /* the first fw_helm_begin sets every slot up */
    c->tracks = calloc((size_t)ntr, sizeof *c->tracks);
    c->have = calloc((size_t)(2 * c->nh), sizeof *c->have);
    c->boxes = calloc((size_t)ntr, sizeof *c->boxes);
    c->gen = calloc((size_t)ntr, sizeof *c->gen);
    c->ready = calloc((size_t)ntr, sizeof *c->ready);
    c->nbox = calloc((size_t)ntr, sizeof *c->nbox);
    c->src = calloc((size_t)ntr, sizeof *c->src);
    c->fail = calloc((size_t)ntr, sizeof *c->fail);
    c->ub2 = calloc((size_t)ntr, sizeof *c->ub2);
    c->lim = calloc((size_t)ntr, sizeof *c->lim);
    c->next = calloc((size_t)ntr, sizeof *c->next);
    c->nextp = calloc((size_t)ntr, sizeof *c->nextp);
    c->ord = calloc((size_t)(6 * c->nh), sizeof *c->ord);
    c->nact = calloc((size_t)c->nchunks, sizeof *c->nact);
    if (!c->tracks || !c->have || !c->boxes || !c->gen || !c->ready || !c->nbox || !c->src ||
        !c->fail || !c->ub2 || !c->lim || !c->next || !c->nextp || !c->ord || !c->nact) {
        fw_helm_ctx_destroy(c);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
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

/* The fastest any candidate track can go over ground (kin_step in track.c):
 * the speed through the water relaxes from U towards U0 (1 - loss), which is
 * at most U0 while the loss terms are not negative; a knowledge base with a
 * negative one (a propeller that gains thrust in the turn) gives no bound.
 * A current the ship knows adds its speed (the track is carried by it,
 * track.h); in calm water the bound is the calm one to the bit. */
static double speed_bound(const fw_ship *ship, const fw_own_state *s)
{
    const fw_nomoto_kb *kb[2] = {&ship->nomoto, &ship->nomoto_port};
    for (int i = 0; i < 2; i++)
        if ((i == 0 || kb[i]->present) &&
            (kb[i]->speed_loss < 0.0 || kb[i]->speed_loss_drift < 0.0))
            return -1.0;
    double U = s->U > 0.0 ? s->U : 0.0, U0 = s->U0 > 0.0 ? s->U0 : U;
    double bound = U > U0 ? U : U0;
    if (s->cur_e != 0.0 || s->cur_n != 0.0)
        bound += hypot(s->cur_e, s->cur_n);
    return bound;
}

void fw_helm_begin(fw_helm_ctx *c, const fw_own_state *own)
{
    c->own = *own;
    /* a port knowledge base of its own breaks the mirror image, and so does
     * a current (its drift is not mirrored with the turn; one along the
     * heading would keep it, but is not worth a case) */
    c->symmetric = own->r == 0.0 && own->rdot == 0.0 && own->delta == 0.0 && own->beta == 0.0 &&
                   own->cur_e == 0.0 && own->cur_n == 0.0 && !c->ship->nomoto_port.present;
    /* the candidates' slots as new only when some was opened (a decision
     * with a threat): else only the keep slot has changed */
    for (int i = 0; i < 2 * c->nh && c->opened; i++)
        c->have[i] = false;
    for (int i = c->opened ? 0 : 2 * c->nh; i <= 2 * c->nh; i++)
        c->ready[i] = c->nbox[i] = c->fail[i] = 0, c->src[i] = -1, c->ub2[i] = INFINITY;
    c->opened = false;
    c->have_keep = false;
    c->origin[0].valid = c->origin[1].valid = false;
    c->prep_t = NULL;
    c->computed = 0;
    c->samples = 0;
    c->umax = speed_bound(c->ship, own);
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

double fw_helm_tracks_predicted(const fw_helm_ctx *c)
{
    return (double)c->samples / c->tracks[0].cap;
}

fw_status fw_helm_track(fw_helm_ctx *c, int side, int i, const fw_track **tr, fw_error *err)
{
    int slot;
    fw_status st = fw_cand_open(c, side, i, &slot, err);
    if (st)
        return st;
    fw_cand_chunk(c, slot, c->nchunks - 1);
    *tr = &c->tracks[slot];
    return FW_OK;
}

fw_status fw_helm_keep_track(fw_helm_ctx *c, const fw_track **tr, fw_error *err)
{
    int slot = 2 * c->nh;
    fw_track *k = &c->tracks[slot];
    if (!c->have_keep) {
        fw_status st = fw_track_start_from(c->ship, &c->def.track, &c->own, 0.0, k,
                                           &c->gen[slot], c->origin, err);
        if (st)
            return st;
        fw_track_boxes_init(k, &c->boxes[slot]);
        fw_cand_chunk(c, slot, c->nchunks - 1);
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

int fw_rule19_sides(const fw_assessment *a)
{
    double rb = a->rel_bearing; /* [0, 2 pi), clockwise from the bow */
    bool forward = rb < 0.5 * FW_PI || rb > 1.5 * FW_PI;
    if (forward)
        return a->situation == FW_SIT_OVERTAKING ? FW_ALLOW_EITHER : FW_ALLOW_STARBOARD;
    return rb <= FW_PI ? FW_ALLOW_PORT : FW_ALLOW_STARBOARD;
}

int fw_permitted_sides(const fw_helm_def *def, const fw_assessment *as, int n)
{
    int allowed = FW_ALLOW_EITHER;
    for (int i = 0; i < n; i++) {
        if (!as[i].enters_domain)
            continue;
        if (as[i].rule19) {
            allowed &= fw_rule19_sides(&as[i]);
            continue;
        }
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

static fw_status ensure_scratch(fw_helm_ctx *c, const fw_target *t, int n, fw_error *err)
{
    if (n > c->cap) {
        if (!fw_resize_each((size_t)n, 5, (void **)&c->idx, sizeof *c->idx, (void **)&c->jlo,
                            sizeof *c->jlo, (void **)&c->jhi, sizeof *c->jhi, (void **)&c->prep,
                            sizeof *c->prep, (void **)&c->memo, sizeof *c->memo) ||
            !fw_resize((void **)&c->act, sizeof *c->act, (size_t)n * (size_t)c->nchunks) ||
            !fw_resize((void **)&c->pbox, sizeof *c->pbox,
                       (size_t)n * (size_t)fw_prep_box_len(fw_track_samples(&c->def.track) - 1)))
            return fw_fail(err, FW_ERUN, "out of memory for %d targets", n);
        for (int i = c->cap; i < n; i++)
            c->memo[i].valid = false; /* the new slots (the old ones are kept) */
        c->cap = n;
    }
    size_t npred = 0, len = (size_t)fw_prep_path_len(&c->def.track);
    for (int i = 0; i < n; i++)
        npred += t[i].pred != NULL;
    if (npred * len > c->paths_cap) {
        if (!fw_resize((void **)&c->paths, sizeof *c->paths, npred * len))
            return fw_fail(err, FW_ERUN, "out of memory for %zu predicted paths", npred);
        c->paths_cap = npred * len;
    }
    return FW_OK;
}

/* The targets prepared, their reach windows, the keep-course check (its
 * clearance, the limiting target, the threats: inside the domain on the keep
 * track) and the check order, threats first (the likeliest to fail), in each
 * chunk's list of the targets whose window holds it. */
static void keep_check(fw_helm_ctx *c, const fw_track *keep, const fw_target *t, int n,
                       fw_helm_result *res)
{
    fw_prep_targets_memo(&c->def.domain, &c->def.track, t, n, c->prep, c->paths, c->memo);
    const fw_chunk_boxes *kb = &c->boxes[2 * c->nh];
    double kbest = INFINITY;
    int nthreat = 0, *threat = c->act; /* scratch: the lists are made after */
    res->limiting = -1;
    size_t blen = (size_t)fw_prep_box_len(kb->nseg);
    for (int i = 0; i < n; i++) {
        fw_prep_reach(c->def.track.dt, &c->prep[i], kb->nseg, c->own.east, c->own.north,
                      c->umax, c->pbox + (size_t)i * blen, &c->jlo[i], &c->jhi[i]);
        /* what matters: below 1 (a threat) and below the smallest yet; an
         * empty window (most targets) is the call's INFINITY without it */
        double m2 = c->jlo[i] >= c->jhi[i]
                        ? INFINITY
                        : fw_target_min2_cap(&c->def.domain, keep, kb, &c->prep[i], c->jlo[i],
                                             c->jhi[i], 0.0, kbest > 1.0 ? kbest : 1.0);
        if (m2 < kbest)
            kbest = m2, res->limiting = i;
        threat[i] = m2 < 1.0;
        nthreat += m2 < 1.0;
    }
    for (int i = 0, a = 0, b = nthreat; i < n; i++)
        c->idx[threat[i] ? a++ : b++] = i;
    res->keep_clearance = sqrt(kbest);
    for (int j = 0; j < c->nchunks; j++)
        c->nact[j] = 0;
    for (int p = 0; p < n; p++) {
        int i = c->idx[p];
        for (int j = c->jlo[i]; j < c->jhi[i]; j++)
            c->act[(size_t)j * (size_t)c->cap + (size_t)c->nact[j]++] = i;
    }
}

/* For each allowed side the least helm whose track keeps every target out
 * (found[s], -1 if none), the port side stopping at the starboard one's. */
static fw_status least_helms(fw_helm_ctx *c, int allowed, int found[2], fw_helm_result *res,
                             fw_error *err)
{
    static const int sides[2] = {FW_SIDE_STARBOARD, FW_SIDE_PORT};
    static const int masks[2] = {FW_ALLOW_STARBOARD, FW_ALLOW_PORT};
    for (int s = 0; s < 2; s++) {
        if (!(allowed & masks[s]))
            continue;
        for (int i = 0; i < c->nh; i++) {
            int slot;
            fw_status st = fw_cand_open(c, sides[s], i, &slot, err);
            if (st)
                return st;
            if (sqrt(fw_cand_fails(c, slot, 1.0)) >= 1.0 && !fw_cand_leaves_band(c, slot)) {
                found[s] = i;
                res->side_helm[s] = fw_helm_value(c, sides[s], i);
                break;
            }
            /* the other side already cleared with less helm: no need to go on */
            if (s == 1 && found[0] >= 0 && i >= found[0])
                break;
        }
    }
    return FW_OK;
}

/* fw_track_clearance of the chosen candidate, over the prepared targets. */
static double chosen_clearance(fw_helm_ctx *c, int slot, int n, int *limiting)
{
    fw_cand_chunk(c, slot, c->nchunks - 1);
    double best = INFINITY;
    *limiting = -1;
    for (int i = 0; i < n; i++) {
        double m2 = fw_target_min2_cap(&c->def.domain, &c->tracks[slot], &c->boxes[slot],
                                       &c->prep[i], c->jlo[i], c->jhi[i], 0.0, best);
        if (m2 < best)
            best = m2, *limiting = i;
    }
    return sqrt(best);
}

fw_status fw_helm_search(fw_helm_ctx *c, const fw_target *t, int n, int allowed,
                         fw_helm_result *res, fw_error *err)
{
    const fw_track *tr;
    fw_status st = fw_helm_keep_track(c, &tr, err);
    if (st || (st = ensure_scratch(c, t, n, err)))
        return st;
    res->allowed = allowed;
    res->side_helm[0] = res->side_helm[1] = NAN;
    res->feasible = true;
    res->band_left = false;
    res->side = FW_SIDE_NONE;
    res->helm = 0.0;
    keep_check(c, tr, t, n, res);
    c->prep_t = t, c->prep_n = n;
    res->threat = res->keep_clearance < 1.0;
    res->clearance = res->keep_clearance;
    if (!res->threat)
        return FW_OK;
    int found[2] = {-1, -1};
    if ((st = least_helms(c, allowed, found, res, err)))
        return st;
    int pick = -1, side = -1;
    if (found[0] >= 0 && (found[1] < 0 || found[0] <= found[1]))
        pick = found[0], side = 0;
    else if (found[1] >= 0)
        pick = found[1], side = 1;
    if (pick < 0) {
        res->feasible = false;
        if ((st = fw_cand_best_available(c, allowed, &pick, &side, err)))
            return st;
        if (pick < 0) {
            res->band_left = true; /* side none, helm 0, the keep clearance */
            return FW_OK;
        }
    }
    int slot;
    res->side = side ? FW_SIDE_PORT : FW_SIDE_STARBOARD;
    res->helm = fw_helm_value(c, res->side, pick);
    if ((st = fw_cand_open(c, res->side, pick, &slot, err)))
        return st;
    if (!res->feasible && c->next[slot] >= c->nchunks) {
        /* the fallback scanned the pick to the end: its bound is the
         * smallest value of all, met first (by index) for lim */
        fw_cand_chunk(c, slot, c->nchunks - 1);
        res->clearance = sqrt(c->ub2[slot]);
        res->limiting = c->lim[slot];
        return FW_OK;
    }
    res->clearance = chosen_clearance(c, slot, n, &res->limiting);
    return FW_OK;
}

/* fw_track_clearance(def, spare track, t, n, stop_below, NULL), over the
 * targets this decision's search prepared when they are these (the reach
 * windows hold for any track from this own state; only values below the
 * smallest yet, or with `only_below` below stop_below, are tested exactly). */
static double spare_clearance(fw_helm_ctx *c, const fw_target *t, int n, double stop_below,
                              bool only_below)
{
    fw_track *tr = &c->tracks[2 * c->nh + 1];
    if (c->prep_t != t || c->prep_n != n)
        return fw_track_clearance(&c->def, tr, t, n, stop_below, NULL);
    fw_chunk_boxes *cb = &c->boxes[2 * c->nh + 1];
    fw_track_boxes(tr, cb);
    double best = INFINITY, stop2 = stop_below * stop_below;
    for (int i = 0; i < n && !(best < stop2); i++) {
        double m2 = fw_target_min2_cap(&c->def.domain, tr, cb, &c->prep[i], c->jlo[i], c->jhi[i],
                                       stop2, only_below && stop2 < best ? stop2 : best);
        if (m2 < best)
            best = m2;
    }
    return sqrt(best);
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
    *clears = spare_clearance(c, t, n, 1.0, true) >= 1.0;
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
 * going on at its straight-course speed on the last heading (carried by the
 * current it knows). */
static double beyond_horizon(const fw_helm_ctx *c, const fw_track *tr, double U0,
                             const fw_target *t, int n)
{
    int k = tr->n - 1;
    double U = U0 > 0.0 ? U0 : c->own.U0 > 0.0 ? c->own.U0 : c->own.U, cl = INFINITY;
    double oe = U * tr->sin_psi[k], on = U * tr->cos_psi[k];
    if (c->own.cur_e != 0.0 || c->own.cur_n != 0.0)
        oe += c->own.cur_e, on += c->own.cur_n;
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
    double cl = spare_clearance(c, t, n, 0.0, false);
    if (beyond && tr->n > 0)
        cl = fmin(cl, beyond_horizon(c, tr, ap->U0, t, n));
    double out = fw_track_band_excess(&c->band, tr);
    *clearance = out > FW_BAND_SLACK_M ? -out / 1852.0 : cl;
    return FW_OK;
}
