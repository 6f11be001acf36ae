/* scn_env.c - a scenario's current and wind (scn_env.h). */
#include "scenario/scn_env.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/files.h"
#include "core/units.h"

/* A tidal stream as the files give it: kn, deg, h, s. */
typedef struct tide_in {
    double rate, neap, set, period_h, t_max, t_spring;
} tide_in;

/* The keys of a tidal stream in map m (P its path) over *t; rate_kn and
 * flood_towards_deg required when req.  A neap rate above the spring rate:
 * FILE:LINE: P.neap_rate_kn. */
static fw_status read_tide(const yt_doc *doc, const yt_node *m, const char *P, bool req,
                           tide_in *t, fw_error *err)
{
    fw_status st;
    bool has_neap = yt_get(m, "neap_rate_kn") != NULL;
    if ((st = (req ? yt_req_number : yt_opt_number)(doc, m, P, "rate_kn", 0.0, 10.0, &t->rate,
                                                     err)) ||
        (st = (req ? yt_req_number : yt_opt_number)(doc, m, P, "flood_towards_deg", 0.0, 360.0,
                                                     &t->set, err)) ||
        (st = yt_opt_number(doc, m, P, "neap_rate_kn", 0.0, 10.0, &t->neap, err)) ||
        (st = yt_opt_number(doc, m, P, "period_h", 1.0, 48.0, &t->period_h, err)) ||
        (st = yt_opt_number(doc, m, P, "max_flood_s", -1e7, 1e7, &t->t_max, err)) ||
        (st = yt_opt_number(doc, m, P, "springs_s", -1e7, 1e7, &t->t_spring, err)))
        return st;
    if (has_neap && t->neap > t->rate) {
        char f[64];
        return fw_fail_at(err, doc->file, yt_key_line(m, "neap_rate_kn"),
                          yt_path(f, sizeof f, P, "neap_rate_kn"),
                          "%g kn is above the spring rate rate_kn (%g kn)", t->neap, t->rate);
    }
    return FW_OK;
}

/* The charted stream of the scenario's network, its directory's tide.yaml:
 *   source: "where the numbers come from"
 *   rate_kn: 2.25, neap_rate_kn: 1.25, flood_towards_deg: 85 */
static fw_status network_tide(const yt_doc *doc, const yt_node *tide, const fw_scenario *s,
                              tide_in *t, fw_error *err)
{
    static const char *const keys[] = {"source", "rate_kn", "neap_rate_kn", "flood_towards_deg",
                                       "period_h", NULL};
    const char *P = "environment.current.tidal.network";
    if (!s->network[0])
        return fw_fail_at(err, doc->file, yt_key_line(tide, "network"), P,
                          "the scenario has no traffic.network to take a tidal stream from");
    /* the network's directory: named by its path, or under the data root */
    char path[1200];
    int k = strchr(s->network, '/')
                ? snprintf(path, sizeof path, "%s/tide.yaml", s->network)
                : snprintf(path, sizeof path, "%s/networks/%s/tide.yaml", fw_data_root(), s->network);
    if (k < 0 || (size_t)k >= sizeof path)
        return fw_fail_at(err, doc->file, yt_key_line(tide, "network"), P, "path too long");
    FILE *f = fopen(path, "rb");
    if (!f)
        return fw_fail_at(err, doc->file, yt_key_line(tide, "network"), P,
                          "network '%s' has no charted tidal stream (no %s)", s->network, path);
    fclose(f);
    yt_doc *td;
    fw_status st = yt_load_file(path, &td, err);
    if (st)
        return st;
    char source[512];
    t->neap = -1.0;
    if (!(st = yt_check_keys(td, td->root, "", keys, err)) &&
        !(st = yt_req_string(td, td->root, "", "source", source, sizeof source, err)))
        st = read_tide(td, td->root, "", true, t, err);
    if (!st && t->neap < 0.0)
        t->neap = t->rate;
    yt_free(td);
    return st;
}

/* tidal: {rate_kn, neap_rate_kn, flood_towards_deg, period_h, max_flood_s,
 * springs_s} or {network: true, ...those to override} into *out. */
static fw_status load_tide(const yt_doc *doc, const yt_node *tide, const fw_scenario *s,
                           fw_current *out, fw_error *err)
{
    static const char *const keys[] = {"rate_kn", "neap_rate_kn", "flood_towards_deg",
                                       "period_h", "max_flood_s", "springs_s", "network", NULL};
    const char *T = "environment.current.tidal";
    tide_in t = {.neap = -1.0, .period_h = FW_M2_PERIOD_S / 3600.0};
    bool net = false;
    fw_status st;
    if ((st = yt_check_keys(doc, tide, T, keys, err)) ||
        (st = yt_opt_bool(doc, tide, T, "network", &net, err)) ||
        (net && (st = network_tide(doc, tide, s, &t, err))))
        return st;
    if (yt_get(tide, "rate_kn") && !yt_get(tide, "neap_rate_kn"))
        t.neap = -1.0; /* a rate of the scenario's own: no modulation unless it says */
    if ((st = read_tide(doc, tide, T, !net, &t, err)))
        return st;
    if (t.neap < 0.0)
        t.neap = t.rate;
    *out = fw_current_tidal_sn(fw_kn_to_ms(t.rate), fw_kn_to_ms(t.neap), fw_deg_to_rad(t.set),
                               t.period_h * 3600.0, t.t_max, t.t_spring);
    return FW_OK;
}

/* current: {speed_kn, towards_deg} or {tidal: {...}} (load_tide) */
static fw_status load_current(const yt_doc *doc, const yt_node *c, const fw_scenario *s,
                              fw_current *out, fw_error *err)
{
    static const char *const keys[] = {"speed_kn", "towards_deg", "tidal", NULL};
    const char *P = "environment.current";
    const yt_node *tide = NULL;
    fw_status st;
    if ((st = yt_check_keys(doc, c, P, keys, err)) ||
        (st = yt_opt_map(doc, c, P, "tidal", &tide, err)))
        return st;
    if (tide) {
        if (yt_get(c, "speed_kn") || yt_get(c, "towards_deg"))
            return yt_fail_key(doc, c, P, "tidal", err,
                               "give a uniform current (speed_kn, towards_deg) or a tidal "
                               "stream, not both");
        return load_tide(doc, tide, s, out, err);
    }
    double speed, towards;
    if ((st = yt_req_number(doc, c, P, "speed_kn", 0.0, 10.0, &speed, err)) ||
        (st = yt_req_number(doc, c, P, "towards_deg", 0.0, 360.0, &towards, err)))
        return st;
    *out = fw_current_uniform(fw_kn_to_ms(speed), fw_deg_to_rad(towards));
    return FW_OK;
}

/* wind: {speed_kn, from_deg, gust_intensity, gust_time_s} into *out. */
static fw_status load_wind(const yt_doc *doc, const yt_node *w, fw_wind *out, fw_error *err)
{
    static const char *const keys[] = {"speed_kn", "from_deg", "gust_intensity", "gust_time_s",
                                       NULL};
    const char *P = "environment.wind";
    double speed, from, gi = 0.0, gt = 0.0;
    fw_status st;
    if ((st = yt_check_keys(doc, w, P, keys, err)) ||
        (st = yt_req_number(doc, w, P, "speed_kn", 0.0, 100.0, &speed, err)) ||
        (st = yt_req_number(doc, w, P, "from_deg", 0.0, 360.0, &from, err)) ||
        (st = yt_opt_number(doc, w, P, "gust_intensity", 0.0, FW_GUST_INTENSITY_MAX, &gi, err)) ||
        (st = yt_opt_number(doc, w, P, "gust_time_s", FW_GUST_TIME_MIN_S, FW_GUST_TIME_MAX_S,
                            &gt, err)))
        return st;
    if (gi > 0.0 && !yt_get(w, "gust_time_s"))
        return yt_fail_key(doc, w, P, "gust_intensity", err,
                           "gusts need their time scale, gust_time_s (%g to %g s)",
                           FW_GUST_TIME_MIN_S, FW_GUST_TIME_MAX_S);
    *out = (fw_wind){.kind = FW_FIELD_UNIFORM, .speed = fw_kn_to_ms(speed),
                     .from = fw_deg_to_rad(from), .gust_intensity = gi, .gust_time = gt};
    return FW_OK;
}

/* environment.visibility_nm (e: the environment map) into s->visibility and
 * the rules' colregs definitions (the own ship's and the background ships') */
static fw_status load_visibility(const yt_doc *doc, const yt_node *e, fw_scenario *s,
                                 fw_error *err)
{
    double nm = 0.0;
    fw_status st = yt_opt_number(doc, e, "environment", "visibility_nm", -1e9, 1e9, &nm, err);
    if (st || !yt_get(e, "visibility_nm"))
        return st;
    if (!(nm > 0.0 && nm <= 100.0))
        return fw_fail_at(err, doc->file, yt_key_line(e, "visibility_nm"),
                          "environment.visibility_nm", "%g: a visibility is more than 0 and "
                          "at most 100 nm (leave it out for clear weather)", nm);
    fw_scn_set_visibility(s, fw_nm_to_m(nm));
    return FW_OK;
}

void fw_scn_set_visibility(fw_scenario *s, double m)
{
    s->visibility = m;
    s->helm.colregs.visibility = m;
    s->reactions.colregs.visibility = m;
}

fw_status fw_scn_load_env(const yt_doc *doc, const yt_node *root, fw_scenario *s, fw_error *err)
{
    static const char *const keys[] = {"current", "wind", "visibility_nm", NULL};
    s->env = fw_default_env();
    s->visibility = 0.0;
    const yt_node *e = NULL, *c = NULL, *w = NULL;
    fw_status st;
    if ((st = yt_opt_map(doc, root, "", "environment", &e, err)) || !e)
        return st;
    if ((st = yt_check_keys(doc, e, "environment", keys, err)) ||
        (st = load_visibility(doc, e, s, err)) ||
        (st = yt_opt_map(doc, e, "environment", "current", &c, err)) ||
        (st = yt_opt_map(doc, e, "environment", "wind", &w, err)) ||
        (c && (st = load_current(doc, c, s, &s->env.current, err))) ||
        (w && (st = load_wind(doc, w, &s->env.wind, err))))
        return st;
    if (w) {
        /* said here, where the file has it, rather than when the run starts */
        fw_error e3 = {0};
        if (fw_env_check_vessel(&s->env, "own ship", &s->ship, !s->nomoto_plant, &e3))
            return yt_fail_key(doc, e, "environment", "wind", err, "%s",
                               strchr(e3.msg, ':') ? strchr(e3.msg, ':') + 2 : e3.msg);
    }
    fw_error e2 = {0};
    if (fw_env_check(&s->env, &e2))
        return fw_fail_at(err, doc->file, e->line, "environment", "%s", e2.msg);
    return FW_OK;
}

/* sensing's radar keys into d->radar (arpa.h; degrees and knots converted) */
static fw_status load_radar(const yt_doc *doc, const yt_node *m, fw_radar_def *r, fw_error *err)
{
    const char *P = "sensing";
    double bearing = fw_rad_to_deg(r->bearing_sd);
    fw_status st;
    if ((st = yt_opt_number(doc, m, P, "range_sd_m", 0.0, 1000.0, &r->range_sd, err)) ||
        (st = yt_opt_number(doc, m, P, "bearing_sd_deg", 0.0, 10.0, &bearing, err)) ||
        (st = yt_opt_number(doc, m, P, "scan_s", 0.5, 10.0, &r->scan, err)) ||
        (st = yt_opt_number(doc, m, P, "alpha", 0.01, 1.0, &r->alpha, err)) ||
        (st = yt_opt_number(doc, m, P, "antenna_height_m", 1.0, 100.0, &r->antenna, err)))
        return st;
    r->bearing_sd = fw_deg_to_rad(bearing);
    r->beta = r->alpha * r->alpha / (2.0 - r->alpha); /* Benedict-Bordner (arpa.h) */
    return FW_OK;
}

fw_status fw_scn_load_sensing(const yt_doc *doc, const yt_node *root, fw_scenario *s,
                              fw_error *err)
{
    static const char *const keys[] = {"mode",           "position_sd_m", "sog_sd_kn",
                                       "cog_sd_deg",     "heading_sd_deg", "dropout",
                                       "latency_s",      "stale_s",        "range_sd_m",
                                       "bearing_sd_deg", "scan_s",         "alpha",
                                       "antenna_height_m", "background", NULL};
    const char *P = "sensing";
    fw_sensing_def *d = &s->sensing;
    *d = fw_default_sensing_def();
    s->sensing_background = true;
    const yt_node *m = NULL;
    fw_status st;
    if ((st = yt_opt_map(doc, root, "", "sensing", &m, err)) || !m)
        return st;
    char mode[16] = "perfect";
    double sog = fw_ms_to_kn(d->sog_sd), cog = fw_rad_to_deg(d->cog_sd),
           hdg = fw_rad_to_deg(d->heading_sd);
    if ((st = yt_check_keys(doc, m, P, keys, err)) ||
        (st = yt_opt_string(doc, m, P, "mode", mode, sizeof mode, err)))
        return st;
    if (fw_sensing_mode_parse(mode, &d->mode))
        return yt_fail_key(doc, m, P, "mode", err,
                           "'%s' is not a sensing mode (perfect, ais, radar or ais+radar)", mode);
    if ((st = yt_opt_number(doc, m, P, "position_sd_m", 0.0, 1000.0, &d->position_sd, err)) ||
        (st = yt_opt_number(doc, m, P, "sog_sd_kn", 0.0, 10.0, &sog, err)) ||
        (st = yt_opt_number(doc, m, P, "cog_sd_deg", 0.0, 90.0, &cog, err)) ||
        (st = yt_opt_number(doc, m, P, "heading_sd_deg", 0.0, 90.0, &hdg, err)) ||
        (st = yt_opt_number(doc, m, P, "dropout", 0.0, 1.0, &d->dropout, err)) ||
        (st = yt_opt_number(doc, m, P, "latency_s", 0.0, 2.0, &d->latency, err)) ||
        (st = yt_opt_number(doc, m, P, "stale_s", 1.0, 86400.0, &d->stale, err)) ||
        (st = load_radar(doc, m, &d->radar, err)) ||
        (st = yt_opt_bool(doc, m, P, "background", &s->sensing_background, err)))
        return st;
    d->sog_sd = fw_kn_to_ms(sog);
    d->cog_sd = fw_deg_to_rad(cog);
    d->heading_sd = fw_deg_to_rad(hdg);
    return FW_OK;
}

fw_status fw_scn_load_mix(const yt_doc *doc, const yt_node *tr, fw_scenario *s, fw_error *err)
{
    static const char *const keys[] = {"compliant", "late", "passive", "late_range_nm", NULL};
    const char *P = "traffic.mix";
    fw_watch_def *w = &s->reactions.watch;
    const yt_node *m = NULL;
    fw_status st;
    if ((st = yt_opt_map(doc, tr, "traffic", "mix", &m, err)) || !m)
        return st;
    double compliant = -1.0, range_nm = 0.0;
    if ((st = yt_check_keys(doc, m, P, keys, err)) ||
        (st = yt_opt_number(doc, m, P, "late", 0.0, 1.0, &w->mix_late, err)) ||
        (st = yt_opt_number(doc, m, P, "passive", 0.0, 1.0, &w->mix_passive, err)) ||
        (st = yt_opt_number(doc, m, P, "compliant", 0.0, 1.0, &compliant, err)) ||
        (st = yt_opt_number(doc, m, P, "late_range_nm", 0.01, 20.0, &range_nm, err)))
        return st;
    double sum = w->mix_late + w->mix_passive + (compliant >= 0.0 ? compliant : 0.0);
    if (compliant >= 0.0 ? fabs(sum - 1.0) > 1e-6 : sum > 1.0 + 1e-6)
        return fw_fail_at(err, doc->file, m->line, P,
                          "the shares sum to %.6g; compliant, late and passive must sum to 1",
                          sum);
    if (w->mix_late > 0.0 && range_nm == 0.0)
        return fw_fail_at(err, doc->file, yt_key_line(m, "late"), "traffic.mix.late_range_nm",
                          "late ships (late > 0) need the range they act at");
    w->mix_range = fw_nm_to_m(range_nm);
    return FW_OK;
}

fw_status fw_scn_load_watch(const yt_doc *doc, const yt_node *tr, fw_scenario *s, fw_error *err)
{
    static const char *const keys[] = {"delay_s", "lapse", "detect_s", "late", "late_range_nm",
                                       "own_ship", NULL};
    const char *P = "traffic.watch";
    fw_watch_def *w = &s->reactions.watch;
    *w = fw_default_watch_def();
    s->own_watch = fw_default_watch_def();
    const yt_node *m = NULL;
    fw_status st;
    if ((st = yt_opt_map(doc, tr, "traffic", "watch", &m, err)) || !m)
        return st;
    if ((st = yt_check_keys(doc, m, P, keys, err)) ||
        (st = yt_opt_number(doc, m, P, "delay_s", 0.0, 3600.0, &w->delay, err)) ||
        (st = yt_opt_number(doc, m, P, "lapse", 0.0, 1.0, &w->lapse, err)) ||
        (st = yt_opt_number(doc, m, P, "detect_s", 0.0, 3600.0, &w->detect, err)) ||
        (st = yt_opt_number(doc, m, P, "late", 0.0, 1.0, &w->late, err)))
        return st;
    double range_nm = 0.0;
    if ((st = yt_opt_number(doc, m, P, "late_range_nm", 0.01, 20.0, &range_nm, err)))
        return st;
    if (w->late > 0.0 && range_nm == 0.0)
        return fw_fail_at(err, doc->file, yt_key_line(m, "late"), "traffic.watch.late_range_nm",
                          "a late action (late > 0) needs the range it happens at");
    w->late_range = fw_nm_to_m(range_nm);
    char own[16] = "perfect";
    if ((st = yt_opt_string(doc, m, P, "own_ship", own, sizeof own, err)))
        return st;
    if (strcmp(own, "human") == 0)
        s->own_watch = *w;
    else if (strcmp(own, "perfect") != 0)
        return fw_fail_at(err, doc->file, yt_key_line(m, "own_ship"), "traffic.watch.own_ship",
                          "'%s': expected perfect or human", own);
    return FW_OK;
}
