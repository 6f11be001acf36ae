/* book.c - the encounter book: what a run keeps per target and per step
 * (book.h).  Only computing: the files are records.c's. */
#include "run/book.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "avoid/helm_search.h"
#include "core/idmap.h"
#include "core/mem.h"

struct fw_book {
    const fw_scenario *s;
    fw_encounter *e;
    int n, cap;
    /* id -> index into e (core/idmap.h): a heavy-traffic hour meets
     * hundreds of ships and every step looks up each one in range */
    fw_idmap ids;
    /* the own ship's heading and speed at each step with a target in sight:
     * the COLREGs audit reads its manoeuvres from them */
    double *h_t, *h_psi, *h_v;
    int h_n, h_cap;
};

fw_status fw_book_create(const fw_scenario *s, fw_book **out, fw_error *err)
{
    fw_book *b = *out = calloc(1, sizeof *b);
    if (!b)
        return fw_fail(err, FW_ERUN, "out of memory for the encounter book");
    b->s = s;
    return FW_OK;
}

void fw_book_destroy(fw_book *b)
{
    if (!b)
        return;
    free(b->e);
    fw_idmap_free(&b->ids);
    fw_free_each(3, b->h_t, b->h_psi, b->h_v);
    free(b);
}

static fw_status history_push(fw_book *r, double t, const fw_mmg_state *x, fw_error *err)
{
    if (r->h_n > 0 && r->h_t[r->h_n - 1] >= t)
        return FW_OK;
    if (r->h_n == r->h_cap) {
        int cap = fw_grown_cap(r->h_cap, 1024);
        if (!fw_resize_each((size_t)cap, 3, (void **)&r->h_t, sizeof *r->h_t, (void **)&r->h_psi,
                            sizeof *r->h_psi, (void **)&r->h_v, sizeof *r->h_v))
            return fw_fail(err, FW_ERUN, "out of memory for the own ship's history");
        r->h_cap = cap;
    }
    r->h_t[r->h_n] = t;
    r->h_psi[r->h_n] = x->psi;
    r->h_v[r->h_n++] = hypot(x->u, x->vm);
    return FW_OK;
}

/* m: hull-to-hull distances are measured for targets whose hulls could be
 * this close (a near miss is 0.1 nm) */
static const double kHullWatch = 1852.0;

static fw_encounter *find(fw_book *r, const fw_target *ts)
{
    int i = fw_idmap_find_keyed(&r->ids, ts->key, ts->id);
    return i >= 0 ? &r->e[i] : NULL;
}

/* A new entry in the book for a ship first seen now. */
static fw_status add(fw_book *r, double t, const fw_target *ts, const fw_assessment *as,
                     fw_encounter **out, fw_error *err)
{
    if (r->n == r->cap) {
        int cap = fw_grown_cap(r->cap, 16);
        if (!fw_resize((void **)&r->e, sizeof *r->e, (size_t)cap))
            return fw_fail(err, FW_ERUN, "out of memory for the encounter book (%d ships)", r->n);
        r->cap = cap;
    }
    int i;
    if (fw_idmap_intern_keyed(&r->ids, ts->key, ts->id, &i))
        return fw_fail(err, FW_ERUN, "out of memory for the encounter book (%d ships)", r->n);
    /* the map numbers ids as the book adds them: i == r->n */
    fw_encounter *e = &r->e[r->n++];
    memset(e, 0, sizeof *e);
    snprintf(e->id, sizeof e->id, "%s", ts->id);
    snprintf(e->type, sizeof e->type, "%s", ts->type);
    e->length = ts->length;
    e->breadth = ts->breadth;
    e->situation = as->situation;
    e->rule19 = as->rule19;
    e->t_detect = t;
    e->dcpa0 = as->dcpa;
    e->tcpa0 = as->tcpa;
    e->min_dist = INFINITY;
    e->min_lambda = INFINITY;
    e->min_hull = INFINITY;
    e->t_act = NAN;
    fw_audit_obs_init(&e->audit_obs);
    *out = e;
    return FW_OK;
}

/* COLREGs reading of a first action (see fw_book_judge for no action). */
static bool action_ok(fw_situation situation, int side)
{
    /* head-on (rule 14) and give-way crossing (rules 15/16): to starboard;
     * stand-on (rule 17c): never to port for a crossing target on the port
     * side; overtaking and being overtaken: either side */
    if (situation == FW_SIT_HEAD_ON || situation == FW_SIT_GIVE_WAY ||
        situation == FW_SIT_STAND_ON)
        return side == FW_SIDE_STARBOARD;
    return true;
}

/* The own ship's and the target's straight tracks from now: how close their
 * hulls would come without manoeuvres (0: a geometric collision candidate). */
static double candidate_miss(const fw_book *r, const fw_mmg_state *own, const fw_target *ts)
{
    double s = sin(own->psi), c = cos(own->psi);
    fw_hull_track a = {own->east, own->north, own->psi, own->u * s + own->vm * c,
                       own->u * c - own->vm * s, r->s->ship.Loa, r->s->ship.B};
    fw_hull_track b = fw_hull_track_of(ts);
    return fw_hull_cpa(&a, &b, INFINITY, NULL);
}

fw_status fw_book_target(fw_book *r, double t, const fw_target *ts, const fw_mmg_state *own,
                         const fw_assessment *as, fw_error *err)
{
    fw_encounter *e = find(r, ts);
    fw_status st = FW_OK;
    if (!e && !(st = add(r, t, ts, as, &e, err)))
        e->cand_miss = candidate_miss(r, own, ts);
    if (st || (st = history_push(r, t, own, err)))
        return st;
    fw_audit_observe(&e->audit_obs, &r->s->audit, t, as->dcpa, as->tcpa);
    if (as->enters_domain)
        e->threat = true;
    double de = ts->east - own->east, dn = ts->north - own->north;
    double d = hypot(de, dn);
    if (d < e->min_dist) {
        e->min_dist = d;
        e->t_min = t;
    }
    /* where the target actually is against the own domain (the same domain
     * and reading as the assessment, grown by the target's hull) */
    double lam = fw_domain_lambda(&r->s->helm.domain, own->east, own->north, own->psi, ts);
    if (lam < e->min_lambda)
        e->min_lambda = lam;
    if (lam < 1.0)
        e->domain_entered = true;
    /* hull to hull: the hulls can only touch within half the sum of their
     * diagonals, and it is worth measuring only within a near miss of that */
    double reach = 0.5 * (hypot(r->s->ship.Loa, r->s->ship.B) + hypot(ts->length, ts->breadth));
    if (d <= reach + kHullWatch) {
        double h = fw_hull_distance(own->east, own->north, own->psi, r->s->ship.Loa, r->s->ship.B,
                                    ts->east, ts->north, ts->heading, ts->length, ts->breadth);
        if (h < e->min_hull)
            e->min_hull = h;
        if (h == 0.0)
            e->collision = true;
    }
    return FW_OK;
}

void fw_book_action(fw_book *r, double t, int side, double helm, const char *primary_id,
                    const fw_target *tg, const fw_assessment *as, int n)
{
    for (int i = 0; i < n; i++) {
        if (!as[i].enters_domain)
            continue;
        fw_encounter *e = find(r, &tg[i]);
        if (!e || e->acted)
            continue;
        e->acted = true;
        e->t_act = t;
        e->act_side = side;
        e->act_helm = helm;
        e->act_situation = as[i].situation;
        e->act_rule19 = as[i].rule19 ? fw_rule19_sides(&as[i]) : 0;
        e->audit_obs.tcpa_act = as[i].tcpa;
        e->primary = primary_id && strcmp(primary_id, e->id) == 0;
    }
}

fw_encounter *fw_book_entries(fw_book *r, int *n)
{
    *n = r->n;
    return r->e;
}

/* Was the action for e on a side rule 19(d) allows (any, when the ship was in
 * sight by then)? */
static bool rule19_side_ok(const fw_encounter *e)
{
    int bit = e->act_side == FW_SIDE_STARBOARD ? FW_ALLOW_STARBOARD : FW_ALLOW_PORT;
    return !e->act_rule19 || (bit & e->act_rule19);
}

void fw_book_judge(fw_book *r, fw_run_summary *sum)
{
    sum->n_encounters = r->n;
    sum->min_dist = INFINITY;
    sum->min_hull = INFINITY;
    sum->colregs_ok = true;
    for (int i = 0; i < r->n; i++) {
        fw_encounter *e = &r->e[i];
        /* no action: right when no action was needed (the target stayed out of
         * the domain) or when the own ship stood on against it; out of sight
         * (rule 19) there is no standing on, and the sides are 19(d)'s */
        if (e->acted && e->act_rule19)
            e->colregs_ok = rule19_side_ok(e);
        else if (e->acted)
            e->colregs_ok = action_ok(e->act_situation, e->act_side);
        else
            e->colregs_ok = !e->domain_entered ||
                            (!e->rule19 && (e->situation == FW_SIT_STAND_ON ||
                                            e->situation == FW_SIT_OVERTAKEN));
        if (e->min_dist < sum->min_dist) {
            sum->min_dist = e->min_dist;
            snprintf(sum->min_dist_id, sizeof sum->min_dist_id, "%s", e->id);
        }
        sum->min_hull = fmin(sum->min_hull, e->min_hull);
        fw_audit_history h = {r->h_t, r->h_psi, r->h_v, r->h_n};
        if (e->rule19)
            fw_audit_evaluate_rule19(&r->s->audit, &e->audit_obs, e->acted, e->t_act,
                                     rule19_side_ok(e), e->t_min, &h, &e->audit);
        else
            fw_audit_evaluate(&r->s->audit, e->situation, &e->audit_obs, e->acted, e->t_act,
                              e->act_side, e->t_min, &h, &e->audit);
        sum->domain_entered |= e->domain_entered;
        sum->collision |= e->collision;
        sum->colregs_ok &= e->colregs_ok;
    }
}
