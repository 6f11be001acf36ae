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
#include "run/run.h"
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

/* A run: what it was asked, what it made, and everything that evolves from
 * step to step (the world's state aside), so that all of it is reachable
 * from here (the snapshot's need). */
struct fw_run {
    fw_run_def def;
    const fw_scenario *s;
    fw_world *w;             /* NULL: the set-up failed */
    fw_vessel *own;
    fw_records *rec;
    fw_survey *sv;           /* NULL: no survey */
    fw_monitor *mon;         /* the traffic monitors */
    fw_run_summary sum;      /* the measures so far */
    long k, n_steps;         /* steps taken, steps in the scenario */
    fw_status failed;        /* the failure that ended the run (FW_OK: none) */
    fw_error fail;           /* its message */
    fw_policy_mode mode_prev;
    int leg_prev;            /* the route's leg at the last step */
    bool unkept_prev;        /* the domain could not be kept at the last step */
    bool r19e_prev;          /* rule 19(e)'s speed was ordered at the last step */
    double helm_prev, e_prev, n_prev;
    int reactions_seen;      /* the world's reactions already in run.log */
    bool kb_outside;         /* the own speed was outside the knowledge base's at the last step */
    fw_assessment *as;       /* the run's own assessments, for a controller that makes none */
    int as_cap;
    double wall0, cpu0;      /* clock and CPU s at the open */
    double t_setup, t_observe, t_loop; /* CPU s (--profile) */
    uint32_t branch;         /* branch.h: 0 unless restored from a snapshot as another */
    void *branch_box;        /* branch.h: where a restored branch leaves its result */
    fw_ais_tracks ais;       /* AIS traffic: what the reading counted (no arrays) */
    fw_dnv_out *dnv;         /* a DNV situation's answer (dnv_out.h); NULL: none */
};

/* The CPU clock with --profile, else 0 (no system calls). */
static double tick(const fw_run *R) { return R->def.profile ? fw_cpu_s() : 0.0; }

/* A line in run.log (none without a run directory). */
static void note(fw_run *R, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void note(fw_run *R, const char *fmt, ...)
{
    FILE *f = R->rec ? fw_records_log(R->rec) : NULL;
    if (!f)
        return;
    va_list ap;
    va_start(ap, fmt);
    vfprintf(f, fmt, ap);
    va_end(ap);
}

/* The survey's lanes: the world's (fw_survey_def.lane; ctx the run). */
static fw_status survey_lane(void *ctx, const fw_target *s, const fw_lane_info **out,
                             fw_error *err)
{
    fw_run *R = ctx;
    *out = NULL;
    return R->w ? fw_world_lane(R->w, s, out, err) : FW_OK;
}

/* The survey's step: every ship in the area, the own ship included.  Their
 * lanes are read as they go (every FW_LANE_REFRESH_S), so that one is known
 * for a ship in a junction when an encounter opens there. */
static fw_status survey_step(fw_run *R, double t, fw_error *err)
{
    const fw_target *a;
    const fw_lane_info *lane;
    int n;
    fw_status st = fw_world_area(R->w, &a, &n, err);
    for (int i = 0; i < n && !st; i++)
        st = fw_world_lane(R->w, &a[i], &lane, err);
    return st ? st : fw_survey_step(R->sv, t, a, n, err);
}

/* Survey totals into the summary, its records into the run directory and to
 * the caller; run.log gets the counts. */
static fw_status survey_finish(fw_run *R, const fw_run_def *def, fw_run_summary *sum,
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
    note(R, "survey: %d traffic encounters (%d head-on, %d overtaking, %d crossing; %d with the "
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
static void record_action(fw_run *R, double t, const fw_decision *d, const fw_target *tg,
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
    note(R, "%9.1f  act %s %.0f deg for %s (%s, range %.0f m, DCPA %.0f m, TCPA %.0f s): %s\n", t,
            fw_side_name(d->search.side), fw_rad_to_deg(fabs(d->helm)), pid ? pid : "-",
            pid ? fw_situation_name(as[d->primary].situation) : "-",
            pid ? as[d->primary].range : 0.0, pid ? as[d->primary].dcpa : 0.0,
            pid ? as[d->primary].tcpa : 0.0, d->reason ? d->reason : "");
}

static void record_mode(fw_run *R, double t, const fw_decision *d, fw_run_summary *sum)
{
    const fw_route *rt = &R->s->route;
    if (rt->n > 0 && d->leg != R->leg_prev && d->leg >= 0 && d->leg < rt->n) {
        note(R, "%9.1f  route: leg %d of %d, %03.0f deg at %.1f kn (wheel over)\n", t, d->leg + 1,
             rt->n, fw_heading_deg(rt->leg[d->leg].course), fw_ms_to_kn(rt->leg[d->leg].speed));
        R->leg_prev = d->leg;
    }
    if (d->unkept && !R->unkept_prev) {
        note(R, "%9.1f  the domain cannot be kept within the route's band: holding %03.0f deg, "
                "speed ordered %.1f kn: %s\n",
             t, fw_heading_deg(fw_vessel_motion(R->own)->psi), fw_ms_to_kn(d->speed),
             d->reason ? d->reason : "");
        if (sum->n_unkept++ == 0)
            sum->t_unkept = t, sum->unkept_speed = d->speed;
        sum->unkept_speed = fmin(sum->unkept_speed, d->speed);
    } else if (!d->unkept && R->unkept_prev) {
        note(R, "%9.1f  the domain can be kept again: speed ordered %.1f kn\n", t,
             fw_ms_to_kn(d->speed));
    }
    R->unkept_prev = d->unkept;
    if (d->rule19e != R->r19e_prev) {
        const fw_target *tg;
        const fw_assessment *as;
        int n;
        fw_vessel_view(R->own, &tg, &as, &n);
        if (d->rule19e && d->rule19e_target >= 0 && d->rule19e_target < n)
            note(R, "%9.1f  rule 19(e): %s out of sight forward of the beam: speed ordered %.1f "
                    "kn, the least at which the ship keeps her course\n",
                 t, tg[d->rule19e_target].id, fw_ms_to_kn(d->speed));
        else
            note(R, "%9.1f  rule 19(e) over: speed ordered %.1f kn\n", t, fw_ms_to_kn(d->speed));
        sum->n_rule19e += d->rule19e;
    }
    R->r19e_prev = d->rule19e;
    if (d->mode == R->mode_prev)
        return;
    note(R, "%9.1f  %s -> %s, helm %.1f deg: %s\n", t,
            fw_policy_mode_name(R->mode_prev), fw_policy_mode_name(d->mode),
            fw_rad_to_deg(d->helm), d->reason ? d->reason : "");
    if (d->mode == FW_MODE_AUTOPILOT && isnan(sum->t_return))
        sum->t_return = t;
    if (R->mode_prev == FW_MODE_AUTOPILOT && d->mode == FW_MODE_STANDBY &&
        isnan(sum->t_on_course))
        sum->t_on_course = t;
    R->mode_prev = d->mode;
}

/* How the acting ship knew the other, for run.log: "" on the truth (perfect
 * sensing), else how and how far from where it was (world/reactions.h). */
static const char *known_note(const fw_reaction *r, char *buf, size_t n)
{
    static const char *const how[] = {"", "", "its AIS", "sight", "its radar"};
    buf[0] = '\0';
    if (r->known_how >= FW_KNOWN_AIS && r->known_how <= FW_KNOWN_RADAR)
        snprintf(buf, n, " [%s known by %s, %.0f m from where it was]", r->other,
                 how[r->known_how], hypot(r->known_e - r->true_e, r->known_n - r->true_n));
    return buf;
}

/* A background ship's course alteration or its return to its lane: run.log
 * and the summary. */
static void record_course(fw_run *R, const fw_reaction *r, fw_run_summary *sum)
{
    if (r->kind == FW_REACT_REJOIN) {
        sum->n_rejoin++;
        note(R, "%9.1f  traffic: %s back on its lane, %.0f deg (given back)\n", r->t, r->ship,
             fw_rad_to_deg(fw_wrap_2pi(r->course_to)));
        return;
    }
    double alt = fw_rad_to_deg(fw_wrap_pi(r->course_to - r->course_from));
    sum->alter_deg_min = sum->n_alter ? fmin(sum->alter_deg_min, alt) : alt;
    sum->alter_deg_max = sum->n_alter ? fmax(sum->alter_deg_max, alt) : alt;
    sum->n_alter++;
    sum->n_give_way++;
    note(R, "%9.1f  traffic: %s gives way to %s (%s): alters %.0f deg to %s, %.0f -> "
            "%.0f deg",
         r->t, r->ship, r->other, fw_situation_name(r->situation), fabs(alt),
         alt < 0.0 ? "port" : "starboard",
         fw_rad_to_deg(fw_wrap_2pi(r->course_from)), fw_rad_to_deg(r->course_to));
    char kn[128];
    if (isnan(r->dcpa_before)) /* a steered ship's further alteration (world/steer.h) */
        note(R, " (steering itself)\n");
    else
        note(R, ", CPA %.0f -> %.0f m%s\n", r->dcpa_before, r->dcpa_after,
             known_note(r, kn, sizeof kn));
}

/* The background ships' new orders: run.log and the summary. */
static void record_reactions(fw_run *R, fw_run_summary *sum)
{
    int n;
    const fw_reaction *x = fw_world_reactions(R->w, &n);
    for (; R->reactions_seen < n; R->reactions_seen++) {
        const fw_reaction *r = &x[R->reactions_seen];
        if (r->kind == FW_REACT_ALTER || r->kind == FW_REACT_REJOIN) {
            record_course(R, r, sum);
            continue;
        }
        if (r->kind == FW_REACT_RESUME) {
            sum->n_resume++;
            note(R, "%9.1f  traffic: %s resumes %.1f kn\n", r->t, r->ship,
                    fw_ms_to_kn(r->speed_to));
            continue;
        }
        sum->n_give_way++;
        sum->n_give_way_short += !r->enough;
        note(R,     "%9.1f  traffic: %s %s %s (%s): %s from %.1f to %.1f kn, CPA %.0f m", r->t,
                r->ship, r->situation == FW_SIT_STAND_ON ? "acts (rule 17(b)) for" : "gives way to",
                r->other, fw_situation_name(r->situation),
                r->speed_to > r->speed_from ? "speeds up" : "slows", fw_ms_to_kn(r->speed_from),
                fw_ms_to_kn(r->speed_to), r->dcpa_before);
        char kn[128];
        if (r->rule19e)
            note(R, " (rule 19(e): the least speed)");
        else if (r->why != FW_WHY_NONE && r->why != FW_WHY_RULE17)
            note(R, " (not altering: %s)", fw_speed_why_name(r->why));
        if (r->enough)
            note(R, " -> %.0f m%s\n", r->dcpa_after, known_note(r, kn, sizeof kn));
        else
            note(R, ": no speed keeps the passing distance, the one that passes farthest%s\n",
                 known_note(r, kn, sizeof kn));
    }
}

/* The own ship's speed against its knowledge base's fitted speeds: a line in
 * run.log when it leaves them, the time outside in the summary. */
static void record_kb_speed(fw_run *R, const fw_mmg_state *x, fw_run_summary *sum)
{
    const fw_nomoto_kb *kb = &R->s->ship.nomoto;
    double kn = fw_ms_to_kn(hypot(x->u, x->vm));
    sum->own_speed_min_kn = fmin(sum->own_speed_min_kn, kn);
    sum->own_speed_max_kn = fmax(sum->own_speed_max_kn, kn);
    bool outside = fw_nomoto_kb_speed(kb, kn) != FW_KB_SPEED_IN;
    if (outside)
        sum->kb_outside_s += R->s->step;
    if (outside && !R->kb_outside)
        note(R,     "%9.1f  warning: own speed %.2f kn is outside %.2f-%.2f kn, the speeds %s's "
                "Nomoto knowledge base was fitted over: its predictions are extrapolated\n",
                fw_world_time(R->w), kn, kb->speed_min_kn, kb->speed_max_kn, R->s->ship.name);
    R->kb_outside = outside;
}

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
    fw_status st = R->sv ? survey_step(R, t, err) : FW_OK;
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
        record_action(R, t, d, seen, seen_as, n_seen, sum);
    const fw_target *me = fw_vessel_record(R->own);
    if (R->dnv && (k == 0 || d->acted || d->mode != R->mode_prev) &&
        (st = fw_dnv_out_event(R->dnv, t, fw_vessel_own_state(R->own), me->course, me->speed, d,
                               tg, as, n, err)))
        return st;
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
    note(R, "run failed: %s\n", err ? err->msg : "");
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
    note(R, "monitors: %d sideways, %d teleports, %d overlaps, %d appearing and %d vanishing "
            "within 2 nm, %d there at the start, %d stopped; largest sideways speed %.2f m/s\n",
         mc->sideways, mc->teleport, mc->overlap, mc->appear, mc->vanish, mc->start_close,
         mc->stopped, mc->max_lateral);
    /* the survey first: summary.json carries its totals */
    fw_status fst = R->sv ? survey_finish(R, &R->def, sum, &ferr) : FW_OK;
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
    note(R, "scenario %s (%s): own ship %s at %.1f kn on %03.0f deg from (%.1f, %.1f) m, "
            "%d explicit targets%s%s, %.0f s in steps of %.3f s, seed %lu\n",
            s->name, s->file, s->ship.name, fw_ms_to_kn(s->speed), fw_heading_deg(s->course),
            s->east, s->north, s->n_targets, s->network[0] ? ", network " : "", s->network,
            s->duration, s->step, s->seed);
    for (int k = 0; k < s->route.n; k++)
        note(R, "route: leg %d of %d from (%.1f, %.1f) m, %03.0f deg, %.0f m at %.1f kn\n", k + 1,
             s->route.n, s->route.leg[k].east, s->route.leg[k].north,
             fw_heading_deg(s->route.leg[k].course), s->route.leg[k].length,
             fw_ms_to_kn(s->route.leg[k].speed));
    if (s->note[0])
        note(R, "%s\n", s->note);
    if (s->ais.file[0])
        note(R,     "traffic: the AIS reports of %s replayed, ids the MMSIs (a ship absent between "
                "reports more than %.0f s apart; `fairway ais summary` counts what was read)\n",
                s->ais.file, s->ais.max_gap);
    if (R->ais.clashes > 0)
        note(R,     "traffic: %ld AIS reports at an instant their MMSI already had, more than %.0f "
                "m from it, dropped: two ships on one MMSI (%d MMSIs, the first %ld); one of each "
                "is replayed\n",
                R->ais.clashes, FW_AIS_CLASH_M, R->ais.clash_ships, R->ais.clash_first);
    if (R->ais.unprojected > 0)
        note(R,     "traffic: %ld AIS reports skipped: the plane cannot hold them (the first at "
                "%s)\n",
                R->ais.unprojected, R->ais.unprojected_at);
    if (cleared > 0)
        note(R,     "traffic: %d ships the fill put within 2 nm of the own ship or on a collision "
                "course with it or with each other taken out at the start\n",
                cleared);
    if (unplaced > 0)
        note(R,     "traffic: %d ships of the fill found no free place on their lanes at the start "
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
    sd.lane = survey_lane, sd.lane_ctx = R;
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
