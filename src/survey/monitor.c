/* monitor.c - the traffic monitors (monitor.h). */
#include "survey/monitor.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/idmap.h"
#include "core/mem.h"
#include "core/units.h"
#include "geom/geom.h"
#include "survey/survey_index.h"

/* What the monitors remember of a ship, by its interned id. */
typedef struct ship_state {
    long seen;          /* stamp of the step it was last seen, 0 = never */
    double t, east, north, heading, speed;
    bool close;         /* within close_range of the own ship when last seen */
    bool sideways;      /* in a sideways episode */
    double slow_since;  /* s, since when slower than stop_speed; < 0: not slow */
    bool stopped;       /* counted for this episode */
    /* the last step's mean heading (moved): its two headings and its sine and
     * cosine, reused while the headings stay (a ship on a straight lane);
     * mean_ok false: none yet */
    double mean_from, mean_to, mean_sin, mean_cos;
    bool mean_ok;
} ship_state;

struct fw_monitor {
    fw_monitor_def def;
    FILE *log;
    fw_monitor_counts c;
    fw_idmap ids;
    ship_state *s;
    int cap;
    long stamp;
    int *prev, nprev, *cur;   /* ids seen in the previous and this step */
    int ccap;
    /* overlaps: the background ships of this step and the pairs overlapping */
    double *x, *y;
    int *bg;                  /* bg[k] = index into the step's ships */
    sv_grid grid;
    sv_pairs pairs;           /* pair key -> stamp of its last overlap */
    const fw_target *ships;
    bool oom;
};

fw_monitor_def fw_default_monitor_def(void)
{
    return (fw_monitor_def){.lateral_max = 2.0, .jump_factor = 3.0, .jump_slack = 10.0,
                            .close_range = 2.0 * FW_NMILE, .stop_speed = fw_kn_to_ms(0.5),
                            .stop_time = 60.0};
}

int fw_monitor_total(const fw_monitor_counts *c)
{
    return c->sideways + c->teleport + c->overlap + c->appear + c->start_close + c->vanish +
           c->stopped;
}

void fw_monitor_destroy(fw_monitor *m)
{
    if (!m)
        return;
    fw_idmap_free(&m->ids);
    sv_grid_free(&m->grid);
    sv_pairs_free(&m->pairs);
    fw_free_each(7, m->s, m->prev, m->cur, m->x, m->y, m->bg, m);
}

fw_status fw_monitor_create(const fw_monitor_def *def, FILE *log, fw_monitor **out,
                            fw_error *err)
{
    *out = NULL;
    if (!(def->lateral_max > 0.0) || !(def->jump_factor >= 1.0) || !(def->jump_slack >= 0.0) ||
        !(def->close_range > 0.0) || !(def->stop_speed >= 0.0) || !(def->stop_time > 0.0))
        return fw_fail(err, FW_EINPUT, "monitor thresholds must be positive");
    fw_monitor *m = calloc(1, sizeof *m);
    if (!m)
        return fw_fail(err, FW_ERUN, "out of memory");
    m->def = *def;
    m->log = log;
    *out = m;
    return FW_OK;
}

const fw_monitor_counts *fw_monitor_counts_of(const fw_monitor *m) { return &m->c; }

static void event(fw_monitor *m, double t, const char *kind, const fw_target *a,
                  const char *other, const char *detail)
{
    if (m->log)
        fprintf(m->log, "%9.1f  monitor: %s %s%s%s at (%.0f, %.0f) m%s%s\n", t, kind, a->id,
                other ? " and " : "", other ? other : "", a->east, a->north,
                detail[0] ? ": " : "", detail);
}

/* Room for n ships this step and for every id interned so far. */
static bool reserve(fw_monitor *m, int n)
{
    if (m->ids.n + n > m->cap) {
        int cap = fw_grown_cap(m->cap, m->ids.n + n);
        if (!fw_resize((void **)&m->s, sizeof *m->s, (size_t)cap))
            return false;
        memset(m->s + m->cap, 0, sizeof *m->s * (size_t)(cap - m->cap));
        m->cap = cap;
    }
    if (n > m->ccap) {
        int cap = fw_grown_cap(m->ccap, n);
        if (!fw_resize_each((size_t)cap, 5, (void **)&m->prev, sizeof *m->prev,
                            (void **)&m->cur, sizeof *m->cur, (void **)&m->x, sizeof *m->x,
                            (void **)&m->y, sizeof *m->y, (void **)&m->bg, sizeof *m->bg))
            return false;
        m->ccap = cap;
    }
    return true;
}

/* A ship seen in the last step too: how it moved. */
static void moved(fw_monitor *m, double t, ship_state *p, const fw_target *a)
{
    double dt = t - p->t;
    double de = a->east - p->east, dn = a->north - p->north;
    /* across the mean of the two headings: a ship turning at a lane vertex
     * moves along its track, not across it */
    if (!(p->mean_ok && p->mean_from == p->heading && p->mean_to == a->heading)) {
        double h = atan2(sin(p->heading) + sin(a->heading), cos(p->heading) + cos(a->heading));
        p->mean_from = p->heading;
        p->mean_to = a->heading;
        p->mean_sin = sin(h);
        p->mean_cos = cos(h);
        p->mean_ok = true;
    }
    double x, y;
    fw_to_body(de, dn, p->mean_sin, p->mean_cos, &x, &y);
    double lat = fabs(y) / dt, step = hypot(de, dn);
    double reach = m->def.jump_factor * fmax(p->speed, a->speed) * dt + m->def.jump_slack;
    char d[96];
    if (step > reach && fabs(y) <= fabs(x)) {
        m->c.teleport++;
        snprintf(d, sizeof d, "moved %.0f m in %.1f s at %.1f kn", step, dt, fw_ms_to_kn(a->speed));
        event(m, t, "teleport", a, NULL, d);
        return;
    }
    /* a jump mostly across the heading is a lane change done in one step:
     * sideways, below */
    if (lat > m->c.max_lateral)
        m->c.max_lateral = lat;
    if (lat > m->def.lateral_max && !p->sideways) {
        m->c.sideways++;
        snprintf(d, sizeof d, "%.1f m/s sideways", lat);
        event(m, t, "sideways", a, NULL, d);
    }
    p->sideways = lat > m->def.lateral_max;
}

static void slow(fw_monitor *m, double t, ship_state *p, const fw_target *a)
{
    if (a->speed >= m->def.stop_speed) {
        p->slow_since = -1.0;
        p->stopped = false;
        return;
    }
    if (p->slow_since < 0.0)
        p->slow_since = t;
    if (!p->stopped && t - p->slow_since >= m->def.stop_time) {
        p->stopped = true;
        m->c.stopped++;
        event(m, t, "stopped", a, NULL, "");
    }
}

static void on_pair(void *ctx, int i, int j, double d2)
{
    (void)d2;
    fw_monitor *m = ctx;
    const fw_target *a = &m->ships[m->bg[i]], *b = &m->ships[m->bg[j]];
    if (!fw_hulls_overlap(a->east, a->north, a->heading, a->length, a->breadth, b->east, b->north,
                          b->heading, b->length, b->breadth))
        return;
    uint64_t key = sv_pair_key(m->cur[m->bg[i]], m->cur[m->bg[j]]);
    int last = sv_pairs_get(&m->pairs, key);
    if (last < 0 || last != m->stamp - 1) {
        m->c.overlap++;
        event(m, m->s[m->cur[m->bg[i]]].t, "overlap", a, b->id, "hulls overlap");
    }
    if (sv_pairs_put(&m->pairs, key, (int)m->stamp))
        m->oom = true;
}

/* Hull overlaps among the background ships of this step. */
static void overlaps(fw_monitor *m, const fw_target *ships, int n)
{
    int k = 0;
    double half = 0.0;
    for (int i = 0; i < n; i++) {
        if (ships[i].own)
            continue;
        m->bg[k] = i;
        m->x[k] = ships[i].east;
        m->y[k] = ships[i].north;
        half = fmax(half, 0.5 * hypot(ships[i].length, ships[i].breadth));
        k++;
    }
    m->ships = ships;
    if (k > 1 && half > 0.0 && sv_grid_pairs(&m->grid, m->x, m->y, k, 2.0 * half + 1.0, on_pair, m))
        m->oom = true;
}

fw_status fw_monitor_step(fw_monitor *m, double t, const fw_target *own, const fw_target *ships,
                          int n, fw_error *err)
{
    if (!reserve(m, n))
        return fw_fail(err, FW_ERUN, "monitor: out of memory for %d ships", n);
    m->stamp++;
    for (int k = 0; k < n; k++) {
        const fw_target *a = &ships[k];
        int i;
        m->cur[k] = -1;
        if (a->own)
            continue; /* an area list holds the own ship too */
        if (fw_idmap_intern_keyed(&m->ids, a->key, a->id, &i) || !reserve(m, n))
            return fw_fail(err, FW_ERUN, "monitor: out of memory for ship ids");
        ship_state *p = &m->s[i];
        m->cur[k] = i;
        bool close = hypot(a->east - own->east, a->north - own->north) < m->def.close_range;
        if (p->seen == m->stamp - 1 && p->seen > 0) {
            moved(m, t, p, a);
        } else if (close && m->stamp == 1) {
            m->c.start_close++;
            event(m, t, "start_close", a, NULL, "there at the start");
        } else if (close) {
            m->c.appear++;
            event(m, t, "appear", a, NULL, "first seen within 2 nm");
        }
        if (p->seen != m->stamp - 1 || p->seen == 0)
            p->slow_since = -1.0, p->stopped = false, p->sideways = false;
        slow(m, t, p, a);
        *p = (ship_state){.seen = m->stamp, .t = t, .east = a->east, .north = a->north,
                          .heading = a->heading, .speed = a->speed, .close = close,
                          .sideways = p->sideways, .slow_since = p->slow_since,
                          .stopped = p->stopped, .mean_from = p->mean_from,
                          .mean_to = p->mean_to, .mean_sin = p->mean_sin,
                          .mean_cos = p->mean_cos, .mean_ok = p->mean_ok};
    }
    /* the ships of the last step that are gone */
    for (int k = 0; k < m->nprev; k++) {
        if (m->prev[k] < 0)
            continue;
        ship_state *p = &m->s[m->prev[k]];
        if (p->seen == m->stamp - 1 && p->close) {
            m->c.vanish++;
            fw_target gone = {.east = p->east, .north = p->north};
            snprintf(gone.id, sizeof gone.id, "%s", m->ids.name[m->prev[k]]);
            event(m, t, "vanish", &gone, NULL, "no longer seen, last within 2 nm");
        }
    }
    overlaps(m, ships, n);
    if (n > 0) /* none seen yet: the arrays may still be NULL */
        memcpy(m->prev, m->cur, sizeof *m->cur * (size_t)n);
    m->nprev = n;
    return m->oom ? fw_fail(err, FW_ERUN, "monitor: out of memory for ship pairs") : FW_OK;
}
