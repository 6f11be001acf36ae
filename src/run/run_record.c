/* run_record.c - what a run's step records (run.h): lines in run.log, the
 * own ship's actions and modes in the encounter book and the summary, the
 * reactive traffic's actions, the traffic survey, the knowledge base's speed
 * range. */
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "core/units.h"
#include "run/run_internal.h"

/* A line in run.log (none without a run directory). */
void fw_run_note(fw_run *R, const char *fmt, ...)
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
fw_status fw_run_survey_lane(void *ctx, const fw_target *s, const fw_lane_info **out,
                             fw_error *err)
{
    fw_run *R = ctx;
    *out = NULL;
    return R->w ? fw_world_lane(R->w, s, out, err) : FW_OK;
}

/* The survey's step: every ship in the area, the own ship included.  Their
 * lanes are read as they go (every FW_LANE_REFRESH_S), so that one is known
 * for a ship in a junction when an encounter opens there. */
fw_status fw_run_survey_step(fw_run *R, double t, fw_error *err)
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
fw_status fw_run_survey_finish(fw_run *R, const fw_run_def *def, fw_run_summary *sum,
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
    fw_run_note(
        R,
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
void fw_run_record_action(fw_run *R, double t, const fw_decision *d, const fw_target *tg,
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
    fw_run_note(R,
                "%9.1f  act %s %.0f deg for %s (%s, range %.0f m, DCPA %.0f m, TCPA %.0f s): %s\n",
                t, fw_side_name(d->search.side), fw_rad_to_deg(fabs(d->helm)), pid ? pid : "-",
                pid ? fw_situation_name(as[d->primary].situation) : "-",
                pid ? as[d->primary].range : 0.0, pid ? as[d->primary].dcpa : 0.0,
                pid ? as[d->primary].tcpa : 0.0, d->reason ? d->reason : "");
}

void fw_run_record_mode(fw_run *R, double t, const fw_decision *d, fw_run_summary *sum)
{
    const fw_route *rt = &R->s->route;
    if (rt->n > 0 && d->leg != R->leg_prev && d->leg >= 0 && d->leg < rt->n) {
        fw_run_note(R, "%9.1f  route: leg %d of %d, %03.0f deg at %.1f kn (wheel over)\n", t,
                    d->leg + 1, rt->n, fw_heading_deg(rt->leg[d->leg].course),
                    fw_ms_to_kn(rt->leg[d->leg].speed));
        R->leg_prev = d->leg;
    }
    if (d->unkept && !R->unkept_prev) {
        fw_run_note(R,
                    "%9.1f  the domain cannot be kept within the route's band: holding %03.0f deg, "
                    "speed ordered %.1f kn: %s\n",
                    t, fw_heading_deg(fw_vessel_motion(R->own)->psi), fw_ms_to_kn(d->speed),
                    d->reason ? d->reason : "");
        if (sum->n_unkept++ == 0)
            sum->t_unkept = t, sum->unkept_speed = d->speed;
        sum->unkept_speed = fmin(sum->unkept_speed, d->speed);
    } else if (!d->unkept && R->unkept_prev) {
        fw_run_note(R, "%9.1f  the domain can be kept again: speed ordered %.1f kn\n", t,
             fw_ms_to_kn(d->speed));
    }
    R->unkept_prev = d->unkept;
    if (d->rule19e != R->r19e_prev) {
        const fw_target *tg;
        const fw_assessment *as;
        int n;
        fw_vessel_view(R->own, &tg, &as, &n);
        if (d->rule19e && d->rule19e_target >= 0 && d->rule19e_target < n)
            fw_run_note(
                R,
                "%9.1f  rule 19(e): %s out of sight forward of the beam: speed ordered %.1f "
                "kn, the least at which the ship keeps her course\n",
                t, tg[d->rule19e_target].id, fw_ms_to_kn(d->speed));
        else
            fw_run_note(R, "%9.1f  rule 19(e) over: speed ordered %.1f kn\n", t,
                        fw_ms_to_kn(d->speed));
        sum->n_rule19e += d->rule19e;
    }
    R->r19e_prev = d->rule19e;
    if (d->mode == R->mode_prev)
        return;
    fw_run_note(R, "%9.1f  %s -> %s, helm %.1f deg: %s\n", t,
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
        fw_run_note(R, "%9.1f  traffic: %s back on its lane, %.0f deg (given back)\n", r->t,
                    r->ship, fw_rad_to_deg(fw_wrap_2pi(r->course_to)));
        return;
    }
    double alt = fw_rad_to_deg(fw_wrap_pi(r->course_to - r->course_from));
    sum->alter_deg_min = sum->n_alter ? fmin(sum->alter_deg_min, alt) : alt;
    sum->alter_deg_max = sum->n_alter ? fmax(sum->alter_deg_max, alt) : alt;
    sum->n_alter++;
    sum->n_give_way++;
    fw_run_note(R, "%9.1f  traffic: %s gives way to %s (%s): alters %.0f deg to %s, %.0f -> "
            "%.0f deg",
         r->t, r->ship, r->other, fw_situation_name(r->situation), fabs(alt),
         alt < 0.0 ? "port" : "starboard",
         fw_rad_to_deg(fw_wrap_2pi(r->course_from)), fw_rad_to_deg(r->course_to));
    char kn[128];
    if (isnan(r->dcpa_before)) /* a steered ship's further alteration (world/steer.h) */
        fw_run_note(R, " (steering itself)\n");
    else
        fw_run_note(R, ", CPA %.0f -> %.0f m%s\n", r->dcpa_before, r->dcpa_after,
             known_note(r, kn, sizeof kn));
}

/* The background ships' new orders: run.log and the summary. */
void fw_run_record_reactions(fw_run *R, fw_run_summary *sum)
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
            fw_run_note(R, "%9.1f  traffic: %s resumes %.1f kn\n", r->t, r->ship,
                    fw_ms_to_kn(r->speed_to));
            continue;
        }
        sum->n_give_way++;
        sum->n_give_way_short += !r->enough;
        fw_run_note(
            R, "%9.1f  traffic: %s %s %s (%s): %s from %.1f to %.1f kn, CPA %.0f m", r->t, r->ship,
            r->situation == FW_SIT_STAND_ON ? "acts (rule 17(b)) for" : "gives way to", r->other,
            fw_situation_name(r->situation), r->speed_to > r->speed_from ? "speeds up" : "slows",
            fw_ms_to_kn(r->speed_from), fw_ms_to_kn(r->speed_to), r->dcpa_before);
        char kn[128];
        if (r->rule19e)
            fw_run_note(R, " (rule 19(e): the least speed)");
        else if (r->why != FW_WHY_NONE && r->why != FW_WHY_RULE17)
            fw_run_note(R, " (not altering: %s)", fw_speed_why_name(r->why));
        if (r->enough)
            fw_run_note(R, " -> %.0f m%s\n", r->dcpa_after, known_note(r, kn, sizeof kn));
        else
            fw_run_note(R,
                        ": no speed keeps the passing distance, the one that passes farthest%s\n",
                        known_note(r, kn, sizeof kn));
    }
}

/* The own ship's speed against its knowledge base's fitted speeds: a line in
 * run.log when it leaves them, the time outside in the summary. */
void fw_run_record_kb_speed(fw_run *R, const fw_mmg_state *x, fw_run_summary *sum)
{
    const fw_nomoto_kb *kb = &R->s->ship.nomoto;
    double kn = fw_ms_to_kn(hypot(x->u, x->vm));
    sum->own_speed_min_kn = fmin(sum->own_speed_min_kn, kn);
    sum->own_speed_max_kn = fmax(sum->own_speed_max_kn, kn);
    bool outside = fw_nomoto_kb_speed(kb, kn) != FW_KB_SPEED_IN;
    if (outside)
        sum->kb_outside_s += R->s->step;
    if (outside && !R->kb_outside)
        fw_run_note(R,
                    "%9.1f  warning: own speed %.2f kn is outside %.2f-%.2f kn, the speeds %s's "
                    "Nomoto knowledge base was fitted over: its predictions are extrapolated\n",
                    fw_world_time(R->w), kn, kb->speed_min_kn, kb->speed_max_kn, R->s->ship.name);
    R->kb_outside = outside;
}
