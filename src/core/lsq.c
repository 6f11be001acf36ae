#include "core/lsq.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

fw_lsq_def fw_default_lsq_def(void)
{
    fw_lsq_def d = {
        .max_iter = 50,
        .fd_step = 1e-4,
        .ftol = 1e-10,
        .xtol = 1e-9,
        .lambda0 = 1e-3,
        .lo = NULL,
        .hi = NULL,
    };
    return d;
}

bool fw_spd_solve(int n, double *A, double *b)
{
    for (int j = 0; j < n; j++) {
        double s = A[j * n + j];
        for (int k = 0; k < j; k++)
            s -= A[j * n + k] * A[j * n + k];
        if (!(s > 0.0))
            return false;
        double ljj = sqrt(s);
        A[j * n + j] = ljj;
        for (int i = j + 1; i < n; i++) {
            double t = A[i * n + j];
            for (int k = 0; k < j; k++)
                t -= A[i * n + k] * A[j * n + k];
            A[i * n + j] = t / ljj;
        }
    }
    for (int i = 0; i < n; i++) { /* L y = b */
        double t = b[i];
        for (int k = 0; k < i; k++)
            t -= A[i * n + k] * b[k];
        b[i] = t / A[i * n + i];
    }
    for (int i = n - 1; i >= 0; i--) { /* L^T x = y */
        double t = b[i];
        for (int k = i + 1; k < n; k++)
            t -= A[k * n + i] * b[k];
        b[i] = t / A[i * n + i];
    }
    return true;
}

static double half_sq(const double *r, int nr)
{
    double s = 0.0;
    for (int i = 0; i < nr; i++)
        s += r[i] * r[i];
    return 0.5 * s;
}

static void clamp(double *p, int np, const fw_lsq_def *def)
{
    for (int i = 0; i < np; i++) {
        if (def->lo && p[i] < def->lo[i])
            p[i] = def->lo[i];
        if (def->hi && p[i] > def->hi[i])
            p[i] = def->hi[i];
    }
}

fw_status fw_lsq_solve(fw_lsq_fn f, void *user, int np, int nr, double *p, const fw_lsq_def *d,
                       fw_lsq_result *res, fw_error *err)
{
    fw_lsq_def def = d ? *d : fw_default_lsq_def();
    memset(res, 0, sizeof *res);
    if (np < 1 || np > FW_LSQ_MAX_P || nr < np || nr > FW_LSQ_MAX_R)
        return fw_fail(err, FW_EINPUT, "least squares: %d parameters and %d residuals", np, nr);
    double *r = malloc(sizeof(double) * (size_t)nr * (size_t)(np + 3));
    if (!r)
        return fw_fail(err, FW_ERUN, "out of memory");
    double *rt = r + nr, *rp = rt + nr, *J = rp + nr; /* J is nr x np, column-major */
    fw_status st;
    clamp(p, np, &def);
    if ((st = f(p, r, user, err)))
        goto out;
    res->evaluations = 1;
    double cost = half_sq(r, nr);
    res->cost0 = cost;
    double lambda = def.lambda0;
    for (int it = 0; it < def.max_iter; it++) {
        res->iterations = it + 1;
        double q[FW_LSQ_MAX_P];
        for (int j = 0; j < np; j++) {
            memcpy(q, p, sizeof(double) * (size_t)np);
            double h = def.fd_step;
            q[j] = p[j] + h;
            if ((st = f(q, rp, user, err)))
                goto out;
            q[j] = p[j] - h;
            if ((st = f(q, rt, user, err)))
                goto out;
            res->evaluations += 2;
            for (int i = 0; i < nr; i++)
                J[j * nr + i] = (rp[i] - rt[i]) / (2.0 * h);
        }
        double JtJ[FW_LSQ_MAX_P * FW_LSQ_MAX_P], g[FW_LSQ_MAX_P];
        for (int a = 0; a < np; a++) {
            g[a] = 0.0;
            for (int i = 0; i < nr; i++)
                g[a] += J[a * nr + i] * r[i];
            for (int b = 0; b <= a; b++) {
                double s = 0.0;
                for (int i = 0; i < nr; i++)
                    s += J[a * nr + i] * J[b * nr + i];
                JtJ[a * np + b] = JtJ[b * np + a] = s;
            }
        }
        bool improved = false;
        for (int tries = 0; tries < 12 && !improved; tries++) {
            double A[FW_LSQ_MAX_P * FW_LSQ_MAX_P], step[FW_LSQ_MAX_P];
            memcpy(A, JtJ, sizeof(double) * (size_t)(np * np));
            for (int a = 0; a < np; a++) {
                A[a * np + a] += lambda * (JtJ[a * np + a] > 0.0 ? JtJ[a * np + a] : 1.0);
                step[a] = -g[a];
            }
            if (!fw_spd_solve(np, A, step)) {
                lambda *= 10.0;
                continue;
            }
            for (int a = 0; a < np; a++)
                q[a] = p[a] + step[a];
            clamp(q, np, &def);
            double dx = 0.0;
            for (int a = 0; a < np; a++)
                dx = fmax(dx, fabs(q[a] - p[a]));
            if ((st = f(q, rt, user, err)))
                goto out;
            res->evaluations++;
            double c = half_sq(rt, nr);
            if (c < cost) {
                double rel = (cost - c) / (cost > 0.0 ? cost : 1.0);
                memcpy(p, q, sizeof(double) * (size_t)np);
                memcpy(r, rt, sizeof(double) * (size_t)nr);
                cost = c;
                lambda = fmax(lambda / 10.0, 1e-12);
                improved = true;
                if (rel < def.ftol || dx < def.xtol)
                    res->converged = true;
            } else {
                lambda *= 10.0;
            }
        }
        if (!improved)
            res->converged = true; /* no descent direction left at this resolution */
        if (res->converged)
            break;
    }
    res->cost = cost;
    st = FW_OK;
out:
    free(r);
    return st;
}
