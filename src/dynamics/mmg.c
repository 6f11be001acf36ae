/* MMG forces and equations of motion, written dimensionally so they stay
 * finite as the speed goes to zero (the non-dimensional forms divide by U). */
#include "dynamics/mmg.h"

#include <math.h>
#include <stdbool.h>

#include "core/units.h"


/* Below this speed the drift angle and the non-dimensional rates are not
 * meaningful; terms that divide by U are dropped (they vanish with U anyway). */
#define FW_MMG_U_MIN 1e-6

/* diag: also fill the diagnostic fields (alpha_R, J, K_T), which the
 * equations of motion do not need and which cost an atan2. */
static inline void forces(const fw_ship *s, const fw_mmg_state *x, double n, fw_mmg_forces *f,
                          bool diag)
{
    const double L = s->L, d = s->d, rho = s->rho;
    const double u = x->u, vm = x->vm, r = x->r, delta = x->delta;
    const double U2 = u * u + vm * vm;
    const double U = sqrt(U2);
    const double rL = r * L; /* r' U */
    const double half_rLd = 0.5 * rho * L * d;

    /* Hull: X'_H U^2 etc. with v' U = vm and r' U = r L. */
    double invU = U > FW_MMG_U_MIN ? 1.0 / U : 0.0;
    double vv = vm * vm, rr = rL * rL;
    f->X_H = half_rLd * (-s->R_0 * U2 + s->X_vv * vv + s->X_vr * vm * rL + s->X_rr * rr +
                         s->X_vvvv * vv * vv * invU * invU);
    f->Y_H = half_rLd * (s->Y_v * vm * U + s->Y_r * rL * U +
                         (s->Y_vvv * vv * vm + s->Y_vvr * vv * rL + s->Y_vrr * vm * rr +
                          s->Y_rrr * rr * rL) * invU);
    f->N_H = half_rLd * L *
             (s->N_v * vm * U + s->N_r * rL * U +
              (s->N_vvv * vv * vm + s->N_vvr * vv * rL + s->N_vrr * vm * rr + s->N_rrr * rr * rL) *
                  invU);

    /* Propeller, 2015 wake form.  Thrust written as rho D^2 (k0 n^2 D^2 +
     * k1 n D u_P + k2 u_P^2), i.e. K_T n^2 D^4 without dividing by n. */
    double beta = atan2(-vm, u);
    double rp = rL * invU; /* r' */
    double beta_P = beta - s->x_P * rp;
    double C_2 = beta_P > 0.0 ? s->C_2_plus : s->C_2_minus;
    double one_wP = (1.0 - s->w_P0) * (1.0 + (1.0 - exp(-s->C_1 * fabs(beta_P))) * (C_2 - 1.0));
    double u_P = u * one_wP;
    double D = s->D_P;
    double KTn2D2 = s->k0 * n * n * D * D + s->k1 * n * D * u_P + s->k2 * u_P * u_P;
    f->w_P = 1.0 - one_wP;
    if (diag) {
        f->J = n > 0.0 ? u_P / (n * D) : INFINITY;
        f->K_T = n > 0.0 ? KTn2D2 / (n * n * D * D) : 0.0;
    }
    f->X_P = (1.0 - s->t_P) * rho * D * D * KTn2D2;

    /* Rudder, finite form of u_R (no division by J). */
    double eta = D / s->H_R;
    if (eta > 1.0)
        eta = 1.0;
    double slip = KTn2D2 > 0.0 ? 8.0 * KTn2D2 / FW_PI : 0.0;
    double u_inf = sqrt(u_P * u_P + slip);
    double ui = u_P + s->kappa * (u_inf - u_P);
    double u_R = s->eps * sqrt(eta * ui * ui + (1.0 - eta) * u_P * u_P);
    double Ubeta_R = U * beta - s->l_R * rL; /* U beta_R */
    double gamma_R = Ubeta_R < 0.0 ? s->gamma_R_minus : s->gamma_R_plus;
    double v_R = gamma_R * Ubeta_R;
    /* U_R^2 sin(alpha_R) with alpha_R = delta - atan2(v_R, u_R), expanded:
     * U_R (u_R sin(delta) - v_R cos(delta)); no inverse trigonometry. */
    double sd = sin(delta), cd = cos(delta);
    double UR = sqrt(u_R * u_R + v_R * v_R);
    double F_N = 0.5 * rho * s->A_R * fw_ship_f_alpha(s) * UR * (u_R * sd - v_R * cd);
    f->u_R = u_R;
    f->v_R = v_R;
    if (diag)
        f->alpha_R = delta - atan2(v_R, u_R);
    f->F_N = F_N;
    f->X_R = -(1.0 - s->t_R) * F_N * sd;
    f->Y_R = -(1.0 + s->a_H) * F_N * cd;
    f->N_R = -(s->x_R + s->a_H * s->x_H) * L * F_N * cd;
}

void fw_mmg_forces_eval(const fw_ship *s, const fw_mmg_state *x, double n, fw_mmg_forces *f)
{
    forces(s, x, n, f, true);
}

void fw_mmg_derivs(const fw_ship *s, const fw_mmg_state *x, double n, double out[6])
{
    fw_mmg_derivs_ext(s, x, n, NULL, out);
}

void fw_mmg_derivs_ext(const fw_ship *s, const fw_mmg_state *x, double n, const double ext[3],
                       double out[6])
{
    fw_mmg_forces f;
    forces(s, x, n, &f, false);
    const double L = s->L, d = s->d, rho = s->rho;
    const double m = rho * s->volume;
    const double scale = 0.5 * rho * L * L * d;
    const double mx = s->m_x * scale, my = s->m_y * scale, Jz = s->J_z * scale * L * L;
    const double kz = s->k_zz * L;
    const double Izg = m * kz * kz;
    const double xg = s->x_G;
    const double u = x->u, vm = x->vm, r = x->r;

    double X = f.X_H + f.X_P + f.X_R;
    double Y = f.Y_H + f.Y_R;
    double N = f.N_H + f.N_R;
    if (ext) /* only then: calm water keeps its bits */
        X += ext[0], Y += ext[1], N += ext[2];

    double udot = (X + (m + my) * vm * r + xg * m * r * r) / (m + mx);
    /* [m + my, xg m; xg m, Izg + xg^2 m + Jz] [vdot; rdot] = [b1; b2] */
    double a11 = m + my, a12 = xg * m, a22 = Izg + xg * xg * m + Jz;
    double b1 = Y - (m + mx) * u * r;
    double b2 = N - xg * m * u * r;
    double det = a11 * a22 - a12 * a12;
    double vdot = (b1 * a22 - a12 * b2) / det;
    double rdot = (a11 * b2 - a12 * b1) / det;

    double c = cos(x->psi), sn = sin(x->psi);
    out[0] = udot;
    out[1] = vdot;
    out[2] = rdot;
    out[3] = u * sn + vm * c; /* east */
    out[4] = u * c - vm * sn; /* north */
    out[5] = r;
}

void fw_mmg_wind(const fw_ship *s, const fw_mmg_state *x, double ce, double cn, double speed,
                 double from, double out[3])
{
    /* over ground: through the water plus the water */
    double sp = sin(x->psi), cp = cos(x->psi);
    double ve = x->u * sp + x->vm * cp + ce, vn = x->u * cp - x->vm * sp + cn;
    double V, gamma;
    fw_apparent_wind(speed, from, x->psi, ve, vn, &V, &gamma);
    fw_windage_force(&s->windage, V, gamma, &out[0], &out[1], &out[2]);
}

fw_status fw_mmg_propeller_for_speed(const fw_ship *s, double U, double *n, fw_error *err)
{
    if (!(U >= 0.0) || !isfinite(U))
        return fw_fail(err, FW_EINPUT, "speed must be a finite value >= 0 (got %g m/s)", U);
    /* Straight running: v = r = 0, beta_P = 0 so 1 - w_P = 1 - w_P0, and the
     * rudder at zero angle gives no surge force.  Surge balance is a quadratic
     * in n: (1 - t_P) rho D^2 (k0 n^2 D^2 + k1 n D u_P + k2 u_P^2) = R. */
    double R = 0.5 * s->rho * s->L * s->d * s->R_0 * U * U;
    double D = s->D_P, u_P = U * (1.0 - s->w_P0);
    double k = (1.0 - s->t_P) * s->rho * D * D;
    double a = k * s->k0 * D * D, b = k * s->k1 * D * u_P, c = k * s->k2 * u_P * u_P - R;
    double disc = b * b - 4.0 * a * c;
    if (a <= 0.0 || disc < 0.0)
        return fw_fail(err, FW_ERUN, "%s: no propeller speed balances the resistance at %g m/s",
                       s->name, U);
    double root = (-b + sqrt(disc)) / (2.0 * a);
    if (!(root >= 0.0))
        return fw_fail(err, FW_ERUN, "%s: propeller speed for %g m/s comes out negative",
                       s->name, U);
    *n = root;
    return FW_OK;
}

fw_mmg_state fw_mmg_straight(double U, double east, double north, double psi)
{
    fw_mmg_state s = {.u = U, .vm = 0.0, .r = 0.0, .east = east, .north = north, .psi = psi,
                      .delta = 0.0};
    return s;
}

/* Forces' residual of straight running: udot, vdot, rdot at r = 0 with the
 * wind's forces at that state. */
static void steady_residual(const fw_ship *s, const fw_mmg_state *x, double n, double ce,
                            double cn, double speed, double from, double out[3])
{
    double ext[3], d[6];
    fw_mmg_wind(s, x, ce, cn, speed, from, ext);
    fw_mmg_derivs_ext(s, x, n, ext, d);
    out[0] = d[0], out[1] = d[1], out[2] = d[2];
}

/* The 3 x 3 system J dx = -F by Cramer's rule; false when J is singular. */
static bool solve3(const double J[3][3], const double F[3], double dx[3])
{
    double det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                 J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                 J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
    if (!(fabs(det) > 0.0) || !isfinite(det))
        return false;
    for (int c = 0; c < 3; c++) {
        double M[3][3];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                M[i][j] = j == c ? -F[i] : J[i][j];
        dx[c] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
                 M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                 M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) /
                det;
    }
    return true;
}

fw_status fw_mmg_steady_wind(const fw_ship *s, double n, double ce, double cn, double speed,
                             double from, fw_mmg_state *x, fw_error *err)
{
    /* Newton's method with a forward-difference Jacobian in (u, vm, delta) */
    const double h[3] = {1e-5, 1e-5, 1e-6};
    x->r = 0.0;
    for (int it = 0; it < 40; it++) {
        double F[3], J[3][3], dx[3];
        steady_residual(s, x, n, ce, cn, speed, from, F);
        for (int j = 0; j < 3; j++) {
            fw_mmg_state y = *x;
            double *p = j == 0 ? &y.u : j == 1 ? &y.vm : &y.delta, G[3];
            *p += h[j];
            steady_residual(s, &y, n, ce, cn, speed, from, G);
            for (int i = 0; i < 3; i++)
                J[i][j] = (G[i] - F[i]) / h[j];
        }
        if (!solve3(J, F, dx))
            break;
        x->u += dx[0], x->vm += dx[1], x->delta += dx[2];
        if (fabs(dx[0]) < 1e-9 && fabs(dx[1]) < 1e-9 && fabs(dx[2]) < 1e-10) {
            if (fabs(x->delta) > s->rudder_max)
                return fw_fail(err, FW_ERUN,
                               "%s: holding the heading in this wind needs %.1f deg of rudder",
                               s->name, fw_rad_to_deg(x->delta));
            return FW_OK;
        }
    }
    return fw_fail(err, FW_ERUN, "%s: no steady straight running found in this wind", s->name);
}
