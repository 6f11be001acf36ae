/* source_track.c - recorded tracks replayed as a traffic source (source_track.h). */
#include "traffic/source_track.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"
#include "core/mem.h"
#include "core/units.h"

typedef fw_rec_point trk_point;

typedef struct trk_ship {
    fw_rec_track tr;     /* info: id, type, size; points sorted by t */
    int cur;         /* the point at or before the present time */
    fw_turn_pred turn; /* the turn of that point, when it has one */
} trk_ship;

typedef struct trk_source {
    fw_source base;
    fw_replay_def def;
    trk_ship *ships; /* sorted by id */
    int n;
    long steps;
    fw_target own;
    bool placed;
    fw_target *out;
} trk_source;

bool fw_rec_track_reserve(fw_rec_track *tr)
{
    if (tr->n < tr->cap)
        return true;
    int cap = fw_grown_cap(tr->cap, 64);
    if (!fw_resize((void **)&tr->p, sizeof *tr->p, (size_t)cap))
        return false;
    tr->cap = cap;
    return true;
}

void fw_rec_tracks_free(fw_rec_track *tracks, int n)
{
    for (int i = 0; tracks && i < n; i++)
        free(tracks[i].p);
    free(tracks);
}

fw_replay_def fw_default_replay_def(void)
{
    return (fw_replay_def){.file = NULL, .step = 1.0, .radius = INFINITY, .max_gap = 1.5};
}

static double trk_time(const fw_source *s)
{
    const trk_source *k = (const trk_source *)s;
    return (double)k->steps * k->def.step;
}

static double trk_step_length(const fw_source *s) { return ((const trk_source *)s)->def.step; }

static fw_status trk_place(fw_source *s, const fw_target *own, fw_error *err)
{
    (void)err;
    trk_source *k = (trk_source *)s;
    k->own = *own;
    k->placed = true;
    return FW_OK;
}

static fw_status trk_advance(fw_source *s, fw_error *err)
{
    (void)err;
    ((trk_source *)s)->steps++;
    return FW_OK;
}

/* Where ship s is at time t; false when it is not there then. */
static bool at(trk_ship *s, double t, double max_gap, fw_target *out)
{
    if (s->tr.n == 0 || t < s->tr.p[0].t - 1e-9 || t > s->tr.p[s->tr.n - 1].t + 1e-9)
        return false;
    while (s->cur + 1 < s->tr.n && s->tr.p[s->cur + 1].t <= t + 1e-9)
        s->cur++;
    while (s->cur > 0 && s->tr.p[s->cur].t > t + 1e-9)
        s->cur--;
    const trk_point *a = &s->tr.p[s->cur], *b = s->cur + 1 < s->tr.n ? a + 1 : a;
    if (b != a && b->t - a->t > max_gap && t > a->t + 1e-9)
        return false; /* between two passes */
    double w = b->t > a->t ? (t - a->t) / (b->t - a->t) : 0.0;
    if (w < 0.0)
        w = 0.0;
    *out = s->tr.info;
    out->east = a->east + w * (b->east - a->east);
    out->north = a->north + w * (b->north - a->north);
    /* a recorded point has one course (AIS: COG, else the heading) and one
     * speed: the record has them as both */
    out->course = out->heading = a->course;
    out->speed = out->stw = a->speed;
    out->pred = NULL;
    if (a->turn_rate > 0.0) {
        fw_turn_pred_init(&s->turn);
        s->turn.rate = a->turn_rate, s->turn.heading = a->turn_to, s->turn.turning = true;
        out->pred = &s->turn.base;
    }
    return true;
}

static fw_status trk_around(fw_source *s, const fw_target **v, int *n, fw_error *err)
{
    trk_source *k = (trk_source *)s;
    *v = k->out;
    *n = 0;
    if (!k->placed)
        return fw_fail(err, FW_ERUN, "track source: no query before the own ship is placed");
    double t = trk_time(s);
    for (int i = 0; i < k->n; i++) {
        fw_target x;
        if (at(&k->ships[i], t, k->def.max_gap, &x) &&
            (isinf(k->def.radius) ||
             hypot(x.east - k->own.east, x.north - k->own.north) <= k->def.radius))
            k->out[(*n)++] = x;
    }
    return FW_OK;
}

/* The recorded ships within r of (e, n) now; no own ship needed. */
static fw_status trk_within(fw_source *s, double e, double n, double r, const fw_target **v,
                            int *m, fw_error *err)
{
    (void)err;
    trk_source *k = (trk_source *)s;
    double t = trk_time(s);
    *v = k->out;
    *m = 0;
    for (int i = 0; i < k->n; i++) {
        fw_target x;
        if (at(&k->ships[i], t, k->def.max_gap, &x) && hypot(x.east - e, x.north - n) <= r)
            k->out[(*m)++] = x;
    }
    return FW_OK;
}

/* Refused: a recorded ship could not be given back meaningfully. */
static fw_status trk_take(fw_source *s, const char *id, fw_target *state, fw_error *err)
{
    (void)s, (void)state;
    return fw_fail(err, FW_EINPUT,
                   "track source: '%s' cannot be taken: its recording says where it is at every "
                   "later time, so it could not rejoin it from wherever fairway leaves it "
                   "without a jump",
                   id);
}

static fw_status trk_area(fw_source *s, const fw_target **v, int *n, fw_error *err)
{
    (void)s;
    *v = NULL;
    *n = 0;
    return fw_fail(err, FW_ERUN, "track source: no area query (a replay has no survey)");
}

static fw_status trk_set_speed(fw_source *s, const char *id, double speed, fw_error *err)
{
    (void)s, (void)id, (void)speed, (void)err;
    return FW_OK; /* a recorded ship went as it went */
}

static void trk_destroy(fw_source *s)
{
    trk_source *k = (trk_source *)s;
    for (int i = 0; i < k->n; i++)
        free(k->ships[i].tr.p);
    fw_free_each(3, k->ships, k->out, k);
}

static const fw_source_ops trk_ops = {.name = "track", .place = trk_place,
                                      .advance = trk_advance, .around = trk_around,
                                      .area = trk_area, .set_speed = trk_set_speed,
                                      .within = trk_within, .take = trk_take,
                                      .time = trk_time, .step_length = trk_step_length,
                                      .destroy = trk_destroy};

/* The columns a track file has (-1: absent). */
enum { C_T, C_ID, C_E, C_N, C_COURSE, C_SPEED, C_TYPE, C_L, C_B, C_RATE, C_TO, NCOL };
static const char *const col_names[NCOL] = {
    "t_s",  "id",       "east_m",    "north_m",         "course_deg", "speed_kn",
    "type", "length_m", "breadth_m", "turn_rate_degps", "turn_to_deg"};

static fw_status header(const char *file, char *line, int col[NCOL], fw_error *err)
{
    char *f[64];
    int n = fw_csv_split(line, f, 64);
    for (int c = 0; c < NCOL; c++) {
        col[c] = -1;
        for (int i = 0; i < n; i++)
            if (strcmp(f[i], col_names[c]) == 0)
                col[c] = i;
        if (c < C_TYPE && col[c] < 0)
            return fw_fail(err, FW_EINPUT, "%s:1: no column %s", file, col_names[c]);
    }
    if ((col[C_RATE] < 0) != (col[C_TO] < 0))
        return fw_fail(err, FW_EINPUT, "%s:1: %s: turn_rate_degps and turn_to_deg come together",
                       file, col_names[col[C_RATE] < 0 ? C_RATE : C_TO]);
    return FW_OK;
}

/* The tracks a file is read into. */
typedef struct trk_list {
    fw_rec_track *v;
    int n;
} trk_list;

static fw_rec_track *ship_of(trk_list *k, const char *id)
{
    for (int i = k->n - 1; i >= 0; i--) /* rows come grouped by time: recent ships last */
        if (strcmp(k->v[i].info.id, id) == 0)
            return &k->v[i];
    if (!fw_resize((void **)&k->v, sizeof *k->v, (size_t)k->n + 1))
        return NULL;
    fw_rec_track *s = &k->v[k->n++];
    memset(s, 0, sizeof *s);
    snprintf(s->info.id, sizeof s->info.id, "%s", id);
    return s;
}

static bool number(const char *s, double *v)
{
    char *end;
    *v = strtod(s, &end);
    return end != s && *end == '\0' && isfinite(*v);
}

/* One data row into its ship. */
static fw_status row(trk_list *k, const char *file, int line_no, char *line, const int col[NCOL],
                     fw_error *err)
{
    char *f[64];
    int n = fw_csv_split(line, f, 64);
    double v[NCOL] = {0};
    /* a turn: both columns empty (none), or a rate above 0 and a heading */
    bool turn = col[C_RATE] >= 0 && col[C_RATE] < n && col[C_TO] < n &&
                (f[col[C_RATE]][0] || f[col[C_TO]][0]);
    for (int c = 0; c < NCOL; c++) {
        if (col[c] < 0 || c == C_ID || c == C_TYPE || ((c == C_RATE || c == C_TO) && !turn))
            continue;
        if (col[c] >= n || !number(f[col[c]], &v[c]))
            return fw_fail(err, FW_EINPUT, "%s:%d: %s: not a number", file, line_no, col_names[c]);
    }
    if (turn && !(v[C_RATE] > 0.0))
        return fw_fail(err, FW_EINPUT, "%s:%d: turn_rate_degps: %.15g: a turn's rate is above 0",
                       file, line_no, v[C_RATE]);
    if (col[C_ID] >= n || !f[col[C_ID]][0] || strlen(f[col[C_ID]]) >= FW_TARGET_ID_MAX)
        return fw_fail(err, FW_EINPUT, "%s:%d: id: empty or too long", file, line_no);
    fw_rec_track *s = ship_of(k, f[col[C_ID]]);
    if (!s || !fw_rec_track_reserve(s))
        return fw_fail(err, FW_ERUN, "%s: out of memory", file);
    if (col[C_TYPE] >= 0 && col[C_TYPE] < n)
        snprintf(s->info.type, sizeof s->info.type, "%s", f[col[C_TYPE]]);
    s->info.length = v[C_L];
    s->info.breadth = v[C_B];
    s->p[s->n++] = (trk_point){.t = v[C_T], .east = v[C_E], .north = v[C_N],
                               .course = fw_deg_to_rad(v[C_COURSE]),
                               .speed = fw_kn_to_ms(v[C_SPEED]),
                               .turn_rate = fw_deg_to_rad(v[C_RATE]),
                               .turn_to = fw_deg_to_rad(v[C_TO])};
    return FW_OK;
}

static fw_status load(trk_list *k, const char *file, fw_error *err)
{
    FILE *fp = fopen(file, "r");
    if (!fp)
        return fw_fail(err, FW_EINPUT, "%s: cannot open the track file", file);
    char line[4096];
    int col[NCOL], line_no = 1;
    fw_status st = fgets(line, sizeof line, fp) ? header(file, line, col, err)
                                                : fw_fail(err, FW_EINPUT, "%s: empty", file);
    while (!st && fgets(line, sizeof line, fp))
        if (line[strspn(line, " \r\n")] != '\0')
            st = row(k, file, ++line_no, line, col, err);
        else
            line_no++;
    fclose(fp);
    return st;
}

static int cmp_point(const void *a, const void *b)
{
    double x = ((const trk_point *)a)->t, y = ((const trk_point *)b)->t;
    return (x > y) - (x < y);
}

static int cmp_ship(const void *a, const void *b)
{
    return strcmp(((const trk_ship *)a)->tr.info.id, ((const trk_ship *)b)->tr.info.id);
}

/* Sorted ships and points; what is wrong with them. */
static fw_status check(trk_source *k, const char *what, fw_error *err)
{
    qsort(k->ships, (size_t)k->n, sizeof *k->ships, cmp_ship);
    for (int i = 0; i < k->n; i++) {
        fw_rec_track *s = &k->ships[i].tr;
        if (!s->info.id[0])
            return fw_fail(err, FW_EINPUT, "%s: a ship without an id", what);
        if (i > 0 && strcmp(s->info.id, k->ships[i - 1].tr.info.id) == 0)
            return fw_fail(err, FW_EINPUT, "%s: ship %s listed twice", what, s->info.id);
        qsort(s->p, (size_t)s->n, sizeof *s->p, cmp_point);
        for (int j = 0; j < s->n; j++) {
            const trk_point *q = &s->p[j];
            if (!isfinite(q->t) || !isfinite(q->east) || !isfinite(q->north) ||
                !isfinite(q->course) || !isfinite(q->speed) || !isfinite(q->turn_to) ||
                !(q->turn_rate >= 0.0 && isfinite(q->turn_rate)))
                return fw_fail(err, FW_EINPUT, "%s: ship %s has a point that is not a number",
                               what, s->info.id);
            if (j > 0 && q->t == s->p[j - 1].t)
                return fw_fail(err, FW_EINPUT, "%s: ship %s has two points at t = %g s", what,
                               s->info.id, q->t);
        }
    }
    return FW_OK;
}

fw_status fw_track_source_create(fw_rec_track *tracks, int n, const fw_replay_def *def,
                                 const char *what, fw_source **out, fw_error *err)
{
    *out = NULL;
    trk_source *k = calloc(1, sizeof *k);
    if (!k || !(k->ships = calloc((size_t)(n > 0 ? n : 1), sizeof *k->ships)) ||
        !(k->out = malloc((size_t)(n > 0 ? n : 1) * sizeof *k->out))) {
        if (k)
            fw_free_each(2, k->ships, k);
        fw_rec_tracks_free(tracks, n);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    k->base.ops = &trk_ops;
    k->def = *def;
    for (int i = 0; i < n; i++)
        k->ships[i].tr = tracks[i];
    free(tracks); /* the points are the ships' now */
    k->n = n;
    fw_status st = !(def->step > 0.0) || !(def->radius > 0.0) || !(def->max_gap > 0.0)
                       ? fw_fail(err, FW_EINPUT, "track source: step > 0, radius > 0, gap > 0")
                       : check(k, what, err);
    if (st) {
        trk_destroy(&k->base);
        return st;
    }
    *out = &k->base;
    return FW_OK;
}

fw_status fw_rec_tracks_load(const char *file, fw_rec_track **tracks, int *n, fw_error *err)
{
    trk_list k = {0};
    fw_status st = load(&k, file, err);
    if (st) {
        fw_rec_tracks_free(k.v, k.n);
        k.v = NULL, k.n = 0;
    }
    *tracks = k.v;
    *n = k.n;
    return st;
}

fw_status fw_replay_source_create(const fw_replay_def *def, fw_source **out, fw_error *err)
{
    *out = NULL;
    if (!def->file)
        return fw_fail(err, FW_EINPUT, "track source: no file");
    trk_list k = {0};
    fw_status st = load(&k, def->file, err);
    if (st) {
        fw_rec_tracks_free(k.v, k.n);
        return st;
    }
    return fw_track_source_create(k.v, k.n, def, def->file, out, err);
}
