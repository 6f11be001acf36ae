/* run.c - the step loop (see run.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "avoid/policy.h"
#include "core/units.h"
#include "dynamics/stepper.h"
#include "run/run.h"
#include "traffic/demand.h"
#include "traffic/netbuild.h"

fw_run_def fw_default_run_def(void)
{
    fw_run_def d = {0};
    d.mode.kind = FW_TRAFFIC_EMBEDDED;
    return d;
}

/* Extra length of each straight edge behind the start and beyond the end of
 * the run, so no ship reaches an edge's end (where SUMO would remove it). */
static const double kBehind = 1000.0, kBeyond = 3000.0;

static void node(FILE *f, const char *id, double e, double n)
{
    fprintf(f, "    <node id=\"%s\" x=\"%.3f\" y=\"%.3f\" type=\"unregulated\"/>\n", id, e, n);
}

/* Plain XML for the own ship's leg and every target's track, and the routes
 * of the targets.  Target lanes allow custom1 only (see run.h). */
static fw_status write_tracks(const fw_scenario *s, const char *sumo, fw_error *err)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/tracks.nod.xml", sumo);
    FILE *nf = fopen(path, "w");
    snprintf(path, sizeof path, "%s/tracks.edg.xml", sumo);
    FILE *ef = fopen(path, "w");
    snprintf(path, sizeof path, "%s/targets.rou.xml", sumo);
    FILE *rf = fopen(path, "w");
    if (!nf || !ef || !rf) {
        if (nf)
            fclose(nf);
        if (ef)
            fclose(ef);
        if (rf)
            fclose(rf);
        return fw_fail(err, FW_ERUN, "cannot write the track network in %s", sumo);
    }
    fprintf(nf, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- written by fairway run: "
                "straight tracks of the own ship and the explicit targets -->\n<nodes>\n");
    fprintf(ef, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<edges>\n");
    fprintf(rf, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<routes>\n");
    double se = sin(s->course), ce = cos(s->course);
    double len = fmax(s->leg, s->speed * s->duration) + kBeyond;
    node(nf, "fw_own_a", s->east - kBehind * se, s->north - kBehind * ce);
    node(nf, "fw_own_b", s->east + len * se, s->north + len * ce);
    fprintf(ef, "    <edge id=\"fw_own\" from=\"fw_own_a\" to=\"fw_own_b\" numLanes=\"1\" "
                "speed=\"30\" width=\"%.1f\" allow=\"ship\" spreadType=\"center\"/>\n",
            fmax(s->ship.B, 10.0));
    for (int i = 0; i < s->n_targets; i++) {
        const fw_scn_target *t = &s->targets[i];
        double te = sin(t->course), tn = cos(t->course);
        double tl = t->speed * s->duration + kBeyond;
        char a[64], b[64], v[32];
        snprintf(a, sizeof a, "fw_t_%s_a", t->id);
        snprintf(b, sizeof b, "fw_t_%s_b", t->id);
        node(nf, a, t->east - kBehind * te, t->north - kBehind * tn);
        node(nf, b, t->east + tl * te, t->north + tl * tn);
        fprintf(ef, "    <edge id=\"fw_t_%s\" from=\"%s\" to=\"%s\" numLanes=\"1\" speed=\"30\" "
                    "width=\"%.1f\" allow=\"custom1\" spreadType=\"center\"/>\n",
                t->id, a, b, fmax(t->breadth, 10.0));
        /* one string for maxSpeed and departSpeed: SUMO refuses a departure
         * faster than the type's maximum by a rounding digit */
        snprintf(v, sizeof v, "%.6f", t->speed);
        fprintf(rf, "    <vType id=\"fw_t_%s\" vClass=\"custom1\" guiShape=\"ship\" length=\"%.3f\" "
                    "width=\"%.3f\" maxSpeed=\"%s\" speedFactor=\"1\" sigma=\"0\" accel=\"1\" "
                    "decel=\"1\" minGap=\"0\" color=\"0.2,0.4,0.9\"/>\n",
                t->id, t->length, t->breadth, v);
        /* departPos is the front bumper: hull centre at the start point */
        fprintf(rf, "    <vehicle id=\"%s\" type=\"fw_t_%s\" depart=\"0\" departLane=\"0\" "
                    "departPos=\"%.3f\" departSpeed=\"%s\">\n        <route edges=\"fw_t_%s\"/>\n"
                    "    </vehicle>\n",
                t->id, t->id, kBehind + 0.5 * t->length, v, t->id);
    }
    fprintf(nf, "</nodes>\n");
    fprintf(ef, "</edges>\n");
    fprintf(rf, "</routes>\n");
    int bad = fclose(nf) | fclose(ef) | fclose(rf);
    return bad ? fw_fail(err, FW_ERUN, "cannot write the track network in %s", sumo) : FW_OK;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp_ship(const void *a, const void *b)
{
    return strcmp(((const fw_target *)a)->id, ((const fw_target *)b)->id);
}

typedef struct loop_state {
    const fw_scenario *s;
    fw_stepper *st;
    fw_traffic *tr;
    fw_helm_ctx *ctx;
    fw_records *rec;
    double n_prop;
    fw_survey *sv;              /* NULL: no survey */
} loop_state;

/* The survey's step: every ship in the area, the own ship included. */
static fw_status survey_step(loop_state *L, double t, fw_error *err)
{
    const fw_target *a;
    int n;
    fw_status st = fw_traffic_area(L->tr, &a, &n, err);
    return st ? st : fw_survey_step(L->sv, t, a, n, err);
}

/* Survey totals into the summary, its records into the run directory and to
 * the caller; run.log gets the counts. */
static fw_status survey_finish(loop_state *L, const fw_run_def *def, fw_run_summary *sum,
                               fw_error *err)
{
    fw_survey_totals tot;
    fw_survey_finish(L->sv, &tot);
    sum->survey = true;
    sum->traffic_ship_s = tot.ship_s;
    sum->n_traffic = tot.n;
    for (int k = 0; k < FW_SURVEY_NTYPES; k++)
        sum->traffic_by_type[k] = tot.by_type[k];
    sum->n_traffic_own = tot.n_own;
    fprintf(fw_records_log(L->rec),
            "survey: %d traffic encounters (%d head-on, %d overtaking, %d crossing; %d with the "
            "own ship) in %.1f ship-hours\n",
            tot.n, tot.by_type[FW_SURVEY_HEAD_ON], tot.by_type[FW_SURVEY_OVERTAKING],
            tot.by_type[FW_SURVEY_CROSSING], tot.n_own, tot.ship_s / 3600.0);
    int n;
    const fw_survey_record *r = fw_survey_records(L->sv, &n);
    if (def->survey_out && n > 0) {
        *def->survey_out = malloc(sizeof **def->survey_out * (size_t)n);
        if (!*def->survey_out)
            return fw_fail(err, FW_ERUN, "out of memory for %d survey records", n);
        memcpy(*def->survey_out, r, sizeof **def->survey_out * (size_t)n);
        *def->n_survey_out = n;
    }
    return fw_records_survey(L->rec, r, n, err);
}

static const char *side_word(int side)
{
    return side == FW_SIDE_STARBOARD ? "starboard" : side == FW_SIDE_PORT ? "port" : "none";
}

static fw_status loop(loop_state *L, fw_run_summary *sum, fw_error *err)
{
    const fw_scenario *s = L->s;
    FILE *log = fw_records_log(L->rec);
    fw_policy pol;
    fw_policy_init(&pol, &s->policy);
    long n_steps = lround(s->duration / s->step);
    long every = lround(s->record_every / s->step);
    int cap = 0;
    fw_target *ships = NULL;
    fw_target *tg = NULL;
    fw_assessment *as = NULL;
    int *order = NULL;
    const char **tid = NULL;
    const fw_assessment **tas = NULL;
    fw_status stt = FW_OK;
    double r_prev = 0.0, e_prev = s->east, n_prev = s->north, helm_prev = 0.0;
    double se = sin(s->course), ce = cos(s->course);
    fw_policy_mode mode_prev = FW_MODE_STANDBY;
    for (long k = 0;; k++) {
        double t = k * s->step;
        const fw_mmg_state *x = fw_stepper_state(L->st);
        const fw_target *raw;
        int n;
        if ((stt = fw_traffic_around(L->tr, &raw, &n, err)))
            break;
        if (L->sv && (stt = survey_step(L, t, err)))
            break;
        if (n > cap) {
            cap = n * 2;
            ships = realloc(ships, sizeof *ships * (size_t)cap);
            tg = realloc(tg, sizeof *tg * (size_t)cap);
            as = realloc(as, sizeof *as * (size_t)cap);
            order = realloc(order, sizeof *order * 2 * (size_t)cap);
            tid = realloc(tid, sizeof *tid * (size_t)cap);
            tas = realloc(tas, sizeof *tas * (size_t)cap);
            if (!ships || !tg || !as || !order || !tid || !tas) {
                stt = fw_fail(err, FW_ERUN, "out of memory");
                break;
            }
        }
        /* converted once, here; sorted by id so the order never depends on SUMO's */
        if (n > 0) { /* no ship in range yet: the arrays may still be NULL */
            memcpy(ships, raw, sizeof *ships * (size_t)n);
            qsort(ships, (size_t)n, sizeof *ships, cmp_ship);
        }
        for (int i = 0; i < n; i++) {
            tg[i] = ships[i];
        }
        fw_own_state own = {.east = x->east, .north = x->north, .psi = x->psi,
                            .U = hypot(x->u, x->vm), .U0 = s->speed,
                            .beta = atan2(-x->vm, x->u), .r = x->r,
                            .rdot = k ? (x->r - r_prev) / s->step : 0.0, .delta = x->delta};
        fw_decision d;
        if ((stt = fw_policy_step(&pol, L->ctx, &s->helm, t, &own, tg, n, as, order, &d, err)))
            break;
        bool row = k % every == 0;
        if (row)
            fw_records_own(L->rec, t, x, d.helm, L->n_prop, fw_policy_mode_name(d.mode));
        for (int i = 0; i < n; i++)
            fw_records_target(L->rec, t, &ships[i], x, &as[i], row);
        if (d.acted) {
            int m = 0;
            for (int i = 0; i < n; i++)
                if (as[i].enters_domain) {
                    tid[m] = ships[i].id;
                    tas[m++] = &as[i];
                }
            const char *pid = d.primary >= 0 && d.primary < n ? ships[d.primary].id : NULL;
            fw_records_action(L->rec, t, d.search.side, d.helm, pid, tid, tas, m);
            sum->n_actions++;
            if (!sum->acted) {
                sum->acted = true;
                sum->t_act = t;
                sum->act_side = d.search.side;
                sum->act_helm = d.helm;
            }
            fprintf(log, "%9.1f  act %s %.0f deg for %s (%s, range %.0f m, DCPA %.0f m, TCPA "
                         "%.0f s): %s\n",
                    t, side_word(d.search.side), fw_rad_to_deg(fabs(d.helm)), pid ? pid : "-",
                    pid ? fw_situation_name(as[d.primary].situation) : "-",
                    pid ? as[d.primary].range : 0.0, pid ? as[d.primary].dcpa : 0.0,
                    pid ? as[d.primary].tcpa : 0.0, d.reason ? d.reason : "");
        }
        if (d.mode != mode_prev) {
            fprintf(log, "%9.1f  %s -> %s, helm %.1f deg: %s\n", t, fw_policy_mode_name(mode_prev),
                    fw_policy_mode_name(d.mode), fw_rad_to_deg(d.helm), d.reason ? d.reason : "");
            if (d.mode == FW_MODE_AUTOPILOT && isnan(sum->t_return))
                sum->t_return = t;
            if (mode_prev == FW_MODE_AUTOPILOT && d.mode == FW_MODE_STANDBY &&
                isnan(sum->t_on_course))
                sum->t_on_course = t;
            mode_prev = d.mode;
        }
        sum->max_helm = fmax(sum->max_helm, fabs(d.helm));
        if (fabs(d.helm - helm_prev) > fw_deg_to_rad(0.5)) {
            sum->helm_orders++;
            helm_prev = d.helm;
        }
        sum->t_end = t;
        if (k >= n_steps)
            break;
        r_prev = x->r;
        fw_stepper_set_helm(L->st, d.helm);
        if ((stt = fw_stepper_advance(L->st, s->step, err)))
            break;
        x = fw_stepper_state(L->st);
        sum->rudder_work += fabs(x->delta) * s->step;
        sum->path_length += hypot(x->east - e_prev, x->north - n_prev);
        e_prev = x->east;
        n_prev = x->north;
        if ((stt = fw_traffic_place(L->tr, x->east, x->north, x->psi, hypot(x->u, x->vm), err)))
            break;
        double t0 = now_s();
        stt = fw_traffic_step(L->tr, err);
        sum->sumo_s += now_s() - t0;
        if (stt)
            break;
    }
    const fw_mmg_state *x = fw_stepper_state(L->st);
    double de = x->east - s->east, dn = x->north - s->north;
    sum->along_track = de * se + dn * ce;
    sum->cross_track = de * ce - dn * se;
    sum->heading_error = fw_wrap_pi(x->psi - s->course);
    sum->path_lengthening = sum->path_length - sum->along_track;
    sum->time_lost = sum->t_end - sum->along_track / s->speed;
    free(ships);
    free(tg);
    free(as);
    free(order);
    free(tid);
    free(tas);
    return stt;
}

fw_status fw_run_scenario(const fw_run_def *def, fw_run_summary *sum, fw_encounter **enc,
                          int *n_enc, fw_error *err)
{
    const fw_scenario *s = def->scenario;
    double wall0 = now_s();
    memset(sum, 0, sizeof *sum);
    snprintf(sum->scenario, sizeof sum->scenario, "%s", s->name);
    snprintf(sum->status, sizeof sum->status, "failed");
    sum->t_act = sum->t_return = sum->t_on_course = NAN;
    sum->min_dist = INFINITY;
    sum->own_length = s->ship.Loa;
    sum->own_breadth = s->ship.B;
    sum->domain = s->helm.domain.size;
    sum->domain_ratio = s->helm.domain.fore_aft_ratio;
    *enc = NULL;
    *n_enc = 0;
    if (def->survey_out) {
        *def->survey_out = NULL;
        *def->n_survey_out = 0;
    }
    loop_state L = {.s = s};
    char sumo[1100], net[1200], routes[2600], slog[1200], nlog[1200], nodes[2400], edges[2400];
    snprintf(sumo, sizeof sumo, "%s/sumo", def->dir);
    if (mkdir(sumo, 0777) != 0)
        return fw_fail(err, FW_ERUN, "cannot create %s", sumo);
    /* Traffic on a network alone needs no track edges (moveToXY places the own
     * ship anywhere): the built network is used as it is, which spares a
     * netconvert per run in a sweep. */
    bool tracks = s->n_targets > 0 || !s->network[0];
    fw_status st = tracks ? write_tracks(s, sumo, err) : FW_OK;
    if (st)
        return st;
    fw_network_files nf = {0};
    /* netconvert runs in sumo/: relative names keep the net.xml independent
     * of the (temporary) run directory's path */
    snprintf(nodes, sizeof nodes, "tracks.nod.xml");
    snprintf(edges, sizeof edges, "tracks.edg.xml");
    snprintf(routes, sizeof routes, "%s/targets.rou.xml", sumo);
    const char *types = NULL;
    char typ[1100] = "";
    if (s->network[0]) {
        /* the network's own sources and the tracks, built together: one code path */
        if ((st = fw_network_find(s->network, &nf, err)))
            return st;
        const char *root = fw_data_root();
        char pre[1024];
        snprintf(pre, sizeof pre, "%s/networks/%s/%s", root, s->network, s->network);
        snprintf(nodes, sizeof nodes, "%s.nod.xml,tracks.nod.xml", pre);
        snprintf(edges, sizeof edges, "%s.edg.xml,tracks.edg.xml", pre);
        snprintf(typ, sizeof typ, "%s.typ.xml", pre);
        types = typ;
        fw_demand dm;
        fw_demand_def dd = fw_default_demand_def();
        dd.density = s->density;
        dd.fill = s->fill;
        dd.end = s->duration + s->step;
        dd.seed = s->seed;
        char drou[1200];
        snprintf(drou, sizeof drou, "%s/demand.rou.xml", sumo);
        if ((st = fw_demand_load(nf.demand, &dm, err)) ||
            (st = fw_demand_write(&dm, &dd, drou, err)))
            return st;
        if (s->n_targets > 0)
            snprintf(routes, sizeof routes, "%s/demand.rou.xml,%s/targets.rou.xml", sumo, sumo);
        else
            snprintf(routes, sizeof routes, "%s", drou);
    }
    snprintf(net, sizeof net, "%s/run.net.xml", sumo);
    snprintf(nlog, sizeof nlog, "%s/netconvert.log", sumo);
    snprintf(slog, sizeof slog, "%s/sumo.log", sumo);
    if (!tracks)
        snprintf(net, sizeof net, "%s", nf.net);
    else if ((st = fw_netconvert(sumo, nodes, edges, types, "run.net.xml", nlog, err)))
        return st;
    fw_traffic_def td = fw_default_traffic_def();
    td.mode = def->mode;
    td.net_file = net;
    td.route_file = routes;
    td.add_file = s->network[0] ? nf.types : NULL;
    td.log_file = slog;
    td.step = s->step;
    td.seed = s->seed;
    td.own_id = "fw_own";
    td.own_length = s->ship.Loa;
    td.own_width = s->ship.B;
    td.own_edge = tracks ? "fw_own" : NULL;
    td.radius = s->radius;
    td.area_radius = s->survey ? s->survey_radius : 0.0;
    fw_mmg_state x0 = fw_mmg_straight(s->speed, s->east, s->north, s->course);
    fw_stepper_def sd = fw_default_stepper_def();
    if ((st = fw_records_open(&L.rec, s, def->dir, err)) ||
        (st = fw_mmg_propeller_for_speed(&s->ship, s->speed, &L.n_prop, err)) ||
        (st = fw_stepper_create(&s->ship, &sd, &L.st, err)) ||
        (st = fw_stepper_start(L.st, 0.0, &x0, L.n_prop, err)) ||
        (st = fw_helm_ctx_create(&s->ship, &s->helm, &L.ctx, err)) ||
        (s->survey && (st = fw_survey_create(&s->survey_def, &L.sv, err))) ||
        (st = fw_traffic_open(&td, &L.tr, err)))
        goto out;
    fprintf(fw_records_log(L.rec),
            "scenario %s (%s): own ship %s at %.1f kn on %03.0f deg from (%.1f, %.1f) m, "
            "%d explicit targets%s%s, %.0f s in steps of %.3f s, seed %lu\n",
            s->name, s->file, s->ship.name, fw_ms_to_kn(s->speed), fw_heading_deg(s->course),
            s->east, s->north, s->n_targets, s->network[0] ? ", network " : "", s->network,
            s->duration, s->step, s->seed);
    /* SUMO inserts the targets during its first step: after it, their
     * positions are those of fairway's t = 0 */
    if ((st = fw_traffic_place(L.tr, x0.east, x0.north, x0.psi, s->speed, err)) ||
        (st = fw_traffic_step(L.tr, err)))
        goto out;
    L.s = s;
    st = loop(&L, sum, err);
    if (st)
        fprintf(fw_records_log(L.rec), "run failed: %s\n", err ? err->msg : "");
    else
        snprintf(sum->status, sizeof sum->status, "ok");
    {
        fw_error ferr = {0}, rerr = {0};
        /* the survey first: summary.json carries its totals */
        fw_status fst = L.sv ? survey_finish(&L, def, sum, &ferr) : FW_OK;
        fw_status rst = fw_records_finish(L.rec, sum, &rerr);
        if (!fst && rst) {
            fst = rst;
            ferr = rerr;
        }
        if (!st && fst) {
            st = fst;
            if (err)
                *err = ferr;
        }
    }
    fw_encounter *e = fw_records_encounters(L.rec, n_enc);
    if (*n_enc > 0) {
        *enc = malloc(sizeof **enc * (size_t)*n_enc);
        if (*enc)
            memcpy(*enc, e, sizeof **enc * (size_t)*n_enc);
        else
            *n_enc = 0;
    }
out:
    fw_traffic_close(L.tr);
    fw_survey_destroy(L.sv);
    sum->wall_s = now_s() - wall0;
    fw_helm_ctx_destroy(L.ctx);
    fw_stepper_destroy(L.st);
    fw_records_close(L.rec);
    return st;
}
