/* report_causation.c - report.md's causation section: the own ship's
 * collision candidates and how many became collisions (the measured
 * causation factor, with Clopper-Pearson intervals) beside IWRAP's. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "study/report_data.h"

/* "k/n = p [lo, hi]" of collisions among candidates, Clopper-Pearson. */
static const char *cf_cell(char *out, size_t sz, const long long *c, double level)
{
    if (c[FW_CAND_N] == 0)
        return snprintf(out, sz, "0 candidates"), out;
    fw_estimate e = fw_clopper_pearson((int)c[FW_CAND_COLLISION], (int)c[FW_CAND_N], level);
    char m[32], lo[32], hi[32];
    snprintf(out, sz, "%lld/%lld = %s [%s, %s]", c[FW_CAND_COLLISION], c[FW_CAND_N],
             fw_rep_fmt(m, e.mean), fw_rep_fmt(lo, e.lo), fw_rep_fmt(hi, e.hi));
    return out;
}

/* The candidates of a set summed over the groups of one behaviour (density
 * too): what a causation factor needs is many candidates. */
static void cf_pool(const fw_study_report *rep, int set, const fw_rep_group *of,
                    long long out[FW_REP_NTYPE][FW_CAND_NSLOT])
{
    memset(out, 0, sizeof(long long) * FW_REP_NTYPE * FW_CAND_NSLOT);
    for (int g = 0; g < rep->n_groups; g++)
        if (strcmp(rep->groups[g].behaviour, of->behaviour) == 0 &&
            rep->groups[g].setting_index == of->setting_index)
            for (int t = 0; t < FW_REP_NTYPE; t++)
                for (int k = 0; k < FW_CAND_NSLOT; k++)
                    out[t][k] += rep->groups[g].cand[set][t][k];
}

static void cf_row(FILE *f, const char *lead, const long long c[FW_REP_NTYPE][FW_CAND_NSLOT],
                   double level)
{
    char b[96];
    fprintf(f, "%s", lead);
    for (int t = 1; t < FW_REP_NTYPE; t++)
        fprintf(f, " %s |", cf_cell(b, sizeof b, c[t], level));
    fprintf(f, " %lld / %lld / %lld | %lld |\n", c[0][FW_CAND_NEAR], c[0][FW_CAND_DOMAIN],
            c[0][FW_CAND_PASSED], c[0][FW_CAND_OTHER_COLL]);
}

/* The first group of its behaviour (and setting of the axes, if any). */
static bool first_of_behaviour(const fw_study_report *rep, int g)
{
    for (int h = 0; h < g; h++)
        if (strcmp(rep->groups[h].behaviour, rep->groups[g].behaviour) == 0 &&
            rep->groups[h].setting_index == rep->groups[g].setting_index)
            return false;
    return true;
}

/* The one paragraph on what the measured factors mean beside IWRAP's, with
 * the pooled numbers of each set and behaviour. */
static void md_causation_note(FILE *f, const fw_study_report *rep)
{
    char lo[32], hi[32];
    long long pool[FW_REP_NTYPE][FW_CAND_NSLOT];
    fprintf(f, "\nWhat the difference from IWRAP means. Measured over all domain sizes "
               "(head-on, overtaking, crossing):");
    for (int set = 0; set < FW_REP_NSET; set++)
        for (int g = 0; g < rep->n_groups; g++)
            if (first_of_behaviour(rep, g)) {
                cf_pool(rep, set, &rep->groups[g], pool);
                fprintf(f, " %s with %s traffic",
                        set == FW_REP_OWN ? "the own ship" : "background pairs",
                        beh(&rep->groups[g]));
                for (int t = 1; t < FW_REP_NTYPE; t++) {
                    long long n = pool[t][FW_CAND_N], k = pool[t][FW_CAND_COLLISION];
                    fw_estimate e = fw_clopper_pearson((int)k, (int)n, rep->level);
                    if (n == 0)
                        fprintf(f, "%s no candidates", t > 1 ? "," : "");
                    else
                        fprintf(f, "%s %lld/%lld [%s, %s]", t > 1 ? "," : "", k, n,
                                fw_rep_fmt(lo, e.lo), fw_rep_fmt(hi, e.hi));
                }
                fprintf(f, ";");
            }
    double need = -log(0.5 * (1.0 - rep->level)) / fw_iwrap_causation[1];
    fprintf(f, " IWRAP's defaults (4.9e-05 to 1.3e-04) are observed rates of real ships with "
               "human watchkeepers and every kind of failure (Fujii's Japanese straits, "
               "Pedersen's crossings); the measured factor is P(collision | candidate) of this "
               "avoidance policy and this traffic model, with the sensing, watchkeeping and sea "
               "its scenario gives them (exact sensing, no lapse and calm water unless it sets "
               "them), so it answers whether the closed loop resolves the candidates it meets, not "
               "how often real ships collide. With no collision among n candidates the upper "
               "end is about 3.7 / n: an interval that could confirm a factor as small as "
               "IWRAP's needs some %.0f candidates, far more than a study of this size meets, "
               "so an own-ship factor of 0 here says only \"below its upper end\". Blind "
               "background ships do not look out at crossings, so their crossing factor should "
               "be near 1 (below it where a speed changed after the first detection): a check "
               "of the candidate definition rather than a finding; in a lane SUMO's "
               "car-following keeps a ship off the one ahead, so overtaking candidates do not "
               "collide even blind. Background ships that give way "
               "by COLREGs and still collide in a share of their candidates orders of "
               "magnitude above IWRAP's show where the traffic model's reactions fail, "
               "not a property of real ships.\n\n",
            need);
}

/* The measured causation factor beside IWRAP's, and what the difference means. */
void fw_rep_md_causation(FILE *f, const fw_study_report *rep)
{
    if (!rep->candidates)
        return;
    char b[FW_REP_SETTING + 160], x[32], y[32], z[32];
    fprintf(f, "## Measured causation factor\n\n"
               "A geometric collision candidate is an encounter whose two straight tracks from "
               "its first detection (own ship: first seen within the avoidance radius; traffic "
               "pair: the survey's first detection) would bring the hulls into contact: the per "
               "encounter form of Pedersen's (1995) and IWRAP's N_G, the collisions if no "
               "aversive manoeuvre were made. The causation factor is collisions among the "
               "candidates / candidates, with its exact (Clopper-Pearson) %.0f%% interval. "
               "IWRAP Mk II defaults: head-on %s, overtaking %s (Fujii et al. 1974), crossing %s "
               "(Pedersen 1995). Own ship: its encounters, by the situation at first detection; "
               "traffic: pairs of background ships (the own ship's pairs are the own set). The "
               "other candidates ended as near miss (hull to hull below near_miss_m) / domain "
               "entered / passed; collisions of non-candidates are counted apart: their tracks "
               "from first detection missed, and a later alteration, speed change or lane "
               "change (or the own ship's manoeuvre) brought them together.\n\n",
            100 * rep->level, fw_rep_fmt(x, fw_iwrap_causation[1]),
            fw_rep_fmt(y, fw_iwrap_causation[2]), fw_rep_fmt(z, fw_iwrap_causation[3]));
    fprintf(f, "| set | density | %s | domain (m) | head-on | overtaking | crossing | "
               "near miss / domain / passed | non-candidate collisions |\n"
               "|---|---|---|---|---|---|---|---|---|\n", fw_rep_traffic_head(rep));
    for (int set = 0; set < FW_REP_NSET; set++)
        for (int g = 0; g < rep->n_groups; g++) {
            const fw_rep_group *G = &rep->groups[g];
            snprintf(b, sizeof b, "| %s | %g | %s | %s |", fw_rep_set_names[set], G->density,
                     beh(G), DOM(G));
            cf_row(f, b, (const long long(*)[FW_CAND_NSLOT])G->cand[set], rep->level);
        }
    /* pooled over the domain sizes (and densities) of each behaviour */
    long long pool[FW_REP_NTYPE][FW_CAND_NSLOT];
    for (int set = 0; set < FW_REP_NSET; set++)
        for (int g = 0; g < rep->n_groups; g++)
            if (first_of_behaviour(rep, g)) {
                cf_pool(rep, set, &rep->groups[g], pool);
                snprintf(b, sizeof b, "| %s | all | %s | all |", fw_rep_set_names[set],
                         beh(&rep->groups[g]));
                cf_row(f, b, (const long long(*)[FW_CAND_NSLOT])pool, rep->level);
            }
    md_causation_note(f, rep);
}
