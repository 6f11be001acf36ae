/* bench_stepper: one simulated hour of the C-3 (1 s control steps, a new helm
 * order every 60 s), stepped by fairway's ARKODE stepper, against a plain
 * fixed-step RK4 of the same model at the same accuracy, in the same run.
 *
 * Accuracy is the final position error against a run at rtol 1e-12.  The RK4
 * baseline uses the largest step (from 1 s down, halving) whose error is no
 * larger than the stepper's.  Prints medians of several repetitions. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"
#include "core/units.h"
#include "dynamics/stepper.h"

static const double orders[] = {20, -10, 35, 0, -35, 5, 15, -25, 0, 30, -5, -20};
enum { HOUR = 3600, REPS = 15 };

static fw_mmg_state run_stepper(const fw_ship *s, const fw_stepper_def *def, double n, long *nfe)
{
    fw_stepper *st;
    fw_error err = {0};
    if (fw_stepper_create(s, def, &st, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        exit(1);
    }
    fw_mmg_state x0 = fw_mmg_straight(fw_kn_to_ms(20.0), 0, 0, 0);
    fw_stepper_start(st, 0.0, &x0, n, &err);
    for (int k = 0; k < HOUR; k++) {
        if (k % 60 == 0)
            fw_stepper_set_helm(st, fw_deg_to_rad(orders[(k / 60) % 12]));
        if (fw_stepper_advance(st, 1.0, &err)) {
            fprintf(stderr, "%s\n", err.msg);
            exit(1);
        }
    }
    fw_mmg_state out = *fw_stepper_state(st);
    if (nfe)
        *nfe = fw_stepper_rhs_evals(st);
    fw_stepper_destroy(st);
    return out;
}

/* Rudder angle at time t for an order given at t0 from delta0 (rate-limited). */
static double servo(double delta0, double order, double rate, double dt)
{
    double diff = order - delta0, reach = fabs(diff) / rate;
    return dt >= reach ? order : delta0 + (diff > 0 ? rate : -rate) * dt;
}

static fw_mmg_state run_rk4(const fw_ship *s, double n, double h)
{
    fw_mmg_state x = fw_mmg_straight(fw_kn_to_ms(20.0), 0, 0, 0);
    double y[6] = {x.u, x.vm, x.r, x.east, x.north, x.psi};
    double order = 0.0, delta0 = 0.0, t0 = 0.0, t = 0.0;
    int sub = (int)lround(1.0 / h);
    for (int k = 0; k < HOUR; k++) {
        if (k % 60 == 0) {
            delta0 = servo(delta0, order, s->rudder_rate, t - t0);
            order = fw_deg_to_rad(orders[(k / 60) % 12]);
            t0 = t;
        }
        for (int j = 0; j < sub; j++) {
            double k1[6], k2[6], k3[6], k4[6], tmp[6];
            double ts[3] = {t, t + 0.5 * h, t + h};
            fw_mmg_state z;
            double *stage[4] = {k1, k2, k3, k4};
            const double c[4] = {0.0, 0.5, 0.5, 1.0};
            for (int q = 0; q < 4; q++) {
                for (int i = 0; i < 6; i++)
                    tmp[i] = y[i] + (q ? c[q] * h * stage[q - 1][i] : 0.0);
                z = (fw_mmg_state){tmp[0], tmp[1], tmp[2], tmp[3], tmp[4], tmp[5], 0.0};
                double tq = q == 0 ? ts[0] : (q == 3 ? ts[2] : ts[1]);
                z.delta = servo(delta0, order, s->rudder_rate, tq - t0);
                fw_mmg_derivs(s, &z, n, stage[q]);
            }
            for (int i = 0; i < 6; i++)
                y[i] += h / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
            t += h;
        }
    }
    return (fw_mmg_state){y[0], y[1], y[2], y[3], y[4], y[5], 0.0};
}

static double dist(fw_mmg_state a, fw_mmg_state b) { return hypot(a.east - b.east, a.north - b.north); }

int main(int argc, char **argv)
{
    const char *out_path = argc > 1 ? argv[1] : NULL;
    fw_error err = {0};
    fw_ship s;
    if (fw_ship_load("c3", &s, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    double n;
    fw_mmg_propeller_for_speed(&s, fw_kn_to_ms(20.0), &n, &err);
    fw_stepper_def tight = fw_default_stepper_def();
    tight.rtol = 1e-12;
    tight.atol_vel = 1e-11;
    tight.atol_pos = 1e-9;
    fw_mmg_state ref = run_stepper(&s, &tight, n, NULL);

    fw_stepper_def def = fw_default_stepper_def();
    long nfe = 0;
    double err_st = dist(run_stepper(&s, &def, n, &nfe), ref);
    double h = 1.0, err_rk = 0.0;
    for (; h > 0.01; h *= 0.5) {
        err_rk = dist(run_rk4(&s, n, h), ref);
        if (err_rk <= err_st)
            break;
    }
    double ts[REPS], tr[REPS];
    for (int i = 0; i < REPS; i++) {
        double a = bench_now();
        run_stepper(&s, &def, n, NULL);
        double b = bench_now();
        run_rk4(&s, n, h);
        double c = bench_now();
        ts[i] = b - a;
        tr[i] = c - b;
    }
    double ms_st = 1e3 * bench_median(ts, REPS), ms_rk = 1e3 * bench_median(tr, REPS);
    char text[1024];
    snprintf(text, sizeof text,
             "one simulated hour, C-3 at 20 kn, 1 s control steps, helm order every 60 s\n"
             "  fairway stepper (ARKODE ERK, rtol %.0e): %8.3f ms  error %.4f m  (%ld RHS evaluations)\n"
             "  fixed-step RK4, h = %.4g s            : %8.3f ms  error %.4f m  (%ld RHS evaluations)\n"
             "  ratio stepper / RK4 at equal accuracy : %8.2f\n"
             "  (medians of %d runs; error = final position against rtol 1e-12)\n",
             def.rtol, ms_st, err_st, nfe, h, ms_rk, err_rk, 4L * HOUR * lround(1.0 / h),
             ms_st / ms_rk, REPS);
    fputs(text, stdout);
    if (out_path) {
        FILE *f = fopen(out_path, "w");
        if (f) {
            fputs(text, f);
            fclose(f);
        }
    }
    return 0;
}
