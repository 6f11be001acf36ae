/* run.c - one scenario run: set-up, a loop of world steps with records, tear-down (run.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "ais/ais_track.h"
#include "core/clock.h"
#include "core/files.h"
#include "core/units.h"
#include "nomoto/nomoto.h"
#include "run/run.h"
#include "traffic/source_mirror.h"
#include "traffic/source_track.h"
#include "traffic/source_sumo.h"
#include "world/controllers.h"
#include "world/world.h"

fw_run_def fw_default_run_def(void)
{
    fw_run_def d = {0};
    d.mode.kind = FW_TRAFFIC_EMBEDDED;
    d.traffic = FW_RUN_TRAFFIC_SUMO;
    return d;
}

const char *fw_run_status_name(fw_run_status s) { return s == FW_RUN_OK ? "ok" : "failed"; }

/* The own ship at t = 0 as a record (hull centre, heading, speed, size). */
static fw_target own_start(const fw_scenario *s)
{
    fw_target o = {.east = s->east, .north = s->north, .course = s->course, .speed = s->speed,
                   .length = s->ship.Loa, .breadth = s->ship.B};
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
                            fw_error *err)
{
    const fw_scenario *s = def->scenario;
    fw_ais_tracks t;
    fw_status st = fw_run_ais_tracks(s, &t, err);
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

/* The world: the source and the own ship (MMG, the avoidance policy). */
static fw_status make_world(const fw_run_def *def, fw_world **w, fw_vessel **own, fw_error *err)
{
    const fw_scenario *s = def->scenario;
    fw_source *src = NULL;
    fw_replay_def td = fw_default_replay_def();
    td.file = s->tracks;
    td.step = s->step;
    td.radius = s->radius;
    /* recorded tracks replay without SUMO, whatever the run asked for */
    fw_status st = s->tracks[0]     ? fw_replay_source_create(&td, &src, err)
                   : s->ais.file[0] ? ais_source(def, &td, &src, err)
                   : def->traffic == FW_RUN_TRAFFIC_KINEMATIC
                       ? fw_run_kinematic_source(s, s->step, s->radius, &src, err)
                       : sumo_source(def, &src, err);
    if (st)
        return st;
    fw_world_def wd = fw_default_world_def();
    wd.step = s->step;
    wd.source = src;
    wd.reactions = s->reactions;
    wd.timing = def->profile;
    if ((st = fw_world_create(&wd, w, err)))
        return st;
    fw_policy_controller_def pd = {.ship = &s->ship, .helm = s->helm, .policy = s->policy};
    fw_controller *ctl;
    if ((st = fw_policy_controller_create(&pd, &ctl, err)))
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
    return fw_world_add_vessel(*w, &vd, own, err);
}

typedef struct run_state {
    const fw_scenario *s;
    fw_world *w;
    fw_vessel *own;
    fw_records *rec;
    fw_survey *sv;           /* NULL: no survey */
    fw_monitor *mon;         /* the traffic monitors */
    fw_policy_mode mode_prev;
    double helm_prev, e_prev, n_prev;
    int reactions_seen;      /* the world's reactions already in run.log */
    bool kb_outside;         /* the own speed was outside the knowledge base's at the last step */
    bool profile;
    double t_setup, t_observe, t_loop; /* CPU s (--profile) */
} run_state;

/* The CPU clock with --profile, else 0 (no system calls). */
static double tick(const run_state *R) { return R->profile ? fw_cpu_s() : 0.0; }

/* The survey's step: every ship in the area, the own ship included. */
static fw_status survey_step(run_state *R, double t, fw_error *err)
{
    const fw_target *a;
    int n;
    fw_status st = fw_world_area(R->w, &a, &n, err);
    return st ? st : fw_survey_step(R->sv, t, a, n, err);
}

/* Survey totals into the summary, its records into the run directory and to
 * the caller; run.log gets the counts. */
static fw_status survey_finish(run_state *R, const fw_run_def *def, fw_run_summary *sum,
                               fw_error *err)
{
    fw_survey_totals tot;
    fw_survey_finish(R->sv, &tot);
    sum->survey = true;
    sum->traffic_ship_s = tot.ship_s;
    sum->n_traffic = tot.n;
    for (int k = 0; k < FW_SURVEY_NTYPES; k++)
        sum->traffic_by_type[k] = tot.by_type[k];
    sum->n_traffic_own = tot.n_own;
    fprintf(fw_records_log(R->rec),
            "survey: %d traffic encounters (%d head-on, %d overtaking, %d crossing; %d with the "
            "own ship) in %.1f ship-hours\n",
            tot.n, tot.by_type[FW_SURVEY_HEAD_ON], tot.by_type[FW_SURVEY_OVERTAKING],
            tot.by_type[FW_SURVEY_CROSSING], tot.n_own, tot.ship_s / 3600.0);
    int n;
    const fw_survey_record *r = fw_survey_records(R->sv, &n);
    if (def->survey_out && n > 0) {
        *def->survey_out = malloc(sizeof **def->survey_out * (size_t)n);
        if (!*def->survey_out)
            return fw_fail(err, FW_ERUN, "out of memory for %d survey records", n);
        memcpy(*def->survey_out, r, sizeof **def->survey_out * (size_t)n);
        *def->n_survey_out = n;
    }
    return fw_records_survey(R->rec, r, n, err);
}

/* The own ship acted this step: the encounter book, the summary and run.log. */
static void record_action(run_state *R, double t, const fw_decision *d, const fw_target *tg,
                          const fw_assessment *as, int n, fw_run_summary *sum)
{
    const char *pid = d->primary >= 0 && d->primary < n ? tg[d->primary].id : NULL;
    fw_records_action(R->rec, t, d->search.side, d->helm, pid, tg, as, n);
    sum->n_actions++;
    if (!sum->acted) {
        sum->acted = true;
        sum->t_act = t;
        sum->act_side = d->search.side;
        sum->act_helm = d->helm;
    }
    fprintf(fw_records_log(R->rec),
            "%9.1f  act %s %.0f deg for %s (%s, range %.0f m, DCPA %.0f m, TCPA %.0f s): %s\n", t,
            fw_side_name(d->search.side), fw_rad_to_deg(fabs(d->helm)), pid ? pid : "-",
            pid ? fw_situation_name(as[d->primary].situation) : "-",
            pid ? as[d->primary].range : 0.0, pid ? as[d->primary].dcpa : 0.0,
            pid ? as[d->primary].tcpa : 0.0, d->reason ? d->reason : "");
}

static void record_mode(run_state *R, double t, const fw_decision *d, fw_run_summary *sum)
{
    if (d->mode == R->mode_prev)
        return;
    fprintf(fw_records_log(R->rec), "%9.1f  %s -> %s, helm %.1f deg: %s\n", t,
            fw_policy_mode_name(R->mode_prev), fw_policy_mode_name(d->mode),
            fw_rad_to_deg(d->helm), d->reason ? d->reason : "");
    if (d->mode == FW_MODE_AUTOPILOT && isnan(sum->t_return))
        sum->t_return = t;
    if (R->mode_prev == FW_MODE_AUTOPILOT && d->mode == FW_MODE_STANDBY &&
        isnan(sum->t_on_course))
        sum->t_on_course = t;
    R->mode_prev = d->mode;
}

/* The background ships' new orders: run.log and the summary. */
static void record_reactions(run_state *R, fw_run_summary *sum)
{
    int n;
    const fw_reaction *x = fw_world_reactions(R->w, &n);
    for (; R->reactions_seen < n; R->reactions_seen++) {
        const fw_reaction *r = &x[R->reactions_seen];
        if (r->kind == FW_REACT_RESUME) {
            sum->n_resume++;
            fprintf(fw_records_log(R->rec), "%9.1f  traffic: %s resumes %.1f kn\n", r->t, r->ship,
                    fw_ms_to_kn(r->speed_to));
            continue;
        }
        sum->n_give_way++;
        sum->n_give_way_short += !r->enough;
        fprintf(fw_records_log(R->rec),
                "%9.1f  traffic: %s %s %s (%s): %s from %.1f to %.1f kn, CPA %.0f m", r->t,
                r->ship, r->situation == FW_SIT_STAND_ON ? "acts (rule 17(b)) for" : "gives way to",
                r->other, fw_situation_name(r->situation),
                r->speed_to > r->speed_from ? "speeds up" : "slows", fw_ms_to_kn(r->speed_from),
                fw_ms_to_kn(r->speed_to), r->dcpa_before);
        if (r->enough)
            fprintf(fw_records_log(R->rec), " -> %.0f m\n", r->dcpa_after);
        else
            fprintf(fw_records_log(R->rec), ": no speed keeps the passing distance, the one that passes farthest\n");
    }
}

/* Everything the records keep of one instant (the world's state and the
 * decision taken on it). */
/* The own ship's speed against its knowledge base's fitted speeds: a line in
 * run.log when it leaves them, the time outside in the summary. */
static void record_kb_speed(run_state *R, const fw_mmg_state *x, fw_run_summary *sum)
{
    const fw_nomoto_kb *kb = &R->s->ship.nomoto;
    double kn = fw_ms_to_kn(hypot(x->u, x->vm));
    sum->own_speed_min_kn = fmin(sum->own_speed_min_kn, kn);
    sum->own_speed_max_kn = fmax(sum->own_speed_max_kn, kn);
    bool outside = fw_nomoto_kb_speed(kb, kn) != FW_KB_SPEED_IN;
    if (outside)
        sum->kb_outside_s += R->s->step;
    if (outside && !R->kb_outside)
        fprintf(fw_records_log(R->rec),
                "%9.1f  warning: own speed %.2f kn is outside %.2f-%.2f kn, the speeds %s's "
                "Nomoto knowledge base was fitted over: its predictions are extrapolated\n",
                fw_world_time(R->w), kn, kb->speed_min_kn, kb->speed_max_kn, R->s->ship.name);
    R->kb_outside = outside;
}

static fw_status observe(run_state *R, long k, fw_run_summary *sum, fw_error *err)
{
    const fw_scenario *s = R->s;
    double t = fw_world_time(R->w);
    fw_status st = R->sv ? survey_step(R, t, err) : FW_OK;
    if (st)
        return st;
    const fw_mmg_state *x = fw_vessel_motion(R->own);
    const fw_decision *d = fw_vessel_decision(R->own);
    const fw_target *tg;
    const fw_assessment *as;
    int n;
    fw_vessel_view(R->own, &tg, &as, &n);
    if ((st = fw_monitor_step(R->mon, t, fw_vessel_record(R->own), tg, n, err)))
        return st;
    bool row = k % lround(s->record_every / s->step) == 0;
    if (row)
        fw_records_own(R->rec, t, x, d->helm, fw_vessel_propeller(R->own),
                       fw_policy_mode_name(d->mode));
    for (int i = 0; i < n; i++)
        if ((st = fw_records_target(R->rec, t, &tg[i], x, &as[i], row, err)))
            return st;
    if (d->acted)
        record_action(R, t, d, tg, as, n, sum);
    record_mode(R, t, d, sum);
    sum->max_helm = fmax(sum->max_helm, fabs(d->helm));
    if (fabs(d->helm - R->helm_prev) > fw_deg_to_rad(0.5)) {
        sum->helm_orders++;
        R->helm_prev = d->helm;
    }
    record_reactions(R, sum);
    record_kb_speed(R, x, sum);
    sum->t_end = t;
    return FW_OK;
}

/* The first instant: the world started and observed. */
static fw_status loop_start(run_state *R, fw_run_summary *sum, fw_error *err)
{
    const fw_scenario *s = R->s;
    R->e_prev = s->east;
    R->n_prev = s->north;
    R->mode_prev = FW_MODE_STANDBY;
    fw_status st = fw_world_start(R->w, err);
    double t1 = tick(R);
    if (!st)
        st = observe(R, 0, sum, err);
    R->t_observe += tick(R) - t1;
    return st;
}

/* One world step, its accumulators and the records of the new instant k. */
static fw_status loop_step(run_state *R, long k, fw_run_summary *sum, fw_error *err)
{
    const fw_scenario *s = R->s;
    fw_status st = fw_world_step(R->w, s->step, err);
    if (st)
        return st;
    const fw_mmg_state *x = fw_vessel_motion(R->own);
    sum->rudder_work += fabs(x->delta) * s->step;
    sum->path_length += hypot(x->east - R->e_prev, x->north - R->n_prev);
    R->e_prev = x->east;
    R->n_prev = x->north;
    double t1 = tick(R);
    st = observe(R, k, sum, err);
    R->t_observe += tick(R) - t1;
    return st;
}

/* The track measures at the end. */
static void loop_end(run_state *R, fw_run_summary *sum)
{
    const fw_scenario *s = R->s;
    const fw_mmg_state *x = fw_vessel_motion(R->own);
    double de = x->east - s->east, dn = x->north - s->north;
    double se = sin(s->course), ce = cos(s->course);
    sum->along_track = de * se + dn * ce;
    sum->cross_track = de * ce - dn * se;
    sum->heading_error = fw_wrap_pi(x->psi - s->course);
    sum->path_lengthening = sum->path_length - sum->along_track;
    sum->time_lost = sum->t_end - sum->along_track / s->speed;
}

/* --profile: where the run's CPU time went, into run.log and onto stderr. */
static void log_profile(const run_state *R, double t_finish, double run_cpu)
{
    const fw_world_timing *tm = fw_world_timing_of(R->w);
    double world = tm->dynamics + tm->place + tm->traffic + tm->read + tm->decide + tm->reactions;
    char line[640];
    snprintf(line, sizeof line,
             "profile: %s, %ld steps, CPU %.3f s (the process so far %.3f): set-up %.3f "
             "(records, SUMO loaded and started, the world); steps %.3f: traffic's step %.3f, "
             "own ship placed %.3f, ships read %.3f, decisions %.3f, traffic's reactions %.3f, "
             "own dynamics %.3f, records and monitors %.3f, the rest %.3f; finish %.3f\n",
             R->s->name, fw_world_steps(R->w), run_cpu, fw_cpu_s(), R->t_setup, R->t_loop,
             tm->traffic, tm->place, tm->read, tm->decide, tm->reactions, tm->dynamics,
             R->t_observe, R->t_loop - world - R->t_observe, t_finish);
    fputs(line, fw_records_log(R->rec));
    fputs(line, stderr);
}

static void init_summary(const fw_run_def *def, fw_run_summary *sum, fw_encounter **enc,
                         int *n_enc)
{
    const fw_scenario *s = def->scenario;
    memset(sum, 0, sizeof *sum);
    snprintf(sum->scenario, sizeof sum->scenario, "%s", s->name);
    sum->status = FW_RUN_FAILED;
    sum->t_act = sum->t_return = sum->t_on_course = NAN;
    sum->min_dist = INFINITY;
    sum->own_length = s->ship.Loa;
    sum->own_breadth = s->ship.B;
    sum->domain = s->helm.domain.size;
    sum->domain_ratio = s->helm.domain.fore_aft_ratio;
    sum->domain_reading = fw_domain_reading_name(s->helm.domain.reading);
    sum->behaviour = s->reactions.behaviour;
    sum->kb_present = s->ship.nomoto.present;
    sum->kb_speed_min_kn = s->ship.nomoto.speed_min_kn;
    sum->kb_speed_max_kn = s->ship.nomoto.speed_max_kn;
    sum->own_speed_min_kn = INFINITY;
    sum->own_speed_max_kn = -INFINITY;
    *enc = NULL;
    *n_enc = 0;
    if (def->survey_out) {
        *def->survey_out = NULL;
        *def->n_survey_out = 0;
    }
}

/* The records' files and the summary, also after a failure part way; the
 * first error wins. */
static fw_status finish(run_state *R, const fw_run_def *def, fw_run_summary *sum,
                        fw_encounter **enc, int *n_enc, fw_status st, fw_error *err)
{
    fw_error ferr = {0}, rerr = {0};
    sum->monitors = *fw_monitor_counts_of(R->mon);
    const fw_monitor_counts *mc = &sum->monitors;
    fprintf(fw_records_log(R->rec),
            "monitors: %d sideways, %d teleports, %d overlaps, %d appearing and %d vanishing "
            "within 2 nm, %d there at the start, %d stopped; largest sideways speed %.2f m/s\n",
            mc->sideways, mc->teleport, mc->overlap, mc->appear, mc->vanish, mc->start_close,
            mc->stopped, mc->max_lateral);
    /* the survey first: summary.json carries its totals */
    fw_status fst = R->sv ? survey_finish(R, def, sum, &ferr) : FW_OK;
    fw_status rst = fw_records_finish(R->rec, sum, &rerr);
    if (!fst && rst) {
        fst = rst;
        ferr = rerr;
    }
    if (!st && fst) {
        st = fst;
        if (err)
            *err = ferr;
    }
    fw_encounter *e = fw_records_encounters(R->rec, n_enc);
    if (*n_enc > 0) {
        *enc = malloc(sizeof **enc * (size_t)*n_enc);
        if (*enc)
            memcpy(*enc, e, sizeof **enc * (size_t)*n_enc);
        else
            st = st ? st : fw_fail(err, FW_ERUN, "out of memory for %d encounters", *n_enc);
        if (!*enc)
            *n_enc = 0;
    }
    return st;
}

static void log_start(run_state *R)
{
    const fw_scenario *s = R->s;
    int cleared = fw_sumo_source_cleared(fw_world_source(R->w));
    fprintf(fw_records_log(R->rec),
            "scenario %s (%s): own ship %s at %.1f kn on %03.0f deg from (%.1f, %.1f) m, "
            "%d explicit targets%s%s, %.0f s in steps of %.3f s, seed %lu\n",
            s->name, s->file, s->ship.name, fw_ms_to_kn(s->speed), fw_heading_deg(s->course),
            s->east, s->north, s->n_targets, s->network[0] ? ", network " : "", s->network,
            s->duration, s->step, s->seed);
    if (s->ais.file[0])
        fprintf(fw_records_log(R->rec),
                "traffic: the AIS reports of %s replayed, ids the MMSIs (a ship absent between "
                "reports more than %.0f s apart; `fairway ais summary` counts what was read)\n",
                s->ais.file, s->ais.max_gap);
    if (cleared > 0)
        fprintf(fw_records_log(R->rec),
                "traffic: %d ships the fill put within 2 nm of the own ship or on a collision "
                "course with it taken out at the start\n",
                cleared);
}

/* A run between open and close (run.h). */
struct fw_run {
    run_state R;
    fw_run_def def;
    fw_run_summary sum;
    fw_encounter *enc0; /* init_summary's outputs, unused until close */
    int n_enc0;
    long k, n_steps;    /* the instant observed last; the run's steps */
    bool ready;         /* set up: the loop ran or may run */
    fw_status st;       /* the first failure (FW_OK: none) */
    fw_error err;       /* its message */
    double wall0, cpu0, t_loop0;
    uint32_t branch;    /* branch.h: 0 the unbranched run */
};

fw_status fw_run_open(const fw_run_def *def, fw_run **out, fw_error *err)
{
    fw_run *r = calloc(1, sizeof *r);
    *out = r;
    if (!r)
        return fw_fail(err, FW_ERUN, "out of memory for a run");
    const fw_scenario *s = def->scenario;
    r->def = *def;
    r->wall0 = fw_clock_s();
    init_summary(def, &r->sum, &r->enc0, &r->n_enc0);
    r->R = (run_state){.s = s, .profile = def->profile};
    run_state *R = &r->R;
    r->cpu0 = tick(R);
    r->n_steps = lround(s->duration / s->step);
    fw_monitor_def md = fw_default_monitor_def();
    fw_status st;
    if ((st = fw_records_open(&R->rec, s, def->dir, &r->err)) ||
        (st = fw_monitor_create(&md, fw_records_log(R->rec), &R->mon, &r->err)) ||
        (s->survey && (st = fw_survey_create(&s->survey_def, &R->sv, &r->err))) ||
        (st = make_world(def, &R->w, &R->own, &r->err))) {
        r->st = st;
        if (err)
            *err = r->err;
        return st;
    }
    log_start(R);
    R->t_setup = tick(R) - r->cpu0;
    r->ready = true;
    r->t_loop0 = tick(R);
    r->st = loop_start(R, &r->sum, &r->err);
    if (r->st && err)
        *err = r->err;
    return r->st;
}

fw_status fw_run_step(fw_run *r, fw_error *err)
{
    if (!r->st && fw_run_done(r))
        r->st = fw_fail(&r->err, FW_EINPUT, "%s: the run has ended (%ld steps)",
                        r->R.s->name, r->n_steps);
    if (!r->st)
        r->st = loop_step(&r->R, ++r->k, &r->sum, &r->err);
    if (r->st && err)
        *err = r->err;
    return r->st;
}

bool fw_run_done(const fw_run *r) { return r->st != FW_OK || r->k >= r->n_steps; }

fw_world *fw_run_world(fw_run *r) { return r->R.w; }
double fw_run_time(const fw_run *r) { return r->R.w ? fw_world_time(r->R.w) : 0.0; }
long fw_run_steps(const fw_run *r) { return r->k; }
const char *fw_run_dir(const fw_run *r) { return r->def.dir; }
uint32_t fw_run_branch(const fw_run *r) { return r->branch; }
void fw_run_set_branch(fw_run *r, uint32_t branch) { r->branch = branch; }

const char *fw_run_def_unforkable(const fw_run_def *d)
{
    bool sumo = !d->scenario->tracks[0] && d->traffic == FW_RUN_TRAFFIC_SUMO;
    if (sumo && d->mode.kind != FW_TRAFFIC_EMBEDDED)
        return "whose SUMO is another process (--sumo gui or remote: libtraci)";
    return NULL;
}

const char *fw_run_unforkable(const fw_run *r) { return fw_run_def_unforkable(&r->def); }

/* Everything the run holds, freed (the summary's clock fields set); r stays. */
static void teardown(fw_run *r)
{
    run_state *R = &r->R;
    r->sum.sumo_s = fw_sumo_source_step_wall(R->w ? fw_world_source(R->w) : NULL);
    fw_world_destroy(R->w);
    fw_survey_destroy(R->sv);
    fw_monitor_destroy(R->mon);
    r->sum.wall_s = fw_clock_s() - r->wall0;
    fw_records_close(R->rec);
}

void fw_run_discard(fw_run *r)
{
    if (!r)
        return;
    teardown(r);
    free(r);
}

fw_status fw_run_close(fw_run *r, fw_run_summary *sum, fw_encounter **enc, int *n_enc,
                       fw_error *err)
{
    *enc = NULL;
    *n_enc = 0;
    if (!r)
        return fw_fail(err, FW_ERUN, "out of memory for a run");
    run_state *R = &r->R;
    fw_status st = r->st;
    if (err && st)
        *err = r->err;
    if (r->ready) {
        loop_end(R, &r->sum);
        R->t_loop = tick(R) - r->t_loop0;
        if (st)
            fprintf(fw_records_log(R->rec), "run failed: %s\n", r->err.msg);
        else
            r->sum.status = FW_RUN_OK;
        double t_finish = tick(R);
        st = finish(R, &r->def, &r->sum, enc, n_enc, st, err);
        if (r->def.profile)
            log_profile(R, tick(R) - t_finish, tick(R) - r->cpu0);
    }
    teardown(r);
    *sum = r->sum;
    free(r);
    return st;
}

fw_status fw_run_scenario(const fw_run_def *def, fw_run_summary *sum, fw_encounter **enc,
                          int *n_enc, fw_error *err)
{
    fw_run *r;
    fw_status st = fw_run_open(def, &r, err);
    while (!st && !fw_run_done(r))
        st = fw_run_step(r, err);
    return fw_run_close(r, sum, enc, n_enc, err);
}
