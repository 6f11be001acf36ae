#include "nomoto/track.h"

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
typedef struct kin {
    const fw_nomoto_kb *kb;
    double L;
    bool slip;                /* the knowledge base has drift or speed loss */
    double east, north;
    double U, U0, beta;       /* speed now, on a straight course, drift angle */
    double sb, cb;            /* sin, cos of beta, kept by rotation: beta moves slowly */
    double cse, csn;          /* unit vector of the course over ground */
    double Eb, Eu;            /* lag factors over one step */
} kin;

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
    double rn = k->U > 0.1 ? r * k->L / k->U : 0.0; /* r' */
    double b_ss = k->kb->drift * rn;
    double b1 = b_ss + (k->beta - b_ss) * k->Eb;
    /* the loss is driven by the drift reached at the step's end, as the
     * identification drives it by the MMG ship's (identify.c) */
    double loss = k->kb->speed_loss * fabs(rn) + k->kb->speed_loss_drift * fabs(b1 * rn);
    double u_ss = k->U0 * (1.0 - (loss < 0.9 ? loss : 0.9)); /* fmin, inlined: loss is finite */
    double U1 = u_ss + (k->U - u_ss) * k->Eu;
    rotate(&k->sb, &k->cb, b1 - k->beta);
    k->beta = b1;
    double ce1 = sn * k->cb - cs * k->sb, cn1 = cs * k->cb + sn * k->sb;
    k->east += 0.5 * dt * (k->U * k->cse + U1 * ce1);
    k->north += 0.5 * dt * (k->U * k->csn + U1 * cn1);
    k->U = U1, k->cse = ce1, k->csn = cn1;
}

fw_status fw_track_predict(const fw_ship *ship, const fw_track_def *def, const fw_own_state *s,
                           double helm, fw_track *out, fw_error *err)
{
    int n = fw_track_samples(def);
    if (n > out->cap)
        return fw_fail(err, FW_EINPUT, "track needs %d samples, buffer holds %d", n, out->cap);
    if (helm > ship->rudder_max)
        helm = ship->rudder_max;
    if (helm < -ship->rudder_max)
        helm = -ship->rudder_max;
    fw_nomoto_indices ix;
    /* the side's own knowledge base (ship.h), slip terms included */
    const fw_nomoto_kb *kb = fw_ship_kb(ship, helm);
    fw_status st = fw_nomoto_indices_at(kb, fw_ms_to_kn(s->U),
                                        fw_rad_to_deg(helm), &ix, err);
    if (st)
        return st;

    /* Pieces of the rudder history: held for the delay, ramp, held at the order. */
    double t_ramp0 = def->delay > 0.0 ? def->delay : 0.0;
    double ramp = fabs(helm - s->delta) / ship->rudder_rate;
    double rho = helm > s->delta ? ship->rudder_rate : -ship->rudder_rate;
    double piece_start[3] = {0.0, t_ramp0, t_ramp0 + ramp};
    double piece_rho[3] = {0.0, ramp > 0.0 ? rho : 0.0, 0.0};
    double piece_delta0[3] = {s->delta, s->delta, helm};

    const double dt = def->dt;
    out->n = n;
    out->dt = dt;
    out->helm = helm;
    double r0 = s->r, v0 = s->rdot, turned0 = 0.0;
    double sn = sin(s->psi), cs = cos(s->psi);
    double prev_turn = 0.0;
    bool steadied = false;
    kin kn;
    kin_init(&kn, ship, kb, s, dt);
    int k = 0;
    for (int p = 0; p < 3 && k < n; p++) {
        double t_end = p < 2 ? piece_start[p + 1] : INFINITY;
        fw_nomoto_piece pc;
        fw_nomoto_piece_init(&pc, &ix, piece_delta0[p], piece_rho[p], r0, v0);
        if (k * dt < t_end) {
            /* Samples in this piece by recurrence: with E = exp(-dt/T),
             * e2(tau + dt) = E2 e2(tau) and phi(tau + dt) = E1 phi(tau) + e2(tau) phi(dt),
             * which is exact and as well conditioned as phi itself. */
            double tau = k * dt - piece_start[p];
            double E1 = exp(-dt / ix.T1), E2 = exp(-dt / ix.T2);
            double phidt = fw_nomoto_phi(ix.T1, ix.T2, dt);
            double e2 = exp(-tau / ix.T2), ph = fw_nomoto_phi(ix.T1, ix.T2, tau);
            double A = ix.T1 * (ix.T2 * pc.h1 + pc.h0);
            double B = ix.T1 * (ix.T2 * pc.h2 + pc.h1);
            double TT = ix.T1 * ix.T2, TS = ix.T1 + ix.T2;
            for (; k < n && k * dt < t_end; k++, tau += dt) {
                double h = pc.h0 * e2 + A * ph;
                double hd = pc.h1 * e2 + B * ph;
                double H = -TT * (hd - pc.h1) - TS * (h - pc.h0);
                double r = pc.c0 + pc.b * tau + h, rd = pc.b + hd;
                double turn = turned0 + pc.c0 * tau + 0.5 * pc.b * tau * tau + H;
                double dl = piece_delta0[p] + piece_rho[p] * tau;
                if (steadied) {
                    turn = prev_turn;
                    r = rd = 0.0;
                    dl = 0.0;
                } else if (def->max_turn > 0.0 && fabs(turn) >= def->max_turn) {
                    /* clamped at the sample: the steadying is instantaneous in
                     * the prediction, an error of at most r dt in heading */
                    steadied = true;
                    turn = copysign(def->max_turn, turn);
                    r = rd = 0.0;
                    dl = 0.0;
                }
                if (k > 0) {
                    double ps = sn, pcs = cs;
                    rotate(&sn, &cs, turn - prev_turn);
                    kin_step(&kn, ps, pcs, sn, cs, r, dt);
                }
                prev_turn = turn;
                out->east[k] = kn.east;
                out->north[k] = kn.north;
                out->psi[k] = s->psi + turn;
                out->r[k] = r;
                out->rdot[k] = rd;
                out->delta[k] = dl;
                out->sin_psi[k] = sn;
                out->cos_psi[k] = cs;
                double ph_next = E1 * ph + e2 * phidt;
                e2 *= E2;
                ph = ph_next;
            }
        }
        if (p < 2) {
            double len = piece_start[p + 1] - piece_start[p];
            double turned;
            fw_nomoto_piece_eval(&pc, len, &r0, &v0, &turned);
            turned0 += turned;
        }
    }
    return FW_OK;
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
    double psi = s->psi, r = s->r, v = s->rdot, delta = s->delta;
    double sn = sin(psi), cs = cos(psi);
    out->n = n;
    out->dt = def->dt;
    out->helm = NAN;
    for (int k = 0; k < n; k++) {
        if (k > 0)
            for (int j = 0; j < sub; j++) {
                double order = -ap->kp * fw_wrap_pi(psi - ap->psi_ref) - ap->kd * r;
                order = fmax(-hmax, fmin(hmax, order));
                int deg = (int)fmin(NDEG - 1, round(fw_rad_to_deg(fabs(order))));
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
                    fw_nomoto_piece_init(&pc, ix, delta, rho, r, v);
                    fw_nomoto_piece_eval(&pc, ramp, &r, &v, &turned);
                    psi += turned;
                    delta += rho * ramp;
                }
                if (h - ramp > 0.0) {
                    fw_nomoto_piece_init(&pc, ix, delta, 0.0, r, v);
                    fw_nomoto_piece_eval(&pc, h - ramp, &r, &v, &turned);
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
    return FW_OK;
}

void fw_track_mirror(const fw_track *src, const fw_own_state *s, fw_track *dst)
{
    double ux = sin(s->psi), uy = cos(s->psi); /* along the initial heading */
    double s2 = sin(2.0 * s->psi), c2 = cos(2.0 * s->psi);
    dst->n = src->n;
    dst->dt = src->dt;
    dst->helm = -src->helm;
    for (int k = 0; k < src->n; k++) {
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
