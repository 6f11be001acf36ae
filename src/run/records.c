/* records.c - the result files of a run: time histories, encounters, summary
 * (records.h); what they are made of is the encounter book's (book.c).
 *
 * Numbers are printed with fixed formats (no %g, whose width depends on the
 * value) and no clock time is written, so reruns are byte-identical.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"
#include "core/json.h"
#include "avoid/helm_search.h"
#include "core/fmt.h"
#include "core/units.h"
#include "geom/geo.h"
#include "geom/turn.h"
#include "run/book.h"
#include "run/encounter_record.h"
#include "run/records.h"

struct fw_records {
    const fw_scenario *s;
    char dir[1024];
    FILE *own, *tgt, *log;
    FILE *sen;     /* sensed.csv: what a sensor (not perfect) made of the ships */
    fw_geo *geo;   /* the scenario's origin: lat/lon columns (NULL: none) */
    fw_book *book; /* the encounter book (book.h): what the files are made of */
    bool turns;    /* targets.csv has the turn columns (fw_records_open) */
};

static FILE *open_in(const char *dir, const char *name, fw_error *err)
{
    char path[1200];
    if (fw_path(path, sizeof path, err, "%s/%s", dir, name))
        return NULL;
    return fw_file_create(path, err);
}

fw_status fw_records_open(fw_records **out, const fw_scenario *s, const char *dir, fw_error *err)
{
    fw_records *r = calloc(1, sizeof *r);
    if (!r)
        return fw_fail(err, FW_ERUN, "out of memory");
    r->s = s;
    *out = r;
    fw_status st = fw_book_create(s, &r->book, err);
    if (st)
        return st;
    st = dir ? fw_path(r->dir, sizeof r->dir, err, "%s", dir) : FW_OK;
    if (st || !dir) /* no directory: the book only */
        return st;
    if (!(r->own = open_in(dir, "own.csv", err)) || !(r->log = open_in(dir, "run.log", err)) ||
        (s->targets_csv && !(r->tgt = open_in(dir, "targets.csv", err))) ||
        (s->targets_csv && s->sensing.mode != FW_SENSE_PERFECT &&
         !(r->sen = open_in(dir, "sensed.csv", err))))
        return FW_ERUN;
    if ((st = fw_scenario_plane(s, &r->geo, err)))
        return st;
    /* with an origin, the positions in degrees too (last, so that the
     * columns of a run in metres are the same either way) */
    const char *geo_cols = r->geo ? ",lat_deg,lon_deg" : "";
    /* the column names of every CSV follow one convention (scenarios/README.md,
     * "Output columns"): speeds over ground in knots as speed_kn beside the
     * targets', the body-frame components in m/s as the manoeuvre CSVs have them */
    fprintf(r->own, "t_s,east_m,north_m,heading_deg,speed_kn,u_mps,v_mps,r_degps,rudder_deg,"
                    "helm_deg,propeller_rps,mode%s\n", geo_cols);
    /* the turn a ship is seen making (geom/turn.h), where one may be: ships
     * the traffic steers (behaviour colregs, give_way course), tracks that
     * may carry their turns (traffic/source_track.h), a situation's targets
     * that do (scenario/scn_dnv.h) */
    r->turns = (s->reactions.behaviour == FW_BEHAVIOUR_COLREGS &&
                s->reactions.give_way == FW_GIVE_WAY_COURSE) ||
               s->tracks[0];
    for (int i = 0; s->waypoint_targets && i < s->n_targets; i++)
        r->turns |= s->target_routes[i].turns;
    if (r->tgt)
        fprintf(r->tgt, "t_s,id,east_m,north_m,heading_deg,speed_kn,range_m,bearing_deg,"
                        "dcpa_m,tcpa_s,situation%s%s\n",
                r->turns ? ",turn_rate_degps,turn_to_deg" : "", geo_cols);
    if (r->sen)
        fprintf(r->sen, "t_s,id,east_m,north_m,course_deg,speed_kn,error_m%s\n", geo_cols);
    return FW_OK;
}

void fw_records_close(fw_records *r)
{
    if (!r)
        return;
    if (r->own)
        fclose(r->own);
    if (r->tgt)
        fclose(r->tgt);
    if (r->log)
        fclose(r->log);
    if (r->sen)
        fclose(r->sen);
    fw_book_destroy(r->book);
    fw_geo_destroy(r->geo);
    free(r);
}

/* ",v[0],v[1],..." onto f, v[k] with dec[k] decimals (as "%.Nf"; fmt.h:
 * printf's exact conversion was most of the time of a row). */
static void put_nums(FILE *f, const double *v, const int *dec, int n)
{
    for (int k = 0; k < n; k++) {
        fputc(',', f);
        fw_put_fixed(f, v[k], dec[k]);
    }
}

/* ",LAT,LON\n" for a run with an origin, else "\n": the end of a CSV row
 * (7 decimals of a degree: about 1 cm). */
static void end_row(const fw_records *r, FILE *f, double east, double north)
{
    double lat, lon;
    if (r->geo && !fw_geo_to_latlon(r->geo, east, north, &lat, &lon, NULL)) {
        put_nums(f, (const double[]){lat, lon}, (const int[]){7, 7}, 2);
        fputc('\n', f);
    } else
        fputs(r->geo ? ",,\n" : "\n", f);
}

FILE *fw_records_log(fw_records *r) { return r->log; }

int fw_records_files(fw_records *r, FILE **f, int max)
{
    FILE *all[] = {r->own, r->log, r->tgt, r->sen};
    int n = 0;
    for (int i = 0; i < 4; i++)
        if (all[i] && n++ < max)
            f[n - 1] = all[i];
    return n;
}

void fw_records_own(fw_records *r, double t, const fw_mmg_state *x, const fw_target *rec,
                    double helm, double n, const char *mode)
{
    /* t_s,east_m,north_m,heading_deg,speed_kn,u_mps,v_mps,r_degps,rudder_deg,helm_deg,
     * propeller_rps,mode */
    if (!r->own)
        return;
    fw_put_fixed(r->own, t, 1);
    put_nums(r->own,
             (const double[]){x->east, x->north, fw_heading_deg(x->psi),
                              fw_ms_to_kn(rec->speed), x->u, x->vm, fw_rad_to_deg(x->r),
                              fw_rad_to_deg(x->delta), fw_rad_to_deg(helm), n},
             (const int[]){2, 2, 3, 3, 4, 4, 5, 3, 3, 4}, 10);
    fputc(',', r->own);
    fputs(mode, r->own);
    end_row(r, r->own, x->east, x->north);
}

fw_status fw_records_target(fw_records *r, double t, const fw_target *ts, const fw_mmg_state *own,
                            const fw_assessment *as, bool record_row, fw_error *err)
{
    fw_status st = fw_book_target(r->book, t, ts, own, as, err);
    if (st)
        return st;
    if (record_row && r->tgt) {
        double d = hypot(ts->east - own->east, ts->north - own->north);
        /* t_s,id,east_m,north_m,heading_deg,speed_kn,range_m,bearing_deg,dcpa_m,tcpa_s,
         * situation */
        fw_put_fixed(r->tgt, t, 1);
        fputc(',', r->tgt);
        fputs(ts->id, r->tgt);
        put_nums(r->tgt,
                 (const double[]){ts->east, ts->north, fw_heading_deg(ts->heading),
                                  fw_ms_to_kn(ts->speed), d, fw_heading_deg(as->bearing),
                                  as->dcpa, as->tcpa},
                 (const int[]){2, 2, 3, 3, 2, 3, 2, 2}, 8);
        fputc(',', r->tgt);
        fputs(fw_situation_name(as->situation), r->tgt);
        const fw_turn_pred *p = r->turns ? fw_turn_pred_of(ts->pred) : NULL;
        if (p && p->turning)
            put_nums(r->tgt,
                     (const double[]){fw_rad_to_deg(p->rate), fw_heading_deg(p->heading)},
                     (const int[]){6, 6}, 2);
        else if (r->turns)
            fputs(",,", r->tgt);
        end_row(r, r->tgt, ts->east, ts->north);
    }
    return FW_OK;
}

void fw_records_sensed(fw_records *r, double t, const fw_target *known, int n_known,
                       const fw_target *truth, int n_truth)
{
    if (!r->sen)
        return;
    for (int i = 0, j = 0; i < n_known; i++) {
        const fw_target *k = &known[i];
        while (j < n_truth && strcmp(truth[j].id, k->id) < 0) /* both sorted by id */
            j++;
        double err = j < n_truth && strcmp(truth[j].id, k->id) == 0
                         ? hypot(k->east - truth[j].east, k->north - truth[j].north)
                         : NAN;
        fw_put_fixed(r->sen, t, 1);
        fputc(',', r->sen);
        fputs(k->id, r->sen);
        put_nums(r->sen,
                 (const double[]){k->east, k->north, fw_heading_deg(k->course),
                                  fw_ms_to_kn(k->speed), err},
                 (const int[]){2, 2, 3, 3, 2}, 5);
        end_row(r, r->sen, k->east, k->north);
    }
}

void fw_records_action(fw_records *r, double t, int side, double helm, const char *primary_id,
                       const fw_target *tg, const fw_assessment *as, int n)
{
    fw_book_action(r->book, t, side, helm, primary_id, tg, as, n);
}

fw_encounter *fw_records_encounters(fw_records *r, int *n)
{
    return fw_book_entries(r->book, n);
}

/* summary.json's numbers: null when not finite */
static void num(FILE *f, const char *fmt, double v)
{
    fw_json_number(f, v, fmt);
}

/* a text field from files (scenario name, ship ids and types): escaped */
static void str(FILE *f, const char *key, const char *v)
{
    fprintf(f, "\"%s\": ", key);
    fw_json_string(f, v);
}

/* "sensing": the own ship's sensor's counts (records.h); with a radar, its
 * scans, plots, tracks and the rms error of the ships known, against the truth. */
static void sensing_json(FILE *f, const fw_run_summary *s, const char *ind)
{
    const fw_sensing_counts *c = &s->sense;
    fprintf(f, "%s  \"sensing\": {\"mode\": \"%s\"", ind, fw_sensing_mode_name(s->sense_mode));
    if (s->sense_mode != FW_SENSE_RADAR)
        fprintf(f, ", \"reports_sent\": %ld, \"lost\": %ld, \"arrived\": %ld", c->sent, c->lost,
                c->arrived);
    if (s->sense_mode == FW_SENSE_RADAR || s->sense_mode == FW_SENSE_AIS_RADAR)
        fprintf(f, ", \"scanned\": %ld, \"plotted\": %ld, \"tracks\": %ld, \"tracks_lost\": %ld, "
                   "\"position_error_rms_m\": %.1f",
                c->scanned, c->plotted, c->tracks, c->tracks_lost,
                c->err_n > 0 ? sqrt(c->err_sq / (double)c->err_n) : 0.0);
    fprintf(f, "},\n");
}

/* The own speed against the knowledge base's fitted speeds (null: none). */
static void kb_json(FILE *f, const fw_run_summary *s, const char *ind)
{
    fprintf(f, "%s  \"knowledge_base_speeds\": ", ind);
    if (!s->kb_present) {
        fprintf(f, "null,\n");
        return;
    }
    fprintf(f, "{\"fitted_min_kn\": %.2f, \"fitted_max_kn\": %.2f, \"own_min_kn\": ",
            s->kb_speed_min_kn, s->kb_speed_max_kn);
    num(f, "%.2f", s->own_speed_min_kn);
    fprintf(f, ", \"own_max_kn\": ");
    num(f, "%.2f", s->own_speed_max_kn);
    fprintf(f, ", \"outside_s\": %.1f, \"warning\": %s},\n", s->kb_outside_s,
            s->kb_outside_s > 0 ? "\"own speed outside the fitted speeds: predictions "
                                  "extrapolated\"" : "null");
}

void fw_summary_json(FILE *f, const fw_run_summary *s, const fw_encounter *e, int n,
                     const char *ind)
{
    fprintf(f, "%s{\n", ind);
    fprintf(f, "%s  ", ind);
    str(f, "scenario", s->scenario);
    fprintf(f, ", \"status\": \"%s\", \"t_end_s\": %.1f,\n", fw_run_status_name(s->status), s->t_end);
    fprintf(f, "%s  \"min_distance_m\": ", ind);
    num(f, "%.1f", s->min_dist);
    fprintf(f, ", ");
    str(f, "closest_target", s->min_dist_id);
    fprintf(f, ", \"min_hull_distance_m\": ");
    num(f, "%.1f", s->min_hull);
    fprintf(f, ",\n");
    fprintf(f, "%s  \"domain_entered\": %s, \"collision\": %s, \"colregs_ok\": %s,\n", ind,
            s->domain_entered ? "true" : "false", s->collision ? "true" : "false",
            s->colregs_ok ? "true" : "false");
    fprintf(f, "%s  \"first_action\": {\"acted\": %s, \"t_s\": ", ind, s->acted ? "true" : "false");
    num(f, "%.1f", s->t_act);
    fprintf(f, ", \"side\": \"%s\", \"helm_deg\": %.1f},\n", fw_side_name(s->act_side),
            fw_rad_to_deg(fabs(s->act_helm)));
    fprintf(f, "%s  \"max_helm_deg\": %.1f, \"t_return_s\": ", ind, fw_rad_to_deg(s->max_helm));
    num(f, "%.1f", s->t_return);
    fprintf(f, ", \"t_on_course_s\": ");
    num(f, "%.1f", s->t_on_course);
    fprintf(f, ",\n%s  \"final_heading_error_deg\": %.2f, \"final_cross_track_m\": %.1f,\n", ind,
            fw_rad_to_deg(s->heading_error), s->cross_track);
    fprintf(f, "%s  \"path_length_m\": %.1f, \"along_track_m\": %.1f, "
               "\"path_lengthening_m\": %.1f, \"time_lost_s\": %.1f,\n",
            ind, s->path_length, s->along_track, s->path_lengthening, s->time_lost);
    fprintf(f, "%s  \"rudder_work_deg_s\": %.1f, \"helm_orders\": %d, \"actions\": %d,\n", ind,
            fw_rad_to_deg(s->rudder_work), s->helm_orders, s->n_actions);
    fprintf(f, "%s  \"own_length_m\": %.1f, \"own_breadth_m\": %.1f, \"domain_m\": %.1f, "
               "\"domain_fore_aft_ratio\": %.2f, \"domain_reading\": \"%s\",\n",
            ind, s->own_length, s->own_breadth, s->domain, s->domain_ratio,
            s->domain_reading ? s->domain_reading : fw_domain_reading_name(FW_DOMAIN_ELLIPSE));
    if (s->survey)
        fprintf(f, "%s  \"survey\": {\"traffic_ship_s\": %.1f, \"encounters\": %d, \"head_on\": %d, "
                   "\"overtaking\": %d, \"crossing\": %d, \"with_own\": %d},\n",
                ind, s->traffic_ship_s, s->n_traffic, s->traffic_by_type[FW_SURVEY_HEAD_ON],
                s->traffic_by_type[FW_SURVEY_OVERTAKING], s->traffic_by_type[FW_SURVEY_CROSSING],
                s->n_traffic_own);
    else
        fprintf(f, "%s  \"survey\": null,\n", ind);
    if (s->ais)
        fprintf(f, "%s  \"ais\": {\"duplicates_dropped\": %ld, \"two_ships_one_mmsi\": %ld, "
                   "\"mmsis_shared\": %d, \"first_mmsi_shared\": %ld, \"not_projected\": %ld},\n",
                ind, s->ais_duplicates, s->ais_clashes, s->ais_clash_ships, s->ais_clash_first,
                s->ais_unprojected);
    if (s->sensed)
        sensing_json(f, s, ind);
    if (s->watched)
        fprintf(f, "%s  \"watch\": {\"encounters\": %ld, \"lapsed\": %ld},\n", ind,
                s->watch_pairs, s->watch_lapsed);
    if (s->mixed)
        fprintf(f, "%s  \"mix\": {\"compliant\": %ld, \"late\": %ld, \"passive\": %ld},\n", ind,
                s->mix[FW_BEH_COMPLIANT], s->mix[FW_BEH_LATE], s->mix[FW_BEH_PASSIVE]);
    if (s->own_watched)
        fprintf(f, "%s  \"own_watch\": {\"ships\": %ld, \"lapsed\": %ld},\n", ind,
                s->own_watch_pairs, s->own_watch_lapsed);
    const fw_monitor_counts *m = &s->monitors;
    fprintf(f, "%s  \"monitors\": {\"sideways\": %d, \"teleport\": %d, \"overlap\": %d, "
               "\"appear\": %d, \"vanish\": %d, \"start_close\": %d, \"stopped\": %d, "
               "\"max_lateral_mps\": %.2f},\n",
            ind, m->sideways, m->teleport, m->overlap, m->appear, m->vanish, m->start_close,
            m->stopped, m->max_lateral);
    fprintf(f, "%s  \"traffic_behaviour\": \"%s\", \"reactions\": {\"give_way\": %d, "
               "\"not_enough\": %d, \"resume\": %d},\n",
            ind, fw_behaviour_name(s->behaviour), s->n_give_way, s->n_give_way_short, s->n_resume);
    if (s->steering)
        fprintf(f, "%s  \"course_alterations\": {\"n\": %d, \"rejoined\": %d, \"min_deg\": %.1f, "
                   "\"max_deg\": %.1f},\n",
                ind, s->n_alter, s->n_rejoin, s->n_alter ? s->alter_deg_min : 0.0,
                s->n_alter ? s->alter_deg_max : 0.0);
    if (s->n_unkept > 0) /* only then: the outputs of runs that kept it are as before */
        fprintf(f, "%s  \"domain_unkept\": {\"episodes\": %d, \"first_t_s\": %.1f, "
                   "\"speed_kn\": %.1f},\n",
                ind, s->n_unkept, s->t_unkept, fw_ms_to_kn(s->unkept_speed));
    if (s->n_rule19e > 0) /* only then, likewise */
        fprintf(f, "%s  \"rule19e_slowdowns\": %d,\n", ind, s->n_rule19e);
    kb_json(f, s, ind);
    fprintf(f, "%s  \"encounters\": [", ind);
    for (int i = 0; i < n; i++) {
        fprintf(f, "%s\n%s    ", i ? "," : "", ind);
        fw_enc_json(f, &e[i]);
    }
    fprintf(f, "%s]\n%s}", n ? "\n  " : "", ind);
}

fw_status fw_records_survey(fw_records *r, const fw_survey_record *rec, int n, fw_error *err)
{
    if (!r->dir[0])
        return FW_OK;
    FILE *f = open_in(r->dir, "traffic_encounters.csv", err);
    if (!f)
        return FW_ERUN;
    /* times to the millisecond: steps are whole milliseconds */
    fprintf(f, "ship_a,ship_b,type,own,t_first_s,range0_m,dcpa0_m,tcpa0_s,min_dist_m,t_min_s,"
               "length_a_m,breadth_a_m,length_b_m,breadth_b_m\n");
    for (int i = 0; i < n; i++) {
        const fw_survey_record *e = &rec[i];
        fprintf(f, "%s,%s,%s,%d,%.3f,%.1f,%.1f,%.1f,%.1f,%.3f,%.1f,%.1f,%.1f,%.1f\n", e->ship_a,
                e->ship_b, fw_survey_type_name(e->type), e->own, e->t_first, e->range0, e->dcpa0,
                e->tcpa0, e->min_dist, e->t_min, e->length_a, e->breadth_a, e->length_b,
                e->breadth_b);
    }
    if (fclose(f) != 0)
        return fw_fail(err, FW_ERUN, "cannot write %s/traffic_encounters.csv: %s", r->dir, strerror(errno));
    return FW_OK;
}

fw_status fw_records_finish(fw_records *r, fw_run_summary *sum, fw_error *err)
{
    fw_book_judge(r->book, sum);
    if (!r->dir[0])
        return FW_OK;
    FILE *f = open_in(r->dir, "encounters.csv", err);
    if (!f)
        return FW_ERUN;
    fw_enc_csv_header(f);
    int n;
    const fw_encounter *e = fw_book_entries(r->book, &n);
    for (int i = 0; i < n; i++)
        fw_enc_csv_row(f, &e[i]);
    if (fclose(f) != 0)
        return fw_fail(err, FW_ERUN, "cannot write %s/encounters.csv: %s", r->dir, strerror(errno));
    f = open_in(r->dir, "summary.json", err);
    if (!f)
        return FW_ERUN;
    fw_summary_json(f, sum, e, n, "");
    fputc('\n', f);
    if (fclose(f) != 0)
        return fw_fail(err, FW_ERUN, "cannot write %s/summary.json: %s", r->dir, strerror(errno));
    return FW_OK;
}
