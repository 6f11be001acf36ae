#include "fit/identify.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/lsq.h"
#include "dynamics/stepper.h"

fw_status fw_ident_turning(const fw_ship *ship, double U, double helm, double dt, int n,
                           double *r, fw_error *err)
{
    return fw_ident_turning_full(ship, U, helm, dt, n, r, NULL, NULL, err);
}

fw_status fw_ident_turning_full(const fw_ship *ship, double U, double helm, double dt, int n,
                                double *r, double *speed, double *beta, fw_error *err)
{
    double prop;
    fw_status s = fw_mmg_propeller_for_speed(ship, U, &prop, err);
    if (s)
        return s;
    fw_stepper_def def = fw_default_stepper_def();
    fw_stepper *st;
    if ((s = fw_stepper_create(ship, &def, &st, err)))
        return s;
    fw_mmg_state x0 = fw_mmg_straight(U, 0.0, 0.0, 0.0);
    if ((s = fw_stepper_start(st, 0.0, &x0, prop, err)))
        goto done;
    fw_stepper_set_helm(st, helm);
    for (int k = 0; k < n; k++) {
        if (k > 0 && (s = fw_stepper_advance(st, dt, err)))
            goto done;
        const fw_mmg_state *x = fw_stepper_state(st);
        r[k] = x->r;
        if (speed)
            speed[k] = hypot(x->u, x->vm);
        if (beta)
            beta[k] = atan2(-x->vm, x->u);
    }
done:
    fw_stepper_destroy(st);
    return s;
}

/* One first-order lag, T, of input in[] (held over each sample), from 0. */
static void lag(const double *in, int n, double dt, double T, double *out)
{
    double E = T > 0.0 ? exp(-dt / T) : 0.0, y = 0.0;
    out[0] = 0.0;
    for (int k = 1; k < n; k++)
        out[k] = y = in[k] + (y - in[k]) * E;
}

/* Best gains c[0..q-1] and one lag T (grid 0..300 s by 0.5 s) for
 * y ~ sum_i c_i lag_T(x_i), q = 1 or 2 inputs (x[i] of m histories of n
 * samples each), by least squares at each lag; returns the RMS residual. */
static double fit_gains_lag(const double *const x[2], int q, const double *y, int m, int n,
                            double dt, double c_out[2], double *T_out, double *buf)
{
    double best = INFINITY;
    for (double T = 0.0; T <= 300.0; T += 0.5) {
        double A[4] = {0}, b[2] = {0}, syy = 0.0;
        for (int j = 0; j < m; j++) {
            for (int i = 0; i < q; i++)
                lag(x[i] + (size_t)j * n, n, dt, T, buf + (size_t)i * n);
            for (int k = 0; k < n; k++) {
                double yk = y[(size_t)j * n + k];
                syy += yk * yk;
                for (int i = 0; i < q; i++) {
                    b[i] += buf[(size_t)i * n + k] * yk;
                    for (int l = 0; l < q; l++)
                        A[i * q + l] += buf[(size_t)i * n + k] * buf[(size_t)l * n + k];
                }
            }
        }
        double c[2] = {b[0], b[1]};
        if (!(A[0] > 0.0) || !fw_spd_solve(q, A, c))
            continue;
        double sse = syy;
        for (int i = 0; i < q; i++)
            sse -= c[i] * b[i];
        if (sse < best) {
            best = sse, *T_out = T;
            for (int i = 0; i < q; i++)
                c_out[i] = c[i];
        }
    }
    return sqrt(fmax(best, 0.0) / (double)(m * n));
}

fw_status fw_ident_slip(const fw_ship *ship, const double *U, const double *helm, int m,
                        double dt, int n, fw_nomoto_kb *kb, double *rms_beta, double *rms_speed,
                        fw_error *err)
{
    if (m < 1 || n < 2)
        return fw_fail(err, FW_EINPUT, "slip fit: need at least one test of two samples");
    /* the first FW_IDENT_SLIP_WINDOW_S of each turn only (identify.h) */
    int nw = (int)floor(FW_IDENT_SLIP_WINDOW_S / dt + 1e-9) + 1;
    if (nw < n)
        n = nw;
    size_t mn = (size_t)m * (size_t)n;
    double *r = malloc(sizeof *r * mn), *sp = malloc(sizeof *sp * mn);
    double *be = malloc(sizeof *be * mn), *x = malloc(sizeof *x * mn);
    double *x2 = malloc(sizeof *x2 * mn), *y = malloc(sizeof *y * mn);
    double *buf = malloc(sizeof *buf * 2 * (size_t)n);
    fw_status s = FW_OK;
    if (!r || !sp || !be || !x || !x2 || !y || !buf) {
        s = fw_fail(err, FW_ERUN, "out of memory for %d turning tests", m);
        goto done;
    }
    for (int j = 0; j < m && !s; j++)
        s = fw_ident_turning_full(ship, U[j], helm[j], dt, n, r + (size_t)j * n,
                                  sp + (size_t)j * n, be + (size_t)j * n, err);
    if (s)
        goto done;
    /* inputs are the MMG's own r' and beta (so the fit sees only the lags,
     * not the yaw error of the Nomoto model); drift: beta ~ drift lag(r') */
    for (size_t i = 0; i < mn; i++)
        x[i] = r[i] * ship->L / sp[i], y[i] = be[i];
    double c[2] = {0.0, 0.0};
    const double *xs[2] = {x, x2};
    *rms_beta = fit_gains_lag(xs, 1, y, m, n, dt, c, &kb->drift_lag_s, buf);
    kb->drift = c[0];
    /* speed: U0 - U ~ U0 lag(speed_loss |r'| + speed_loss_drift |beta r'|) */
    for (int j = 0; j < m; j++)
        for (int k = 0; k < n; k++) {
            size_t i = (size_t)j * n + k;
            double rn = fabs(r[i] * ship->L / sp[i]);
            x[i] = U[j] * rn;
            x2[i] = U[j] * fabs(be[i]) * rn;
            y[i] = U[j] - sp[i];
        }
    *rms_speed = fit_gains_lag(xs, 2, y, m, n, dt, c, &kb->speed_lag_s, buf);
    kb->speed_loss = c[0];
    kb->speed_loss_drift = c[1];
done:
    free(r), free(sp), free(be), free(x), free(x2), free(y), free(buf);
    return s;
}

void fw_ident_response(const fw_nomoto_indices *ix, double helm, double rate, double dt, int n,
                       double *r)
{
    double t_ramp = fabs(helm) / rate, rho = helm > 0 ? rate : -rate;
    fw_nomoto_piece ramp, hold;
    fw_nomoto_piece_init(&ramp, ix, 0.0, rho, 0.0, 0.0);
    double r1, v1;
    fw_nomoto_piece_eval(&ramp, t_ramp, &r1, &v1, NULL);
    fw_nomoto_piece_init(&hold, ix, helm, 0.0, r1, v1);
    for (int k = 0; k < n; k++) {
        double t = k * dt;
        if (t < t_ramp)
            fw_nomoto_piece_eval(&ramp, t, &r[k], NULL, NULL);
        else
            fw_nomoto_piece_eval(&hold, t - t_ramp, &r[k], NULL, NULL);
    }
}

static fw_nomoto_indices from_params(const double p[4])
{
    /* T1 and T2 as logarithms keep them positive; K, T3 free */
    return (fw_nomoto_indices){.K = p[0], .T1 = exp(p[1]), .T2 = exp(p[2]), .T3 = p[3]};
}

static double sse(const double p[4], const double *r, int n, double dt, double helm,
                  double rate, double *model)
{
    fw_nomoto_indices ix = from_params(p);
    fw_ident_response(&ix, helm, rate, dt, n, model);
    double s = 0.0;
    for (int k = 0; k < n; k++)
        s += (model[k] - r[k]) * (model[k] - r[k]);
    return isfinite(s) ? s : INFINITY;
}

fw_status fw_ident_fit(const double *r, int n, double dt, double helm, double rate,
                       fw_nomoto_indices *out, double *rms_rel, fw_error *err)
{
    return fw_ident_fit_from(r, n, dt, helm, rate, NULL, out, rms_rel, err);
}

fw_status fw_ident_fit_from(const double *r, int n, double dt, double helm, double rate,
                            const fw_nomoto_indices *start, fw_nomoto_indices *out,
                            double *rms_rel, fw_error *err)
{
    double *model = malloc(sizeof(double) * 6 * (size_t)n);
    if (!model)
        return fw_fail(err, FW_ERUN, "out of memory");
    double *J = model + n; /* 4 columns of n, then a scratch model */
    double *trial = model + 5 * n;
    double r_end = r[n - 1];
    /* start: steady gain from the last sample, T1 fast, T2 and T3 slow */
    double p[4] = {r_end / helm, log(10.0), log(80.0), 60.0};
    const double log_tmax = log(fmax(n * dt / 3.0, 20.0));
    if (start && start->T1 > 0.0 && start->T2 > 0.0 && start->T1 != start->T2) {
        /* the given start's branch: K from the data (the start's gain may be
         * another ship's), the time constants as given */
        p[1] = fmin(log(start->T1), log_tmax), p[2] = fmin(log(start->T2), log_tmax);
        p[3] = start->T3;
    }
    double f = sse(p, r, n, dt, helm, rate, model), lambda = 1e-3;
    for (int it = 0; it < 300; it++) {
        double h[4] = {1e-6 * fmax(fabs(p[0]), 1e-6), 1e-6, 1e-6, 1e-6 * fmax(fabs(p[3]), 1.0)};
        for (int j = 0; j < 4; j++) {
            double q[4] = {p[0], p[1], p[2], p[3]};
            q[j] += h[j];
            sse(q, r, n, dt, helm, rate, trial);
            for (int k = 0; k < n; k++)
                J[j * n + k] = (trial[k] - model[k]) / h[j];
        }
        double A[16], g[4];
        for (int a = 0; a < 4; a++) {
            g[a] = 0.0;
            for (int k = 0; k < n; k++)
                g[a] += J[a * n + k] * (r[k] - model[k]);
            for (int b = 0; b < 4; b++) {
                double s = 0.0;
                for (int k = 0; k < n; k++)
                    s += J[a * n + k] * J[b * n + k];
                A[a * 4 + b] = s;
            }
        }
        bool improved = false;
        while (lambda < 1e12) {
            double M[16], step[4];
            memcpy(M, A, sizeof M);
            memcpy(step, g, sizeof step);
            for (int a = 0; a < 4; a++)
                M[a * 4 + a] += lambda * (A[a * 4 + a] > 0 ? A[a * 4 + a] : 1e-30);
            if (fw_spd_solve(4, M, step)) {
                double q[4] = {p[0] + step[0], p[1] + step[1], p[2] + step[2], p[3] + step[3]};
                /* a time constant over a third of the record is not seen by
                 * it: the fit would trade it for a pole-zero near-cancellation
                 * (T2 ~ T3 in the thousands of seconds) that jumps from one
                 * rudder angle to the next and ruins the regression */
                q[1] = fmin(q[1], log_tmax);
                q[2] = fmin(q[2], log_tmax);
                double fq = sse(q, r, n, dt, helm, rate, trial);
                if (fq < f) {
                    bool tiny = f - fq < 1e-12 * f;
                    memcpy(p, q, sizeof p);
                    f = fq;
                    memcpy(model, trial, sizeof(double) * (size_t)n);
                    lambda = fmax(lambda * 0.3, 1e-9);
                    improved = !tiny;
                    break;
                }
            }
            lambda *= 10.0;
        }
        if (!improved)
            break;
    }
    *out = from_params(p);
    if (out->T1 > out->T2) { /* eq 9 is symmetric: report T1 <= T2 as the paper does */
        double t = out->T1;
        out->T1 = out->T2;
        out->T2 = t;
    }
    *rms_rel = sqrt(f / n) / fabs(r_end);
    free(model);
    if (!isfinite(*rms_rel))
        return fw_fail(err, FW_ERUN, "Nomoto fit did not converge");
    return FW_OK;
}

static double basis(fw_nomoto_basis b, double U, double d)
{
    fw_nomoto_index one = {.n = 1, .basis = {b}, .coef = {1.0}};
    return fw_nomoto_index_eval(&one, U, d);
}

fw_status fw_ident_regress(fw_nomoto_index *ix, const double *U_kn, const double *d_deg,
                           const double *value, int m, fw_error *err)
{
    int q = ix->n;
    if (m < q)
        return fw_fail(err, FW_EINPUT, "regression needs at least %d grid points, got %d", q, m);
    /* normal equations on columns scaled to unit norm (the basis values span
     * 1e-2 .. 1e3) */
    double A[FW_NB_COUNT * FW_NB_COUNT] = {0}, b[FW_NB_COUNT] = {0}, sc[FW_NB_COUNT] = {0};
    for (int j = 0; j < q; j++) {
        for (int i = 0; i < m; i++)
            sc[j] += pow(basis(ix->basis[j], U_kn[i], d_deg[i]), 2);
        sc[j] = sc[j] > 0 ? 1.0 / sqrt(sc[j]) : 1.0;
    }
    for (int i = 0; i < m; i++) {
        double x[FW_NB_COUNT];
        for (int j = 0; j < q; j++)
            x[j] = basis(ix->basis[j], U_kn[i], d_deg[i]) * sc[j];
        for (int j = 0; j < q; j++) {
            b[j] += x[j] * value[i];
            for (int k = 0; k < q; k++)
                A[j * q + k] += x[j] * x[k];
        }
    }
    if (!fw_spd_solve(q, A, b))
        return fw_fail(err, FW_ERUN, "regression is singular: the grid does not determine "
                                     "the %d terms (add speeds or rudder angles)", q);
    for (int j = 0; j < q; j++)
        ix->coef[j] = b[j] * sc[j];
    return FW_OK;
}
