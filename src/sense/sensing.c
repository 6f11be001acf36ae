/* sensing.c - the ships a vessel knows of: the truth, their AIS reports, the
 * radar's tracks (sensing.h). */
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
                            .stale = 360.0, .radar = fw_default_radar_def()};
}

/* fw_sensing_mode order */
static const char *const kModes[] = {"perfect", "ais", "radar", "ais+radar"};
enum { kNModes = 4 };

const char *fw_sensing_mode_name(fw_sensing_mode m)
{
    return (unsigned)m < kNModes ? kModes[m] : "?";
}

fw_status fw_sensing_mode_parse(const char *text, fw_sensing_mode *out)
{
    for (int i = 0; i < kNModes; i++)
        if (strcmp(text, kModes[i]) == 0) {
            *out = (fw_sensing_mode)i;
            return FW_OK;
        }
    return FW_EINPUT;
}

fw_status fw_sensing_check(const fw_sensing_def *d, fw_error *err)
{
    const fw_radar_def *r = &d->radar;
    const double v[] = {d->position_sd, d->sog_sd,      d->cog_sd,      d->heading_sd,
                        d->stale,       r->range_sd,    r->bearing_sd,  r->antenna};
    const char *const name[] = {"position_sd", "sog_sd",   "cog_sd",         "heading_sd",
                                "stale",       "range_sd", "bearing_sd", "antenna_height"};
    for (int i = 0; i < 8; i++)
        if (!(v[i] >= 0.0 && isfinite(v[i])))
            return fw_fail(err, FW_EINPUT, "sensing %s %g: must be 0 or more", name[i], v[i]);
    if (!(d->dropout >= 0.0 && d->dropout <= 1.0))
        return fw_fail(err, FW_EINPUT, "sensing dropout %g: a probability, in [0, 1]",
                       d->dropout);
    if (!(d->latency >= 0.0 && d->latency <= 2.0))
        return fw_fail(err, FW_EINPUT, "sensing latency %g s: in [0, 2] s (below the shortest "
                                       "reporting interval)", d->latency);
    if (!(r->scan > 0.0 && isfinite(r->scan)))
        return fw_fail(err, FW_EINPUT, "sensing scan %g s: must be more than 0", r->scan);
    if (!(r->alpha > 0.0 && r->alpha <= 1.0) || !(r->beta > 0.0 && r->beta < 2.0))
        return fw_fail(err, FW_EINPUT, "sensing alpha %g, beta %g: alpha in (0, 1], beta in "
                                       "(0, 2)", r->alpha, r->beta);
    if ((unsigned)d->mode >= kNModes)
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

/* What the sensor keeps of one ship. */
typedef struct link {
    bool streams;        /* its streams taken */
    fw_ais_tx ais;       /* its AIS reports (sensing.h) */
    /* radar */
    fw_ab_track trk;     /* plots 0: no track */
    double t_track;      /* s, its first plot */
    unsigned hist;       /* its last scans, newest in bit 0: 1 plotted */
    int n_hist;          /* scans since it began, up to 10 */
    long k_last;         /* the number of the last scan it had */
    fw_rng *rnoise, *rdetect;
} link;

struct fw_sensor {
    fw_sensing_def def;
    bool ais, radar;     /* the mode's parts */
    fw_target own;       /* where the antenna is (fw_sensor_place) */
    bool placed, scanning;
    long next_scan;      /* the next scan's number: at next_scan x radar.scan */
    fw_rng_getter rng;
    void *ctx;
    uint32_t salt;       /* the receiver's key (0: the own ship's, fw_sensor_set_salt) */
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
    s->ais = def->mode == FW_SENSE_AIS || def->mode == FW_SENSE_AIS_RADAR;
    s->radar = def->mode == FW_SENSE_RADAR || def->mode == FW_SENSE_AIS_RADAR;
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
    if (!l->streams) {
        uint32_t key = fw_rng_link_key(s->salt, fw_rng_vessel_key(a->id));
        if (s->ais && (!(l->ais.noise = s->rng(s->ctx, key, FW_PURPOSE_SENSING)) ||
                       !(l->ais.loss = s->rng(s->ctx, key, FW_PURPOSE_AIS_DROPOUT))))
            return NULL;
        if (s->radar && (!(l->rnoise = s->rng(s->ctx, key, FW_PURPOSE_RADAR)) ||
                         !(l->rdetect = s->rng(s->ctx, key, FW_PURPOSE_RADAR_DETECT))))
            return NULL;
        l->streams = true;
    }
    return l;
}

/* The report ship a sends at t: its state with its GNSS and sensors' noise. */
static fw_ais_sent make_report(const fw_sensing_def *d, fw_rng *noise, const fw_target *a,
                                 double t)
{
    fw_ais_sent r = {.t = t};
    r.east = a->east + d->position_sd * fw_rng_normal(noise);
    r.north = a->north + d->position_sd * fw_rng_normal(noise);
    r.sog = fmax(0.0, a->speed + d->sog_sd * fw_rng_normal(noise));
    r.cog = fw_wrap_2pi(a->course + d->cog_sd * fw_rng_normal(noise));
    r.heading = fw_wrap_2pi(a->heading + d->heading_sd * fw_rng_normal(noise));
    r.sog_e = r.sog * sin(r.cog);
    r.sog_n = r.sog * cos(r.cog);
    return r;
}

void fw_ais_tx_step(const fw_sensing_def *d, fw_ais_tx *l, const fw_target *a, double t,
                    fw_sensing_counts *c)
{
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
        c->arrived++;
    }
    if (t < l->t_next - 1e-9)
        return;
    /* due (a ship turning reports sooner: its new interval counts from now) */
    l->t_next = t + phase * fw_ais_interval(a->speed, turning);
    c->sent++;
    fw_ais_sent r = make_report(d, l->noise, a, t);
    if (d->dropout > 0.0 && fw_rng_uniform(l->loss) < d->dropout) {
        c->lost++;
        return;
    }
    if (d->latency > 0.0) {
        if (l->n_queued == FW_AIS_IN_FLIGHT) { /* cannot happen within the bounds: the oldest goes */
            memmove(l->queued, l->queued + 1, sizeof *l->queued * (FW_AIS_IN_FLIGHT - 1));
            l->n_queued--;
        }
        l->queued[l->n_queued++] = r;
        return;
    }
    l->last = r, l->known = true;
    c->arrived++;
}

bool fw_ais_tx_known(const fw_sensing_def *d, const fw_ais_tx *l, const fw_target *a, double t,
                     fw_target *out)
{
    if (!l->known || t - l->last.t > d->stale)
        return false;
    /* what the last report says of ship a at t: dead reckoned */
    const fw_ais_sent *r = &l->last;
    double age = t - r->t;
    *out = *a; /* id, type, length, breadth, key, own: its static data */
    out->east = r->east + r->sog_e * age;
    out->north = r->north + r->sog_n * age;
    out->course = r->cog;
    out->speed = r->sog;
    out->heading = r->heading;
    out->stw = r->sog; /* AIS says nothing of the water */
    out->pred = NULL;
    return true;
}

void fw_sensor_set_salt(fw_sensor *s, uint32_t receiver) { s->salt = receiver; }

void fw_sensor_place(fw_sensor *s, const fw_target *own)
{
    s->own = *own;
    s->placed = true;
}

/* Scans since the track began that missed it (of the last 10 at most). */
static int misses(const link *l)
{
    int hits = 0;
    for (int b = 0; b < l->n_hist; b++)
        hits += (l->hist >> b) & 1u;
    return l->n_hist - hits;
}

/* The ship's track is lost: a new one starts at its next plot. */
static void drop_track(fw_sensor *s, link *l)
{
    l->trk = (fw_ab_track){0};
    l->hist = 0u, l->n_hist = 0;
    s->counts.tracks_lost++;
}

/* Ship a's scans number k0..k1, the truth at t moved back to each. */
static void radar_step(fw_sensor *s, link *l, const fw_target *a, double t, long k0, long k1)
{
    const fw_radar_def *d = &s->def.radar;
    const fw_target *o = &s->own;
    /* a ship out of the sensor's sight for more than 5 scans (not in the
     * truth it was given) was missed by them all: its track is lost */
    if (l->trk.plots > 0 && k1 >= k0 && k0 - l->k_last - 1 > 5)
        drop_track(s, l);
    if (k1 >= k0)
        l->k_last = k1;
    for (long k = k0; k <= k1; k++) {
        double ts = (double)k * d->scan, back = t - ts;
        double te = a->east - a->speed * sin(a->course) * back;
        double tn = a->north - a->speed * cos(a->course) * back;
        double oe = o->east - o->speed * sin(o->course) * back;
        double on = o->north - o->speed * cos(o->course) * back;
        double pd = fw_radar_pd(d, hypot(te - oe, tn - on), a->length);
        bool hit = fw_rng_uniform(l->rdetect) < pd;
        s->counts.scanned += pd > 0.0;
        if (l->trk.plots > 0) {
            l->hist = ((l->hist << 1) | hit) & 0x3ffu;
            l->n_hist += l->n_hist < 10;
        } else if (hit) {
            l->t_track = ts, l->hist = 1u, l->n_hist = 1;
            s->counts.tracks++;
        }
        if (hit) {
            double ze, zn;
            fw_radar_plot(d, l->rnoise, oe, on, te, tn, &ze, &zn);
            fw_ab_update(&l->trk, d, ts, ze, zn);
            s->counts.plotted++;
        } else if (l->trk.plots > 0 && misses(l) > 5) { /* MSC.192(79) 5.25.4.3 */
            drop_track(s, l);
        }
    }
}

/* s, a track is shown once this old (MSC.192(79) 5.25.4.1: the trend within
 * one minute) */
static const double kTrackShown = 60.0;

/* What the radar's track says of ship a at t, if it shows one. */
static bool track_target(const link *l, const fw_target *a, double t, fw_target *out)
{
    if (l->trk.plots < 2 || t - l->t_track < kTrackShown - 1e-9)
        return false;
    *out = *a; /* id, type, length, breadth, key, own */
    fw_ab_predict(&l->trk, t, &out->east, &out->north);
    out->course = fw_wrap_2pi(atan2(l->trk.ve, l->trk.vn));
    out->speed = hypot(l->trk.ve, l->trk.vn);
    out->heading = out->course; /* a radar sees no heading */
    out->stw = out->speed;
    out->pred = NULL;
    return true;
}

/* The scans due by t, numbers *k0..*k1 (none: *k1 < *k0); the first update
 * starts the scans at the first at or after it. */
static void due_scans(fw_sensor *s, double t, long *k0, long *k1)
{
    double T = s->def.radar.scan;
    if (!s->scanning) {
        s->next_scan = (long)ceil(t / T - 1e-9);
        s->scanning = true;
    }
    *k0 = s->next_scan;
    *k1 = (long)floor(t / T + 1e-9);
    if (*k1 >= *k0)
        s->next_scan = *k1 + 1;
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
    if (s->radar && !s->placed)
        return fw_fail(err, FW_EINPUT, "radar sensing: where the antenna is was not given "
                                       "(fw_sensor_place)");
    long k0 = 0, k1 = -1;
    if (s->radar)
        due_scans(s, t, &k0, &k1);
    for (int j = 0; j < n; j++) {
        const fw_target *a = &truth[j];
        link *l = link_of(s, a);
        if (!l)
            return fw_fail(err, FW_ERUN, "out of memory for the sensor's ships");
        if (s->ais)
            fw_ais_tx_step(&s->def, &l->ais, a, t, &s->counts);
        if (s->radar)
            radar_step(s, l, a, t, k0, k1);
        fw_target *out = &known[*n_known];
        if (s->ais && fw_ais_tx_known(&s->def, &l->ais, a, t, out)) {
            /* AIS first (MSC.192(79) 5.29) */
        } else if (!(s->radar && track_target(l, a, t, out)))
            continue;
        (*n_known)++;
        if (s->radar) {
            double de = out->east - a->east, dn = out->north - a->north;
            s->counts.err_sq += de * de + dn * dn;
            s->counts.err_n++;
        }
    }
    return FW_OK;
}
