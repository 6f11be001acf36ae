/* The own ship's integrator.
 *
 * Why ARKODE's explicit Runge-Kutta (ERKStep, Cash-Karp 5(4)) and not CVODE: the MMG model is not stiff (its fastest time constant is the yaw
 * response, tens of seconds at full scale), and its inputs jump often -- the
 * avoidance logic may change the helm order at any control step, and every
 * helm change also moves the kink where the rudder reaches its order.  A jump
 * in an input needs a re-initialisation.  CVODE's Adams method restarts at
 * order 1 with a tiny step after each one and needs dozens of steps to climb
 * back (measured when this integrator was chosen, with a CVODE stepper the
 * project did not keep: 20.6 ms per simulated hour against 3.0 ms for plain
 * RK4; bench/bench_stepper.c measures this one against RK4 today).  A
 * one-step method has no history to lose: after a re-initialisation it
 * resumes with the last accepted step size.  Its dense
 * output also lets one internal step span several 1 s control steps when
 * nothing changes, so the integrator is NOT re-initialised at every step.
 * Cash-Karp rather than Dormand-Prince: on an hour of helm orders every 60 s
 * (bench/bench_stepper.c) it needed fewer right-hand-side evaluations (21100
 * against 23500) for a 20 times smaller error (0.001 m against 0.023 m) at the
 * same rtol = 1e-8; Verner 6(5) needed twice as many.
 *
 * The rudder is not an ODE state: between input changes it moves at the rate
 * limit towards the order, so its angle is a known piecewise-linear function
 * of time.  The instant it reaches the order is a kink of the right-hand side
 * (delta' jumps to zero) known in advance, so the integrator stops exactly
 * there (a stop time) and is re-initialised -- no root finding needed.
 */
#include "dynamics/stepper.h"

#include <arkode/arkode_erkstep.h>
#include <math.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { NEQ = 6 };

struct fw_stepper {
    const fw_ship *ship;
    fw_stepper_def def;
    SUNContext ctx;
    N_Vector y;
    N_Vector atol;
    void *ark;
    bool started;
    bool drift;        /* a current moves the water (else the calm right-hand side) */
    bool windy;        /* a wind blows (else no wind force, not even a zero one) */
    double wind_speed, wind_from; /* m/s, rad: the wind now (fw_stepper_set_wind) */

    double t;          /* current time (the state below is at t) */
    fw_mmg_state s;
    double n;          /* propeller speed, rev/s */
    double helm;       /* order, rad */

    /* rudder segment: delta(t) = seg_delta0 + seg_rate * (t - seg_t0) until seg_t1 */
    double seg_t0, seg_delta0, seg_rate, seg_t1;
    bool need_reinit;  /* an input changed since the integrator last ran */
    double h_last;     /* last step size, reused after re-initialisation */
    long nfe_total;    /* RHS evaluations over all segments */
    long reinits;
    char sundials_msg[256];
};

fw_stepper_def fw_default_stepper_def(void)
{
    fw_stepper_def d = {
        .rtol = 1e-8,
        .atol_vel = 1e-7,
        .atol_pos = 1e-5,
        .max_step = 0.0,
        .current = {.kind = FW_FIELD_NONE},
        .wind = {.kind = FW_FIELD_NONE},
    };
    return d;
}

static double rudder_at(const fw_stepper *st, double t)
{
    if (t >= st->seg_t1)
        return st->helm;
    return st->seg_delta0 + st->seg_rate * (t - st->seg_t0);
}

static int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void *user)
{
    fw_stepper *st = user;
    const sunrealtype *v = N_VGetArrayPointer(y);
    fw_mmg_state s = {.u = v[0], .vm = v[1], .r = v[2], .east = v[3], .north = v[4],
                      .psi = v[5], .delta = rudder_at(st, t)};
    double d[NEQ], ce = 0.0, cn = 0.0;
    if (st->drift)
        fw_current_at(&st->def.current, v[3], v[4], t, &ce, &cn);
    if (st->windy) {
        double wind[3];
        fw_mmg_wind(st->ship, &s, ce, cn, st->wind_speed, st->wind_from, wind);
        fw_mmg_derivs_ext(st->ship, &s, st->n, wind, d);
    } else {
        fw_mmg_derivs(st->ship, &s, st->n, d);
    }
    if (st->drift) {
        /* over ground: through the water plus the water (stepper.h) */
        d[3] += ce;
        d[4] += cn;
    }
    sunrealtype *out = N_VGetArrayPointer(ydot);
    for (int i = 0; i < NEQ; i++) {
        if (!isfinite(d[i]))
            return -1; /* unrecoverable: ARKODE stops with ARK_RHSFUNC_FAIL */
        out[i] = d[i];
    }
    return 0;
}

static void on_sundials_error(int code, const char *module, const char *function, char *msg,
                              void *user)
{
    fw_stepper *st = user;
    snprintf(st->sundials_msg, sizeof st->sundials_msg, "%s/%s (%d): %s", module, function, code,
             msg);
}

static fw_status check(fw_stepper *st, int flag, const char *call, fw_error *err)
{
    if (flag >= 0)
        return FW_OK;
    char *name = ERKStepGetReturnFlagName(flag);
    fw_fail(err, FW_ERUN, "%s failed at t = %.3f s: %s%s%s", call, st->t, name ? name : "?",
            st->sundials_msg[0] ? "; " : "", st->sundials_msg);
    free(name);
    return FW_ERUN;
}

fw_status fw_stepper_create(const fw_ship *ship, const fw_stepper_def *def, fw_stepper **out,
                            fw_error *err)
{
    *out = NULL;
    fw_stepper *st = calloc(1, sizeof *st);
    if (!st)
        return fw_fail(err, FW_ERUN, "out of memory");
    st->ship = ship;
    st->def = def ? *def : fw_default_stepper_def();
    st->drift = !fw_current_is_none(&st->def.current);
    if (!(st->def.rtol > 0.0) || !(st->def.atol_vel > 0.0) || !(st->def.atol_pos > 0.0)) {
        free(st);
        return fw_fail(err, FW_EINPUT, "stepper tolerances must be positive");
    }
    fw_env env = {.current = st->def.current, .wind = st->def.wind};
    if (fw_env_check(&env, err) || fw_env_check_vessel(&env, "stepper", ship, true, err)) {
        free(st);
        return FW_EINPUT;
    }
    st->windy = !fw_wind_is_calm(&st->def.wind);
    fw_wind_at(&st->def.wind, 0.0, 0.0, 0.0, &st->wind_speed, &st->wind_from);
    if (SUNContext_Create(NULL, &st->ctx)) {
        free(st);
        return fw_fail(err, FW_ERUN, "SUNContext_Create failed");
    }
    st->y = N_VNew_Serial(NEQ, st->ctx);
    st->atol = N_VNew_Serial(NEQ, st->ctx);
    if (!st->y || !st->atol) {
        fw_stepper_destroy(st);
        return fw_fail(err, FW_ERUN, "N_VNew_Serial failed");
    }
    /* Absolute tolerances per component: yaw rate and heading are scaled by L
     * so an error in them means the same distance as one in sway or position. */
    sunrealtype *a = N_VGetArrayPointer(st->atol);
    a[0] = a[1] = st->def.atol_vel;
    a[2] = st->def.atol_vel / ship->L;
    a[3] = a[4] = st->def.atol_pos;
    a[5] = st->def.atol_pos / ship->L;
    *out = st;
    return FW_OK;
}

void fw_stepper_destroy(fw_stepper *st)
{
    if (!st)
        return;
    if (st->ark)
        ERKStepFree(&st->ark);
    if (st->y)
        N_VDestroy(st->y);
    if (st->atol)
        N_VDestroy(st->atol);
    if (st->ctx)
        SUNContext_Free(&st->ctx);
    free(st);
}

/* Starts a rudder segment at the current time towards the current order. */
static void new_segment(fw_stepper *st)
{
    double diff = st->helm - st->s.delta;
    st->seg_t0 = st->t;
    st->seg_delta0 = st->s.delta;
    if (diff == 0.0) {
        st->seg_rate = 0.0;
        st->seg_t1 = st->t;
    } else {
        st->seg_rate = diff > 0.0 ? st->ship->rudder_rate : -st->ship->rudder_rate;
        st->seg_t1 = st->t + fabs(diff) / st->ship->rudder_rate;
    }
    st->need_reinit = true;
}

static void load_y(fw_stepper *st)
{
    sunrealtype *v = N_VGetArrayPointer(st->y);
    v[0] = st->s.u;
    v[1] = st->s.vm;
    v[2] = st->s.r;
    v[3] = st->s.east;
    v[4] = st->s.north;
    v[5] = st->s.psi;
}

static void store_y(fw_stepper *st, N_Vector y, double t)
{
    const sunrealtype *v = N_VGetArrayPointer(y);
    st->s.u = v[0];
    st->s.vm = v[1];
    st->s.r = v[2];
    st->s.east = v[3];
    st->s.north = v[4];
    st->s.psi = v[5];
    st->t = t;
    st->s.delta = rudder_at(st, t);
}

fw_status fw_stepper_start(fw_stepper *st, double t0, const fw_mmg_state *s0, double n,
                           fw_error *err)
{
    const double *v = &s0->u;
    for (int i = 0; i < 7; i++)
        if (!isfinite(v[i]))
            return fw_fail(err, FW_EINPUT, "initial state has a non-finite value");
    if (!isfinite(n) || n < 0.0)
        return fw_fail(err, FW_EINPUT, "propeller speed must be finite and >= 0");
    if (fabs(s0->delta) > st->ship->rudder_max * (1.0 + 1e-12))
        return fw_fail(err, FW_EINPUT, "initial rudder angle beyond the maximum");
    st->t = t0;
    st->s = *s0;
    st->n = n;
    st->helm = s0->delta;
    st->sundials_msg[0] = '\0';
    load_y(st);
    int flag;
    if (!st->ark) {
        st->ark = ERKStepCreate(rhs, t0, st->y, st->ctx);
        if (!st->ark)
            return fw_fail(err, FW_ERUN, "ERKStepCreate failed");
        if (check(st, ERKStepSetErrHandlerFn(st->ark, on_sundials_error, st), "ERKStepSetErrHandlerFn", err) ||
            check(st, ERKStepSetUserData(st->ark, st), "ERKStepSetUserData", err) ||
            check(st, ERKStepSVtolerances(st->ark, st->def.rtol, st->atol), "ERKStepSVtolerances", err) ||
            check(st, ERKStepSetTableNum(st->ark, ARKODE_CASH_KARP_6_4_5), "ERKStepSetTableNum", err) ||
            check(st, ERKStepSetMaxNumSteps(st->ark, 100000), "ERKStepSetMaxNumSteps", err) ||
            check(st, ERKStepSetDenseOrder(st->ark, 5), "ERKStepSetDenseOrder", err))
            return FW_ERUN;
        if (st->def.max_step > 0.0 &&
            check(st, ERKStepSetMaxStep(st->ark, st->def.max_step), "ERKStepSetMaxStep", err))
            return FW_ERUN;
    } else {
        flag = ERKStepReInit(st->ark, rhs, t0, st->y);
        if (check(st, flag, "ERKStepReInit", err))
            return FW_ERUN;
    }
    st->h_last = 0.0;
    st->nfe_total = 0;
    st->reinits = 0;
    st->started = true;
    new_segment(st);
    if (check(st, ERKStepSetStopTime(st->ark, st->t + 1e9), "ERKStepSetStopTime", err))
        return FW_ERUN;
    st->need_reinit = false; /* the integrator was just (re)initialised here */
    return FW_OK;
}

void fw_stepper_set_helm(fw_stepper *st, double helm)
{
    double max = st->ship->rudder_max;
    if (!isfinite(helm))
        return;
    if (helm > max)
        helm = max;
    if (helm < -max)
        helm = -max;
    if (helm == st->helm)
        return;
    st->helm = helm;
    new_segment(st);
}

void fw_stepper_set_wind(fw_stepper *st, double speed, double from)
{
    if (!st->windy || !isfinite(speed) || speed < 0.0 || !isfinite(from) ||
        (speed == st->wind_speed && from == st->wind_from))
        return;
    st->wind_speed = speed;
    st->wind_from = from;
    st->need_reinit = true;
}

void fw_stepper_set_propeller(fw_stepper *st, double n)
{
    if (!isfinite(n) || n < 0.0 || n == st->n)
        return;
    st->n = n;
    st->need_reinit = true;
}

static fw_status reinit(fw_stepper *st, fw_error *err)
{
    long nfe = 0;
    ERKStepGetNumRhsEvals(st->ark, &nfe);
    st->nfe_total += nfe;
    load_y(st);
    if (check(st, ERKStepReInit(st->ark, rhs, st->t, st->y), "ERKStepReInit", err))
        return FW_ERUN;
    /* No internal step may cross the rudder's kink: even when the caller
     * asks for an earlier time, ERK steps beyond it and interpolates back.
     * Without a kink ahead the stop time is pushed out of the way (6.4 has no
     * way to clear it, and an old one would lie behind the new start). */
    double tstop = st->seg_t1 > st->t ? st->seg_t1 : st->t + 1e9;
    if (check(st, ERKStepSetStopTime(st->ark, tstop), "ERKStepSetStopTime", err))
        return FW_ERUN;
    if (st->h_last > 0.0 && check(st, ERKStepSetInitStep(st->ark, st->h_last), "ERKStepSetInitStep", err))
        return FW_ERUN;
    st->reinits++;
    st->need_reinit = false;
    return FW_OK;
}

static fw_status evolve_to(fw_stepper *st, double tout, fw_error *err)
{
    sunrealtype tret = st->t;
    int flag = ERKStepEvolve(st->ark, tout, st->y, &tret, ARK_NORMAL);
    if (check(st, flag, "ERKStepEvolve", err))
        return FW_ERUN;
    double h = 0.0;
    ERKStepGetLastStep(st->ark, &h);
    if (h > 0.0)
        st->h_last = h;
    store_y(st, st->y, tout);
    return FW_OK;
}

fw_status fw_stepper_advance(fw_stepper *st, double dt, fw_error *err)
{
    if (!st->started)
        return fw_fail(err, FW_ERUN, "stepper advanced before fw_stepper_start");
    if (!(dt > 0.0) || !isfinite(dt))
        return fw_fail(err, FW_EINPUT, "time step must be positive (got %g s)", dt);
    st->sundials_msg[0] = '\0';
    const double t_end = st->t + dt;
    /* Tolerance for "the kink is at the end of this step": below it the
     * rudder is simply at its order at t_end. */
    const double eps = 1e-9 * (1.0 + fabs(t_end));
    for (;;) {
        if (st->need_reinit && reinit(st, err))
            return FW_ERUN;
        bool kink_inside = st->seg_t1 > st->t && st->seg_t1 < t_end - eps;
        if (!kink_inside) {
            bool kink_at_end = st->seg_t1 > st->t && st->seg_t1 <= t_end + eps;
            if (evolve_to(st, kink_at_end ? st->seg_t1 : t_end, err))
                return FW_ERUN;
            if (kink_at_end) {
                st->t = t_end;
                st->s.delta = st->helm;
                st->need_reinit = true; /* the next step starts past the kink */
            }
            break;
        }
        if (evolve_to(st, st->seg_t1, err))
            return FW_ERUN;
        st->s.delta = st->helm;
        st->need_reinit = true;
    }
    for (int i = 0; i < NEQ; i++)
        if (!isfinite((&st->s.u)[i]))
            return fw_fail(err, FW_ERUN, "state became non-finite at t = %.3f s", st->t);
    return FW_OK;
}

const fw_mmg_state *fw_stepper_state(const fw_stepper *st) { return &st->s; }
double fw_stepper_time(const fw_stepper *st) { return st->t; }
double fw_stepper_helm(const fw_stepper *st) { return st->helm; }
double fw_stepper_propeller(const fw_stepper *st) { return st->n; }
long fw_stepper_reinits(const fw_stepper *st) { return st->reinits; }

long fw_stepper_rhs_evals(const fw_stepper *st)
{
    long nfe = 0;
    if (st->ark)
        ERKStepGetNumRhsEvals(st->ark, &nfe);
    return st->nfe_total + nfe;
}
