/* scn_env.c - a scenario's current and wind (scn_env.h). */
#include "scenario/scn_env.h"

#include <string.h>

#include "core/units.h"

/* current: {speed_kn, towards_deg} or {tidal: {rate_kn, flood_towards_deg,
 * period_h, max_flood_s}} */
static fw_status load_current(const yt_doc *doc, const yt_node *c, fw_current *out,
                              fw_error *err)
{
    static const char *const keys[] = {"speed_kn", "towards_deg", "tidal", NULL};
    static const char *const tkeys[] = {"rate_kn", "flood_towards_deg", "period_h",
                                        "max_flood_s", NULL};
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
        const char *T = "environment.current.tidal";
        double rate, set, period_h = FW_M2_PERIOD_S / 3600.0, t_max = 0.0;
        if ((st = yt_check_keys(doc, tide, T, tkeys, err)) ||
            (st = yt_req_number(doc, tide, T, "rate_kn", 0.0, 10.0, &rate, err)) ||
            (st = yt_req_number(doc, tide, T, "flood_towards_deg", 0.0, 360.0, &set, err)) ||
            (st = yt_opt_number(doc, tide, T, "period_h", 1.0, 48.0, &period_h, err)) ||
            (st = yt_opt_number(doc, tide, T, "max_flood_s", -1e7, 1e7, &t_max, err)))
            return st;
        *out = fw_current_tidal(fw_kn_to_ms(rate), fw_deg_to_rad(set), period_h * 3600.0, t_max);
        return FW_OK;
    }
    double speed, towards;
    if ((st = yt_req_number(doc, c, P, "speed_kn", 0.0, 10.0, &speed, err)) ||
        (st = yt_req_number(doc, c, P, "towards_deg", 0.0, 360.0, &towards, err)))
        return st;
    *out = fw_current_uniform(fw_kn_to_ms(speed), fw_deg_to_rad(towards));
    return FW_OK;
}

fw_status fw_scn_load_env(const yt_doc *doc, const yt_node *root, fw_scenario *s, fw_error *err)
{
    static const char *const keys[] = {"current", "wind", NULL};
    static const char *const wkeys[] = {"speed_kn", "from_deg", NULL};
    s->env = fw_default_env();
    const yt_node *e = NULL, *c = NULL, *w = NULL;
    fw_status st;
    if ((st = yt_opt_map(doc, root, "", "environment", &e, err)) || !e)
        return st;
    if ((st = yt_check_keys(doc, e, "environment", keys, err)) ||
        (st = yt_opt_map(doc, e, "environment", "current", &c, err)) ||
        (st = yt_opt_map(doc, e, "environment", "wind", &w, err)) ||
        (c && (st = load_current(doc, c, &s->env.current, err))))
        return st;
    if (w) {
        double speed, from;
        const char *P = "environment.wind";
        if ((st = yt_check_keys(doc, w, P, wkeys, err)) ||
            (st = yt_req_number(doc, w, P, "speed_kn", 0.0, 100.0, &speed, err)) ||
            (st = yt_req_number(doc, w, P, "from_deg", 0.0, 360.0, &from, err)))
            return st;
        s->env.wind = (fw_wind){.kind = FW_FIELD_UNIFORM, .speed = fw_kn_to_ms(speed),
                                .from = fw_deg_to_rad(from)};
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
                                       "antenna_height_m", NULL};
    const char *P = "sensing";
    fw_sensing_def *d = &s->sensing;
    *d = fw_default_sensing_def();
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
        (st = load_radar(doc, m, &d->radar, err)))
        return st;
    d->sog_sd = fw_kn_to_ms(sog);
    d->cog_sd = fw_deg_to_rad(cog);
    d->heading_sd = fw_deg_to_rad(hdg);
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
