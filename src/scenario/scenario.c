/* Scenario files: the schema, checked field by field (see scenario.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"
#include "core/units.h"
#include "nomoto/nomoto.h"
#include "scenario/position.h"
#include "scenario/scn_ais.h"
#include "scenario/scn_env.h"
#include "scenario/scn_netroute.h"
#include "scenario/scn_route.h"
#include "scenario/scenario.h"
#include "traffic/demand.h"
#include "yaml/yaml_tree.h"

/* own_ship's start, course, speed and planned leg (without a route). */
static fw_status load_own_line(const yt_doc *doc, const yt_node *root, const yt_node *own,
                               fw_scenario *s, fw_error *err)
{
    double course_deg, speed_kn, gamma;
    fw_status st;
    if ((st = fw_scn_load_position(doc, own, "own_ship", s, &s->east, &s->north, &gamma, err)) ||
        (st = yt_req_number(doc, own, "own_ship", "course_deg", 0, 360, &course_deg, err)) ||
        (st = yt_req_number(doc, own, "own_ship", "speed_kn", 1, 40, &speed_kn, err)))
        return st;
    s->course = fw_wrap_2pi(fw_deg_to_rad(course_deg) - gamma);
    s->speed = fw_kn_to_ms(speed_kn);
    /* where it is going: a leg length along the course or a destination on it */
    const yt_node *dest = yt_get(own, "destination");
    bool has_leg = yt_get(own, "leg_nm") != NULL;
    if (has_leg == (dest != NULL))
        return fw_fail_at(err, doc->file, yt_key_line(root, "own_ship"), "own_ship",
                          "give exactly one of leg_nm, destination or route");
    if (has_leg) {
        double leg_nm;
        if ((st = yt_req_number(doc, own, "own_ship", "leg_nm", 0.1, 500, &leg_nm, err)))
            return st;
        s->leg = fw_nm_to_m(leg_nm);
    } else {
        static const char *const dkeys[] = {"east_m", "north_m", "lat_deg", "lon_deg", NULL};
        double e, n, g;
        const yt_node *d;
        if ((st = yt_req_map(doc, own, "own_ship", "destination", &d, err)) ||
            (st = yt_check_keys(doc, d, "own_ship.destination", dkeys, err)) ||
            (st = fw_scn_load_position(doc, d, "own_ship.destination", s, &e, &n, &g, err)))
            return st;
        double de = e - s->east, dn = n - s->north, leg = hypot(de, dn);
        /* the planned track is the course line: the destination must lie on it */
        if (leg < 185.2 || fabs(de * cos(s->course) - dn * sin(s->course)) > 0.01 * leg ||
            de * sin(s->course) + dn * cos(s->course) <= 0)
            return fw_fail_at(err, doc->file, yt_key_line(own, "destination"),
                              "own_ship.destination",
                              "must lie ahead on the course line, at least 0.1 nm away");
        s->leg = leg;
    }
    const fw_nomoto_kb *kb = &s->ship.nomoto;
    if (fw_nomoto_kb_speed(kb, speed_kn) == FW_KB_SPEED_REFUSED)
        return fw_fail_at(err, doc->file, yt_key_line(own, "speed_kn"), "own_ship.speed_kn",
                          "%g kn is beyond %s's Nomoto knowledge base, fitted over %g-%g kn, by "
                          "more than its x%g margin (%.1f-%.1f kn)",
                          speed_kn, s->ship.name, kb->speed_min_kn, kb->speed_max_kn,
                          FW_KB_SPEED_MARGIN, kb->speed_min_kn / FW_KB_SPEED_MARGIN,
                          kb->speed_max_kn * FW_KB_SPEED_MARGIN);
    return FW_OK;
}

static fw_status load_own(const yt_doc *doc, const yt_node *root, fw_scenario *s, fw_error *err)
{
    static const char *const keys[] = {"ship", "east_m", "north_m", "lat_deg", "lon_deg",
                                       "course_deg", "speed_kn", "leg_nm", "destination",
                                       "route", "network_route", "dynamics", NULL};
    const yt_node *own;
    fw_status st;
    char ship[512];
    if ((st = yt_req_map(doc, root, "", "own_ship", &own, err)) ||
        (st = yt_check_keys(doc, own, "own_ship", keys, err)) ||
        (st = yt_req_string(doc, own, "own_ship", "ship", ship, sizeof ship, err)))
        return st;
    char dyn[16] = "mmg";
    if ((st = yt_opt_string(doc, own, "own_ship", "dynamics", dyn, sizeof dyn, err)))
        return st;
    if (strcmp(dyn, "mmg") != 0 && strcmp(dyn, "nomoto") != 0)
        return fw_fail_at(err, doc->file, yt_key_line(own, "dynamics"), "own_ship.dynamics",
                          "'%s': expected mmg or nomoto", dyn);
    s->nomoto_plant = strcmp(dyn, "nomoto") == 0;
    fw_error serr = {0};
    if ((st = fw_ship_load(ship, &s->ship, &serr)))
        return fw_fail_at(err, doc->file, yt_key_line(own, "ship"), "own_ship.ship", "%s",
                          serr.msg);
    if (yt_get(own, "network_route"))
        return fw_scn_load_net_route(doc, root, own, s, err);
    return yt_get(own, "route") ? fw_scn_load_route(doc, own, s, err)
                                : load_own_line(doc, root, own, s, err);
}

static fw_status load_target(const yt_doc *doc, const yt_node *t, const char *path,
                             const fw_scenario *s, fw_target *o, fw_error *err)
{
    static const char *const keys[] = {"id", "type", "east_m", "north_m", "lat_deg", "lon_deg",
                                       "course_deg", "speed_kn", "length_m", "breadth_m", NULL};
    fw_status st;
    if (t->kind != YT_MAP)
        return fw_fail_at(err, doc->file, t->line, path, "expected a map (id, east_m, ...)");
    double c, v, gamma;
    snprintf(o->type, sizeof o->type, "cargo");
    if ((st = yt_check_keys(doc, t, path, keys, err)) ||
        (st = yt_req_string(doc, t, path, "id", o->id, sizeof o->id, err)) ||
        (st = yt_opt_string(doc, t, path, "type", o->type, sizeof o->type, err)) ||
        (st = fw_scn_load_position(doc, t, path, s, &o->east, &o->north, &gamma, err)) ||
        (st = yt_req_number(doc, t, path, "course_deg", 0, 360, &c, err)) ||
        (st = yt_req_number(doc, t, path, "speed_kn", 0.5, 40, &v, err)) ||
        (st = yt_req_number(doc, t, path, "length_m", 5, 500, &o->length, err)) ||
        (st = yt_req_number(doc, t, path, "breadth_m", 1, 80, &o->breadth, err)))
        return st;
    char msg[200];
    if (!yt_name_ok(o->id, 24, true, "up to 24 letters, digits, '-' or '_'", msg, sizeof msg))
        return yt_fail_key(doc, t, path, "id", err, "%s", msg);
    if (!yt_name_ok(o->type, 63, true, "letters, digits, '-' or '_'", msg, sizeof msg))
        return yt_fail_key(doc, t, path, "type", err, "%s", msg);
    if (o->breadth > o->length)
        return yt_fail_key(doc, t, path, "breadth_m", err, "%g m exceeds the length %g m",
                           o->breadth, o->length);
    o->course = fw_wrap_2pi(fw_deg_to_rad(c) - gamma);
    o->speed = fw_kn_to_ms(v);
    /* a scenario's ship at t = 0 knows no drift and no current */
    o->heading = o->course, o->stw = o->speed;
    return FW_OK;
}

/* traffic.tracks: a CSV of recorded tracks (traffic/source_track.h), its path
 * relative to the scenario file; the traffic then is that alone. */
static fw_status load_tracks(const yt_doc *doc, const yt_node *tr, fw_scenario *s, fw_error *err)
{
    fw_status st = fw_scn_file_key(doc, tr, "traffic", "tracks", s->file, s->tracks,
                                   sizeof s->tracks, err);
    if (st || !s->tracks[0])
        return st;
    if (s->network[0] || yt_get(tr, "targets") || yt_get(tr, "ais"))
        return fw_fail_at(err, doc->file, yt_key_line(tr, "tracks"), "traffic.tracks",
                          "recorded tracks are the whole traffic: no network, targets or AIS "
                          "with them");
    return FW_OK;
}

/* traffic.network: a network's name, or a directory's path relative to the
 * scenario's (scn_ais.h fw_scn_network_ref). */
static fw_status network_key(const yt_doc *doc, const yt_node *tr, fw_scenario *s, fw_error *err)
{
    char value[sizeof s->network] = "";
    s->network[0] = '\0';
    fw_status st = yt_opt_string(doc, tr, "traffic", "network", value, sizeof value, err);
    if (st || !value[0])
        return st;
    if (!fw_scn_network_ref(doc->file, value, s->network, sizeof s->network))
        return fw_fail_at(err, doc->file, yt_key_line(tr, "network"), "traffic.network",
                          "path too long");
    return FW_OK;
}

static fw_status load_traffic(const yt_doc *doc, const yt_node *root, fw_scenario *s,
                              fw_error *err)
{
    static const char *const keys[] = {"network", "density", "fill", "targets", "behaviour",
                                       "tracks", "ais", "ais_start", "ais_end",
                                       "ais_max_gap_s", "ais_columns", "waterway", "watch",
                                       "give_way", "mix", NULL};
    const yt_node *tr, *seq = NULL;
    fw_status st;
    if ((st = yt_req_map(doc, root, "", "traffic", &tr, err)) ||
        (st = yt_check_keys(doc, tr, "traffic", keys, err)) ||
        (st = network_key(doc, tr, s, err)) ||
        (st = yt_opt_number(doc, tr, "traffic", "density", 0, 100, &s->density, err)) ||
        (st = yt_opt_seq(doc, tr, "traffic", "targets", &seq, err)))
        return st;
    char beh[32] = "colregs";
    if ((st = yt_opt_string(doc, tr, "traffic", "behaviour", beh, sizeof beh, err)))
        return st;
    if (fw_behaviour_parse(beh, &s->reactions.behaviour))
        return fw_fail_at(err, doc->file, yt_key_line(tr, "behaviour"), "traffic.behaviour",
                          "'%s': expected colregs or blind", beh);
    char gw[32] = "course";
    if ((st = yt_opt_string(doc, tr, "traffic", "give_way", gw, sizeof gw, err)))
        return st;
    if (fw_give_way_parse(gw, &s->reactions.give_way))
        return fw_fail_at(err, doc->file, yt_key_line(tr, "give_way"), "traffic.give_way",
                          "'%s': expected speed or course", gw);
    if ((st = fw_scn_load_watch(doc, tr, s, err)) || (st = fw_scn_load_mix(doc, tr, s, err)))
        return st;
    char ww[32] = "open-sea";
    if ((st = yt_opt_string(doc, tr, "traffic", "waterway", ww, sizeof ww, err)))
        return st;
    if (fw_waterway_parse(ww, &s->waterway))
        return fw_fail_at(err, doc->file, yt_key_line(tr, "waterway"), "traffic.waterway",
                          "'%s': expected open-sea, tss or channel", ww);
    /* a channel's lanes are the water, a scheme's traffic lane is where a
     * ship proceeds (rule 10(b)(i)); elsewhere it may go anywhere (reactions.h) */
    s->reactions.room_from_lanes = s->waterway == FW_WATERWAY_CHANNEL;
    s->reactions.room_traffic_lanes = s->waterway == FW_WATERWAY_TSS;
    /* the own ship's policy with no helm clearing in a scheme (policy.h) */
    s->policy.tss = s->waterway == FW_WATERWAY_TSS;
    /* the audit's risk distance for this water and this ship (audit.h) */
    s->audit = fw_audit_def_for(s->waterway, s->ship.Loa);
    long fill = 0;
    if ((st = yt_opt_int(doc, tr, "traffic", "fill", 0, 10000, &fill, err)))
        return st;
    s->fill = (int)fill;
    if (s->network[0]) {
        fw_network_files nf;
        fw_error nerr = {0};
        if (fw_network_find(s->network, &nf, &nerr))
            return fw_fail_at(err, doc->file, yt_key_line(tr, "network"), "traffic.network",
                              "%s", nerr.msg);
        /* the demand is read by every run: a bad one is refused now, not per run */
        fw_demand *dm = malloc(sizeof *dm);
        if (!dm)
            return fw_fail(err, FW_ERUN, "out of memory");
        fw_status dst = fw_demand_load(nf.demand, dm, &nerr);
        if (!dst)
            dst = fw_network_check_demand(&nf, dm, &nerr);
        free(dm);
        if (dst)
            return fw_fail_at(err, doc->file, yt_key_line(tr, "network"), "traffic.network",
                              "%s", nerr.msg);
        if ((st = fw_scn_route_on_network(doc, root, s, &nf, err)))
            return st;
    }
    if (seq) {
        if (seq->n > FW_SCN_MAX_TARGETS)
            return fw_fail_at(err, doc->file, seq->line, "traffic.targets",
                              "%zu targets, at most %d", seq->n, FW_SCN_MAX_TARGETS);
        for (size_t i = 0; i < seq->n; i++) {
            char path[64];
            snprintf(path, sizeof path, "traffic.targets[%zu]", i);
            fw_target *o = &s->targets[i];
            if ((st = load_target(doc, seq->items[i], path, s, o, err)))
                return st;
            for (size_t j = 0; j < i; j++)
                if (strcmp(s->targets[j].id, o->id) == 0)
                    return fw_fail_at(err, doc->file, yt_key_line(seq->items[i], "id"), path,
                                      "id '%s' used twice", o->id);
            /* a target inside the own hull (or touching it) is no encounter */
            if (fw_hulls_overlap(s->east, s->north, s->course, s->ship.Loa, s->ship.B, o->east,
                                 o->north, o->heading, o->length, o->breadth))
                return fw_fail_at(err, doc->file, seq->items[i]->line, path,
                                  "target '%s' starts overlapping the own ship's hull", o->id);
            s->n_targets++;
        }
    }
    if ((st = load_tracks(doc, tr, s, err)) || (st = fw_scn_load_ais(doc, tr, s, err)))
        return st;
    if (!s->network[0] && s->n_targets == 0 && !s->tracks[0] && !s->ais.file[0])
        return fw_fail_at(err, doc->file, yt_key_line(root, "traffic"), "traffic",
                          "needs a network, recorded tracks, AIS reports or at least one target");
    return FW_OK;
}

/* avoidance.return: track (the default) or heading (the paper's return);
 * avoidance.domain_from: hull (the default: the domain's size is a
 * clearance beyond the own hull, geom/geom.h) or centre (the paper's);
 * avoidance.domain_reading: ellipse (the default) or transverse (the
 * paper's clearance from the target's side, geom/geom.h). */
static fw_status load_return(const yt_doc *doc, const yt_node *a, fw_scenario *s, fw_error *err)
{
    char ret[16] = "", from[16] = "", reading[16] = "";
    fw_status st = yt_opt_string(doc, a, "avoidance", "return", ret, sizeof ret, err);
    if (!st)
        st = yt_opt_string(doc, a, "avoidance", "domain_from", from, sizeof from, err);
    if (!st)
        st = yt_opt_string(doc, a, "avoidance", "domain_reading", reading, sizeof reading, err);
    if (st)
        return st;
    int rd = reading[0] ? fw_domain_reading_parse(reading) : (int)s->helm.domain.reading;
    if (rd < 0)
        return fw_fail_at(err, doc->file, yt_key_line(a, "domain_reading"),
                          "avoidance.domain_reading", "'%s': expected ellipse or transverse",
                          reading);
    s->helm.domain.reading = (fw_domain_reading)rd;
    if (ret[0] && fw_return_parse(ret, &s->policy.ret))
        return fw_fail_at(err, doc->file, yt_key_line(a, "return"), "avoidance.return",
                          "'%s': expected track or heading", ret);
    if (strcmp(from, "centre") == 0)
        s->helm.domain.own_half_length = s->helm.domain.own_half_breadth = 0.0;
    else if (from[0] && strcmp(from, "hull") != 0)
        return fw_fail_at(err, doc->file, yt_key_line(a, "domain_from"), "avoidance.domain_from",
                          "'%s': expected hull or centre", from);
    return FW_OK;
}

static fw_status load_avoidance(const yt_doc *doc, const yt_node *root, fw_scenario *s,
                                fw_error *err)
{
    static const char *const keys[] = {"domain_m", "fore_aft_ratio", "min_helm_deg",
                                       "max_helm_deg", "horizon_s", "act_range_nm",
                                       "act_lookahead_s", "standon_act_range_nm",
                                       "standon_act_time_s", "overtake_side", "radius_nm",
                                       "return", "domain_from", "domain_reading", NULL};
    const yt_node *a = NULL;
    fw_status st;
    if ((st = yt_opt_map(doc, root, "", "avoidance", &a, err)))
        return st;
    /* the domain about the own hull unless the scenario says centre */
    s->helm.domain.own_half_length = 0.5 * s->ship.Loa;
    s->helm.domain.own_half_breadth = 0.5 * s->ship.B;
    if (!a)
        return FW_OK; /* every other setting has the paper's default */
    double act = fw_m_to_nm(s->policy.act_range), so = fw_m_to_nm(s->policy.standon_act_range);
    double radius = fw_m_to_nm(s->radius);
    const char *P = "avoidance";
    if ((st = yt_check_keys(doc, a, P, keys, err)) ||
        (st = yt_opt_number(doc, a, P, "domain_m", 10, 5000, &s->helm.domain.size, err)) ||
        (st = yt_opt_number(doc, a, P, "fore_aft_ratio", 0.2, 10, &s->helm.domain.fore_aft_ratio,
                            err)) ||
        (st = yt_opt_number(doc, a, P, "min_helm_deg", 1, 35, &s->helm.min_helm_deg, err)) ||
        (st = yt_opt_number(doc, a, P, "max_helm_deg", 1, 45, &s->helm.max_helm_deg, err)) ||
        (st = yt_opt_number(doc, a, P, "horizon_s", 60, 3600, &s->helm.track.horizon, err)) ||
        (st = yt_opt_number(doc, a, P, "act_range_nm", 0.1, 20, &act, err)) ||
        (st = yt_opt_number(doc, a, P, "act_lookahead_s", 0, 600, &s->policy.act_lookahead,
                            err)) ||
        (st = yt_opt_number(doc, a, P, "standon_act_range_nm", 0.05, 20, &so, err)) ||
        (st = yt_opt_number(doc, a, P, "standon_act_time_s", 0, 3600, &s->policy.standon_act_time,
                            err)) ||
        (st = yt_opt_number(doc, a, P, "radius_nm", 0.5, 50, &radius, err)))
        return st;
    char side[16] = "";
    if ((st = load_return(doc, a, s, err)) ||
        (st = yt_opt_string(doc, a, P, "overtake_side", side, sizeof side, err)))
        return st;
    if (side[0]) {
        if (strcmp(side, "either") == 0)
            s->helm.overtake_side = 0;
        else if (strcmp(side, "starboard") == 0)
            s->helm.overtake_side = 1;
        else if (strcmp(side, "port") == 0)
            s->helm.overtake_side = -1;
        else
            return fw_fail_at(err, doc->file, yt_key_line(a, "overtake_side"),
                              "avoidance.overtake_side", "'%s': expected either, starboard or port",
                              side);
    }
    if (s->helm.min_helm_deg > s->helm.max_helm_deg)
        return fw_fail_at(err, doc->file, yt_key_line(a, "min_helm_deg"), "avoidance.min_helm_deg",
                          "%g deg exceeds max_helm_deg %g", s->helm.min_helm_deg,
                          s->helm.max_helm_deg);
    if (s->helm.max_helm_deg > fw_rad_to_deg(s->ship.rudder_max) + 1e-9)
        return fw_fail_at(err, doc->file, yt_key_line(a, "max_helm_deg"), "avoidance.max_helm_deg",
                          "%g deg exceeds the ship's rudder limit %g deg", s->helm.max_helm_deg,
                          fw_rad_to_deg(s->ship.rudder_max));
    /* the helms the search tries must be ones the knowledge base was fitted
     * at: below its smallest angle it would use that angle's indices */
    const fw_nomoto_kb *kb = &s->ship.nomoto;
    const char *key = s->helm.min_helm_deg < kb->rudder_min_deg - 1e-9   ? "min_helm_deg"
                      : s->helm.max_helm_deg > kb->rudder_max_deg + 1e-9 ? "max_helm_deg"
                                                                          : NULL;
    if (kb->present && key)
        return fw_fail_at(err, doc->file, yt_key_line(a, key), key[1] == 'i'
                              ? "avoidance.min_helm_deg" : "avoidance.max_helm_deg",
                          "%g deg is outside %g-%g deg, the rudder angles %s's Nomoto knowledge "
                          "base was fitted over",
                          key[1] == 'i' ? s->helm.min_helm_deg : s->helm.max_helm_deg,
                          kb->rudder_min_deg, kb->rudder_max_deg, s->ship.name);
    s->policy.act_range = fw_nm_to_m(act);
    s->policy.standon_act_range = fw_nm_to_m(so);
    s->radius = fw_nm_to_m(radius);
    return FW_OK;
}

static fw_status load_survey(const yt_doc *doc, const yt_node *root, fw_scenario *s,
                             fw_error *err)
{
    static const char *const keys[] = {"radius_nm", "range_m", "dcpa_m", "tcpa_s",
                                       "hysteresis_m", NULL};
    const yt_node *v = NULL;
    fw_status st;
    if ((st = yt_opt_map(doc, root, "", "survey", &v, err)))
        return st;
    if (!v)
        return FW_OK; /* no section: no survey */
    fw_survey_def *d = &s->survey_def;
    double radius = fw_m_to_nm(s->survey_radius);
    const char *P = "survey";
    if ((st = yt_check_keys(doc, v, P, keys, err)) ||
        (st = yt_opt_number(doc, v, P, "radius_nm", 0.5, 50, &radius, err)) ||
        (st = yt_opt_number(doc, v, P, "range_m", 10, 20000, &d->range, err)) ||
        (st = yt_opt_number(doc, v, P, "dcpa_m", 1, 20000, &d->dcpa, err)) ||
        (st = yt_opt_number(doc, v, P, "tcpa_s", 1, 7200, &d->tcpa, err)) ||
        (st = yt_opt_number(doc, v, P, "hysteresis_m", 0, 20000, &d->hysteresis, err)))
        return st;
    s->survey = true;
    s->survey_radius = fw_nm_to_m(radius);
    return FW_OK;
}

static fw_status load_run(const yt_doc *doc, const yt_node *root, fw_scenario *s, fw_error *err)
{
    static const char *const keys[] = {"duration_s", "step_s", "seed", NULL};
    static const char *const okeys[] = {"targets_csv", "record_every_s", "fcd", NULL};
    const yt_node *r, *o = NULL;
    long seed = 1;
    fw_status st;
    if ((st = yt_req_map(doc, root, "", "run", &r, err)) ||
        (st = yt_check_keys(doc, r, "run", keys, err)) ||
        (st = yt_req_number(doc, r, "run", "duration_s", 1, 86400, &s->duration, err)) ||
        (st = yt_opt_number(doc, r, "run", "step_s", 0.1, 10, &s->step, err)) ||
        (st = yt_opt_int(doc, r, "run", "seed", 0, 2147483647L, &seed, err)))
        return st;
    s->seed = (unsigned long)seed;
    /* SUMO's clock counts milliseconds: a step that is not a whole number of
     * them would drift against fairway's */
    if (fabs(s->step * 1000 - round(s->step * 1000)) > 1e-6)
        return fw_fail_at(err, doc->file, yt_key_line(r, "step_s"), "run.step_s",
                          "%g s is not a whole number of milliseconds", s->step);
    if ((st = yt_opt_map(doc, root, "", "outputs", &o, err)))
        return st;
    s->record_every = s->step;
    if (o && ((st = yt_check_keys(doc, o, "outputs", okeys, err)) ||
              (st = yt_opt_bool(doc, o, "outputs", "targets_csv", &s->targets_csv, err)) ||
              (st = yt_opt_bool(doc, o, "outputs", "fcd", &s->fcd, err)) ||
              (st = yt_opt_number(doc, o, "outputs", "record_every_s", s->step, 3600,
                                  &s->record_every, err))))
        return st;
    double k = s->record_every / s->step;
    if (fabs(k - round(k)) > 1e-6)
        return fw_fail_at(err, doc->file, yt_key_line(o, "record_every_s"),
                          "outputs.record_every_s", "%g s is not a multiple of run.step_s %g s",
                          s->record_every, s->step);
    return FW_OK;
}

fw_status fw_scenario_defaults(const char *path, fw_scenario *s, fw_error *err)
{
    memset(s, 0, sizeof *s);
    if (fw_path_copy(s->file, sizeof s->file, path, err))
        return err->status;
    s->density = 1.0;
    s->reactions = fw_default_reactions_def();
    s->helm = fw_default_helm_def();
    s->audit = fw_default_audit_def();
    s->policy = fw_default_policy_def();
    s->radius = fw_nm_to_m(8.0); /* Imazu targets start 6 nm off: see them from the start */
    s->survey_radius = fw_nm_to_m(6.0);
    s->survey_def = fw_default_survey_def();
    s->step = 1.0;
    s->record_every = s->step;
    s->seed = 1;
    s->targets_csv = true;
    /* what the sections' loaders set when a section is absent */
    s->env = fw_default_env();
    s->sensing = fw_default_sensing_def();
    s->reactions.watch = fw_default_watch_def();
    s->own_watch = fw_default_watch_def();
    return FW_OK;
}

fw_status fw_scenario_load(const char *path, fw_scenario *s, fw_error *err)
{
    return fw_scenario_load_with(path, NULL, 0, s, err);
}

fw_status fw_scenario_load_with(const char *path, const fw_setting *settings, int n,
                                fw_scenario *s, fw_error *err)
{
    static const char *const keys[] = {"name", "description", "origin", "own_ship", "traffic",
                                       "avoidance", "survey", "environment", "sensing", "run",
                                       "outputs", NULL};
    if (fw_scenario_defaults(path, s, err))
        return err->status;
    yt_doc *doc = NULL;
    fw_status st = yt_load_file(path, &doc, err);
    if (st)
        return st;
    for (int i = 0; i < n && !st; i++)
        st = yt_set(doc, settings[i].key, settings[i].value, err);
    if (st)
        goto out;
    const yt_node *root = doc->root;
    if ((st = yt_top_map(doc, keys, "name, own_ship, traffic, run", s->name, sizeof s->name,
                         s->description, sizeof s->description, err)))
        goto out;
    char msg[200];
    if (!yt_name_ok(s->name, 63, false,
                    "letters, digits, '-' or '_' (it names the output directory)", msg,
                    sizeof msg)) {
        st = fw_fail_at(err, doc->file, yt_key_line(root, "name"), "name", "%s", msg);
        goto out;
    }
    if ((st = fw_scn_load_origin(doc, root, s, err)) || (st = load_own(doc, root, s, err)) ||
        (st = load_traffic(doc, root, s, err)) ||
        (st = load_avoidance(doc, root, s, err)) || (st = load_survey(doc, root, s, err)) ||
        (st = fw_scn_load_env(doc, root, s, err)) ||
        (st = fw_scn_load_sensing(doc, root, s, err)) || (st = load_run(doc, root, s, err)))
        goto out;
out:
    yt_free(doc);
    return st;
}

const char *fw_scenario_randomness(const fw_scenario *s)
{
    /* Each setting that makes a world element draw after its start belongs
     * here as it comes (watchkeeping delays and lapses, gusts ...) */
    if (s->sensing.mode != FW_SENSE_PERFECT)
        return NULL; /* AIS reports: noise, slots, dropouts, drawn as they are sent */
    if (s->reactions.behaviour == FW_BEHAVIOUR_COLREGS && fw_watch_def_draws(&s->reactions.watch))
        return NULL; /* lapses, times to detect, late actions: drawn per encounter as it comes */
    if (fw_watch_def_draws(&s->own_watch))
        return NULL; /* the own ship's, likewise */
    if (fw_wind_gusty(&s->env.wind))
        return NULL; /* the wind's gusts, one draw a step */
    return "none of its settings draws: perfect sensing, flawless watchkeeping, steady wind";
}
