#include "core/files.h"
#include "dynamics/manoeuvre.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/units.h"

void fw_history_free(fw_history *h)
{
    free(h->s);
    h->s = NULL;
    h->n = h->cap = 0;
}

static fw_status history_add(fw_history *h, const fw_stepper *st, fw_error *err)
{
    if (!h)
        return FW_OK;
    if (h->n == h->cap) {
        size_t cap = h->cap ? 2 * h->cap : 1024;
        fw_sample *s = realloc(h->s, cap * sizeof *s);
        if (!s)
            return fw_fail(err, FW_ERUN, "out of memory for the time history");
        h->s = s;
        h->cap = cap;
    }
    const fw_mmg_state *x = fw_stepper_state(st);
    h->s[h->n++] = (fw_sample){
        .t = fw_stepper_time(st), .east = x->east, .north = x->north, .psi = x->psi,
        .u = x->u, .vm = x->vm, .r = x->r, .delta = x->delta, .helm = fw_stepper_helm(st),
        .n = fw_stepper_propeller(st)};
    return FW_OK;
}

fw_status fw_history_write_csv(const fw_history *h, const char *path, fw_error *err)
{
    /* Written to a temporary name and renamed, so a failure never leaves a
     * truncated file where a complete one is expected. */
    char tmp[1024];
    FILE *f = fw_file_begin(path, tmp, sizeof tmp, err);
    if (!f)
        return err->status;
    fprintf(f, "t_s,east_m,north_m,heading_deg,u_mps,v_mps,r_degps,rudder_deg,helm_deg,"
               "propeller_rps\n");
    for (size_t i = 0; i < h->n; i++) {
        const fw_sample *s = &h->s[i];
        fprintf(f, "%.3f,%.4f,%.4f,%.5f,%.6f,%.6f,%.7f,%.4f,%.4f,%.5f\n", s->t, s->east, s->north,
                fw_rad_to_deg(s->psi), s->u, s->vm, fw_rad_to_deg(s->r),
                fw_rad_to_deg(s->delta), fw_rad_to_deg(s->helm), s->n);
    }
    return fw_file_commit(f, tmp, path, err);
}

/* What every standard manoeuvre starts from: the approach speed unset (the
 * caller's), samples every 0.5 s, an hour at most, the default stepper. */
#define MANOEUVRE_DEFAULTS \
    .speed = 0.0, .sample_dt = 0.5, .max_time = 3600.0, .stepper = fw_default_stepper_def()

fw_turning_def fw_default_turning_def(void)
{
    return (fw_turning_def){MANOEUVRE_DEFAULTS, .rudder = fw_deg_to_rad(35.0),
                            .max_turn = fw_deg_to_rad(720.0)};
}

fw_zigzag_def fw_default_zigzag_def(void)
{
    return (fw_zigzag_def){MANOEUVRE_DEFAULTS, .angle = fw_deg_to_rad(10.0), .first_side = 1,
                           .executes = 4};
}

static fw_status check_common(const fw_ship *ship, double speed, double rudder, double dt,
                              fw_error *err)
{
    if (!(speed > 0.0) || !isfinite(speed))
        return fw_fail(err, FW_EINPUT, "approach speed must be positive (got %g kn)",
                       fw_ms_to_kn(speed));
    if (!(fabs(rudder) > 0.0) || fabs(rudder) > ship->rudder_max * (1 + 1e-12))
        return fw_fail(err, FW_EINPUT, "rudder angle %g deg is outside (0, %g] deg for %s",
                       fw_rad_to_deg(fabs(rudder)), fw_rad_to_deg(ship->rudder_max), ship->name);
    if (!(dt > 0.0))
        return fw_fail(err, FW_EINPUT, "sampling step must be positive");
    return FW_OK;
}

/* The manoeuvre's common inputs checked, then a stepper started in straight
 * steady running at the approach speed (*n its propeller speed). */
static fw_status start_straight(const fw_ship *ship, double speed, double rudder, double dt,
                                const fw_stepper_def *def, fw_stepper **st, double *n,
                                fw_error *err)
{
    *st = NULL;
    fw_status s = check_common(ship, speed, rudder, dt, err);
    if (s || (s = fw_mmg_propeller_for_speed(ship, speed, n, err)))
        return s;
    if ((s = fw_stepper_create(ship, def, st, err)))
        return s;
    fw_mmg_state x0 = fw_mmg_straight(speed, 0.0, 0.0, 0.0);
    if ((s = fw_stepper_start(*st, 0.0, &x0, *n, err))) {
        fw_stepper_destroy(*st);
        *st = NULL;
    }
    return s;
}

/* Linear interpolation of b at the point where a crosses level between two samples. */
static double cross(double a0, double a1, double b0, double b1, double level)
{
    double f = (level - a0) / (a1 - a0);
    return b0 + f * (b1 - b0);
}

/* The ground positions at 360 and 720 deg of heading change: a current
 * moves the steady circle by its drift in that time (MSC/Circ.1053
 * 3.4.2.5).  One sample step (turn from prev_turn, position from pe, pn at
 * pt) into res->drift, t_drift, drift_towards once 720 deg is reached. */
typedef struct drift_points {
    double e, n, t; /* at 360 deg */
    bool got360, got720;
} drift_points;

static void circle_drift(drift_points *c, fw_turning_result *res, double prev_turn, double turn,
                         double pe, double pn, double pt, const fw_mmg_state *x, double t)
{
    if (!c->got360 && turn >= 2 * FW_PI) {
        c->e = cross(prev_turn, turn, pe, x->east, 2 * FW_PI);
        c->n = cross(prev_turn, turn, pn, x->north, 2 * FW_PI);
        c->t = cross(prev_turn, turn, pt, t, 2 * FW_PI);
        c->got360 = true;
    }
    if (c->got360 && !c->got720 && turn >= 4 * FW_PI) {
        double e = cross(prev_turn, turn, pe, x->east, 4 * FW_PI) - c->e;
        double n = cross(prev_turn, turn, pn, x->north, 4 * FW_PI) - c->n;
        res->drift = hypot(e, n);
        res->drift_towards = fw_wrap_2pi(atan2(e, n));
        res->t_drift = cross(prev_turn, turn, pt, t, 4 * FW_PI) - c->t;
        c->got720 = true;
    }
}

fw_status fw_turning_run(const fw_ship *ship, const fw_turning_def *def, fw_turning_result *res,
                         fw_history *hist, fw_error *err)
{
    memset(res, 0, sizeof *res);
    fw_stepper *st;
    fw_status s = start_straight(ship, def->speed, def->rudder, def->sample_dt, &def->stepper,
                                 &st, &res->propeller, err);
    if (s)
        return s;
    const double side = def->rudder > 0.0 ? 1.0 : -1.0;
    res->L = ship->L;
    fw_stepper_set_helm(st, def->rudder);
    if ((s = history_add(hist, st, err)))
        goto done;

    /* Heading change, unwrapped, positive in the turning direction. */
    double prev_turn = 0.0, prev_x = 0.0, prev_y = 0.0, prev_t = 0.0;
    double prev_e = 0.0, prev_n = 0.0; /* over ground */
    drift_points cd = {.got360 = false};
    bool got90 = false, got180 = false;
    res->drift = res->t_drift = res->drift_towards = NAN;
    /* For the steady values, keep the samples of the last full circle: a ring
     * of (turn, t, u) would do, but the history of one circle is short. */
    size_t cap = 0, count = 0;
    double *ring_turn = NULL, *ring_t = NULL, *ring_U = NULL;
    cap = (size_t)(def->max_time / def->sample_dt) + 2;
    ring_turn = malloc(cap * sizeof *ring_turn);
    ring_t = malloc(cap * sizeof *ring_t);
    ring_U = malloc(cap * sizeof *ring_U);
    if (!ring_turn || !ring_t || !ring_U) {
        s = fw_fail(err, FW_ERUN, "out of memory");
        goto free_rings;
    }
    ring_turn[count] = 0.0;
    ring_t[count] = 0.0;
    ring_U[count++] = def->speed;
    while (fw_stepper_time(st) < def->max_time) {
        if ((s = fw_stepper_advance(st, def->sample_dt, err)) || (s = history_add(hist, st, err)))
            goto free_rings;
        const fw_mmg_state *x = fw_stepper_state(st);
        double turn = side * x->psi, t = fw_stepper_time(st);
        /* the IMO measures are the water's: a current's drift taken out
         * (MSC/Circ.1053 3.4.2.3); none in calm water */
        double de = 0.0, dn = 0.0;
        fw_current_drift(&def->stepper.current, 0.0, 0.0, 0.0, t, &de, &dn);
        double adv = x->north - dn, trans = side * (x->east - de);
        circle_drift(&cd, res, prev_turn, turn, prev_e, prev_n, prev_t, x, t);
        prev_e = x->east, prev_n = x->north;
        if (!got90 && turn >= FW_PI / 2) {
            res->advance = cross(prev_turn, turn, prev_x, adv, FW_PI / 2);
            res->transfer = cross(prev_turn, turn, prev_y, trans, FW_PI / 2);
            res->t90 = cross(prev_turn, turn, prev_t, t, FW_PI / 2);
            got90 = true;
        }
        if (!got180 && turn >= FW_PI) {
            res->tactical_diameter = cross(prev_turn, turn, prev_y, trans, FW_PI);
            res->t180 = cross(prev_turn, turn, prev_t, t, FW_PI);
            got180 = true;
        }
        ring_turn[count] = turn;
        ring_t[count] = t;
        ring_U[count++] = hypot(x->u, x->vm);
        prev_turn = turn;
        prev_x = adv;
        prev_y = trans;
        prev_t = t;
        if (turn >= def->max_turn)
            break;
    }
    if (!got180) {
        s = fw_fail(err, FW_ERUN,
                    "%s did not turn 180 deg within %.0f s at %.1f kn and %.0f deg rudder",
                    ship->name, def->max_time, fw_ms_to_kn(def->speed),
                    fw_rad_to_deg(def->rudder));
        goto free_rings;
    }
    /* Steady values over the last full circle (or whatever came after 180 deg). */
    double last = ring_turn[count - 1];
    double from = last - 2 * FW_PI > FW_PI ? last - 2 * FW_PI : FW_PI;
    size_t i0 = 0;
    while (i0 < count && ring_turn[i0] < from)
        i0++;
    double sumU = 0.0;
    for (size_t i = i0; i < count; i++)
        sumU += ring_U[i];
    res->steady_speed = sumU / (double)(count - i0);
    res->steady_rate = (ring_turn[count - 1] - ring_turn[i0]) / (ring_t[count - 1] - ring_t[i0]);
    res->advance_ok = res->advance <= 4.5 * ship->L;
    res->tactical_ok = res->tactical_diameter <= 5.0 * ship->L;
    s = FW_OK;
free_rings:
    free(ring_turn);
    free(ring_t);
    free(ring_U);
done:
    fw_stepper_destroy(st);
    return s;
}

void fw_imo_overshoot_limits(double angle_deg, double L_over_V, double *limit1, double *limit2)
{
    if (fabs(angle_deg - 20.0) < 1e-9) {
        *limit1 = 25.0;
        *limit2 = -1.0;
        return;
    }
    if (fabs(angle_deg - 10.0) > 1e-9) {
        *limit1 = *limit2 = -1.0; /* the standard covers 10/10 and 20/20 only */
        return;
    }
    if (L_over_V < 10.0) {
        *limit1 = 10.0;
        *limit2 = 25.0;
    } else if (L_over_V >= 30.0) {
        *limit1 = 20.0;
        *limit2 = 40.0;
    } else {
        *limit1 = 5.0 + 0.5 * L_over_V;
        *limit2 = 17.5 + 0.75 * L_over_V;
    }
}

fw_status fw_zigzag_run(const fw_ship *ship, const fw_zigzag_def *def, fw_zigzag_result *res,
                        fw_history *hist, fw_error *err)
{
    memset(res, 0, sizeof *res);
    if (def->executes < 2)
        return fw_fail(err, FW_EINPUT, "a zig-zag needs at least 2 helm reversals");
    fw_stepper *st;
    fw_status s = start_straight(ship, def->speed, def->angle, def->sample_dt, &def->stepper,
                                 &st, &res->propeller, err);
    if (s)
        return s;
    const double a = fabs(def->angle);
    double side = def->first_side >= 0 ? 1.0 : -1.0;
    fw_stepper_set_helm(st, side * a);
    if ((s = history_add(hist, st, err)))
        goto done;
    /* side is the direction of the current helm; the heading is checked
     * against side * a.  Overshoot k is the heading's excursion beyond the
     * trigger angle after reversal k. */
    int executes = 0;
    double peak = 0.0;
    double over[3] = {0};
    while (fw_stepper_time(st) < def->max_time) {
        if ((s = fw_stepper_advance(st, def->sample_dt, err)) || (s = history_add(hist, st, err)))
            goto done;
        double psi = fw_stepper_state(st)->psi;
        if (executes > 0 && executes <= 2) {
            /* after reversal k the heading still moves the old way: -side */
            double excursion = -side * psi;
            if (excursion > peak)
                peak = excursion;
            over[executes] = peak - a;
        }
        if (side * psi >= a) {
            if (executes == 0)
                res->t_first_execute = fw_stepper_time(st);
            side = -side;
            fw_stepper_set_helm(st, side * a);
            executes++;
            peak = -INFINITY;
            if (executes >= def->executes)
                break;
        }
    }
    if (executes < 3) {
        s = fw_fail(err, FW_ERUN, "%s: zig-zag did not complete 3 helm reversals in %.0f s",
                    ship->name, def->max_time);
        goto done;
    }
    res->overshoot1 = over[1];
    res->overshoot2 = over[2];
    res->L_over_V = ship->L / def->speed;
    double l1, l2;
    fw_imo_overshoot_limits(fw_rad_to_deg(a), res->L_over_V, &l1, &l2);
    res->limit1 = l1 >= 0 ? fw_deg_to_rad(l1) : -1.0;
    res->limit2 = l2 >= 0 ? fw_deg_to_rad(l2) : -1.0;
    res->ok1 = l1 < 0 || res->overshoot1 <= res->limit1;
    res->ok2 = l2 < 0 || res->overshoot2 <= res->limit2;
    s = FW_OK;
done:
    fw_stepper_destroy(st);
    return s;
}
