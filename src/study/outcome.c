/* outcome.c - a study run's results as flat records and bytes (see outcome.h). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/units.h"
#include "study/outcome.h"

void fw_outcome_failed(fw_outcome *o, int run_id, const char *reason)
{
    memset(o, 0, sizeof *o);
    o->run_id = run_id;
    snprintf(o->status, sizeof o->status, "failed");
    snprintf(o->reason, sizeof o->reason, "%s", reason && reason[0] ? reason : "unknown");
    o->min_dist = NAN;
}

void fw_outcome_free(fw_outcome *o)
{
    free(o->enc);
    free(o->traffic);
    o->enc = NULL;
    o->traffic = NULL;
    o->n_enc = o->n_traffic = 0;
}

double fw_closeness(double min_hull)
{
    if (!(min_hull < FW_CLOSENESS_RANGE)) /* NAN too: no hull within the range */
        return 0.0;
    return 1.0 - fmax(min_hull, 0.0) / FW_CLOSENESS_RANGE;
}

const char *fw_outcome_ended(bool collision, double min_hull, double near_miss, bool domain)
{
    if (collision || min_hull == 0.0)
        return "collision";
    if (min_hull < near_miss)
        return "near miss";
    return domain ? "domain" : "passed";
}

fw_status fw_outcome_from_run(fw_outcome *o, const fw_study *s, int run_id,
                              const fw_run_summary *sum, const fw_encounter *e, int n,
                              const fw_survey_record *sv, int n_sv, fw_error *err)
{
    memset(o, 0, sizeof *o);
    o->run_id = run_id;
    snprintf(o->status, sizeof o->status, "ok");
    o->sim_s = sum->t_end;
    o->wall_s = sum->wall_s;
    o->sumo_s = sum->sumo_s;
    o->n_actions = sum->n_actions;
    o->min_dist = isfinite(sum->min_dist) ? sum->min_dist : NAN;
    o->domain_entered = sum->domain_entered;
    o->collision = sum->collision;
    o->colregs_ok = sum->colregs_ok;
    o->max_helm_deg = fw_rad_to_deg(sum->max_helm);
    o->path_length = sum->path_length;
    o->path_lengthening = sum->path_lengthening;
    o->time_lost = sum->time_lost;
    o->rudder_work_deg_s = fw_rad_to_deg(sum->rudder_work);
    o->helm_orders = sum->helm_orders;
    /* hull to hull, as the outcome of each encounter; the centre distance
     * is the secondary reading */
    o->near_miss = isfinite(sum->min_hull) && sum->min_hull < s->near_miss;
    o->near_miss_centre = isfinite(sum->min_dist) && sum->min_dist < s->near_miss;
    o->closeness = fw_closeness(sum->min_hull);
    o->traffic_ship_s = sum->survey ? sum->traffic_ship_s : NAN;
    snprintf(o->behaviour, sizeof o->behaviour, "%s", fw_behaviour_name(sum->behaviour));
    o->give_way = sum->n_give_way;
    o->give_way_short = sum->n_give_way_short;
    o->monitors = sum->monitors;
    o->min_hull = isfinite(sum->min_hull) ? sum->min_hull : NAN;
    o->traffic = n_sv > 0 ? calloc((size_t)n_sv, sizeof *o->traffic) : NULL;
    if (n_sv > 0 && !o->traffic)
        return fw_fail(err, FW_ERUN, "out of memory");
    o->n_traffic = n_sv;
    for (int i = 0; i < n_sv; i++) {
        fw_outcome_traffic *y = &o->traffic[i];
        snprintf(y->ship_a, sizeof y->ship_a, "%s", sv[i].ship_a);
        snprintf(y->ship_b, sizeof y->ship_b, "%s", sv[i].ship_b);
        snprintf(y->type, sizeof y->type, "%s", fw_survey_type_name(sv[i].type));
        y->own = sv[i].own;
        y->t_first = sv[i].t_first;
        y->range0 = sv[i].range0;
        y->dcpa0 = sv[i].dcpa0;
        y->tcpa0 = sv[i].tcpa0;
        y->min_dist = sv[i].min_dist;
        y->t_min = sv[i].t_min;
        y->min_hull = isfinite(sv[i].min_hull) ? sv[i].min_hull : NAN;
        y->cand_miss = sv[i].cand_miss;
        y->candidate = sv[i].cand_miss == 0.0;
        snprintf(y->outcome, sizeof y->outcome, "%s",
                 fw_outcome_ended(false, sv[i].min_hull, s->near_miss, false));
    }
    o->enc = n > 0 ? calloc((size_t)n, sizeof *o->enc) : NULL;
    if (n > 0 && !o->enc) {
        fw_outcome_free(o);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    for (int i = 0; i < n; i++) {
        const fw_encounter *x = &e[i];
        if (!(x->min_dist < s->encounter_range || x->threat))
            continue;
        fw_outcome_encounter *y = &o->enc[o->n_enc++];
        y->e = *x;
        y->v.near_miss = x->min_hull < s->near_miss; /* false when NAN: never within 1 nm */
        y->v.near_miss_centre = x->min_dist < s->near_miss;
        y->v.closeness = fw_closeness(x->min_hull);
        snprintf(y->v.outcome, sizeof y->v.outcome, "%s",
                 fw_outcome_ended(x->collision, x->min_hull, s->near_miss, x->domain_entered));
    }
    return FW_OK;
}

/* Layout: magic, version, header struct (pointers zeroed), then the two
 * arrays.  Same build on both ends, so the structs' layout is shared. */
static const uint32_t kMagic = 0x66776f31u; /* "fwo1" */

fw_status fw_outcome_pack(const fw_outcome *o, unsigned char **buf, size_t *n, fw_error *err)
{
    size_t ne = (size_t)o->n_enc * sizeof *o->enc, nt = (size_t)o->n_traffic * sizeof *o->traffic;
    size_t total = 2 * sizeof(uint32_t) + sizeof *o + ne + nt;
    unsigned char *b = malloc(total), *p = b;
    if (!b)
        return fw_fail(err, FW_ERUN, "out of memory");
    uint32_t head[2] = {kMagic, (uint32_t)sizeof *o};
    memcpy(p, head, sizeof head);
    p += sizeof head;
    fw_outcome h = *o;
    h.enc = NULL;
    h.traffic = NULL;
    memcpy(p, &h, sizeof h);
    p += sizeof h;
    if (ne)
        memcpy(p, o->enc, ne);
    p += ne;
    if (nt)
        memcpy(p, o->traffic, nt);
    *buf = b;
    *n = total;
    return FW_OK;
}

fw_status fw_outcome_unpack(const unsigned char *buf, size_t n, fw_outcome *o, fw_error *err)
{
    memset(o, 0, sizeof *o);
    uint32_t head[2];
    if (n < sizeof head + sizeof *o)
        return fw_fail(err, FW_ERUN, "worker result truncated (%zu bytes)", n);
    memcpy(head, buf, sizeof head);
    if (head[0] != kMagic || head[1] != sizeof *o)
        return fw_fail(err, FW_ERUN, "worker result from another fairway build");
    memcpy(o, buf + sizeof head, sizeof *o);
    o->enc = NULL;
    o->traffic = NULL;
    o->status[sizeof o->status - 1] = '\0';
    o->reason[sizeof o->reason - 1] = '\0';
    size_t ne = (size_t)o->n_enc * sizeof *o->enc, nt = (size_t)o->n_traffic * sizeof *o->traffic;
    if (o->n_enc < 0 || o->n_traffic < 0 || n != sizeof head + sizeof *o + ne + nt) {
        o->n_enc = o->n_traffic = 0;
        return fw_fail(err, FW_ERUN, "worker result of inconsistent size (%zu bytes)", n);
    }
    const unsigned char *p = buf + sizeof head + sizeof *o;
    if (ne && !(o->enc = malloc(ne)))
        return fw_fail(err, FW_ERUN, "out of memory");
    if (ne)
        memcpy(o->enc, p, ne);
    if (nt && !(o->traffic = malloc(nt))) {
        fw_outcome_free(o);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    if (nt)
        memcpy(o->traffic, p + ne, nt);
    return FW_OK;
}
