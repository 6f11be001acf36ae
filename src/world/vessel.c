/* vessel.c - a vessel's dynamics and what it shows (vessel.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/mem.h"
#include "core/units.h"
#include "world/vessel_internal.h"

fw_vessel_def fw_default_vessel_def(void)
{
    return (fw_vessel_def){.id = "own", .role = FW_ROLE_OWN, .dynamics = FW_DYN_MMG,
                           .radius = 6.0 * 1852.0};
}

/* How far the heading (rad), the current (m/s) may move before the steady
 * wind drift is made again: 0.25 deg, 0.01 m/s.  Measured on c3-mmg at 12 kn
 * in a 30 kn beam wind: the leeway changes by 0.03 mm/s over 0.25 deg of
 * heading (about 0.01 m over a 10-minute prediction). */
static const double kDriftPsi = 0.25 * FW_PI / 180.0, kDriftCur = 0.01;

/* The steady drift of an MMG ship with windage in the world's mean wind at
 * its heading now (world/vessel.h "Wind drift"): the sway of straight running
 * (dynamics/mmg.h fw_mmg_steady_wind) across the heading (m/s east, north),
 * and its drift angle; zero in still air, for a ship without windage or a
 * Nomoto vessel, or where no steady straight running exists. */
static void wind_drift(fw_vessel *v, double ce, double cn, double *de, double *dn,
                       double *beta_ss, double *u_ss)
{
    *de = *dn = *beta_ss = 0.0;
    *u_ss = v->U0;
    const fw_wind *w = &v->env->wind;
    const fw_mmg_state *x = &v->motion;
    if (v->dyn != FW_DYN_MMG || fw_wind_is_calm(w) || !v->ship->windage.present)
        return;
    if (!(v->drift.valid && fabs(x->psi - v->drift.psi) < kDriftPsi &&
          v->drift.n == v->n_prop && fabs(ce - v->drift.ce) < kDriftCur &&
          fabs(cn - v->drift.cn) < kDriftCur)) {
        /* from the last solution (a step or two of Newton's method), else
         * from the ship's state */
        fw_mmg_state y = v->drift.valid && v->drift.ok ? v->drift.x : *x;
        y.psi = x->psi;
        fw_error err = {0};
        v->drift.ok =
            fw_mmg_steady_wind(v->ship, v->n_prop, ce, cn, w->speed, w->from, &y, &err) == FW_OK;
        if (v->drift.ok)
            v->drift.x = y;
        v->drift.valid = true;
        v->drift.psi = x->psi, v->drift.n = v->n_prop, v->drift.ce = ce, v->drift.cn = cn;
    }
    if (!v->drift.ok)
        return;
    double vm = v->drift.x.vm;
    *de = vm * cos(x->psi), *dn = -vm * sin(x->psi);
    *beta_ss = atan2(-vm, v->drift.x.u);
    *u_ss = v->drift.x.u;
}

/* The policy's view of the vessel and its record, from the motion state.
 * The policy's own state is through the water plus the current at the ship
 * (the track predictor adds it, track.h); the record has the hull's heading
 * and speed through the water, and the course and speed over ground (what
 * the others' CPA needs): in a current the triangle of velocities, in calm
 * water psi - beta (it differs from the heading in a turn, where the hull
 * drifts outwards) at the speed through the water. */
static void refresh(fw_vessel *v, double dt)
{
    const fw_mmg_state *x = &v->motion;
    double ce = 0.0, cn = 0.0;
    fw_current_at(&v->env->current, x->east, x->north, v->t, &ce, &cn);
    v->cur.valid = true, v->cur.t = v->t, v->cur.east = x->east, v->cur.north = x->north;
    v->cur.ce = ce, v->cur.cn = cn;
    double stw = hypot(x->u, x->vm), beta = atan2(-x->vm, x->u);
    if (v->dyn == FW_DYN_MMG) {
        v->own = (fw_own_state){.east = x->east, .north = x->north, .psi = x->psi,
                                .U = stw, .U0 = v->U0, .beta = beta, .r = x->r,
                                .rdot = v->advanced ? (x->r - v->r_prev) / dt : 0.0,
                                .delta = x->delta, .cur_e = ce, .cur_n = cn};
        double de, dn, beta_ss, u_ss;
        wind_drift(v, ce, cn, &de, &dn, &beta_ss, &u_ss);
        if (de != 0.0 || dn != 0.0) {
            /* the prediction carries it as it carries the current, starts
             * from the drift angle beyond the leeway's and goes on at the
             * straight-course speed the wind leaves (track.h) */
            v->own.cur_e += de, v->own.cur_n += dn;
            v->own.beta -= beta_ss;
            v->own.U0 = u_ss;
            v->own.delta_wind = v->drift.x.delta;
        }
    } else {
        v->own = v->nom;
        v->own.cur_e = ce, v->own.cur_n = cn;
    }
    fw_target *t = &v->record;
    t->pred = v->pred && !(v->pred->steady && v->pred->steady(v->pred)) ? v->pred : NULL;
    t->east = x->east;
    t->north = x->north;
    t->heading = x->psi;
    t->stw = stw;
    if (ce == 0.0 && cn == 0.0) {
        /* calm water: the direction of motion, the heading less the drift
         * angle (the same bits as the heading on a straight course, where
         * beta = -0) */
        t->course = x->psi - beta;
        t->speed = stw;
    } else {
        double ve = x->u * sin(x->psi) + x->vm * cos(x->psi) + ce;
        double vn = x->u * cos(x->psi) - x->vm * sin(x->psi) + cn;
        t->course = x->psi + fw_wrap_pi(atan2(ve, vn) - x->psi); /* near psi, as psi is kept */
        t->speed = hypot(ve, vn);
    }
}

static void nomoto_motion(fw_vessel *v)
{
    const fw_own_state *s = &v->nom;
    v->motion = (fw_mmg_state){.u = s->U, .vm = 0.0, .r = s->r, .east = s->east,
                               .north = s->north, .psi = s->psi, .delta = s->delta};
}

static fw_status init_mmg(fw_vessel *v, const fw_vessel_def *def, fw_error *err)
{
    fw_stepper_def sd = fw_default_stepper_def();
    sd.current = v->env->current;
    sd.wind = v->env->wind;
    fw_mmg_state x0 = fw_mmg_straight(def->speed, def->east, def->north, def->course);
    fw_status st;
    if ((st = fw_mmg_propeller_for_speed(def->ship, def->speed, &v->n_prop, err)) ||
        (st = fw_stepper_create(def->ship, &sd, &v->st, err)) ||
        (st = fw_stepper_start(v->st, 0.0, &x0, v->n_prop, err)))
        return st;
    v->motion = *fw_stepper_state(v->st);
    return FW_OK;
}

fw_status fw_vessel_init(fw_vessel *v, const fw_vessel_def *def, double dt, const fw_env *env,
                         fw_error *err)
{
    v->env = env;
    if (!def->id || !def->id[0] || strlen(def->id) >= sizeof v->id)
        return fw_fail(err, FW_EINPUT, "vessel id must have 1..%d characters",
                       FW_TARGET_ID_MAX - 1);
    if (!def->ship)
        return fw_fail(err, FW_EINPUT, "vessel '%s' has no ship", def->id);
    if (def->role != FW_ROLE_OWN && def->role != FW_ROLE_OTHER)
        return fw_fail(err, FW_EINPUT, "vessel '%s': role %d is not a role", def->id,
                       (int)def->role);
    if (!(def->radius > 0.0) || !isfinite(def->east) || !isfinite(def->north) ||
        !isfinite(def->course) || !(def->speed >= 0.0))
        return fw_fail(err, FW_EINPUT, "vessel '%s': not a start state (or sight <= 0)", def->id);
    snprintf(v->id, sizeof v->id, "%s", def->id);
    v->ship = def->ship;
    v->dyn = def->dynamics;
    v->role = def->role;
    v->radius = def->radius;
    v->U0 = def->speed;
    v->pred = def->predictor;
    v->record = (fw_target){.length = def->ship->Loa, .breadth = def->ship->B,
                            .pred = def->predictor};
    snprintf(v->record.id, sizeof v->record.id, "%s", def->id);
    snprintf(v->record.type, sizeof v->record.type, "%s", def->ship->name);
    fw_status st;
    if (v->dyn == FW_DYN_MMG) {
        if ((st = init_mmg(v, def, err)))
            return st;
    } else {
        v->nom = def->start_state
                     ? *def->start_state
                     : (fw_own_state){.east = def->east, .north = def->north, .psi = def->course,
                                      .U = def->speed, .U0 = def->speed};
        if ((st = fw_track_alloc(&v->one, 2, err)))
            return st;
        nomoto_motion(v);
    }
    refresh(v, dt);
    return FW_OK;
}

void fw_vessel_free(fw_vessel *v)
{
    fw_stepper_destroy(v->st);
    fw_track_free(&v->one);
    fw_controller_destroy(v->ctl);
    fw_free_each(5, v->view, v->as, v->order, v->truth, (void *)v->lanes);
}

/* A speed order (fw_decision.speed, a route leg's): the MMG ship's propeller
 * set to the revolutions of that speed on a straight course (the ship then
 * gathers or loses way by its own dynamics); the Nomoto plant, which has no
 * surge dynamics, takes the speed at once. */
static fw_status order_speed(fw_vessel *v, double speed, fw_error *err)
{
    if (v->dyn == FW_DYN_MMG) {
        double n;
        fw_status st = fw_mmg_propeller_for_speed(v->ship, speed, &n, err);
        if (st)
            return st;
        fw_stepper_set_propeller(v->st, n);
        v->n_prop = n;
    } else {
        v->nom.U = v->nom.U0 = speed;
    }
    v->U0 = speed;
    return FW_OK;
}

fw_status fw_vessel_advance(fw_vessel *v, double dt, fw_error *err)
{
    fw_status st;
    if (v->d.speed > 0.0 && v->d.speed != v->U0 && (st = order_speed(v, v->d.speed, err)))
        return st;
    if (v->dyn == FW_DYN_MMG) {
        v->r_prev = v->motion.r;
        fw_stepper_set_helm(v->st, v->d.helm);
        if (v->env->wind.gust_intensity > 0.0) {
            /* the gust of this step (env.h; the world draws it) */
            double speed, from;
            fw_wind_at(&v->env->wind, v->motion.east, v->motion.north, v->t, &speed, &from);
            fw_stepper_set_wind(v->st, speed, from);
        }
        if ((st = fw_stepper_advance(v->st, dt, err)))
            return st;
        v->motion = *fw_stepper_state(v->st);
    } else {
        /* one step of the predicted track, the light plant: its state is
         * the prediction's, speed and drift as they were */
        fw_track_def one = {.dt = dt, .horizon = dt};
        /* carried by the current at the start of the step: refresh's at
         * the same place and time (the same answer: the field is the run's) */
        if (v->cur.valid && v->cur.t == v->t && v->cur.east == v->nom.east &&
            v->cur.north == v->nom.north)
            v->nom.cur_e = v->cur.ce, v->nom.cur_n = v->cur.cn;
        else
            fw_current_at(&v->env->current, v->nom.east, v->nom.north, v->t, &v->nom.cur_e,
                          &v->nom.cur_n);
        if ((st = fw_track_predict(v->ship, &one, &v->nom, v->d.helm, &v->one, err)))
            return st;
        v->nom.east = v->one.east[1], v->nom.north = v->one.north[1];
        v->nom.psi = v->one.psi[1], v->nom.r = v->one.r[1];
        v->nom.delta = v->one.delta[1], v->nom.rdot = v->one.rdot[1];
        nomoto_motion(v);
    }
    v->advanced = true;
    v->t += dt;
    refresh(v, dt);
    return FW_OK;
}

fw_status fw_vessel_reserve(fw_vessel *v, int n, fw_error *err)
{
    if (n <= v->cap)
        return FW_OK;
    int cap = fw_grown_cap(v->cap, n);
    if (!fw_resize((void **)&v->view, sizeof *v->view, (size_t)cap) ||
        !fw_resize((void **)&v->truth, sizeof *v->truth, (size_t)cap) ||
        !fw_resize((void **)&v->as, sizeof *v->as, (size_t)cap) ||
        !fw_resize((void **)&v->order, sizeof *v->order, 2 * (size_t)cap) ||
        !fw_resize((void **)&v->lanes, sizeof *v->lanes, (size_t)cap))
        return fw_fail(err, FW_ERUN, "out of memory for %d targets", n);
    v->cap = cap;
    return FW_OK;
}

const char *fw_vessel_id(const fw_vessel *v) { return v->id; }
const fw_ship *fw_vessel_ship(const fw_vessel *v) { return v->ship; }
const fw_mmg_state *fw_vessel_motion(const fw_vessel *v) { return &v->motion; }
const fw_own_state *fw_vessel_own_state(const fw_vessel *v) { return &v->own; }
const fw_target *fw_vessel_record(const fw_vessel *v) { return &v->record; }
double fw_vessel_propeller(const fw_vessel *v) { return v->n_prop; }
const fw_decision *fw_vessel_decision(const fw_vessel *v) { return &v->d; }
fw_controller *fw_vessel_controller(fw_vessel *v) { return v->ctl; }
fw_vessel_role fw_vessel_role_of(const fw_vessel *v) { return v->role; }
bool fw_vessel_taken(const fw_vessel *v) { return v->taken; }

void fw_vessel_truth(const fw_vessel *v, const fw_target **targets, int *n, bool *sensed)
{
    *sensed = v->sensed;
    *targets = v->sensed ? v->truth : v->view;
    *n = v->sensed ? v->n_truth : v->n_view;
}

void fw_vessel_view(const fw_vessel *v, const fw_target **targets, const fw_assessment **as,
                    int *n)
{
    *targets = v->view;
    *as = v->ctl && v->ctl->ops->assesses ? v->as : NULL;
    *n = v->n_view;
}
