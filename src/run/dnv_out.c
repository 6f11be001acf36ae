/* dnv_out.c - DNV's situation output of a run (dnv_out.h). */
#include "run/dnv_out.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/files.h"
#include "core/json.h"
#include "core/units.h"
#include "geom/geo.h"
#include "run/dnv_situation.h"

#define DNV_OUT_VERSION "0.2.0"
#define FAIRWAY_VERSION "0.1.0" /* main.c --version */

struct fw_dnv_out {
    const fw_scenario *s;
    fw_geo *g;
    char *buf;   /* the events written so far (open_memstream) */
    size_t len;
    FILE *ev;
    int n;
    fw_track tr; /* the predicted track of an avoidance */
};

fw_status fw_dnv_out_create(const fw_scenario *s, fw_dnv_out **out, fw_error *err)
{
    fw_dnv_out *o = *out = calloc(1, sizeof *o);
    if (!o)
        return fw_fail(err, FW_ERUN, "out of memory");
    o->s = s;
    fw_status st = fw_scenario_plane(s, &o->g, err);
    if (!st && !o->g)
        st = fw_fail(err, FW_EINPUT, "%s: a situation output needs an origin", s->file);
    if (!st && !(o->ev = open_memstream(&o->buf, &o->len)))
        st = fw_fail(err, FW_ERUN, "out of memory");
    if (!st)
        st = fw_track_alloc(&o->tr, fw_track_samples(&s->helm.track), err);
    if (st) {
        fw_dnv_out_destroy(o);
        *out = NULL;
    }
    return st;
}

void fw_dnv_out_destroy(fw_dnv_out *o)
{
    if (!o)
        return;
    if (o->ev)
        fclose(o->ev);
    free(o->buf);
    fw_geo_destroy(o->g);
    fw_track_free(&o->tr);
    free(o);
}

static fw_status position(fw_dnv_out *o, double e, double n, double *gamma, fw_error *err)
{
    return fw_dnv_position(o->ev, o->g, e, n, 7, gamma, err);
}

/* A grid direction as true degrees in [0, 360). */
static double true_deg(double grid, double gamma)
{
    return fw_heading_deg(fw_wrap_2pi(grid + gamma));
}

/* ISO 8601 UTC of the run's time t (whole seconds unless t has a fraction). */
static void iso_time(const fw_scenario *s, double t, char *out, size_t n)
{
    double at = s->utc_start + t;
    time_t whole = (time_t)floor(at);
    struct tm tm;
    gmtime_r(&whole, &tm);
    char base[32];
    strftime(base, sizeof base, "%Y-%m-%dT%H:%M:%S", &tm);
    long ms = lround((at - floor(at)) * 1000.0);
    if (ms > 0 && ms < 1000)
        snprintf(out, n, "%s.%03ldZ", base, ms);
    else
        snprintf(out, n, "%sZ", base);
}

static fw_status waypoint(fw_dnv_out *o, bool first, double e, double n, double kn, fw_error *err)
{
    fprintf(o->ev, "%s\n        {", first ? "" : ",");
    fw_status st = position(o, e, n, NULL, err);
    if (!st && !first)
        fprintf(o->ev, ", \"leg\": {\"sog\": %.2f}", kn);
    fprintf(o->ev, "}");
    return st;
}

/* The planned route from the own ship (dnv_out.h). */
static fw_status route(fw_dnv_out *o, const fw_own_state *own, const fw_decision *d, double sog,
                       fw_error *err)
{
    const fw_scenario *s = o->s;
    double pe = own->east, pn = own->north;
    fprintf(o->ev, "      \"waypoints\": [");
    fw_status st = waypoint(o, true, pe, pn, 0.0, err);
    bool avoid = d->mode == FW_MODE_AVOID, steady = d->mode == FW_MODE_STEADY;
    if (!st && (avoid || steady)) {
        const fw_track_def *td = &s->helm.track;
        if ((st = fw_track_predict(&s->ship, td, own, avoid ? d->helm : 0.0, &o->tr, err)))
            return st;
        int every = (int)fmax(1.0, round(60.0 / o->tr.dt));
        for (int k = every; k < o->tr.n && !st; k += every) {
            double e = o->tr.east[k], n = o->tr.north[k];
            st = waypoint(o, false, e, n, fw_ms_to_kn(hypot(e - pe, n - pn) / (every * o->tr.dt)),
                          err);
            pe = e, pn = n;
        }
    }
    double end_e = s->east + s->leg * sin(s->course), end_n = s->north + s->leg * cos(s->course);
    if (!st && hypot(end_e - pe, end_n - pn) > 1.0)
        st = waypoint(o, false, end_e, end_n, fw_ms_to_kn(avoid || steady ? s->speed : sog), err);
    fprintf(o->ev, "\n      ],\n");
    return st;
}

static const char *encounter_type(const fw_assessment *a)
{
    if (!a->enters_domain)
        return "No Risk";
    switch (a->situation) {
    case FW_SIT_HEAD_ON: return "Head-on";
    case FW_SIT_OVERTAKING: return "Overtaking give-way";
    case FW_SIT_OVERTAKEN: return "Overtaking stand-on";
    case FW_SIT_GIVE_WAY: return "Crossing give-way";
    case FW_SIT_STAND_ON: return "Crossing stand-on";
    }
    return "No Risk";
}

static fw_status target(fw_dnv_out *o, int i, const fw_target *t, const fw_assessment *a,
                        fw_error *err)
{
    char *end;
    long id = strtol(t->id, &end, 10);
    fprintf(o->ev, "%s\n        {\"id\": %ld, ", i ? "," : "", *end || end == t->id ? i + 1L : id);
    double gamma;
    fw_status st = position(o, t->east, t->north, &gamma, err);
    if (st)
        return st;
    fprintf(o->ev, ", \"sog\": %.2f, \"cog\": %.2f, \"heading\": %.2f, \"cpa\": %.4f, ",
            fw_ms_to_kn(t->speed), true_deg(t->course, gamma), true_deg(t->heading, gamma),
            fw_m_to_nm(a->dcpa));
    fprintf(o->ev, "\"tcpa\": ");
    fw_json_number(o->ev, a->tcpa, "%.1f");
    fprintf(o->ev, ", \"range\": %.4f, \"encounterType\": \"%s\"}", fw_m_to_nm(a->range),
            encounter_type(a));
    return FW_OK;
}

fw_status fw_dnv_out_event(fw_dnv_out *o, double t, const fw_own_state *own, double cog,
                           double sog, const fw_decision *d, const fw_target *tg,
                           const fw_assessment *as, int n, fw_error *err)
{
    char when[48];
    iso_time(o->s, t, when, sizeof when);
    fprintf(o->ev, "%s\n    {\n      \"time\": \"%s\",\n", o->n ? "," : "", when);
    fw_status st = route(o, own, d, sog, err);
    double gamma;
    fprintf(o->ev, "      \"ownShip\": {");
    if (st || (st = position(o, own->east, own->north, &gamma, err)))
        return st;
    fprintf(o->ev, ", \"sog\": %.2f, \"cog\": %.2f, \"heading\": %.2f},\n", fw_ms_to_kn(sog),
            true_deg(cog, gamma), true_deg(own->psi, gamma));
    fprintf(o->ev, "      \"targetShips\": [");
    for (int i = 0; i < n && !st; i++)
        st = target(o, i, &tg[i], &as[i], err);
    fprintf(o->ev, "%s],\n      \"fairway\": {\"mode\": \"%s\", \"helmDeg\": %.1f, \"reason\": ",
            n ? "\n      " : "", fw_policy_mode_name(d->mode), fw_rad_to_deg(d->helm));
    fw_json_string(o->ev, d->reason ? d->reason : "");
    fprintf(o->ev, "}\n    }");
    o->n++;
    return st;
}

/* systemUnderTest.configuration: fairway and its settings. */
static void configuration(FILE *f, const fw_scenario *s)
{
    const fw_helm_def *h = &s->helm;
    fprintf(f, "    \"configuration\": {\n      \"name\": \"fairway\",\n"
               "      \"vendor\": \"fairway (open source)\",\n      \"version\": \"%s\",\n",
            FAIRWAY_VERSION);
    fprintf(f, "      \"ownShipModel\": ");
    fw_json_string(f, s->ship.name);
    fprintf(f, ",\n      \"ownShipDynamics\": \"%s\",\n"
               "      \"ownShipLengthM\": %.1f,\n      \"ownShipBreadthM\": %.1f,\n"
               "      \"domainM\": %.1f,\n      \"domainForeAftRatio\": %.2f,\n"
               "      \"helmDeg\": [%.1f, %.1f],\n      \"horizonS\": %.0f,\n"
               "      \"actRangeNm\": %.2f,\n      \"returnTo\": \"%s\"\n    },\n",
            s->nomoto_plant ? "nomoto" : "mmg", s->ship.Loa, s->ship.B, h->domain.size,
            h->domain.fore_aft_ratio, h->min_helm_deg, h->max_helm_deg, h->track.horizon,
            fw_m_to_nm(s->policy.act_range),
            fw_return_name(s->policy.ret));
}

fw_status fw_dnv_out_write(fw_dnv_out *o, const char *path, fw_error *err)
{
    if (fflush(o->ev) != 0)
        return fw_fail(err, FW_ERUN, "out of memory for the situation output");
    char tmp[1200];
    FILE *f = fw_file_begin(path, tmp, sizeof tmp, err);
    if (!f)
        return err->status;
    fprintf(f, "{\n  \"version\": \"%s\",\n  \"systemUnderTest\": {\n", DNV_OUT_VERSION);
    configuration(f, o->s);
    fprintf(f, "    \"eventData\": [");
    if (o->len > 0)
        fwrite(o->buf, 1, o->len, f);
    fprintf(f, "\n    ]\n  }\n}\n");
    return fw_file_commit(f, tmp, path, err);
}
