/* lsq.h - small dense nonlinear least squares (Levenberg-Marquardt).
 *
 * For fits with a handful of parameters and residuals that come from
 * simulations (calibration against sea trials, Nomoto index identification):
 * the Jacobian is taken by central differences, parameters may have bounds.
 */
#ifndef FW_LSQ_H
#define FW_LSQ_H

#include <stdbool.h>

#include "core/error.h"

/* Fills r[0..nr) for parameters p[0..np).  A non-zero status aborts the fit. */
typedef fw_status (*fw_lsq_fn)(const double *p, double *r, void *user, fw_error *err);

typedef struct fw_lsq_def {
    int max_iter;
    double fd_step;   /* central-difference step, absolute, per parameter */
    double ftol;      /* stop when the relative cost decrease is below this */
    double xtol;      /* or when the step is below this (max norm) */
    double lambda0;   /* initial damping */
    const double *lo, *hi; /* optional bounds (NULL = none) */
} fw_lsq_def;

fw_lsq_def fw_default_lsq_def(void);

typedef struct fw_lsq_result {
    int iterations, evaluations;
    double cost0, cost; /* 0.5 sum r^2 at the start and the end */
    bool converged;
} fw_lsq_result;

enum { FW_LSQ_MAX_P = 16, FW_LSQ_MAX_R = 4096 };

fw_status fw_lsq_solve(fw_lsq_fn f, void *user, int np, int nr, double *p, const fw_lsq_def *def,
                       fw_lsq_result *res, fw_error *err);

/* Solves the n x n symmetric positive definite system A x = b in place
 * (Cholesky); returns false if A is not positive definite. */
bool fw_spd_solve(int n, double *A, double *b);

#endif
