/* fairway identify: Nomoto indices and their regression from MMG turning tests. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/args.h"
#include "cli/commands.h"
#include "core/units.h"
#include "nomoto/identify.h"
#include "yaml/yaml_edit.h"

enum { MAXV = 32 };

static void help(void)
{
    printf("usage: fairway identify --ship NAME [--speeds 14.55,20.12,26.7]\n"
           "                        [--rudders 5,10,15,20,25,30,35] [--sides both|starboard|port]\n"
           "                        [--duration 900] [--out FILE]\n"
           "\n"
           "Runs MMG turning tests (straight steady running at each speed in knots, then\n"
           "the helm in degrees, 1 s samples of the yaw rate for --duration seconds), fits\n"
           "Nomoto's K, T1, T2, T3 to each history by Levenberg-Marquardt against the\n"
           "rudder's real ramp at the rudder rate, prints each fit's RMS error relative\n"
           "to the final rate, fits the regression forms of the ship file's knowledge\n"
           "base (default: the paper's equations 10-13) by linear least squares over\n"
           "all points (both sides pooled), compares it with the knowledge base in the\n"
           "ship file, fits the drift angle and speed loss in turns that the track\n"
           "prediction adds to Nomoto's model (drift and speed_loss per unit r' = r L / U,\n"
           "each with a first-order lag, from the same tests), and writes a copy of the\n"
           "ship file with the new nomoto: block\n"
           "(default FILE: NAME-identified.yaml in the current directory).\n");
}

static void write_index(FILE *f, const char *name, const fw_nomoto_index *ix)
{
    fprintf(f, "  %s: {", name);
    for (int k = 0; k < ix->n; k++) {
        const char *b = fw_nomoto_basis_names[ix->basis[k]];
        fprintf(f, "%s%s%s%s: %.9g", k ? ", " : "", strcmp(b, "1") == 0 ? "\"" : "", b,
                strcmp(b, "1") == 0 ? "\"" : "", ix->coef[k]);
    }
    fprintf(f, "}\n");
}

int fw_cmd_identify(int argc, char **argv)
{
    fw_error err = {0};
    const char *ship_name = NULL, *out_path = NULL, *val, *sides = "both";
    double speeds[MAXV] = {14.55, 20.12, 26.7}, rudders[MAXV] = {5, 10, 15, 20, 25, 30, 35};
    int ns = 3, nr = 7;
    double duration = 900.0;
    fw_args a = {argc, argv, 0};
    while (a.i < argc) {
        if (fw_is_help(argv[a.i])) {
            help();
            return 0;
        }
        if (fw_args_opt(&a, "--ship", &ship_name, &err)) {
        } else if (fw_args_opt(&a, "--out", &out_path, &err)) {
        } else if (fw_args_opt(&a, "--sides", &sides, &err)) {
        } else if (fw_args_opt(&a, "--speeds", &val, &err)) {
            if (!err.status)
                fw_parse_list("--speeds", val, speeds, MAXV, &ns, &err);
        } else if (fw_args_opt(&a, "--rudders", &val, &err)) {
            if (!err.status)
                fw_parse_list("--rudders", val, rudders, MAXV, &nr, &err);
        } else if (fw_args_opt(&a, "--duration", &val, &err)) {
            if (!err.status)
                fw_parse_double("--duration", val, &duration, &err);
        } else {
            fw_fail(&err, FW_EINPUT, "identify: unknown option '%s'", argv[a.i]);
        }
        if (err.status)
            return fw_report(&err);
    }
    if (!ship_name)
        return fw_report((fw_fail(&err, FW_EINPUT, "identify: --ship is required"), &err));
    int side_lo = strcmp(sides, "port") == 0 ? 1 : 0, side_hi = strcmp(sides, "starboard") == 0 ? 0 : 1;
    if (strcmp(sides, "both") && strcmp(sides, "port") && strcmp(sides, "starboard"))
        return fw_report((fw_fail(&err, FW_EINPUT, "--sides: both, starboard or port"), &err));
    if (!(duration >= 60.0 && duration <= 7200.0))
        return fw_report((fw_fail(&err, FW_EINPUT, "--duration: 60 to 7200 s"), &err));
    for (int i = 0; i < ns; i++)
        if (!(speeds[i] >= 1.0 && speeds[i] <= 60.0))
            return fw_report((fw_fail(&err, FW_EINPUT, "--speeds: %g kn outside 1-60", speeds[i]), &err));
    fw_ship ship;
    if (fw_ship_load(ship_name, &ship, &err))
        return fw_report(&err);
    for (int j = 0; j < nr; j++)
        if (!(rudders[j] >= 1.0 && fw_deg_to_rad(rudders[j]) <= ship.rudder_max * (1 + 1e-12)))
            return fw_report((fw_fail(&err, FW_EINPUT, "--rudders: %g deg outside 1 to the maximum",
                                      rudders[j]), &err));
    int n = (int)duration + 1, m = 0;
    double *r = malloc(sizeof(double) * (size_t)n);
    int cap = ns * nr * 2;
    double *U = malloc(sizeof(double) * 8 * (size_t)cap), *D = U + cap, *UM = D + 5 * cap, *HM = D + 6 * cap, *V[4] = {D + cap, D + 2 * cap, D + 3 * cap, D + 4 * cap};
    double worst = 0.0;
    printf("# MMG turning tests of %s, %.0f s each; fit of eq 8 to the ramp response\n", ship.name, duration);
    printf("%8s %6s %10s %8s %8s %8s %10s %8s\n", "U_kn", "helm", "K", "T1", "T2", "T3", "Kd_deg_s", "rms_pct");
    for (int i = 0; i < ns; i++)
        for (int j = 0; j < nr; j++)
            for (int s = side_lo; s <= side_hi; s++) {
                double helm = fw_deg_to_rad(rudders[j]) * (s ? -1 : 1), rms;
                fw_nomoto_indices ix, start, *pstart = NULL;
                /* start on the knowledge base's branch (the paper's for the
                 * C-3): see fw_ident_fit_from */
                if (ship.nomoto.present &&
                    !fw_nomoto_indices_at(&ship.nomoto, speeds[i], rudders[j], &start, NULL))
                    pstart = &start;
                if (fw_ident_turning(&ship, fw_kn_to_ms(speeds[i]), helm, 1.0, n, r, &err) ||
                    fw_ident_fit_from(r, n, 1.0, helm, ship.rudder_rate, pstart, &ix, &rms, &err)) {
                    free(r), free(U);
                    return fw_report(&err);
                }
                printf("%8.2f %+6.0f %10.5f %8.2f %8.2f %8.2f %10.4f %8.2f\n", speeds[i],
                       fw_rad_to_deg(helm), ix.K, ix.T1, ix.T2, ix.T3, ix.K * rudders[j], 100 * rms);
                worst = fmax(worst, rms);
                U[m] = speeds[i], D[m] = rudders[j], UM[m] = fw_kn_to_ms(speeds[i]), HM[m] = helm;
                V[0][m] = ix.K, V[1][m] = ix.T1, V[2][m] = ix.T2, V[3][m++] = ix.T3;
            }
    printf("worst RMS error: %.2f%% of the final rate (floor 5%%)\n", 100 * worst);
    /* regression in the knowledge base's forms (the paper's when the file has none) */
    fw_nomoto_kb kb = ship.nomoto, old = ship.nomoto;
    if (!kb.present) {
        fw_ship c3;
        if (fw_ship_load("c3", &c3, &err)) {
            free(r), free(U);
            return fw_report(&err);
        }
        kb = c3.nomoto;
    }
    fw_nomoto_index *ixs[4] = {&kb.K, &kb.T1, &kb.T2, &kb.T3};
    for (int x = 0; x < 4; x++)
        if (fw_ident_regress(ixs[x], U, D, V[x], m, &err)) {
            free(r), free(U);
            return fw_report(&err);
        }
    /* drift and speed loss in turns (track.h), from the same tests */
    double rms_b, rms_u;
    if (fw_ident_slip(&ship, UM, HM, m, 1.0, n, &kb, &rms_b, &rms_u, &err)) {
        free(r), free(U);
        return fw_report(&err);
    }
    printf("drift %.4f rad per unit r', lag %.1f s (RMS %.2f deg); speed loss %.4f per unit |r'|, "
           "lag %.1f s (RMS %.3f kn)\n",
           kb.drift, kb.drift_lag_s, fw_rad_to_deg(rms_b), kb.speed_loss, kb.speed_lag_s,
           fw_ms_to_kn(rms_u));
    double smin = speeds[0], smax = speeds[0], dmin = rudders[0], dmax = rudders[0];
    for (int i = 0; i < ns; i++)
        smin = fmin(smin, speeds[i]), smax = fmax(smax, speeds[i]);
    for (int j = 0; j < nr; j++)
        dmin = fmin(dmin, rudders[j]), dmax = fmax(dmax, rudders[j]);
    if (old.present) {
        printf("# regression vs the ship file's knowledge base (%s) on the grid\n", ship.file);
        printf("%8s %6s %18s %18s %18s %18s\n", "U_kn", "d", "K d new/old", "T1 new/old", "T2 new/old", "T3 new/old");
        for (int i = 0; i < ns; i++)
            for (int j = 0; j < nr; j++) {
                double u = speeds[i], d = rudders[j];
                printf("%8.2f %6.0f %8.4f/%-9.4f %8.2f/%-9.2f %8.2f/%-9.2f %8.2f/%-9.2f\n", u, d,
                       fw_nomoto_index_eval(&kb.K, u, d) * d, fw_nomoto_index_eval(&old.K, u, d) * d,
                       fw_nomoto_index_eval(&kb.T1, u, d), fw_nomoto_index_eval(&old.T1, u, d),
                       fw_nomoto_index_eval(&kb.T2, u, d), fw_nomoto_index_eval(&old.T2, u, d),
                       fw_nomoto_index_eval(&kb.T3, u, d), fw_nomoto_index_eval(&old.T3, u, d));
            }
    }
    char def_out[600];
    if (!out_path) {
        snprintf(def_out, sizeof def_out, "%s-identified.yaml", ship.name);
        out_path = def_out;
    }
    /* copy the ship file, then replace its nomoto: block */
    FILE *in = fopen(ship.file, "rb"), *out = fopen(out_path, "wb");
    if (!in || !out) {
        if (in)
            fclose(in);
        if (out)
            fclose(out);
        free(r), free(U);
        return fw_report((fw_fail(&err, FW_EINPUT, "%s: cannot write", out_path), &err));
    }
    char buf[8192];
    size_t k;
    while ((k = fread(buf, 1, sizeof buf, in)) > 0)
        fwrite(buf, 1, k, out);
    fclose(in);
    fclose(out);
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    fprintf(f, "# Nomoto knowledge base identified by `fairway identify` from MMG turning\n"
               "# tests of this ship (%d points, %s), worst fit RMS %.2f%% of the final rate.\n"
               "# U in knots, d = |rudder| in deg, K in 1/s (K d in deg/s), T1, T2, T3 in s.\n",
            m, sides, 100 * worst);
    fprintf(f, "nomoto:\n  source: fairway identify (MMG turning tests)\n");
    fprintf(f, "  speed_min_kn: %g\n  speed_max_kn: %g\n  rudder_min_deg: %g\n  rudder_max_deg: %g\n",
            smin, smax, dmin, dmax);
    write_index(f, "K", &kb.K);
    write_index(f, "T1", &kb.T1);
    write_index(f, "T2", &kb.T2);
    write_index(f, "T3", &kb.T3);
    fprintf(f, "  drift: %.6g        # rad of drift angle per unit r' = r L / U\n"
               "  drift_lag_s: %.4g\n"
               "  speed_loss: %.6g   # fraction of the straight-course speed per unit |r'|\n"
               "  speed_lag_s: %.4g\n",
            kb.drift, kb.drift_lag_s, kb.speed_loss, kb.speed_lag_s);
    fclose(f);
    fw_status st = fw_yaml_replace_block(out_path, "nomoto", text, &err);
    free(text);
    free(r), free(U);
    if (st)
        return fw_report(&err);
    fw_ship check;
    if (fw_ship_load(out_path, &check, &err))
        return fw_report(&err);
    printf("wrote %s\n", out_path);
    return 0;
}
