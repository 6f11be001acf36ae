/* reactions_sense.c - what a reacting background ship knows of the others
 * (reactions.h, "Sensing"): the AIS reports every ship sends, heard by all;
 * by eye a ship in sight without a report; by its own radar's tracks a ship
 * out of sight without one. */
#include <math.h>
#include <string.h>

#include "core/mem.h"
#include "world/reactions_internal.h"

bool fw_react_sensing(const fw_reactions *r)
{
    return r->def.sensing.mode != FW_SENSE_PERFECT;
}

static bool has_ais(const fw_reactions *r)
{
    fw_sensing_mode m = r->def.sensing.mode;
    return m == FW_SENSE_AIS || m == FW_SENSE_AIS_RADAR;
}

static bool has_radar(const fw_reactions *r)
{
    fw_sensing_mode m = r->def.sensing.mode;
    return m == FW_SENSE_RADAR || m == FW_SENSE_AIS_RADAR;
}

fw_status fw_react_sense_reserve(fw_reactions *r, int m, fw_error *err)
{
    if (m <= r->sense_cap)
        return FW_OK;
    if (!fw_resize_each((size_t)m, 8, (void **)&r->truth, sizeof *r->truth, (void **)&r->how,
                        sizeof *r->how, (void **)&r->undo_j, sizeof *r->undo_j,
                        (void **)&r->undo_t, sizeof *r->undo_t, (void **)&r->undo_how,
                        sizeof *r->undo_how, (void **)&r->radar_in, sizeof *r->radar_in,
                        (void **)&r->radar_truth, sizeof *r->radar_truth,
                        (void **)&r->radar_known, sizeof *r->radar_known))
        return fw_fail(err, FW_ERUN, "out of memory for what %d ships know", m);
    r->sense_cap = m;
    return FW_OK;
}

/* Ship i's AIS transmitter (its state st): its streams on first use. */
static fw_status ais_streams(fw_reactions *r, react_state *st, const fw_target *a, fw_error *err)
{
    if (st->ais.noise)
        return FW_OK;
    uint32_t key = fw_rng_vessel_key(a->id);
    if (!r->rng || !(st->ais.noise = r->rng(r->rng_ctx, key, FW_PURPOSE_AIS_TX)) ||
        !(st->ais.loss = r->rng(r->rng_ctx, key, FW_PURPOSE_AIS_TX_LOSS)))
        return fw_fail(err, FW_ERUN, "the reacting traffic's AIS needs the world's streams");
    return FW_OK;
}

fw_status fw_react_sense_step(fw_reactions *r, double t, fw_target *all, const int *idx, int m,
                              fw_error *err)
{
    memcpy(r->truth, all, sizeof *all * (size_t)m);
    for (int i = 0; i < m; i++) {
        r->how[i] = FW_KNOWN_NOT;
        if (!has_ais(r))
            continue;
        react_state *st = &r->s[idx[i]];
        fw_status s2 = ais_streams(r, st, &r->truth[i], err);
        if (s2)
            return s2;
        fw_ais_tx_step(&r->def.sensing, &st->ais, &r->truth[i], t, &r->ais_counts);
        if (fw_ais_tx_known(&r->def.sensing, &st->ais, &r->truth[i], t, &all[i]))
            r->how[i] = FW_KNOWN_AIS;
    }
    return FW_OK;
}

/* Entry j of the list becomes *k (known as how) for the look under way. */
static void put(fw_reactions *r, int j, const fw_target *k, fw_known how)
{
    fw_target *all = (fw_target *)r->all;
    r->undo_j[r->n_undo] = j;
    r->undo_t[r->n_undo] = all[j];
    r->undo_how[r->n_undo++] = r->how[j];
    all[j] = *k;
    r->how[j] = how;
    r->sn[j] = sin(k->course);
    r->cs[j] = cos(k->course);
}

/* Ship self's radar (made on first use): its tracks of the ships out of
 * sight and without a report, radar_in[0..k-1] (list indices), put in. */
static fw_status radar_look(fw_reactions *r, double t, int self, react_state *st, int k,
                            fw_error *err)
{
    if (!st->radar) {
        fw_sensing_def d = r->def.sensing;
        d.mode = FW_SENSE_RADAR;
        fw_status s2 = fw_sensor_create(&d, r->rng, r->rng_ctx, &st->radar, err);
        if (s2)
            return s2;
        fw_sensor_set_salt(st->radar, fw_rng_vessel_key(r->truth[self].id));
    }
    int nk = 0;
    for (int q = 0; q < k; q++)
        r->radar_truth[q] = r->truth[r->radar_in[q]];
    fw_sensor_place(st->radar, &r->truth[self]);
    /* what it knows comes in its input's order, the ships without a track left out */
    fw_status s2 = fw_sensor_update(st->radar, t, r->radar_truth, k, r->radar_known, &nk, err);
    for (int q = 0, p = 0; !s2 && q < k && p < nk; q++)
        if (strcmp(r->radar_known[p].id, r->radar_truth[q].id) == 0)
            put(r, r->radar_in[q], &r->radar_known[p++], FW_KNOWN_RADAR);
    return s2;
}

fw_status fw_react_sense_begin(fw_reactions *r, double t, int self, int m, react_state *st,
                               fw_error *err)
{
    r->n_undo = 0;
    const fw_target *me = &r->truth[self];
    /* it knows itself */
    put(r, self, me, FW_KNOWN_TRUTH);
    double range2 = r->def.range * r->def.range;
    int k = 0;
    for (int j = 0; j < m; j++) {
        if (j == self || r->how[j] != FW_KNOWN_NOT)
            continue;
        const fw_target *o = &r->truth[j];
        double de = o->east - me->east, dn = o->north - me->north, d2 = de * de + dn * dn;
        if (d2 > range2)
            continue;
        if (!fw_not_in_sight(&r->def.colregs, sqrt(d2)))
            put(r, j, o, FW_KNOWN_EYE); /* in sight: seen */
        else if (has_radar(r))
            r->radar_in[k++] = j;
    }
    return k > 0 && has_radar(r) ? radar_look(r, t, self, st, k, err) : FW_OK;
}

void fw_react_sense_end(fw_reactions *r)
{
    fw_target *all = (fw_target *)r->all;
    for (int u = r->n_undo - 1; u >= 0; u--) {
        int j = r->undo_j[u];
        all[j] = r->undo_t[u];
        r->how[j] = r->undo_how[u];
        r->sn[j] = sin(all[j].course);
        r->cs[j] = cos(all[j].course);
    }
    r->n_undo = 0;
}

void fw_react_sense_note(const fw_reactions *r, int j, fw_reaction *x)
{
    if (!r->truth || j < 0)
        return;
    x->known_how = r->how[j];
    x->known_e = r->all[j].east, x->known_n = r->all[j].north;
    x->true_e = r->truth[j].east, x->true_n = r->truth[j].north;
}

bool fw_reactions_known(const fw_reactions *r, const fw_target *self, const fw_target *o,
                        double t, fw_target *out)
{
    *out = *o;
    if (!r || !fw_react_sensing(r))
        return true;
    int k = has_ais(r) ? fw_idmap_find_keyed(&r->ids, o->key, o->id) : -1;
    if (k >= 0 && k < r->cap && fw_ais_tx_known(&r->def.sensing, &r->s[k].ais, o, t, out))
        return true;
    *out = *o; /* in sight: seen */
    return !fw_not_in_sight(&r->def.colregs, hypot(o->east - self->east, o->north - self->north));
}

void fw_react_sense_free(fw_reactions *r)
{
    for (int i = 0; i < r->cap; i++)
        fw_sensor_destroy(r->s[i].radar);
    fw_free_each(8, r->truth, r->how, r->undo_j, r->undo_t, r->undo_how, r->radar_in,
                 r->radar_truth, r->radar_known);
}
