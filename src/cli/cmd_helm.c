/* fairway helm: one avoidance decision for an own ship and its targets. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "avoid/policy.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "core/json.h"
#include "core/units.h"
#include "ship/ship.h"

enum { MAX_TARGETS = 1000 };

static void help(void)
{
    printf(
        "usage: fairway helm --ship NAME --own E,N,COURSE,SPEED\n"
        "                    --target E,N,COURSE,SPEED[,LENGTH,BREADTH] ...\n"
        "                    [--domain M] [--fore-aft-ratio R] [--json]\n"
        "\n"
        "One collision-avoidance decision (the paper's helm search): assesses each\n"
        "target (range, bearing, DCPA/TCPA, COLREGs situation, domain entry if both\n"
        "keep course), searches the least helm from 10 to 35 deg on the side COLREGs\n"
        "permits whose Nomoto-predicted track keeps every target outside the domain,\n"
        "and says whether the action policy would act now.\n"
        "Positions in metres east/north, courses in degrees (0 = north, clockwise),\n"
        "speeds in knots (0 to 40), target length/breadth in metres (default 0: a\n"
        "point); positions within 10000 km, no target on the own ship's position.\n"
        "--domain: transverse semi-axis of the elliptic domain (default 300 m);\n"
        "--fore-aft-ratio: fore-aft semi-axis / transverse (default 1).\n"
        "\n"
        "--json prints one object:\n"
        "  ship, domain_m, fore_aft_ratio\n"
        "  targets[]: index, range_m, bearing_deg (true), rel_bearing_deg, dcpa_m,\n"
        "    tcpa_s, situation (head-on|overtaking|being overtaken|crossing give-way|\n"
        "    crossing stand-on), enters_domain, t_enter_s (null if never), rank\n"
        "    (0 = most dangerous), min_distance_m and t_min_s (on the chosen track)\n"
        "  threat: keeping course lets a target into the domain\n"
        "  feasible: some helm up to the maximum keeps all targets out\n"
        "  side (\"starboard\"|\"port\"|\"none\"), helm_deg (signed, + starboard):\n"
        "    the least clearing helm, or the best available if not feasible\n"
        "  starboard_helm_deg, port_helm_deg: least clearing helm per side searched (null if none)\n"
        "  allowed: sides COLREGs permit (\"starboard\"|\"port\"|\"either\")\n"
        "  clearance: smallest normalised domain radius on the chosen track (>= 1 outside)\n"
        "  act_now, decision (\"keep course\"|\"turn\"), reason\n"
        "Exit codes: 0 ok, 1 the prediction failed, 2 bad input.\n");
}

/* Positions beyond this (m) are typing slips, and would print as 300 digits. */
#define MAX_POSITION_M 1e7

static fw_status parse_ship_state(const char *opt, const char *text, bool target, double v[6],
                                  fw_error *err)
{
    int n;
    fw_status st = fw_parse_list(opt, text, v, 6, &n, err);
    if (st)
        return st;
    if (!(n == 4 || (target && n == 6)))
        return fw_fail(err, FW_EINPUT, "%s: expected E,N,COURSE,SPEED%s, got '%s'", opt,
                       target ? "[,LENGTH,BREADTH]" : "", text);
    if (fabs(v[0]) > MAX_POSITION_M || fabs(v[1]) > MAX_POSITION_M)
        return fw_fail(err, FW_EINPUT, "%s: position (%.15g, %.15g) m is beyond %.15g km", opt, v[0], v[1],
                       MAX_POSITION_M / 1000);
    if (v[3] < 0.0)
        return fw_fail(err, FW_EINPUT, "%s: speed %.15g kn is negative", opt, v[3]);
    if (v[3] > FW_SPEED_MAX_KN)
        return fw_fail(err, FW_EINPUT, "%s: speed %.15g kn is above %.15g kn", opt, v[3],
                       FW_SPEED_MAX_KN);
    if (n == 6 && (v[4] < 0.0 || v[5] < 0.0 || v[4] > 1000.0 || v[5] > 1000.0))
        return fw_fail(err, FW_EINPUT, "%s: length and breadth must be 0 to 1000 m", opt);
    if (n == 4)
        v[4] = v[5] = 0.0;
    return FW_OK;
}

static const char *allowed_name(int a)
{
    return a == FW_ALLOW_EITHER ? "either" : a == FW_ALLOW_PORT ? "port" : "starboard";
}

static void json_num(const char *key, double v, const char *fmt, bool comma)
{
    fw_json_string(stdout, key);
    printf(": ");
    fw_json_number(stdout, v, fmt);
    printf(comma ? ", " : "");
}

static void json_str(const char *key, const char *v, bool comma)
{
    fw_json_string(stdout, key);
    printf(": ");
    fw_json_string(stdout, v);
    printf(comma ? ", " : "");
}

typedef struct helm_in {
    const char *ship_name, *own_text;
    bool json;
    fw_helm_def hdef;
    fw_target *tg;
    int n;
    double own_v[6];
} helm_in;

static fw_status opt_positive(void *ctx, const char *opt, const char *val, fw_error *err)
{
    double *out = ctx;
    if (fw_parse_double(opt, val, out, err))
        return err->status;
    if (!(*out > 0.0))
        return fw_fail(err, FW_EINPUT, "%s: must be positive", opt);
    return FW_OK;
}

static fw_status opt_own(void *ctx, const char *opt, const char *val, fw_error *err)
{
    helm_in *in = ctx;
    in->own_text = val;
    return parse_ship_state(opt, val, false, in->own_v, err);
}

static fw_status opt_target(void *ctx, const char *opt, const char *val, fw_error *err)
{
    helm_in *in = ctx;
    double v[6];
    if (parse_ship_state(opt, val, true, v, err))
        return err->status;
    if (in->n >= MAX_TARGETS)
        return fw_fail(err, FW_EINPUT, "--target: at most %d targets", MAX_TARGETS);
    fw_target *t = &in->tg[in->n];
    *t = fw_target_undrifted((fw_target){.east = v[0], .north = v[1],
                                         .course = fw_deg_to_rad(v[2]),
                                         .speed = fw_kn_to_ms(v[3]), .length = v[4],
                                         .breadth = v[5]});
    snprintf(t->id, sizeof t->id, "%d", in->n + 1); /* numbered as given */
    in->n++;
    return FW_OK;
}

/* Returns -1 to go on, else the exit code. */
static int parse_options(int argc, char **argv, helm_in *in, fw_error *err)
{
    const fw_opt opts[] = {
        FW_OPT("--json", FW_OPT_FLAG, &in->json), FW_OPT("--ship", FW_OPT_TEXT, &in->ship_name),
        FW_OPT_FN("--own", opt_own, in),          FW_OPT_FN("--target", opt_target, in),
        FW_OPT_FN("--domain", opt_positive, &in->hdef.domain.size),
        FW_OPT_FN("--fore-aft-ratio", opt_positive, &in->hdef.domain.fore_aft_ratio),
        FW_OPT_END,
    };
    int rc = fw_args_parse(argc, argv, "helm", opts, help, NULL, NULL, err);
    if (rc >= 0)
        return rc;
    if (!in->ship_name)
        return fw_report((fw_fail(err, FW_EINPUT, "helm: --ship is required"), err));
    if (!in->own_text)
        return fw_report((fw_fail(err, FW_EINPUT, "helm: --own is required"), err));
    for (int i = 0; i < in->n; i++)
        if (hypot(in->tg[i].east - in->own_v[0], in->tg[i].north - in->own_v[1]) < 1.0)
            return fw_report((fw_fail(err, FW_EINPUT,
                                      "--target %d: at the own ship's position (%.15g, %.15g) m: a "
                                      "target must be apart from the own ship",
                                      i + 1, in->own_v[0], in->own_v[1]), err));
    return -1;
}

typedef struct helm_out {
    const fw_ship *ship;
    const helm_in *in;
    const fw_own_state *own;
    const fw_assessment *as;
    const fw_decision *d;
    const fw_track *tr;
} helm_out;

static void print_json(const helm_out *o)
{
    const fw_helm_def *hdef = &o->in->hdef;
    const fw_helm_result *r = &o->d->search;
    printf("{");
    json_str("ship", o->ship->name, true);
    json_num("domain_m", hdef->domain.size, "%.1f", true);
    json_num("fore_aft_ratio", hdef->domain.fore_aft_ratio, "%.3f", true);
    printf("\"targets\": [");
    for (int i = 0; i < o->in->n; i++) {
        const fw_assessment *as = &o->as[i];
        double tmin, dmin = fw_track_min_distance(o->tr, &o->in->tg[i], &tmin);
        printf("%s{\"index\": %d, ", i ? ", " : "", i);
        json_num("range_m", as->range, "%.1f", true);
        json_num("bearing_deg", fw_rad_to_deg(as->bearing), "%.2f", true);
        json_num("rel_bearing_deg", fw_rad_to_deg(as->rel_bearing), "%.2f", true);
        json_num("dcpa_m", as->dcpa, "%.1f", true);
        json_num("tcpa_s", as->tcpa, "%.1f", true);
        json_str("situation", fw_situation_name(as->situation), true);
        printf("\"enters_domain\": %s, ", as->enters_domain ? "true" : "false");
        json_num("t_enter_s", as->t_enter, "%.1f", true);
        printf("\"rank\": %d, ", as->rank);
        json_num("min_distance_m", dmin, "%.1f", true);
        json_num("t_min_s", tmin, "%.1f", false);
        printf("}");
    }
    printf("], \"threat\": %s, \"feasible\": %s, ", r->threat ? "true" : "false",
           r->feasible ? "true" : "false");
    json_str("side", fw_side_name(r->side), true);
    json_num("helm_deg", fw_rad_to_deg(r->helm), "%.0f", true);
    json_num("starboard_helm_deg", fw_rad_to_deg(r->side_helm[0]), "%.0f", true);
    json_num("port_helm_deg", fw_rad_to_deg(r->side_helm[1]), "%.0f", true);
    json_str("allowed", allowed_name(r->allowed), true);
    json_num("clearance", r->clearance, "%.3f", true);
    printf("\"act_now\": %s, ", o->d->acted ? "true" : "false");
    json_str("decision", o->d->mode == FW_MODE_AVOID ? "turn" : "keep course", true);
    json_str("reason", o->d->reason, false);
    printf("}\n");
}

static void print_table(const helm_out *o)
{
    const fw_helm_def *hdef = &o->in->hdef;
    const fw_helm_result *r = &o->d->search;
    printf("own ship %s at (%.0f, %.0f) m, course %.1f deg, %.2f kn; domain %.0f m "
           "(fore-aft ratio %.2f)\n",
           o->ship->name, o->own->east, o->own->north, fw_heading_deg(o->own->psi),
           o->in->own_v[3], hdef->domain.size, hdef->domain.fore_aft_ratio);
    printf("  #  range m  brg  rel   DCPA m  TCPA s  situation           domain entry  "
           "rank  min dist m (t s)\n");
    for (int i = 0; i < o->in->n; i++) {
        const fw_assessment *as = &o->as[i];
        double tmin, dmin = fw_track_min_distance(o->tr, &o->in->tg[i], &tmin);
        char entry[32];
        if (as->enters_domain)
            snprintf(entry, sizeof entry, "at %.0f s", as->t_enter);
        else
            snprintf(entry, sizeof entry, "no");
        printf("%3d %8.0f %4.0f %4.0f %8.0f %7.0f  %-19s %-13s %4d  %8.0f (%.0f)\n", i,
               as->range, fw_rad_to_deg(as->bearing), fw_rad_to_deg(as->rel_bearing), as->dcpa,
               as->tcpa, fw_situation_name(as->situation), entry, as->rank, dmin, tmin);
    }
    if (!r->threat)
        printf("no target enters the domain: keep course, rudder amidships\n");
    else
        printf("required: %s %.0f deg (allowed: %s)%s; clearance %.2f\n", fw_side_name(r->side),
               fabs(fw_rad_to_deg(r->helm)), allowed_name(r->allowed),
               r->feasible ? "" : " - NOT ENOUGH: avoidance by helm is not possible, "
                                  "best available action",
               r->clearance);
    printf("decision: %s (%s)\n", o->d->mode == FW_MODE_AVOID ? "turn" : "keep course",
           o->d->reason);
}

/* The decision, and the track it chose (for each target's closest approach). */
static fw_status decide(const fw_ship *ship, helm_in *in, const fw_own_state *own,
                        fw_helm_ctx *ctx, fw_assessment *as, int *order, fw_error *err)
{
    fw_policy pol;
    fw_policy_def pdef = fw_default_policy_def();
    fw_policy_init(&pol, &pdef);
    fw_decision d;
    fw_policy_input pi = {.ctx = ctx, .helm = &in->hdef, .t = 0.0, .own = own, .targets = in->tg,
                          .n = in->n, .as = as, .order = order};
    fw_status st = fw_policy_step(&pol, &pi, &d, err);
    if (st)
        return st;
    const fw_track *tr;
    fw_helm_begin(ctx, own); /* the policy's lookahead used the spare track only */
    fw_helm_keep_track(ctx, &tr, err);
    if (d.search.side != FW_SIDE_NONE) {
        int i = (int)lround((fabs(fw_rad_to_deg(d.search.helm)) - in->hdef.min_helm_deg) /
                            in->hdef.step_deg);
        fw_helm_track(ctx, d.search.side, i, &tr, err);
    }
    helm_out o = {ship, in, own, as, &d, tr};
    if (in->json)
        print_json(&o);
    else
        print_table(&o);
    return FW_OK;
}

int fw_cmd_helm(int argc, char **argv)
{
    fw_error err = {0};
    helm_in in = {.hdef = fw_default_helm_def()};
    if (!(in.tg = calloc(MAX_TARGETS, sizeof *in.tg)))
        return 1;
    int rc = parse_options(argc, argv, &in, &err);
    fw_ship ship;
    if (rc < 0 && fw_ship_load(in.ship_name, &ship, &err))
        rc = fw_report(&err);
    if (rc >= 0) {
        free(in.tg);
        return rc;
    }
    fw_warn_nomoto_speed(&ship, in.own_v[3], NULL, "--own speed");
    fw_own_state own = {.east = in.own_v[0], .north = in.own_v[1],
                        .psi = fw_deg_to_rad(in.own_v[2]), .U = fw_kn_to_ms(in.own_v[3])};
    fw_helm_ctx *ctx = NULL;
    fw_assessment *as = calloc((size_t)in.n + 1, sizeof *as);
    int *order = calloc(2 * (size_t)in.n + 2, sizeof *order);
    fw_status st = !as || !order ? fw_fail(&err, FW_ERUN, "out of memory")
                                 : fw_helm_ctx_create(&ship, &in.hdef, &ctx, &err);
    if (!st)
        st = decide(&ship, &in, &own, ctx, as, order, &err);
    rc = st ? fw_report(&err) : 0;
    free(as);
    free(order);
    fw_helm_ctx_destroy(ctx);
    free(in.tg);
    return rc;
}
