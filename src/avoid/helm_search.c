#include "avoid/helm_search.h"

#include <math.h>
#include <stdlib.h>

#include "core/units.h"

enum { CHUNK = 8 }; /* segments per culling box: 40 s at the default dt */

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
};

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
        return fw_fail(err, FW_EINPUT, "ship '%s' has no Nomoto knowledge base (nomoto:)",
                       ship->name);
    fw_helm_ctx *c = calloc(1, sizeof *c);
    if (!c)
        return fw_fail(err, FW_ERUN, "out of memory");
    c->ship = ship;
    c->def = *def;
    c->nh = (int)floor((def->max_helm_deg - def->min_helm_deg) / def->step_deg + 1e-9) + 1;
    int ntr = 2 * c->nh + 2;
    c->tracks = calloc((size_t)ntr, sizeof *c->tracks);
    c->have = calloc((size_t)(2 * c->nh), sizeof *c->have);
    if (!c->tracks || !c->have) {
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

void fw_helm_ctx_destroy(fw_helm_ctx *c)
{
    if (!c)
        return;
    if (c->tracks)
        for (int i = 0; i < 2 * c->nh + 2; i++)
            fw_track_free(&c->tracks[i]);
    free(c->tracks);
    free(c->have);
    free(c);
}

void fw_helm_begin(fw_helm_ctx *c, const fw_own_state *own)
{
    c->own = *own;
    c->symmetric = own->r == 0.0 && own->rdot == 0.0 && own->delta == 0.0;
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

/* Smallest lambda^2 = (x/a)^2 + (y/b)^2 on the segment from (x0, y0) to (x1, y1). */
static double seg_min_lambda2(double x0, double y0, double x1, double y1, double a, double b)
{
    double ia = 1.0 / (a * a), ib = 1.0 / (b * b);
    double dx = x1 - x0, dy = y1 - y0;
    double q = dx * dx * ia + dy * dy * ib;
    double s = q > 0.0 ? -(x0 * dx * ia + y0 * dy * ib) / q : 0.0;
    if (s < 0.0)
        s = 0.0;
    if (s > 1.0)
        s = 1.0;
    double x = x0 + s * dx, y = y0 + s * dy;
    return x * x * ia + y * y * ib;
}

double fw_track_clearance(const fw_helm_def *def, const fw_track *tr, const fw_target *t, int n,
                          double stop_below, int *limiting)
{
    /* bounding boxes of the own track per chunk of CHUNK segments */
    int nseg = tr->n - 1;
    int nch = (nseg + CHUNK - 1) / CHUNK;
    double box[64][4];
    if (nch > 64)
        nch = 64; /* chunks beyond 64 are checked without culling */
    for (int j = 0; j < nch; j++) {
        int k0 = j * CHUNK, k1 = k0 + CHUNK < nseg ? k0 + CHUNK : nseg;
        double e0 = tr->east[k0], e1 = e0, n0 = tr->north[k0], n1 = n0;
        for (int k = k0 + 1; k <= k1; k++) {
            e0 = fmin(e0, tr->east[k]);
            e1 = fmax(e1, tr->east[k]);
            n0 = fmin(n0, tr->north[k]);
            n1 = fmax(n1, tr->north[k]);
        }
        box[j][0] = e0, box[j][1] = e1, box[j][2] = n0, box[j][3] = n1;
    }
    double best = INFINITY;
    int lim = -1;
    double stop2 = stop_below * stop_below;
    for (int i = 0; i < n; i++) {
        const fw_target *g = &t[i];
        double ve = g->speed * sin(g->course), vn = g->speed * cos(g->course);
        double sc = sin(g->course), cc = cos(g->course);
        /* beyond this centre distance the target is outside the domain whatever
         * the relative heading */
        double reach = def->domain.size * fmax(1.0, def->domain.fore_aft_ratio) +
                       0.5 * hypot(g->length, g->breadth);
        double tmin2 = INFINITY;
        for (int j = 0; j * CHUNK < nseg; j++) {
            int k0 = j * CHUNK, k1 = k0 + CHUNK < nseg ? k0 + CHUNK : nseg;
            if (j < nch) {
                double ta = k0 * tr->dt, tb = k1 * tr->dt;
                double ea = g->east + ve * ta, eb = g->east + ve * tb;
                double na = g->north + vn * ta, nb = g->north + vn * tb;
                if (fmin(ea, eb) - reach > box[j][1] || fmax(ea, eb) + reach < box[j][0] ||
                    fmin(na, nb) - reach > box[j][3] || fmax(na, nb) + reach < box[j][2])
                    continue;
            }
            double px = 0, py = 0, pa = 1, pb = 1;
            for (int k = k0; k <= k1; k++) {
                double tk = k * tr->dt;
                double dx = g->east + ve * tk - tr->east[k];
                double dy = g->north + vn * tk - tr->north[k];
                double s = tr->sin_psi[k], c = tr->cos_psi[k];
                double x = dx * s + dy * c, y = dx * c - dy * s;
                double a, b;
                fw_domain_axes(&def->domain, g, cc * c + sc * s, sc * c - cc * s, &a, &b);
                if (k > k0) {
                    /* body-frame offsets interpolated linearly over the segment:
                     * the frame turns by r dt (about 1 deg), a sub-metre error */
                    double l2 = seg_min_lambda2(px, py, x, y, 0.5 * (pa + a), 0.5 * (pb + b));
                    if (l2 < tmin2)
                        tmin2 = l2;
                }
                px = x, py = y, pa = a, pb = b;
            }
            if (tmin2 < stop2)
                break;
        }
        if (tmin2 < best) {
            best = tmin2;
            lim = i;
        }
        if (best < stop2)
            break;
    }
    if (limiting)
        *limiting = lim;
    return sqrt(best);
}

double fw_track_min_distance(const fw_track *tr, const fw_target *g, double *t_min)
{
    double ve = g->speed * sin(g->course), vn = g->speed * cos(g->course);
    double best = INFINITY, tb = 0.0, px = 0.0, py = 0.0;
    for (int k = 0; k < tr->n; k++) {
        double tk = k * tr->dt;
        double dx = g->east + ve * tk - tr->east[k], dy = g->north + vn * tk - tr->north[k];
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

fw_status fw_helm_search(fw_helm_ctx *c, const fw_target *t, int n, int allowed,
                         fw_helm_result *res, fw_error *err)
{
    const fw_track *tr;
    fw_status st = fw_helm_keep_track(c, &tr, err);
    if (st)
        return st;
    res->allowed = allowed;
    res->keep_clearance = fw_track_clearance(&c->def, tr, t, n, 0.0, &res->limiting);
    res->side_helm[0] = res->side_helm[1] = NAN;
    res->threat = res->keep_clearance < 1.0;
    res->feasible = true;
    res->side = FW_SIDE_NONE;
    res->helm = 0.0;
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
            if (fw_track_clearance(&c->def, tr, t, n, 1.0, NULL) >= 1.0) {
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
        /* nothing clears: the helm that keeps the nearest target farthest out */
        res->feasible = false;
        double best = -1.0;
        for (int s = 0; s < 2; s++) {
            if (!(allowed & masks[s]))
                continue;
            for (int i = 0; i < c->nh; i++) {
                if ((st = fw_helm_track(c, sides[s], i, &tr, err)))
                    return st;
                /* branch and bound: a track is abandoned as soon as some
                 * target comes closer than the best track's nearest one */
                double cl = fw_track_clearance(&c->def, tr, t, n, best > 0.0 ? best : 0.0, NULL);
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
