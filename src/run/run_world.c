/* run_world.c - a run's world from its scenario: the traffic source (SUMO,
 * the kinematic source, recorded tracks, AIS reports) and the own ship
 * (run_world.h; the run's set-up, run.c). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "ais/ais_track.h"
#include "avoid/route.h"
#include "core/files.h"
#include "core/units.h"
#include "run/run_world.h"
#include "scenario/scn_dnv.h"
#include "traffic/source_mirror.h"
#include "traffic/source_sumo.h"
#include "traffic/source_track.h"
#include "world/controllers.h"

/* The own ship at t = 0 as a record (hull centre, heading, speed, size). */
static fw_target own_start(const fw_scenario *s)
{
    fw_target o = {.east = s->east, .north = s->north, .course = s->course, .speed = s->speed,
                   .heading = s->course, .stw = s->speed, .length = s->ship.Loa,
                   .breadth = s->ship.B};
    snprintf(o.id, sizeof o.id, "fw_own");
    return o;
}

/* m, how far out the reactive traffic is watched: beyond sight by what
 * two ships crossing at 15 kn close in the reactions' horizon of 15
 * minutes, 4 nm, so that a ship coming into sight has been giving way
 * already (none with blind traffic). */
static double near_radius(const fw_scenario *s)
{
    if (s->reactions.behaviour == FW_BEHAVIOUR_BLIND)
        return 0.0;
    return s->radius + 4.0 * FW_NMILE;
}

/* The run's sumo/ directory, created: SUMO's files and logs. */
static fw_status sumo_dir(const fw_run_def *def, char *dir, size_t n, fw_error *err)
{
    if (!def->dir)
        return fw_fail(err, FW_EINPUT, "%s: SUMO traffic needs a run directory",
                       def->scenario->file);
    fw_status st = fw_path(dir, n, err, "%s/sumo", def->dir);
    if (!st && mkdir(dir, 0777) != 0)
        st = fw_fail(err, FW_ERUN, "cannot create %s", dir);
    return st;
}

static fw_status sumo_source(const fw_run_def *def, fw_source **src, fw_error *err)
{
    const fw_scenario *s = def->scenario;
    char dir[1100];
    fw_status st = sumo_dir(def, dir, sizeof dir, err);
    if (st)
        return st;
    fw_sumo_source_def dflt = fw_default_sumo_source_def();
    fw_sumo_source_def sd = {.mode = def->mode, .dir = dir, .network = s->network,
                             .density = s->density, .fill = s->fill, .seed = s->seed,
                             .duration = s->duration, .step = s->step, .fcd = s->fcd,
                             .fcd_period = s->record_every,
                             .proj = s->plane[0] ? s->plane : NULL,
                             .proj_off_e = s->plane_off_e, .proj_off_n = s->plane_off_n,
                             .targets = s->targets,
                             .n_targets = s->n_targets, .own = own_start(s), .own_leg = s->leg,
                             .radius = s->radius,
                             .area_radius = s->survey ? s->survey_radius : 0.0,
                             .near_radius = near_radius(s),
                             .clear_range = dflt.clear_range, .clear_cpa = dflt.clear_cpa,
                             .clear_tcpa = dflt.clear_tcpa};
    return fw_sumo_source_create(&sd, src, err);
}

fw_status fw_run_kinematic_source(const fw_scenario *s, double step, double radius,
                                  fw_source **src, fw_error *err)
{
    if (s->network[0])
        return fw_fail(err, FW_EINPUT, "%s: traffic on network '%s' needs SUMO, not the "
                                       "kinematic source", s->file, s->network);
    fw_kin_ship ships[FW_SCN_MAX_TARGETS];
    for (int i = 0; i < s->n_targets; i++)
        ships[i] = (fw_kin_ship){.start = s->targets[i]};
    fw_kinematic_def kd = fw_default_kinematic_def();
    kd.ships = ships;
    kd.n = s->n_targets;
    kd.step = step;
    kd.radius = radius;
    kd.area_radius = s->survey ? s->survey_radius : 0.0;
    kd.own_id = "fw_own";
    return fw_kinematic_source_create(&kd, src, err);
}

fw_status fw_run_ais_tracks(const fw_scenario *s, fw_ais_tracks *t, fw_error *err)
{
    const fw_scn_ais *a = &s->ais;
    fw_ais_track_def d = fw_default_ais_track_def();
    d.origin_lat = s->origin_lat;
    d.origin_lon = s->origin_lon;
    if (s->plane[0]) {
        d.proj = s->plane;
        d.off_e = s->plane_off_e;
        d.off_n = s->plane_off_n;
    }
    d.start = a->start;
    d.end = a->end;
    d.start_rel = a->start_rel;
    d.end_rel = a->end_rel;
    d.max_gap = a->max_gap;
    fw_ais_columns cols;
    if (a->columns[0] && fw_ais_columns_parse(a->columns, s->file, &cols, err))
        return err->status;
    d.cols = a->columns[0] ? &cols : NULL;
    fw_status st = fw_ais_tracks_load(a->file, &d, t, err);
    if (!st && t->n == 0)
        st = fw_fail(err, FW_EINPUT, "%s: no ship reports in the scenario's window and within "
                                     "%.0f km of its origin", a->file, d.area_radius / 1000);
    return st;
}

/* AIS reports replayed (ais/ais_track.h), the run's t = 0 the window's
 * start; with SUMO traffic also shown in SUMO (traffic/source_mirror.h). */
static fw_status ais_source(const fw_run_def *def, const fw_replay_def *td, fw_source **src,
                            fw_ais_tracks *info, fw_error *err)
{
    const fw_scenario *s = def->scenario;
    fw_ais_tracks t;
    fw_status st = fw_run_ais_tracks(s, &t, err);
    if (!st) {
        *info = t; /* the counts only */
        info->v = NULL;
        info->ships = NULL;
    }
    fw_replay_def d = *td;
    d.max_gap = s->ais.max_gap;
    bool sumo = def->traffic == FW_RUN_TRAFFIC_SUMO;
    if (sumo)
        d.radius = INFINITY; /* every ship shown; the mirror applies the sight */
    if (!st)
        st = fw_ais_replay_source_create(&t, &d, src, err);
    fw_ais_tracks_free(&t);
    if (st || !sumo)
        return st;
    char dir[1100];
    if ((st = sumo_dir(def, dir, sizeof dir, err)))
        return st;
    fw_mirror_def md = {.mode = def->mode, .dir = dir, .step = s->step, .seed = s->seed,
                        .own = own_start(s), .own_leg = s->leg, .duration = s->duration,
                        .radius = s->radius};
    fw_source *inner = *src;
    *src = NULL;
    return fw_mirror_source_create(inner, &md, src, err);
}

/* One point of a waypoint track: at t, (e, n), on course c at speed v. */
static bool push_point(fw_rec_track *tr, double t, double e, double n, double c, double v)
{
    if (!fw_rec_track_reserve(tr))
        return false;
    tr->p[tr->n++] = (fw_rec_point){.t = t, .east = e, .north = n, .course = c, .speed = v};
    return true;
}

/* The turns a situation's target was seen making (scn_dnv.h) on its track
 * (points in time order): a point at each turn's time, where the track puts
 * the ship then, heading and at the speed the turn says (a leg is a chord
 * of a turn, at its mean speed), and every point with the turn in force. */
static bool add_turns(fw_rec_track *tr, const fw_scn_turn *u, int nu)
{
    /* s: a turn on a waypoint (the situation's times are to the ms; a
     * waypoint's is the sum of its legs' times, to within a few us) */
    const double same = 1e-3;
    int n = tr->n, m = 0, j = 0;
    fw_rec_point *p = malloc(sizeof *p * (size_t)(n + nu));
    double rate = 0.0, to = 0.0;
    if (!p)
        return false;
    for (int k = 0; k < n; k++) {
        const fw_rec_point *b = &tr->p[k], *a = k > 0 ? b - 1 : b;
        double head = b->course, speed = b->speed, t_b = b->t;
        for (; j < nu && u[j].t <= b->t + same; j++) {
            rate = u[j].rate, to = u[j].to;
            bool on_b = fabs(u[j].t - b->t) <= same;
            if (on_b)
                head = u[j].heading, speed = u[j].speed, t_b = fmin(t_b, u[j].t);
            if (k == 0 || on_b)
                continue; /* before it appears, or on b */
            double w = (u[j].t - a->t) / (b->t - a->t);
            p[m++] = (fw_rec_point){.t = u[j].t, .east = a->east + w * (b->east - a->east),
                                    .north = a->north + w * (b->north - a->north),
                                    .course = u[j].heading, .speed = u[j].speed,
                                    .turn_rate = rate, .turn_to = to};
        }
        p[m] = *b;
        p[m].t = t_b;
        p[m].course = head, p[m].speed = speed, p[m].turn_rate = rate, p[m++].turn_to = to;
    }
    free(tr->p);
    tr->p = p, tr->n = m, tr->cap = n + nu;
    return true;
}

/* Targets following waypoints (scenario.h fw_scn_route, a DNV situation):
 * each a track through its waypoints from its appearance, straight at each
 * leg's speed, and on along its last leg past the run's end unless it
 * vanishes there; the recorded-track source replays
 * them (no gaps: max_gap infinite). */
static fw_status waypoint_source(const fw_scenario *s, const fw_replay_def *td, fw_source **src,
                                 fw_error *err)
{
    fw_rec_track *tr = calloc((size_t)s->n_targets + 1, sizeof *tr);
    if (!tr)
        return fw_fail(err, FW_ERUN, "out of memory");
    bool ok = true;
    for (int i = 0; i < s->n_targets && ok; i++) {
        const fw_scn_route *r = &s->target_routes[i];
        tr[i].info = s->targets[i];
        double t = r->appear, c = 0.0, v = 0.0;
        for (int k = 0; k + 1 < r->n && ok; k++) {
            const fw_scn_waypoint *a = &r->wp[k], *b = &r->wp[k + 1];
            double de = b->east - a->east, dn = b->north - a->north;
            c = fw_wrap_2pi(atan2(de, dn));
            v = b->speed;
            ok = push_point(&tr[i], t, a->east, a->north, c, v);
            t += hypot(de, dn) / v;
        }
        const fw_scn_waypoint *z = &r->wp[r->n - 1];
        double after = fmax(s->duration + 2.0 * s->step - t, 0.0) * v;
        if (isfinite(r->vanish))
            after = 0.0;
        ok = ok && push_point(&tr[i], t, z->east, z->north, c, v) &&
             (after <= 0.0 || push_point(&tr[i], t + after / v, z->east + after * sin(c),
                                         z->north + after * cos(c), c, v));
        fw_scn_turn *u = NULL;
        int nu = 0;
        fw_status st = ok && r->turns ? fw_scn_dnv_turns(s->file, i, &u, &nu, err) : FW_OK;
        if (st) {
            fw_rec_tracks_free(tr, s->n_targets);
            return st;
        }
        ok = ok && (nu == 0 || add_turns(&tr[i], u, nu));
        free(u);
    }
    if (!ok) {
        fw_rec_tracks_free(tr, s->n_targets);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    fw_replay_def d = *td;
    d.max_gap = INFINITY;
    return fw_track_source_create(tr, s->n_targets, &d, s->file, src, err);
}

/* The world: the source and the own ship (MMG, the avoidance policy or the
 * caller's controller, which is destroyed here if the world is not made). */
fw_status fw_run_make_world(const fw_run_def *def, fw_world **w, fw_vessel **own,
                            fw_ais_tracks *ais, fw_error *err)
{
    memset(ais, 0, sizeof *ais);
    const fw_scenario *s = def->scenario;
    fw_controller *ctl = def->controller;
    fw_source *src = NULL;
    fw_replay_def td = fw_default_replay_def();
    td.file = s->tracks;
    td.step = s->step;
    td.radius = s->radius;
    /* recorded tracks replay without SUMO, whatever the run asked for */
    fw_status st = s->tracks[0]     ? fw_replay_source_create(&td, &src, err)
                   : s->waypoint_targets ? waypoint_source(s, &td, &src, err)
                   : s->ais.file[0] ? ais_source(def, &td, &src, ais, err)
                   : def->traffic == FW_RUN_TRAFFIC_KINEMATIC
                       ? fw_run_kinematic_source(s, s->step, s->radius, &src, err)
                       : sumo_source(def, &src, err);
    fw_world_def wd = fw_default_world_def();
    wd.step = s->step;
    wd.source = src;
    wd.reactions = s->reactions;
    wd.timing = def->profile;
    wd.seed = s->seed; /* the replication's: fairway's random streams (core/rng.h) */
    wd.env = s->env;   /* the scenario's current and wind (calm by default) */
    wd.own_sensing = s->sensing; /* what the own ship knows of the others */
    if (s->sensing_background) /* and the reacting traffic (world/reactions.h) */
        wd.reactions.sensing = s->sensing;
    wd.own_watch = s->own_watch; /* and how soon it notices them */
    if (st || (st = fw_world_create(&wd, w, err))) {
        fw_controller_destroy(ctl);
        return st;
    }
    fw_policy_controller_def pd = {.ship = &s->ship, .helm = s->helm, .policy = s->policy};
    /* its planned route: the scenario's, or one leg from its start on its
     * course at its speed */
    pd.policy.route = s->route.n > 0 ? s->route
                                     : fw_route_line(s->east, s->north, s->course, s->speed,
                                                     fmax(s->leg, s->speed * s->duration));
    /* in a wind, a ship with its rudder amidships turns into it (the wind's
     * yaw moment: 32 deg in 10 minutes for the C-3 in a 30 kn beam wind); in
     * a current it keeps its heading and is set off its track (2.0 km in half
     * an hour across the Dover tidal stream at 12 kn, crossing the lanes).
     * A master corrects for both, so in either its one leg is steered as a
     * route is (route.h), over ground; in calm air and water the rudder
     * stays amidships until the first avoidance */
    if (s->route.n == 0 &&
        (!fw_wind_is_calm(&s->env.wind) || s->env.current.kind != FW_FIELD_NONE))
        pd.policy.route.steered = true;
    /* a waterway's room is the hull's: its centre keeps half its breadth in */
    for (int k = 0; k < pd.policy.route.n; k++) {
        fw_route_leg *l = &pd.policy.route.leg[k];
        if (l->room_starboard > 0.0)
            l->room_starboard = fmax(1.0, l->room_starboard - 0.5 * s->ship.B);
        if (l->room_port > 0.0)
            l->room_port = fmax(1.0, l->room_port - 0.5 * s->ship.B);
    }
    if (!ctl && (st = fw_policy_controller_create(&pd, &ctl, err)))
        return st;
    fw_vessel_def vd = fw_default_vessel_def();
    vd.id = "fw_own";
    vd.ship = &s->ship;
    vd.dynamics = s->nomoto_plant ? FW_DYN_NOMOTO : FW_DYN_MMG;
    vd.east = s->east;
    vd.north = s->north;
    vd.course = s->course;
    vd.speed = s->speed;
    vd.radius = s->radius;
    vd.controller = ctl;
    fw_vessel_handle h;
    if ((st = fw_world_add_vessel(*w, &vd, &h, err)))
        return st;
    *own = fw_world_vessel(*w, h); /* never removed: borrowed for the run */
    return FW_OK;
}
