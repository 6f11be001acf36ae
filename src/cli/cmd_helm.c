/* fairway helm: one avoidance decision for an own ship and its targets. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "avoid/policy.h"
#include "cli/args.h"
#include "cli/commands.h"
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
        "speeds in knots, target length/breadth in metres (default 0: a point).\n"
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
    if (v[3] < 0.0)
        return fw_fail(err, FW_EINPUT, "%s: speed %g kn is negative", opt, v[3]);
    if (v[3] > 60.0)
        return fw_fail(err, FW_EINPUT, "%s: speed %g kn is above 60 kn", opt, v[3]);
    if (n == 6 && (v[4] < 0.0 || v[5] < 0.0))
        return fw_fail(err, FW_EINPUT, "%s: length and breadth must not be negative", opt);
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
    printf("\"%s\": ", key);
    if (isfinite(v))
        printf(fmt, v);
    else
        printf("null");
    printf(comma ? ", " : "");
}

int fw_cmd_helm(int argc, char **argv)
{
    fw_error err = {0};
    const char *ship_name = NULL, *own_text = NULL, *val;
    bool json = false;
    fw_helm_def hdef = fw_default_helm_def();
    fw_target *tg = calloc(MAX_TARGETS, sizeof *tg);
    int n = 0;
    double own_v[6];
    fw_args a = {argc, argv, 0};
    int rc = 2;
    if (!tg)
        return 1;
    while (a.i < argc) {
        if (fw_is_help(argv[a.i])) {
            help();
            free(tg);
            return 0;
        }
        if (fw_args_flag(&a, "--json")) {
            json = true;
        } else if (fw_args_opt(&a, "--ship", &ship_name, &err)) {
            if (err.status || !ship_name)
                goto fail;
        } else if (fw_args_opt(&a, "--own", &own_text, &err)) {
            if (err.status || parse_ship_state("--own", own_text, false, own_v, &err))
                goto fail;
        } else if (fw_args_opt(&a, "--target", &val, &err)) {
            double v[6];
            if (err.status || parse_ship_state("--target", val, true, v, &err))
                goto fail;
            if (n >= MAX_TARGETS) {
                fw_fail(&err, FW_EINPUT, "--target: at most %d targets", MAX_TARGETS);
                goto fail;
            }
            tg[n] = (fw_target){.east = v[0], .north = v[1], .course = fw_deg_to_rad(v[2]),
                                .speed = fw_kn_to_ms(v[3]), .length = v[4], .breadth = v[5]};
            snprintf(tg[n].id, sizeof tg[n].id, "%d", n + 1); /* numbered as given */
            n++;
        } else if (fw_args_opt(&a, "--domain", &val, &err)) {
            if (err.status || fw_parse_double("--domain", val, &hdef.domain.size, &err))
                goto fail;
            if (!(hdef.domain.size > 0.0)) {
                fw_fail(&err, FW_EINPUT, "--domain: must be positive");
                goto fail;
            }
        } else if (fw_args_opt(&a, "--fore-aft-ratio", &val, &err)) {
            if (err.status ||
                fw_parse_double("--fore-aft-ratio", val, &hdef.domain.fore_aft_ratio, &err))
                goto fail;
            if (!(hdef.domain.fore_aft_ratio > 0.0)) {
                fw_fail(&err, FW_EINPUT, "--fore-aft-ratio: must be positive");
                goto fail;
            }
        } else {
            fw_fail(&err, FW_EINPUT, "helm: unknown option '%s' (see fairway helm --help)",
                    argv[a.i]);
            goto fail;
        }
    }
    if (!ship_name) {
        fw_fail(&err, FW_EINPUT, "helm: --ship is required");
        goto fail;
    }
    if (!own_text) {
        fw_fail(&err, FW_EINPUT, "helm: --own is required");
        goto fail;
    }
    fw_ship ship;
    if (fw_ship_load(ship_name, &ship, &err))
        goto fail;
    fw_own_state own = {.east = own_v[0], .north = own_v[1], .psi = fw_deg_to_rad(own_v[2]),
                        .U = fw_kn_to_ms(own_v[3])};
    fw_helm_ctx *ctx;
    if (fw_helm_ctx_create(&ship, &hdef, &ctx, &err))
        goto fail;
    fw_assessment *as = calloc((size_t)n + 1, sizeof *as);
    int *order = calloc(2 * (size_t)n + 2, sizeof *order);
    fw_policy pol;
    fw_policy_def pdef = fw_default_policy_def();
    fw_policy_init(&pol, &pdef);
    fw_decision d;
    fw_policy_input in = {.ctx = ctx, .helm = &hdef, .t = 0.0, .own = &own, .targets = tg,
                          .n = n, .as = as, .order = order};
    fw_status st = !as || !order ? fw_fail(&err, FW_ERUN, "out of memory")
                                 : fw_policy_step(&pol, &in, &d, &err);
    if (st) {
        rc = fw_report(&err);
    } else {
        rc = 0;
        const fw_track *tr;
        fw_helm_begin(ctx, &own); /* the policy's lookahead used the spare track only */
        fw_helm_keep_track(ctx, &tr, &err);
        if (d.search.side != FW_SIDE_NONE) {
            int i = (int)lround((fabs(fw_rad_to_deg(d.search.helm)) - hdef.min_helm_deg) /
                                hdef.step_deg);
            fw_helm_track(ctx, d.search.side, i, &tr, &err);
        }
        const fw_helm_result *r = &d.search;
        const char *decision = d.mode == FW_MODE_AVOID ? "turn" : "keep course";
        if (json) {
            printf("{\"ship\": \"%s\", ", ship.name);
            json_num("domain_m", hdef.domain.size, "%.1f", true);
            json_num("fore_aft_ratio", hdef.domain.fore_aft_ratio, "%.3f", true);
            printf("\"targets\": [");
            for (int i = 0; i < n; i++) {
                double tmin, dmin = fw_track_min_distance(tr, &tg[i], &tmin);
                printf("%s{\"index\": %d, ", i ? ", " : "", i);
                json_num("range_m", as[i].range, "%.1f", true);
                json_num("bearing_deg", fw_rad_to_deg(as[i].bearing), "%.2f", true);
                json_num("rel_bearing_deg", fw_rad_to_deg(as[i].rel_bearing), "%.2f", true);
                json_num("dcpa_m", as[i].dcpa, "%.1f", true);
                json_num("tcpa_s", as[i].tcpa, "%.1f", true);
                printf("\"situation\": \"%s\", \"enters_domain\": %s, ",
                       fw_situation_name(as[i].situation), as[i].enters_domain ? "true" : "false");
                json_num("t_enter_s", as[i].t_enter, "%.1f", true);
                printf("\"rank\": %d, ", as[i].rank);
                json_num("min_distance_m", dmin, "%.1f", true);
                json_num("t_min_s", tmin, "%.1f", false);
                printf("}");
            }
            printf("], \"threat\": %s, \"feasible\": %s, \"side\": \"%s\", ",
                   r->threat ? "true" : "false", r->feasible ? "true" : "false",
                   fw_side_name(r->side));
            json_num("helm_deg", fw_rad_to_deg(r->helm), "%.0f", true);
            json_num("starboard_helm_deg", fw_rad_to_deg(r->side_helm[0]), "%.0f", true);
            json_num("port_helm_deg", fw_rad_to_deg(r->side_helm[1]), "%.0f", true);
            printf("\"allowed\": \"%s\", ", allowed_name(r->allowed));
            json_num("clearance", r->clearance, "%.3f", true);
            printf("\"act_now\": %s, \"decision\": \"%s\", \"reason\": \"%s\"}\n",
                   d.acted ? "true" : "false", decision, d.reason);
        } else {
            printf("own ship %s at (%.0f, %.0f) m, course %.1f deg, %.2f kn; domain %.0f m "
                   "(fore-aft ratio %.2f)\n",
                   ship.name, own.east, own.north, fw_heading_deg(own.psi), own_v[3],
                   hdef.domain.size, hdef.domain.fore_aft_ratio);
            printf("  #  range m  brg  rel   DCPA m  TCPA s  situation           domain entry  "
                   "rank  min dist m (t s)\n");
            for (int i = 0; i < n; i++) {
                double tmin, dmin = fw_track_min_distance(tr, &tg[i], &tmin);
                char entry[32];
                if (as[i].enters_domain)
                    snprintf(entry, sizeof entry, "at %.0f s", as[i].t_enter);
                else
                    snprintf(entry, sizeof entry, "no");
                printf("%3d %8.0f %4.0f %4.0f %8.0f %7.0f  %-19s %-13s %4d  %8.0f (%.0f)\n", i,
                       as[i].range, fw_rad_to_deg(as[i].bearing), fw_rad_to_deg(as[i].rel_bearing),
                       as[i].dcpa, as[i].tcpa, fw_situation_name(as[i].situation), entry,
                       as[i].rank, dmin, tmin);
            }
            if (!r->threat)
                printf("no target enters the domain: keep course, rudder amidships\n");
            else
                printf("required: %s %.0f deg (allowed: %s)%s; clearance %.2f\n",
                       fw_side_name(r->side), fabs(fw_rad_to_deg(r->helm)), allowed_name(r->allowed),
                       r->feasible ? "" : " - NOT ENOUGH: avoidance by helm is not possible, "
                                          "best available action",
                       r->clearance);
            printf("decision: %s (%s)\n", decision, d.reason);
        }
    }
    free(as);
    free(order);
    fw_helm_ctx_destroy(ctx);
    free(tg);
    return rc;
fail:
    free(tg);
    return fw_report(&err);
}
