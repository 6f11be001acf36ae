#include "nomoto/track.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>

#include "core/units.h"
#include "nomoto/nomoto.h"

fw_track_def fw_default_track_def(void)
{
    return (fw_track_def){.dt = 5.0, .horizon = 600.0, .max_turn = fw_deg_to_rad(90.0),
                          .delay = 0.0};
}

int fw_track_samples(const fw_track_def *def)
{
    return (int)floor(def->horizon / def->dt + 1e-9) + 1;
}

fw_status fw_track_alloc(fw_track *tr, int cap, fw_error *err)
{
    double *block = malloc(sizeof(double) * 8 * (size_t)cap);
    if (!block)
        return fw_fail(err, FW_ERUN, "out of memory for a %d-sample track", cap);
    tr->cap = cap;
    tr->n = 0;
    tr->east = block;
    tr->north = block + cap;
    tr->psi = block + 2 * cap;
    tr->r = block + 3 * cap;
    tr->delta = block + 4 * cap;
    tr->sin_psi = block + 5 * cap;
    tr->cos_psi = block + 6 * cap;
    tr->rdot = block + 7 * cap;
    return FW_OK;
}

void fw_track_free(fw_track *tr)
{
    free(tr->east);
    tr->east = NULL;
}

/* Unit vector (sin, cos) of heading a+d from that of a; for the small d of one
 * sample step a 5th-order series (error < d^6/720, 1e-12 at 2 deg) is cheaper
 * than sin and cos, and the rotation keeps the vector's length. */
static void sin_cos(double d, double *sd, double *cd)
{
    *sd = sin(d);
    *cd = cos(d);
}

/* Inlined (it runs twice per sample; the library's sine and cosine, rare,
 * stay out of line). */
static inline void rotate(double *s, double *c, double d)
{
    double sd, cd;
    if (fabs(d) < 0.035) {
        double d2 = d * d;
        sd = d * (1.0 - d2 / 6.0 * (1.0 - d2 / 20.0));
        cd = 1.0 - d2 / 2.0 * (1.0 - d2 / 12.0);
    } else {
        sin_cos(d, &sd, &cd);
    }
    double s0 = *s, c0 = *c;
    *s = s0 * cd + c0 * sd;
    *c = c0 * cd - s0 * sd;
}

/* Position, speed and drift along a predicted track (see track.h). */
typedef fw_track_kin kin;

static void kin_init(kin *k, const fw_ship *ship, const fw_nomoto_kb *kb, const fw_own_state *s,
                     double dt)
{
    k->kb = kb;
    k->L = ship->L;
    k->slip = kb->drift > 0.0 || kb->speed_loss != 0.0 || kb->speed_loss_drift > 0.0;
    k->east = s->east, k->north = s->north;
    k->U = s->U > 0.0 ? s->U : 0.0;
    k->U0 = s->U0 > 0.0 ? s->U0 : k->U;
    k->beta = s->beta;
    k->sb = sin(s->beta), k->cb = cos(s->beta);
    k->cse = sin(s->psi - s->beta), k->csn = cos(s->psi - s->beta);
    /* the lags are solved exactly for an input held over a step (the yaw
     * rate at its end): a first-order hold would gain nothing at dt = 5 s
     * against lags of a minute and more */
    k->Eb = kb->drift_lag_s > 0.0 ? exp(-dt / kb->drift_lag_s) : 0.0;
    k->Eu = kb->speed_lag_s > 0.0 ? exp(-dt / kb->speed_lag_s) : 0.0;
    k->cur_e = s->cur_e, k->cur_n = s->cur_n;
    k->drift = s->cur_e != 0.0 || s->cur_n != 0.0;
}

/* Samples k0..k1-1 carried by the current (track.h: the positions above are
 * through the water; a separate pass, so the calm loop is untouched). */
static void drift_run(const kin *k, fw_track *out, int k0, int k1, double dt)
{
    if (!k->drift)
        return;
    for (int j = k0; j < k1; j++) {
        double t = j * dt;
        out->east[j] += k->cur_e * t;
        out->north[j] += k->cur_n * t;
    }
}

/* One step of dt from heading vector (ps, pc) to (sn, cs), yaw rate r at its end. */
static inline void kin_step(kin *k, double ps, double pc, double sn, double cs, double r,
                            double dt)
{
    if (!k->slip) {
        /* trapezoid on the unit vectors: direction exact for a constant
         * rate, length short by (d psi)^2/12 (< 1e-4) */
        k->east += 0.5 * k->U * dt * (ps + sn);
        k->north += 0.5 * k->U * dt * (pc + cs);
        return;
    }
    /* r' (a zero rate, on a straight or steadied stretch, is its own r':
     * +-0 L / U, without the division on the speed's chain) */
    double rn = k->U > 0.1 ? (r == 0.0 ? r : r * k->L / k->U) : 0.0;
    double b_ss = k->kb->drift * rn;
    double b1 = b_ss + (k->beta - b_ss) * k->Eb;
    /* the loss is driven by the drift reached at the step's end, as the
     * identification drives it by the MMG ship's (identify.c); at r' = 0 it
     * is +-0 and u_ss = U0 (1 - 0) = U0 exactly */
    double u_ss = k->U0;
    if (rn != 0.0 || !isfinite(b1)) {
        double loss = k->kb->speed_loss * fabs(rn) + k->kb->speed_loss_drift * fabs(b1 * rn);
        u_ss = k->U0 * (1.0 - (loss < 0.9 ? loss : 0.9)); /* fmin, inlined: loss is finite */
    }
    double U1 = u_ss + (k->U - u_ss) * k->Eu;
    rotate(&k->sb, &k->cb, b1 - k->beta);
    k->beta = b1;
    double ce1 = sn * k->cb - cs * k->sb, cn1 = cs * k->cb + sn * k->sb;
    k->east += 0.5 * dt * (k->U * k->cse + U1 * ce1);
    k->north += 0.5 * dt * (k->U * k->csn + U1 * cn1);
    k->U = U1, k->cse = ce1, k->csn = cn1;
}

/* The helm-independent start of a track from s: kin_init's and the heading's
 * unit vector, from the origin when it holds them for this knowledge base
 * (made there the first time). */
static void start_state(fw_track_gen *g, const fw_ship *ship, const fw_nomoto_kb *kb,
                        const fw_own_state *s, double dt, fw_track_origin *origin)
{
    fw_track_origin *o = origin ? &origin[kb != &ship->nomoto] : NULL;
    if (o && o->valid && o->dt == dt) {
        g->kn = o->kn;
        g->sn = o->sn, g->cs = o->cs;
        return;
    }
    kin_init(&g->kn, ship, kb, s, dt);
    g->sn = sin(s->psi), g->cs = cos(s->psi);
    if (o)
        *o = (fw_track_origin){.valid = true, .dt = dt, .kn = g->kn, .sn = g->sn, .cs = g->cs};
}

fw_status fw_track_start(const fw_ship *ship, const fw_track_def *def, const fw_own_state *s,
                         double helm, fw_track *out, fw_track_gen *g, fw_error *err)
{
    return fw_track_start_from(ship, def, s, helm, out, g, NULL, err);
}

fw_status fw_track_start_from(const fw_ship *ship, const fw_track_def *def,
                              const fw_own_state *s, double helm, fw_track *out,
                              fw_track_gen *g, fw_track_origin origin[2], fw_error *err)
{
    int n = fw_track_samples(def);
    if (n > out->cap)
        return fw_fail(err, FW_EINPUT, "track needs %d samples, buffer holds %d", n, out->cap);
    if (helm > ship->rudder_max)
        helm = ship->rudder_max;
    if (helm < -ship->rudder_max)
        helm = -ship->rudder_max;
    /* the side's own knowledge base (ship.h), slip terms included */
    const fw_nomoto_kb *kb = fw_ship_kb(ship, helm);
    fw_status st = fw_nomoto_indices_at(kb, fw_ms_to_kn(s->U), fw_rad_to_deg(helm), &g->ix, err);
    if (st)
        return st;

    /* Pieces of the rudder history: held for the delay, ramp, held at the order. */
    double t_ramp0 = def->delay > 0.0 ? def->delay : 0.0;
    double ramp = fabs(helm - s->delta) / ship->rudder_rate;
    double rho = helm > s->delta ? ship->rudder_rate : -ship->rudder_rate;
    g->piece_start[0] = 0.0, g->piece_start[1] = t_ramp0, g->piece_start[2] = t_ramp0 + ramp;
    g->piece_rho[0] = 0.0, g->piece_rho[1] = ramp > 0.0 ? rho : 0.0, g->piece_rho[2] = 0.0;
    g->piece_delta0[0] = g->piece_delta0[1] = s->delta, g->piece_delta0[2] = helm;

    g->dt = def->dt;
    g->max_turn = def->max_turn;
    g->psi0 = s->psi;
    out->n = n;
    out->dt = def->dt;
    out->helm = helm;
    g->n = n;
    g->k = 0;
    g->p = 0;
    g->in_piece = false;
    g->have_E = false;
    g->r0 = s->r, g->v0 = s->rdot, g->turned0 = 0.0;
    g->dw = s->delta_wind;
    g->prev_turn = 0.0;
    g->steadied = false;
    start_state(g, ship, kb, s, def->dt, origin);
    return FW_OK;
}

/* fw_nomoto_phi(T1, T2, t) from e2 = exp(-t / T2) made already (and
 * *e1 = exp(-t / T1) if e1 is not NULL): its operations on the same values,
 * so the same bits, without making the exponentials again. */
static inline double phi_from(double T1, double T2, double t, const double *e1, double e2)
{
    double dT = T1 - T2;
    double x = t * dT / (T1 * T2);
    if (fabs(x) < 1e-3) {
        double s = 1.0 + x * (0.5 + x * (1.0 / 6.0 + x / 24.0));
        return e2 * t / (T1 * T2) * s;
    }
    return ((e1 ? *e1 : exp(-t / T1)) - e2) / dT;
}

/* The homogeneous part of a piece's response at tau (h, its slope hd, its
 * integral H) from e2 = exp(-tau / T2) and ph = phi(tau), with A = T1 (T2 h1
 * + h0), B = T1 (T2 h2 + h1), TT = T1 T2 and TS = T1 + T2: the operations of
 * fw_nomoto_piece_eval on the same values, so the same bits ((-T1) T2 is
 * -(T1 T2) exactly). */
static inline void piece_homog(const fw_nomoto_piece *pc, double A, double B, double TT,
                               double TS, double e2, double ph, double *h, double *hd, double *H)
{
    *h = pc->h0 * e2 + A * ph;
    *hd = pc->h1 * e2 + B * ph;
    *H = -TT * (*hd - pc->h1) - TS * (*h - pc->h0);
}

/* fw_nomoto_piece_eval(pc, t, r, rdot, turned) to the bit, inlined, with
 * exp(-t / T2) made once for the response and phi (the library's phi makes
 * it again): the autopilot's track evaluates two pieces a step. */
static inline void piece_eval(const fw_nomoto_piece *pc, double t, double *r, double *rdot,
                              double *turned)
{
    double T1 = pc->T1, T2 = pc->T2, e2 = exp(-t / T2), ph = phi_from(T1, T2, t, NULL, e2);
    double h, hd, H;
    piece_homog(pc, T1 * (T2 * pc->h1 + pc->h0), T1 * (T2 * pc->h2 + pc->h1), T1 * T2, T1 + T2,
                e2, ph, &h, &hd, &H);
    *r = pc->c0 + pc->b * t + h;
    *rdot = pc->b + hd;
    *turned = pc->c0 * t + 0.5 * pc->b * t * t + H;
}

/* Enters piece g->p at sample g->k: its response from the state reached, and
 * the recurrences' factors if a sample falls in it. */
static void piece_enter(fw_track_gen *g)
{
    int p = g->p;
    fw_track_piece *q = &g->q;
    q->t_end = p < 2 ? g->piece_start[p + 1] : INFINITY;
    /* the rudder beyond the wind's (0 in still air: the same bits) */
    fw_nomoto_piece_init(&q->pc, &g->ix, g->piece_delta0[p] - g->dw, g->piece_rho[p], g->r0,
                         g->v0);
    if (g->k * g->dt < q->t_end) {
        /* Samples in this piece by recurrence: with E = exp(-dt/T),
         * e2(tau + dt) = E2 e2(tau) and phi(tau + dt) = E1 phi(tau) + e2(tau) phi(dt),
         * which is exact and as well conditioned as phi itself. */
        const fw_nomoto_indices *ix = &g->ix;
        double dt = g->dt;
        q->tau = g->k * dt - g->piece_start[p];
        if (!g->have_E) { /* the same for every piece of the track */
            q->E1 = exp(-dt / ix->T1), q->E2 = exp(-dt / ix->T2);
            q->phidt = phi_from(ix->T1, ix->T2, dt, &q->E1, q->E2);
            g->have_E = true;
        }
        if (q->tau == 0.0 && !signbit(q->tau)) {
            /* what exp(-0 / T2) and phi(+0) give (the ramp from the start) */
            q->e2 = 1.0, q->ph = 0.0;
        } else {
            q->e2 = exp(-q->tau / ix->T2);
            q->ph = phi_from(ix->T1, ix->T2, q->tau, NULL, q->e2);
        }
        q->A = ix->T1 * (ix->T2 * q->pc.h1 + q->pc.h0);
        q->B = ix->T1 * (ix->T2 * q->pc.h2 + q->pc.h1);
        q->TT = ix->T1 * ix->T2, q->TS = ix->T1 + ix->T2;
    }
    g->in_piece = true;
}

/* Positions of samples k0..k1-1 (k0 >= 1) from the headings, yaw rates and
 * the position at k0 - 1 already there: kin_step sample by sample, as a loop
 * of its own (its speed chain, with a division, bounds the time per sample;
 * apart from the heading's recurrence the CPU overlaps it better). */
static void kin_run(kin *kp, fw_track *out, int k0, int k1, double dt)
{
    kin kn = *kp;
    const double *sp = out->sin_psi, *cp = out->cos_psi, *rr = out->r;
    for (int k = k0; k < k1; k++) {
        kin_step(&kn, sp[k - 1], cp[k - 1], sp[k], cp[k], rr[k], dt);
        out->east[k] = kn.east;
        out->north[k] = kn.north;
    }
    drift_run(&kn, out, k0, k1, dt);
    *kp = kn;
}

/* Headings, yaw rates and rudder angles of samples g->k .. kmax-1 within the
 * present piece (their positions: kin_run).  The state it carries from sample
 * to sample is worked on in locals (the stores into the track may alias the
 * generator otherwise), and only that is written back: the candidates are
 * extended a chunk at a time, and copying the whole generator in and out
 * cost more than a chunk's headings. */
static void piece_run(fw_track_gen *gp, fw_track *out, int kmax)
{
    const fw_track_piece *qp = &gp->q;
    const fw_nomoto_piece pc = qp->pc;
    const double dt = gp->dt, dl0 = gp->piece_delta0[gp->p], rh = gp->piece_rho[gp->p];
    const double t_end = qp->t_end, A = qp->A, B = qp->B, TT = qp->TT, TS = qp->TS;
    const double E1 = qp->E1, E2 = qp->E2, phidt = qp->phidt;
    const double turned0 = gp->turned0, max_turn = gp->max_turn, psi0 = gp->psi0;
    double tau = qp->tau, e2 = qp->e2, ph = qp->ph;
    double sn = gp->sn, cs = gp->cs, prev_turn = gp->prev_turn;
    bool steadied = gp->steadied;
    int k = gp->k;
    for (; k < kmax && k * dt < t_end; k++, tau += dt) {
        double h, hd, H;
        piece_homog(&pc, A, B, TT, TS, e2, ph, &h, &hd, &H);
        double r = pc.c0 + pc.b * tau + h, rd = pc.b + hd;
        double turn = turned0 + pc.c0 * tau + 0.5 * pc.b * tau * tau + H;
        double dl = dl0 + rh * tau;
        if (steadied) {
            turn = prev_turn;
            r = rd = 0.0;
            dl = 0.0;
        } else if (max_turn > 0.0 && fabs(turn) >= max_turn) {
            /* clamped at the sample: the steadying is instantaneous in
             * the prediction, an error of at most r dt in heading */
            steadied = true;
            turn = copysign(max_turn, turn);
            r = rd = 0.0;
            dl = 0.0;
        }
        if (k > 0)
            rotate(&sn, &cs, turn - prev_turn);
        prev_turn = turn;
        out->psi[k] = psi0 + turn;
        out->r[k] = r;
        out->rdot[k] = rd;
        out->delta[k] = dl;
        out->sin_psi[k] = sn;
        out->cos_psi[k] = cs;
        double ph_next = E1 * ph + e2 * phidt;
        e2 *= E2;
        ph = ph_next;
    }
    gp->k = k;
    gp->q.tau = tau, gp->q.e2 = e2, gp->q.ph = ph;
    gp->sn = sn, gp->cs = cs, gp->prev_turn = prev_turn;
    gp->steadied = steadied;
}

/* Headings of samples g->k .. kmax-1, piece by piece. */
static void headings(fw_track_gen *g, fw_track *out, int kmax)
{
    if (kmax > g->n)
        kmax = g->n;
    while (g->k < kmax && g->p < 3) {
        if (!g->in_piece)
            piece_enter(g);
        piece_run(g, out, kmax);
        if (g->k * g->dt < g->q.t_end)
            return; /* paused inside the piece */
        if (g->p < 2) {
            double len = g->piece_start[g->p + 1] - g->piece_start[g->p], turned;
            piece_eval(&g->q.pc, len, &g->r0, &g->v0, &turned);
            g->turned0 += turned;
        }
        g->p++;
        g->in_piece = false;
    }
}

/* The first sample of positions to make (sample 0 is the start). */
static int kin_from(fw_track_gen *g, fw_track *out, int k0)
{
    if (k0 == 0 && g->k > 0) {
        out->east[0] = g->kn.east;
        out->north[0] = g->kn.north;
    }
    return k0 > 1 ? k0 : 1;
}

void fw_track_extend(fw_track_gen *g, fw_track *out, int kmax)
{
    int k0 = g->k;
    headings(g, out, kmax);
    kin_run(&g->kn, out, kin_from(g, out, k0), g->k, g->dt);
}

fw_status fw_track_predict(const fw_ship *ship, const fw_track_def *def, const fw_own_state *s,
                           double helm, fw_track *out, fw_error *err)
{
    fw_track_gen g;
    fw_status st = fw_track_start(ship, def, s, helm, out, &g, err);
    if (!st)
        fw_track_extend(&g, out, g.n);
    return st;
}

/* fmax(-hmax, fmin(hmax, order)), inlined (libm's are calls): as glibc's
 * minsd and maxsd a tie gives the second argument, a NaN order hmax (and
 * the sign of a zero order, which only hmax = 0 could meet, changes nothing
 * downstream: order < 0, order > delta and |order - delta| read it alike). */
static inline double clamp_order(double order, double hmax)
{
    double o = hmax < order || order != order ? hmax : order;
    return -hmax > o ? -hmax : o;
}

/* (int)fmin(most, round(x)) for x >= 0 or NaN, inlined: below `most` the
 * fraction x - trunc(x) is exact, and round gives trunc + 1 from one half on. */
static inline int whole_degrees(double x, int most)
{
    if (!(x < most))
        return most;
    int d = (int)x;
    return d + (x - d >= 0.5);
}

fw_status fw_track_predict_steer(const fw_ship *ship, const fw_track_def *def,
                                 const fw_own_state *s, const fw_steer_def *ap, fw_track *out,
                                 fw_error *err)
{
    int n = fw_track_samples(def);
    if (n > out->cap)
        return fw_fail(err, FW_EINPUT, "track needs %d samples, buffer holds %d", n, out->cap);
    double hmax = fmin(fabs(ap->max_helm), ship->rudder_max);
    /* the indices follow the order (they depend on the rudder angle, as the
     * step loop's ship does): by whole degrees, evaluated when first needed */
    enum { NDEG = 91 };
    fw_nomoto_indices tab[2][NDEG]; /* [0] starboard orders, [1] port (ship.h) */
    bool have[2][NDEG] = {{false}};
    double U_kn = fw_ms_to_kn(s->U);
    /* the order is re-evaluated at most every 5 s (the step loop does it
     * every second): 2.7 m off the one-second loop over 10 minutes, at a
     * fifth of the cost */
    int sub = (int)fmax(1.0, round(def->dt / 5.0));
    double h = def->dt / sub;
    kin kn;
    /* the slip terms of the starboard block: the order changes side */
    kin_init(&kn, ship, &ship->nomoto, s, h);
    if (ap->U0 > 0.0)
        kn.U0 = ap->U0;
    double psi = s->psi, r = s->r, v = s->rdot, delta = s->delta;
    double sn = sin(psi), cs = cos(psi);
    out->n = n;
    out->dt = def->dt;
    out->helm = NAN;
    for (int k = 0; k < n; k++) {
        if (k > 0)
            for (int j = 0; j < sub; j++) {
                double order = -ap->kp * fw_wrap_pi(psi - ap->psi_ref) - ap->kd * r;
                if (s->delta_wind != 0.0)
                    order += s->delta_wind; /* the policy's autopilot holds against the wind */
                order = clamp_order(order, hmax);
                int deg = whole_degrees(fw_rad_to_deg(fabs(order)), NDEG - 1);
                int side = order < 0.0 && ship->nomoto_port.present;
                if (!have[side][deg]) {
                    fw_status st = fw_nomoto_indices_at(fw_ship_kb(ship, order), U_kn, deg,
                                                        &tab[side][deg], err);
                    if (st)
                        return st;
                    have[side][deg] = true;
                }
                const fw_nomoto_indices *ix = &tab[side][deg];
                /* the rudder: ramp to the order at the rudder rate, then hold */
                double ramp = fmin(h, fabs(order - delta) / ship->rudder_rate);
                double rho = order > delta ? ship->rudder_rate : -ship->rudder_rate;
                double psi0 = psi, turned;
                fw_nomoto_piece pc;
                if (ramp > 0.0) {
                    fw_nomoto_piece_init(&pc, ix, delta - s->delta_wind, rho, r, v);
                    piece_eval(&pc, ramp, &r, &v, &turned);
                    psi += turned;
                    delta += rho * ramp;
                }
                if (h - ramp > 0.0) {
                    fw_nomoto_piece_init(&pc, ix, delta - s->delta_wind, 0.0, r, v);
                    piece_eval(&pc, h - ramp, &r, &v, &turned);
                    psi += turned;
                }
                double ps = sn, pcs = cs;
                rotate(&sn, &cs, psi - psi0);
                kin_step(&kn, ps, pcs, sn, cs, r, h);
            }
        out->east[k] = kn.east;
        out->north[k] = kn.north;
        out->psi[k] = psi;
        out->r[k] = r;
        out->rdot[k] = v;
        out->delta[k] = delta;
        out->sin_psi[k] = sn;
        out->cos_psi[k] = cs;
    }
    drift_run(&kn, out, 0, n, def->dt);
    return FW_OK;
}

void fw_track_mirror_range(const fw_track *src, const fw_own_state *s, fw_track *dst, int k0,
                           int k1)
{
    /* the mirror image of a track carried by a current is carried by the
     * mirrored current: the other helm's track only when the current is
     * along the heading (the helm search mirrors in still water only) */
    assert(s->cur_e == 0.0 && s->cur_n == 0.0 && "mirrored track in a current");
    double ux = sin(s->psi), uy = cos(s->psi); /* along the initial heading */
    double s2 = sin(2.0 * s->psi), c2 = cos(2.0 * s->psi);
    dst->n = src->n;
    dst->dt = src->dt;
    dst->helm = -src->helm;
    for (int k = k0; k < k1; k++) {
        double dx = src->east[k] - s->east, dy = src->north[k] - s->north;
        double along = dx * ux + dy * uy;
        double perp = dx * uy - dy * ux; /* starboard offset */
        dst->east[k] = s->east + along * ux - perp * uy;
        dst->north[k] = s->north + along * uy + perp * ux;
        dst->psi[k] = 2.0 * s->psi - src->psi[k];
        dst->r[k] = -src->r[k];
        dst->rdot[k] = -src->rdot[k];
        dst->delta[k] = -src->delta[k];
        /* heading 2 psi0 - psi: sin = s2 cos - c2 sin, cos = c2 cos + s2 sin */
        dst->sin_psi[k] = s2 * src->cos_psi[k] - c2 * src->sin_psi[k];
        dst->cos_psi[k] = c2 * src->cos_psi[k] + s2 * src->sin_psi[k];
    }
}

void fw_track_mirror(const fw_track *src, const fw_own_state *s, fw_track *dst)
{
    fw_track_mirror_range(src, s, dst, 0, src->n);
}
