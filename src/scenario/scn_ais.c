/* scn_ais.c - a scenario's AIS traffic keys and its file keys (scn_ais.h). */
#include "scenario/scn_ais.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ais/ais.h"

bool fw_scn_network_ref(const char *scenario_file, const char *value, char *out, size_t n)
{
    const char *slash = strrchr(scenario_file, '/');
    int k = !strchr(value, '/') || value[0] == '/' || !slash
                ? snprintf(out, n, "%s", value)
                : snprintf(out, n, "%.*s/%s", (int)(slash - scenario_file), scenario_file, value);
    return k >= 0 && (size_t)k < n;
}

fw_status fw_scn_file_key(const yt_doc *doc, const yt_node *map, const char *path,
                          const char *key, const char *scenario_file, char *out, size_t n,
                          fw_error *err)
{
    char rel[512] = "", field[128];
    out[0] = '\0';
    fw_status st = yt_opt_string(doc, map, path, key, rel, sizeof rel, err);
    if (st || !rel[0])
        return st;
    yt_path(field, sizeof field, path, key);
    int line = yt_key_line(map, key);
    const char *slash = strrchr(scenario_file, '/');
    int k = rel[0] == '/' || !slash
                ? snprintf(out, n, "%s", rel)
                : snprintf(out, n, "%.*s/%s", (int)(slash - scenario_file), scenario_file, rel);
    if (k < 0 || (size_t)k >= n) {
        out[0] = '\0';
        return fw_fail_at(err, doc->file, line, field, "path too long");
    }
    FILE *f = fopen(out, "r");
    if (!f)
        return fw_fail_at(err, doc->file, line, field, "%s: cannot open", out);
    fclose(f);
    return FW_OK;
}

/* ais_start / ais_end: a UTC time or seconds after the first report. */
static fw_status window_key(const yt_doc *doc, const yt_node *tr, const char *key, double *t,
                            bool *rel, fw_error *err)
{
    const yt_node *v = yt_get(tr, key);
    if (!v)
        return FW_OK;
    char *end = NULL;
    if (v->kind == YT_SCALAR && fw_ais_parse_time(v->str, t)) {
        *rel = false;
        return FW_OK;
    }
    if (v->kind == YT_SCALAR && !v->quoted) {
        *t = strtod(v->str, &end);
        if (end != v->str && *end == '\0' && isfinite(*t) && *t >= 0 && *t <= 86400.0 * 366) {
            *rel = true;
            return FW_OK;
        }
    }
    return yt_fail_key(doc, tr, "traffic", key, err,
                       "expected \"YYYY-MM-DD HH:MM:SS\" (UTC) or seconds after the file's first "
                       "report (0 to a year)");
}

fw_status fw_scn_load_ais(const yt_doc *doc, const yt_node *tr, fw_scenario *s, fw_error *err)
{
    fw_scn_ais *a = &s->ais;
    a->start = a->end = NAN;
    a->max_gap = 300.0;
    fw_status st = fw_scn_file_key(doc, tr, "traffic", "ais", s->file, a->file, sizeof a->file,
                                   err);
    if (st)
        return st;
    if (!a->file[0]) {
        static const char *const keys[] = {"ais_start", "ais_end", "ais_max_gap_s",
                                           "ais_columns"};
        for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
            if (yt_get(tr, keys[i]))
                return yt_fail_key(doc, tr, "traffic", keys[i], err, "needs traffic.ais");
        return FW_OK;
    }
    int line = yt_key_line(tr, "ais");
    if (!s->has_origin)
        return fw_fail_at(err, doc->file, line, "traffic.ais",
                          "AIS positions are latitudes and longitudes: the scenario needs its "
                          "origin: {lat_deg, lon_deg}");
    if (s->network[0] || yt_get(tr, "targets"))
        return fw_fail_at(err, doc->file, line, "traffic.ais",
                          "AIS reports are the whole traffic: no network or targets with them");
    if ((st = window_key(doc, tr, "ais_start", &a->start, &a->start_rel, err)) ||
        (st = window_key(doc, tr, "ais_end", &a->end, &a->end_rel, err)) ||
        (st = yt_opt_number(doc, tr, "traffic", "ais_max_gap_s", 1, 3600, &a->max_gap, err)) ||
        (st = yt_opt_string(doc, tr, "traffic", "ais_columns", a->columns, sizeof a->columns,
                            err)))
        return st;
    if (!isnan(a->start) && !isnan(a->end) && a->start_rel == a->end_rel && !(a->end > a->start))
        return yt_fail_key(doc, tr, "traffic", "ais_end", err, "is not after ais_start");
    /* the header now: a file the run could not read is refused at load */
    fw_ais_columns cols = fw_ais_dma_columns();
    char what[128];
    snprintf(what, sizeof what, "%s:%d: traffic.ais_columns", doc->file,
             yt_key_line(tr, "ais_columns"));
    fw_ais_reader *rd = NULL;
    fw_error aerr = {0};
    if (a->columns[0] && (st = fw_ais_columns_parse(a->columns, what, &cols, err)))
        return st;
    st = fw_ais_open(a->file, &cols, &rd, &aerr);
    fw_ais_close(rd);
    return st ? fw_fail_at(err, doc->file, line, "traffic.ais", "%s", aerr.msg) : FW_OK;
}
