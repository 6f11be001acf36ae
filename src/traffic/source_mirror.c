/* source_mirror.c - a replay shown in SUMO (source_mirror.h). */
#include "traffic/source_mirror.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"
#include "core/idmap.h"
#include "core/mem.h"
#include "traffic/netbuild.h"

typedef struct mirror {
    fw_source base;
    fw_source *inner;
    fw_traffic *tr;
    double radius;
    fw_target own;
    fw_idmap ids;     /* every ship ever shown */
    long *shown;      /* per id: the sync it was last shown at, -1: not in SUMO */
    int cap;
    long sync;
    fw_target *out;   /* around(): the inner's within the radius */
    int out_cap;
} mirror;

static const char kMirrorTag[] = "mirror";

/* SUMO shows the inner's ships of now: new ones added, all moved, gone ones out. */
static fw_status sync_ships(mirror *m, fw_error *err)
{
    const fw_target *v;
    int n;
    fw_status st = fw_source_around(m->inner, &v, &n, err);
    m->sync++;
    for (int i = 0; !st && i < n; i++) {
        int k;
        if (fw_idmap_intern(&m->ids, v[i].id, &k) != 0)
            return fw_fail(err, FW_ERUN, "out of memory");
        if (k >= m->cap) {
            int cap = fw_grown_cap(m->cap, k + 1);
            if (!fw_resize((void **)&m->shown, sizeof *m->shown, (size_t)cap))
                return fw_fail(err, FW_ERUN, "out of memory");
            for (int j = m->cap; j < cap; j++)
                m->shown[j] = -1;
            m->cap = cap;
        }
        double len = v[i].length > 0 ? v[i].length : 10.0; /* AIS without A-D: a small craft */
        double wid = v[i].breadth > 0 ? v[i].breadth : 3.0;
        if (m->shown[k] < 0)
            st = fw_traffic_add_placed(m->tr, v[i].id, len, wid, err);
        if (!st)
            st = fw_traffic_move(m->tr, v[i].id, v[i].east, v[i].north, v[i].heading, len, err);
        m->shown[k] = m->sync;
    }
    for (int k = 0; !st && k < m->ids.n; k++)
        if (m->shown[k] >= 0 && m->shown[k] != m->sync) {
            st = fw_traffic_remove(m->tr, m->ids.name[k], err);
            m->shown[k] = -1;
        }
    return st;
}

static fw_status mr_place(fw_source *s, const fw_target *own, fw_error *err)
{
    mirror *m = (mirror *)s;
    m->own = *own;
    fw_status st = fw_source_place(m->inner, own, err);
    return st ? st : fw_traffic_place(m->tr, own->east, own->north, own->heading, own->speed, err);
}

static fw_status mr_advance(fw_source *s, fw_error *err)
{
    mirror *m = (mirror *)s;
    fw_status st = fw_source_advance(m->inner, err);
    if (!st)
        st = sync_ships(m, err);
    return st ? st : fw_traffic_step(m->tr, err);
}

static fw_status mr_around(fw_source *s, const fw_target **v, int *n, fw_error *err)
{
    mirror *m = (mirror *)s;
    const fw_target *all;
    int na;
    *v = m->out;
    *n = 0;
    fw_status st = fw_source_around(m->inner, &all, &na, err);
    if (st)
        return st;
    if (!fw_reserve((void **)&m->out, sizeof *m->out, &m->out_cap, na))
        return fw_fail(err, FW_ERUN, "out of memory");
    for (int i = 0; i < na; i++)
        if (hypot(all[i].east - m->own.east, all[i].north - m->own.north) <= m->radius)
            m->out[(*n)++] = all[i];
    *v = m->out;
    return FW_OK;
}

static fw_status mr_area(fw_source *s, const fw_target **v, int *n, fw_error *err)
{
    return fw_source_area(((mirror *)s)->inner, v, n, err);
}

static fw_status mr_set_speed(fw_source *s, const char *id, double speed, fw_error *err)
{
    return fw_source_set_speed(((mirror *)s)->inner, id, speed, err);
}

static double mr_time(const fw_source *s) { return fw_source_time(((const mirror *)s)->inner); }

static double mr_step_length(const fw_source *s)
{
    return fw_source_step_length(((const mirror *)s)->inner);
}

static void mr_destroy(fw_source *s)
{
    mirror *m = (mirror *)s;
    fw_source_destroy(m->inner);
    fw_traffic_close(m->tr);
    fw_idmap_free(&m->ids);
    fw_free_each(3, m->shown, m->out, m);
}

static const fw_source_ops mirror_ops = {.name = kMirrorTag, .place = mr_place,
                                         .advance = mr_advance, .around = mr_around,
                                         .area = mr_area, .set_speed = mr_set_speed,
                                         .time = mr_time, .step_length = mr_step_length,
                                         .destroy = mr_destroy};

fw_traffic *fw_mirror_source_traffic(fw_source *s)
{
    return s && s->ops == &mirror_ops ? ((mirror *)s)->tr : NULL;
}

/* SUMO's network: one edge along the own ship's leg or its run at its
 * speed, whichever is longer, 2 km beyond either end (the own ship's SUMO
 * vehicle must not reach the end of its lane). */
static fw_status build_net(const fw_mirror_def *d, char *net, size_t n, fw_error *err)
{
    char np[1200], ep[1200], log[1200];
    fw_status st;
    if ((st = fw_path(np, sizeof np, err, "%s/mirror.nod.xml", d->dir)) ||
        (st = fw_path(ep, sizeof ep, err, "%s/mirror.edg.xml", d->dir)) ||
        (st = fw_path(log, sizeof log, err, "%s/netconvert.log", d->dir)) ||
        (st = fw_path(net, n, err, "%s/mirror.net.xml", d->dir)))
        return st;
    char nt[1300], et[1300] = "";
    FILE *nf = fw_file_begin(np, nt, sizeof nt, err);
    FILE *ef = nf ? fw_file_begin(ep, et, sizeof et, err) : NULL;
    if (!nf || !ef) {
        fw_file_abort(nf, nt);
        return err->status;
    }
    const fw_target *o = &d->own;
    double se = sin(o->course), ce = cos(o->course), len = fmax(d->own_leg, o->speed * d->duration) + 2000.0;
    fprintf(nf, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- written by fairway: the "
                "own ship's leg, for a replay shown in SUMO -->\n<nodes>\n"
                "    <node id=\"fw_own_a\" x=\"%.3f\" y=\"%.3f\" type=\"unregulated\"/>\n"
                "    <node id=\"fw_own_b\" x=\"%.3f\" y=\"%.3f\" type=\"unregulated\"/>\n"
                "</nodes>\n",
            o->east - 2000.0 * se, o->north - 2000.0 * ce, o->east + len * se,
            o->north + len * ce);
    fprintf(ef, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<edges>\n"
                "    <edge id=\"fw_own\" from=\"fw_own_a\" to=\"fw_own_b\" numLanes=\"1\" "
                "speed=\"30\" width=\"%.1f\" allow=\"ship\" spreadType=\"center\"/>\n</edges>\n",
            fmax(o->breadth, 10.0));
    if ((st = fw_file_commit(nf, nt, np, err))) {
        fw_file_abort(ef, et);
        return st;
    }
    if ((st = fw_file_commit(ef, et, ep, err)))
        return st;
    return fw_netconvert(d->dir, "mirror.nod.xml", "mirror.edg.xml", NULL, NULL, "mirror.net.xml",
                         log, err);
}

fw_status fw_mirror_source_create(fw_source *inner, const fw_mirror_def *def, fw_source **out,
                                  fw_error *err)
{
    *out = NULL;
    mirror *m = calloc(1, sizeof *m);
    if (!m) {
        fw_source_destroy(inner);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    m->base.ops = &mirror_ops;
    m->inner = inner;
    m->radius = def->radius;
    m->own = def->own;
    char net[1200], log[1200];
    fw_traffic_def td = fw_default_traffic_def();
    td.mode = def->mode;
    td.net_file = net;
    td.log_file = log;
    td.step = def->step;
    td.seed = def->seed;
    td.own_id = def->own.id;
    td.own_length = def->own.length;
    td.own_width = def->own.breadth;
    td.own_edge = "fw_own";
    td.radius = isfinite(def->radius) ? def->radius : 50e3; /* SUMO's query: unused here */
    fw_status st;
    if ((st = build_net(def, net, sizeof net, err)) ||
        (st = fw_path(log, sizeof log, err, "%s/sumo.log", def->dir)) ||
        (st = fw_traffic_open(&td, &m->tr, err)) || (st = mr_place(&m->base, &def->own, err)) ||
        (st = sync_ships(m, err))) {
        mr_destroy(&m->base);
        return st;
    }
    *out = &m->base;
    return FW_OK;
}
