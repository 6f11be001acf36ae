/* sensing.c - the ships a vessel knows of: the truth, or their AIS reports
 * (sensing.h). */
#include "sense/sensing.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/idmap.h"
#include "core/mem.h"
#include "core/units.h"

/* rad/s: a ship turning faster is "changing course" for its AIS (reports
 * 3 times as often); 0.1 deg/s is well above a ship holding its course in a
 * seaway and below any alteration of course worth the name. */
static const double kTurning = 0.1 * FW_PI / 180.0;

fw_sensing_def fw_default_sensing_def(void)
{
    return (fw_sensing_def){.mode = FW_SENSE_PERFECT, .position_sd = 10.0,
                            .sog_sd = 0.1 * FW_KNOT, .cog_sd = fw_deg_to_rad(1.0),
                            .heading_sd = fw_deg_to_rad(0.5), .dropout = 0.0, .latency = 0.0,
                            .stale = 360.0};
}

static const char *const kModes[] = {"perfect", "ais"}; /* fw_sensing_mode order */

const char *fw_sensing_mode_name(fw_sensing_mode m)
{
    return (unsigned)m < 2 ? kModes[m] : "?";
}

fw_status fw_sensing_mode_parse(const char *text, fw_sensing_mode *out)
{
    for (int i = 0; i < 2; i++)
        if (strcmp(text, kModes[i]) == 0) {
            *out = (fw_sensing_mode)i;
            return FW_OK;
        }
    return FW_EINPUT;
}

fw_status fw_sensing_check(const fw_sensing_def *d, fw_error *err)
{
    const double v[] = {d->position_sd, d->sog_sd, d->cog_sd, d->heading_sd, d->stale};
    const char *const name[] = {"position_sd", "sog_sd", "cog_sd", "heading_sd", "stale"};
    for (int i = 0; i < 5; i++)
        if (!(v[i] >= 0.0 && isfinite(v[i])))
            return fw_fail(err, FW_EINPUT, "sensing %s %g: must be 0 or more", name[i], v[i]);
    if (!(d->dropout >= 0.0 && d->dropout <= 1.0))
        return fw_fail(err, FW_EINPUT, "sensing dropout %g: a probability, in [0, 1]",
                       d->dropout);
    if (!(d->latency >= 0.0 && d->latency <= 2.0))
        return fw_fail(err, FW_EINPUT, "sensing latency %g s: in [0, 2] s (below the shortest "
                                       "reporting interval)", d->latency);
    if ((unsigned)d->mode > FW_SENSE_AIS)
        return fw_fail(err, FW_EINPUT, "sensing mode %d: not a mode", (int)d->mode);
    return FW_OK;
}

double fw_ais_interval(double speed, bool turning)
{
    double kn = fw_ms_to_kn(speed);
    if (kn <= 3.0 && !turning)
        return 180.0;
    if (kn <= 14.0)
        return turning ? 10.0 / 3.0 : 10.0;
    if (kn <= 23.0)
        return turning ? 2.0 : 6.0;
    return 2.0;
}

/* A report: where the ship was, as its AIS said, when it was sent. */
typedef struct report {
    double t, east, north, sog, cog, heading;
} report;

/* What the sensor keeps of one ship. */
/* Reports on their way at once: the latency is at most 2 s, the shortest
 * interval 2 s (and a first phase may be shorter). */
enum { kInFlight = 4 };

typedef struct link {
    bool started, known;
    double t_next;       /* s, its next report */
    double t_prev, course_prev; /* its course over ground when last seen */
    report last;         /* the last that arrived */
    report queued[kInFlight]; /* on their way, oldest first */
    int n_queued;
    fw_rng *noise, *loss;
} link;

struct fw_sensor {
    fw_sensing_def def;
    fw_rng_getter rng;
    void *ctx;
    fw_idmap ids;
    link *links;
    int cap;
    fw_sensing_counts counts;
};

fw_status fw_sensor_create(const fw_sensing_def *def, fw_rng_getter rng, void *rng_ctx,
                           fw_sensor **out, fw_error *err)
{
    *out = NULL;
    fw_status st = fw_sensing_check(def, err);
    if (st)
        return st;
    if (def->mode != FW_SENSE_PERFECT && !rng)
        return fw_fail(err, FW_EINPUT, "sensing %s needs the world's random streams",
                       fw_sensing_mode_name(def->mode));
    fw_sensor *s = calloc(1, sizeof *s);
    if (!s)
        return fw_fail(err, FW_ERUN, "out of memory");
    s->def = *def;
    s->rng = rng;
    s->ctx = rng_ctx;
    *out = s;
    return FW_OK;
}

void fw_sensor_destroy(fw_sensor *s)
{
    if (!s)
        return;
    fw_idmap_free(&s->ids);
    free(s->links);
    free(s);
}

fw_sensing_counts fw_sensor_counts(const fw_sensor *s) { return s->counts; }

/* Ship a's link (made on first sight), NULL when out of memory. */
static link *link_of(fw_sensor *s, const fw_target *a)
{
    int k;
    if (fw_idmap_intern(&s->ids, a->id, &k))
        return NULL;
    if (k >= s->cap) {
        int cap = fw_grown_cap(s->cap, k + 1);
        if (!fw_resize((void **)&s->links, sizeof *s->links, (size_t)cap))
            return NULL;
        memset(s->links + s->cap, 0, sizeof *s->links * (size_t)(cap - s->cap));
        s->cap = cap;
    }
    link *l = &s->links[k];
    if (!l->started) {
        uint32_t key = fw_rng_vessel_key(a->id);
        l->noise = s->rng(s->ctx, key, FW_PURPOSE_SENSING);
        l->loss = s->rng(s->ctx, key, FW_PURPOSE_AIS_DROPOUT);
        if (!l->noise || !l->loss)
            return NULL;
    }
    return l;
}

/* The report ship a sends at t: its state with its GNSS and sensors' noise. */
static report make_report(const fw_sensing_def *d, link *l, const fw_target *a, double t)
{
    report r = {.t = t};
    r.east = a->east + d->position_sd * fw_rng_normal(l->noise);
    r.north = a->north + d->position_sd * fw_rng_normal(l->noise);
    r.sog = fmax(0.0, a->speed + d->sog_sd * fw_rng_normal(l->noise));
    r.cog = fw_wrap_2pi(a->course + d->cog_sd * fw_rng_normal(l->noise));
    r.heading = fw_wrap_2pi(a->heading + d->heading_sd * fw_rng_normal(l->noise));
    return r;
}

/* One ship's reports up to t: sent when due, lost or on their way, arrived. */
static void ais_step(fw_sensor *s, link *l, const fw_target *a, double t)
{
    const fw_sensing_def *d = &s->def;
    bool turning = l->started && t > l->t_prev &&
                   fabs(fw_wrap_pi(a->course - l->course_prev)) / (t - l->t_prev) > kTurning;
    /* a ship first seen has been reporting all along: its last report is
     * sent now, and its next one comes at a random phase of its interval
     * (its slot) */
    double phase = 1.0;
    if (!l->started) {
        phase = fw_rng_uniform(l->noise);
        l->t_next = t;
        l->started = true;
    }
    l->t_prev = t, l->course_prev = a->course;
    while (l->n_queued > 0 && t >= l->queued[0].t + d->latency - 1e-9) {
        l->last = l->queued[0], l->known = true;
        memmove(l->queued, l->queued + 1, sizeof *l->queued * (size_t)--l->n_queued);
        s->counts.arrived++;
    }
    if (t < l->t_next - 1e-9)
        return;
    /* due (a ship turning reports sooner: its new interval counts from now) */
    l->t_next = t + phase * fw_ais_interval(a->speed, turning);
    s->counts.sent++;
    report r = make_report(d, l, a, t);
    if (d->dropout > 0.0 && fw_rng_uniform(l->loss) < d->dropout) {
        s->counts.lost++;
        return;
    }
    if (d->latency > 0.0) {
        if (l->n_queued == kInFlight) { /* cannot happen within the bounds: the oldest goes */
            memmove(l->queued, l->queued + 1, sizeof *l->queued * (kInFlight - 1));
            l->n_queued--;
        }
        l->queued[l->n_queued++] = r;
        return;
    }
    l->last = r, l->known = true;
    s->counts.arrived++;
}

/* What the last report says of ship a at t: dead reckoned. */
static void dead_reckon(const link *l, const fw_target *a, double t, fw_target *out)
{
    const report *r = &l->last;
    double age = t - r->t;
    *out = *a; /* id, type, length, breadth, key, own: its static data */
    out->east = r->east + r->sog * age * sin(r->cog);
    out->north = r->north + r->sog * age * cos(r->cog);
    out->course = r->cog;
    out->speed = r->sog;
    out->heading = r->heading;
    out->stw = r->sog; /* AIS says nothing of the water */
    out->pred = NULL;
}

fw_status fw_sensor_update(fw_sensor *s, double t, const fw_target *truth, int n,
                           fw_target *known, int *n_known, fw_error *err)
{
    *n_known = 0;
    if (s->def.mode == FW_SENSE_PERFECT) {
        if (n > 0)
            memcpy(known, truth, sizeof *truth * (size_t)n);
        *n_known = n;
        return FW_OK;
    }
    for (int j = 0; j < n; j++) {
        link *l = link_of(s, &truth[j]);
        if (!l)
            return fw_fail(err, FW_ERUN, "out of memory for the sensor's ships");
        ais_step(s, l, &truth[j], t);
        if (l->known && t - l->last.t <= s->def.stale)
            dead_reckon(l, &truth[j], t, &known[(*n_known)++]);
    }
    return FW_OK;
}
