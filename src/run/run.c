/* run.c - one scenario run as a steppable object: open (set-up), step (one
 * world step and its records), close (finish, write) (run.h). */
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "core/clock.h"
#include "core/files.h"
#include "core/mem.h"
#include "core/units.h"
#include "nomoto/nomoto.h"
#include "run/dnv_out.h"
#include "run/run_internal.h"
#include "run/run_world.h"
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

/* The CPU clock with --profile, else 0 (no system calls). */
static double tick(const fw_run *R) { return R->def.profile ? fw_cpu_s() : 0.0; }

/* The targets' assessments: the controller's, or, for one that makes none
 * (the oracle's fixed manoeuvre), the run's, as the policy would make them. */
static fw_status assessments(fw_run *R, const fw_target *tg, int n, const fw_assessment **as,
                             fw_error *err)
{
    if (*as || n == 0)
        return FW_OK;
    if (n > R->as_cap) {
        int cap = fw_grown_cap(R->as_cap, n);
        if (!fw_resize((void **)&R->as, sizeof *R->as, (size_t)cap))
            return fw_fail(err, FW_ERUN, "out of memory for %d assessments", n);
        R->as_cap = cap;
    }
    const fw_helm_def *h = &R->s->helm;
    fw_colregs_def colregs = h->colregs;
    if (colregs.rank_range_m <= 0.0)
        colregs.rank_range_m = R->s->policy.act_range; /* as the policy (policy.c) */
    /* the records read of a predicted path only its domain entry (book.c,
     * dnv_out.c): the entry-only form skips what cannot enter */
    fw_assess_entries(&colregs, &h->domain, h->track.horizon, fw_vessel_own_state(R->own), tg, n,
                      R->as);
    *as = R->as;
    return FW_OK;
}

/* Everything the records keep of one instant (the world's state and the
 * decision taken on it). */
static fw_status observe(fw_run *R, long k, fw_run_summary *sum, fw_error *err)
{
    const fw_scenario *s = R->s;
    double t = fw_world_time(R->w);
    fw_status st = R->sv ? fw_run_survey_step(R, t, err) : FW_OK;
    if (st)
        return st;
    const fw_mmg_state *x = fw_vessel_motion(R->own);
    const fw_decision *d = fw_vessel_decision(R->own);
    const fw_target *tg, *seen;
    const fw_assessment *as, *seen_as;
    int n, n_seen;
    bool sensed;
    /* the records keep what was there; with a sensor the policy decided on
     * what it knew (seen): its actions are recorded against that */
    fw_vessel_view(R->own, &seen, &seen_as, &n_seen);
    fw_vessel_truth(R->own, &tg, &n, &sensed);
    as = sensed ? NULL : seen_as;
    if ((st = assessments(R, tg, n, &as, err)) ||
        (st = fw_monitor_step(R->mon, t, fw_vessel_record(R->own), tg, n, err)))
        return st;
    const fw_watch_def *wd = &s->reactions.watch;
    if (fw_watch_def_active(wd)) {
        sum->watched = true;
        fw_world_watch_counts(R->w, &sum->watch_pairs, &sum->watch_lapsed);
    }
    if (fw_watch_def_mixed(wd)) {
        sum->mixed = true;
        fw_world_mix_counts(R->w, sum->mix);
    }
    if (fw_watch_def_active(&s->own_watch)) {
        sum->own_watched = true;
        fw_world_own_watch_counts(R->w, &sum->own_watch_pairs, &sum->own_watch_lapsed);
    }
    if (s->sensing.mode != FW_SENSE_PERFECT) {
        fw_sensing_counts c = fw_world_sensing_counts(R->w);
        sum->sensed = true;
        sum->sense_mode = s->sensing.mode;
        sum->sense = c;
    }
    if (!sensed)
        seen = tg, seen_as = as, n_seen = n;
    else if (!seen_as)
        n_seen = 0; /* a controller that assesses nothing names no ship it acted for */
    bool row = k % lround(s->record_every / s->step) == 0;
    if (row && sensed)
        fw_records_sensed(R->rec, t, seen, n_seen, tg, n);
    if (row)
        fw_records_own(R->rec, t, x, fw_vessel_record(R->own), d->helm,
                       fw_vessel_propeller(R->own), fw_policy_mode_name(d->mode));
    for (int i = 0; i < n; i++)
        if ((st = fw_records_target(R->rec, t, &tg[i], x, &as[i], row, err)))
            return st;
    if (d->acted)
        fw_run_record_action(R, t, d, seen, seen_as, n_seen, sum);
    const fw_target *me = fw_vessel_record(R->own);
    if (R->dnv && (k == 0 || d->acted || d->mode != R->mode_prev) &&
        (st = fw_dnv_out_event(R->dnv, t, fw_vessel_own_state(R->own), me->course, me->speed, d,
                               tg, as, n, err)))
        return st;
    fw_run_record_mode(R, t, d, sum);
    sum->max_helm = fmax(sum->max_helm, fabs(d->helm));
    if (fabs(d->helm - R->helm_prev) > fw_deg_to_rad(0.5)) {
        sum->helm_orders++;
        R->helm_prev = d->helm;
    }
    fw_run_record_reactions(R, sum);
    fw_run_record_kb_speed(R, x, sum);
    sum->t_end = t;
    return FW_OK;
}

/* The track measures: where the own ship ended against its planned track. */
static void track_measures(fw_run *R)
{
    const fw_scenario *s = R->s;
    fw_run_summary *sum = &R->sum;
    const fw_mmg_state *x = fw_vessel_motion(R->own);
    if (s->route.n > 0) {
        /* a route: the progress along it, against its nearest leg */
        int k;
        sum->along_track = fw_route_progress(&s->route, x->east, x->north, NULL, &k);
        sum->cross_track = fw_route_cross(&s->route, k, x->east, x->north);
        sum->heading_error = fw_wrap_pi(x->psi - s->route.leg[k].course);
        sum->path_lengthening = sum->path_length - sum->along_track;
        sum->time_lost = sum->t_end - fw_route_time(&s->route, sum->along_track);
        return;
    }
    double de = x->east - s->east, dn = x->north - s->north;
    double se = sin(s->course), ce = cos(s->course);
    sum->along_track = de * se + dn * ce;
    sum->cross_track = de * ce - dn * se;
    sum->heading_error = fw_wrap_pi(x->psi - s->course);
    sum->path_lengthening = sum->path_length - sum->along_track;
    sum->time_lost = sum->t_end - sum->along_track / s->speed;
}

/* The run failed: it is done; the failure is kept for fw_run_close. */
static fw_status fail_run(fw_run *R, fw_status st, const fw_error *err)
{
    R->failed = st;
    if (err)
        R->fail = *err;
    R->fail.status = st;
    fw_run_note(R, "run failed: %s\n", err ? err->msg : "");
    return st;
}

/* --profile: where the run's CPU time went, into run.log and onto stderr. */
static void log_profile(const fw_run *R, double t_finish, double run_cpu)
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
    if (R->rec && fw_records_log(R->rec))
        fputs(line, fw_records_log(R->rec));
    fputs(line, stderr);
}

static void init_summary(const fw_run_def *def, fw_run_summary *sum)
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
    sum->steering = s->reactions.behaviour == FW_BEHAVIOUR_COLREGS &&
                    s->reactions.give_way == FW_GIVE_WAY_COURSE;
    sum->kb_present = s->ship.nomoto.present;
    sum->kb_speed_min_kn = s->ship.nomoto.speed_min_kn;
    sum->kb_speed_max_kn = s->ship.nomoto.speed_max_kn;
    sum->own_speed_min_kn = INFINITY;
    sum->own_speed_max_kn = -INFINITY;
    if (def->survey_out) {
        *def->survey_out = NULL;
        *def->n_survey_out = 0;
    }
}

/* The records' files and the summary, also after a failure part way; the
 * first error wins. */
static fw_status finish(fw_run *R, fw_encounter **enc, int *n_enc, fw_status st, fw_error *err)
{
    fw_error ferr = {0}, rerr = {0};
    fw_run_summary *sum = &R->sum;
    sum->monitors = *fw_monitor_counts_of(R->mon);
    const fw_monitor_counts *mc = &sum->monitors;
    fw_run_note(R,
                "monitors: %d sideways, %d teleports, %d overlaps, %d appearing and %d vanishing "
                "within 2 nm, %d there at the start, %d stopped; largest sideways speed %.2f m/s\n",
                mc->sideways, mc->teleport, mc->overlap, mc->appear, mc->vanish, mc->start_close,
                mc->stopped, mc->max_lateral);
    /* the survey first: summary.json carries its totals */
    fw_status fst = R->sv ? fw_run_survey_finish(R, &R->def, sum, &ferr) : FW_OK;
    fw_status rst = fw_records_finish(R->rec, sum, &rerr);
    char so[1100];
    if (!rst && R->dnv && !(rst = fw_path(so, sizeof so, &rerr, "%s/situation_output.json",
                                          R->def.dir)))
        rst = fw_dnv_out_write(R->dnv, so, &rerr);
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

static void log_start(fw_run *R)
{
    const fw_scenario *s = R->s;
    int cleared = fw_sumo_source_cleared(fw_world_source(R->w));
    int unplaced = fw_sumo_source_unplaced(fw_world_source(R->w));
    fw_run_note(R, "scenario %s (%s): own ship %s at %.1f kn on %03.0f deg from (%.1f, %.1f) m, "
            "%d explicit targets%s%s, %.0f s in steps of %.3f s, seed %lu\n",
            s->name, s->file, s->ship.name, fw_ms_to_kn(s->speed), fw_heading_deg(s->course),
            s->east, s->north, s->n_targets, s->network[0] ? ", network " : "", s->network,
            s->duration, s->step, s->seed);
    for (int k = 0; k < s->route.n; k++)
        fw_run_note(R, "route: leg %d of %d from (%.1f, %.1f) m, %03.0f deg, %.0f m at %.1f kn\n",
                    k + 1, s->route.n, s->route.leg[k].east, s->route.leg[k].north,
                    fw_heading_deg(s->route.leg[k].course), s->route.leg[k].length,
                    fw_ms_to_kn(s->route.leg[k].speed));
    if (s->note[0])
        fw_run_note(R, "%s\n", s->note);
    if (s->ais.file[0])
        fw_run_note(R,
                    "traffic: the AIS reports of %s replayed, ids the MMSIs (a ship absent between "
                    "reports more than %.0f s apart; `fairway ais summary` counts what was read)\n",
                    s->ais.file, s->ais.max_gap);
    if (R->ais.clashes > 0)
        fw_run_note(
            R,
            "traffic: %ld AIS reports at an instant their MMSI already had, more than %.0f "
            "m from it, dropped: two ships on one MMSI (%d MMSIs, the first %ld); one of each "
            "is replayed\n",
            R->ais.clashes, FW_AIS_CLASH_M, R->ais.clash_ships, R->ais.clash_first);
    if (R->ais.unprojected > 0)
        fw_run_note(R,
                    "traffic: %ld AIS reports skipped: the plane cannot hold them (the first at "
                    "%s)\n",
                    R->ais.unprojected, R->ais.unprojected_at);
    if (cleared > 0)
        fw_run_note(R,
                    "traffic: %d ships the fill put within 2 nm of the own ship or on a collision "
                    "course with it or with each other taken out at the start\n",
                    cleared);
    if (unplaced > 0)
        fw_run_note(R,
                    "traffic: %d ships of the fill found no free place on their lanes at the start "
                    "and were not placed (the fill is more than the lanes hold)\n",
                    unplaced);
}

/* The set-up: records, monitors, survey, the world (def->controller taken
 * over by fw_run_make_world, or destroyed here if it is never reached). */
static fw_status set_up(fw_run *R, fw_error *err)
{
    const fw_scenario *s = R->s;
    fw_monitor_def md = fw_default_monitor_def();
    fw_survey_def sd = s->survey_def;
    sd.lane = fw_run_survey_lane, sd.lane_ctx = R;
    fw_status st;
    if ((st = fw_records_open(&R->rec, s, R->def.dir, err)) ||
        (st = fw_monitor_create(&md, fw_records_log(R->rec), &R->mon, err)) ||
        (s->survey && (st = fw_survey_create(&sd, &R->sv, err))) ||
        (s->situation_output && R->def.dir && (st = fw_dnv_out_create(s, &R->dnv, err)))) {
        fw_controller_destroy(R->def.controller);
        return st;
    }
    if ((st = fw_run_make_world(&R->def, &R->w, &R->own, &R->ais, err))) {
        fw_world_destroy(R->w); /* the world holds the controller if it was made */
        R->w = NULL;
        R->own = NULL;
    }
    if (!st && s->ais.file[0]) {
        R->sum.ais = true;
        R->sum.ais_duplicates = R->ais.duplicates;
        R->sum.ais_clashes = R->ais.clashes;
        R->sum.ais_clash_ships = R->ais.clash_ships;
        R->sum.ais_clash_first = R->ais.clash_first;
        R->sum.ais_unprojected = R->ais.unprojected;
    }
    return st;
}

fw_status fw_run_open(const fw_run_def *def, fw_run **out, fw_error *err)
{
    double wall0 = fw_clock_s();
    fw_run *R = *out = calloc(1, sizeof *R);
    if (!R) {
        fw_controller_destroy(def->controller);
        return fw_fail(err, FW_ERUN, "out of memory for a run");
    }
    R->def = *def;
    R->s = def->scenario;
    R->wall0 = wall0;
    R->cpu0 = tick(R);
    init_summary(def, &R->sum);
    R->n_steps = lround(R->s->duration / R->s->step);
    R->e_prev = R->s->east;
    R->n_prev = R->s->north;
    R->mode_prev = FW_MODE_STANDBY;
    fw_status st = set_up(R, err);
    if (st) {
        R->failed = st;
        if (err)
            R->fail = *err;
        return st;
    }
    log_start(R);
    double t0 = tick(R);
    R->t_setup = t0 - R->cpu0;
    st = fw_world_start(R->w, err);
    double t1 = tick(R);
    if (st || (st = observe(R, 0, &R->sum, err)))
        fail_run(R, st, err);
    double t2 = tick(R);
    R->t_observe += t2 - t1;
    R->t_loop += t2 - t0;
    return st;
}

fw_status fw_run_step(fw_run *R, fw_error *err)
{
    if (fw_run_done(R))
        return fw_fail(err, FW_EINPUT, "%s: the run is done (%ld steps, t = %.1f s)%s", R->s->name,
                       R->k, fw_run_time(R), R->failed ? ", failed" : "");
    const fw_scenario *s = R->s;
    fw_run_summary *sum = &R->sum;
    double t0 = tick(R);
    fw_status st = fw_world_step(R->w, s->step, err);
    if (st) {
        R->t_loop += tick(R) - t0;
        return fail_run(R, st, err);
    }
    const fw_mmg_state *x = fw_vessel_motion(R->own);
    sum->rudder_work += fabs(x->delta) * s->step;
    sum->path_length += hypot(x->east - R->e_prev, x->north - R->n_prev);
    R->e_prev = x->east;
    R->n_prev = x->north;
    R->k++;
    double t1 = tick(R);
    st = observe(R, R->k, sum, err);
    double t2 = tick(R);
    R->t_observe += t2 - t1;
    R->t_loop += t2 - t0;
    return st ? fail_run(R, st, err) : FW_OK;
}

bool fw_run_done(const fw_run *R) { return R->failed || R->k >= R->n_steps; }
long fw_run_steps(const fw_run *R) { return R->k; }
double fw_run_time(const fw_run *R) { return R->w ? fw_world_time(R->w) : 0.0; }
fw_world *fw_run_world(fw_run *R) { return R->w; }

double fw_run_min_hull(fw_run *R)
{
    int n = 0;
    const fw_encounter *e = R->rec ? fw_records_encounters(R->rec, &n) : NULL;
    double m = INFINITY;
    for (int i = 0; i < n; i++)
        m = fmin(m, e[i].min_hull);
    return m;
}

int fw_run_files(fw_run *R, FILE **files, int max)
{
    return R->rec ? fw_records_files(R->rec, files, max) : 0;
}

/* Everything the run holds freed but R itself (the summary's clock fields
 * set); nothing written that was not written already. */
static void teardown(fw_run *R)
{
    R->sum.sumo_s = fw_sumo_source_step_wall(R->w ? fw_world_source(R->w) : NULL);
    fw_world_destroy(R->w);
    fw_survey_destroy(R->sv);
    fw_monitor_destroy(R->mon);
    R->sum.wall_s = fw_clock_s() - R->wall0;
    fw_records_close(R->rec);
    fw_dnv_out_destroy(R->dnv);
    free(R->as);
}

fw_status fw_run_close(fw_run *R, fw_run_summary *sum, fw_encounter **enc, int *n_enc,
                       fw_error *err)
{
    *enc = NULL;
    *n_enc = 0;
    fw_status st = R->failed;
    if (st && err)
        *err = R->fail;
    if (R->w) {
        double t0 = tick(R);
        track_measures(R);
        double t_finish = tick(R);
        R->t_loop += t_finish - t0;
        if (!st)
            R->sum.status = FW_RUN_OK;
        st = finish(R, enc, n_enc, st, err);
        if (R->def.profile)
            log_profile(R, tick(R) - t_finish, tick(R) - R->cpu0);
    }
    teardown(R);
    *sum = R->sum;
    free(R);
    return st;
}

void fw_run_discard(fw_run *R)
{
    if (!R)
        return;
    teardown(R);
    free(R);
}

const char *fw_run_dir(const fw_run *R) { return R->def.dir; }
uint32_t fw_run_branch(const fw_run *R) { return R->branch; }
void fw_run_set_branch(fw_run *R, uint32_t branch, void *box)
{
    R->branch = branch;
    R->branch_box = box;
    /* branch.h: a restored branch b > 0 draws fresh numbers from here on.
     * The table grows by a word; out of memory here leaves the parent's
     * numbers, which a caller sees as a branch no different from its parent */
    if (branch > 0 && R->w)
        (void)fw_world_rekey(R->w, branch);
}
void *fw_run_branch_box(const fw_run *R) { return R->branch_box; }

const char *fw_run_def_unforkable(const fw_run_def *d)
{
    bool sumo = !d->scenario->tracks[0] && !d->scenario->waypoint_targets &&
                d->traffic == FW_RUN_TRAFFIC_SUMO;
    if (sumo && d->mode.kind != FW_TRAFFIC_EMBEDDED)
        return "whose SUMO is another process (--sumo gui or remote: libtraci)";
    return NULL;
}

const char *fw_run_unforkable(const fw_run *R) { return fw_run_def_unforkable(&R->def); }

fw_status fw_run_scenario(const fw_run_def *def, fw_run_summary *sum, fw_encounter **enc,
                          int *n_enc, fw_error *err)
{
    fw_run *r;
    fw_status st = fw_run_open(def, &r, err);
    if (!r) {
        init_summary(def, sum);
        *enc = NULL;
        *n_enc = 0;
        return st;
    }
    while (!st && !fw_run_done(r))
        st = fw_run_step(r, err);
    return fw_run_close(r, sum, enc, n_enc, err);
}
