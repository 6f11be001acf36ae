/* identify.h - Nomoto indices from MMG turning tests, and their regression.
 *
 * A turning test starts in straight steady running at U (propeller from the
 * surge balance), orders the helm, and samples the yaw rate every dt.  The
 * fit is Levenberg-Marquardt on (K, T1, T2, T3) against the exact response of
 * eq 8 to the rudder as it really moves (a ramp at the rudder rate, then
 * held), not to a step: at 35 deg the ramp lasts 12 s, a third of T1.  The
 * regression is linear least squares over the grid with the basis terms of
 * eqs 10-13 (or of the ship file's own knowledge base).
 */
#ifndef FW_IDENTIFY_H
#define FW_IDENTIFY_H

#include "nomoto/nomoto.h"
#include "ship/ship.h"

/* Yaw rate (rad/s) at t = k dt, k = 0..n-1, of an MMG turning test. */
fw_status fw_ident_turning(const fw_ship *ship, double U, double helm, double dt, int n,
                           double *r, fw_error *err);

/* The same with the speed over ground (m/s) and drift angle (rad, + when the
 * hull slides to port in a starboard turn) at each sample; either may be NULL. */
fw_status fw_ident_turning_full(const fw_ship *ship, double U, double helm, double dt, int n,
                                double *r, double *speed, double *beta, fw_error *err);

/* The slip terms are fitted over the first 5 minutes of each turn: the
 * decisions are made 2-6 minutes before the closest approach and a
 * manoeuvre is re-predicted every step, so that is the span the predictions
 * must get right.  Over 15 minutes the fit is pulled towards the steady
 * turn's speed and the track is off twice as far at 5 minutes. */
#define FW_IDENT_SLIP_WINDOW_S 300.0

/* The knowledge base's drift and speed-loss terms (ship.h) from m MMG turning
 * tests (speed U[j] m/s, helm[j] rad), n samples dt apart (only the first
 * FW_IDENT_SLIP_WINDOW_S used): for each, the gains by linear least squares
 * at every lag on a 0.5 s grid up to 300 s, driven by the MMG's own r' and
 * beta so the yaw model's error stays out of the fit.  Fills kb->drift,
 * drift_lag_s, speed_loss, speed_loss_drift, speed_lag_s; *rms_beta (rad) and
 * *rms_speed (m/s) are the residuals. */
fw_status fw_ident_slip(const fw_ship *ship, const double *U, const double *helm, int m,
                        double dt, int n, fw_nomoto_kb *kb, double *rms_beta, double *rms_speed,
                        fw_error *err);

/* Response of eq 8 from rest to a rudder ramped at `rate` to `helm` (rad). */
void fw_ident_response(const fw_nomoto_indices *ix, double helm, double rate, double dt, int n,
                       double *r);

/* Fits ix (K, T1, T2, T3; T1 <= T2 on return) to r; *rms_rel = RMS error /
 * |final rate|. */
fw_status fw_ident_fit(const double *r, int n, double dt, double helm, double rate,
                       fw_nomoto_indices *ix, double *rms_rel, fw_error *err);

/* The same from a given start (NULL: the default).  The fit has two local
 * minima of nearly equal error on these histories: a fast branch (T1 2-4 s,
 * T3 < T2) and the paper's (T1 10-25 s, T3 a little above T2); Levenberg-
 * Marquardt stays on the start's branch, so a start on one branch for the
 * whole grid keeps the indices smooth for the regression. */
fw_status fw_ident_fit_from(const double *r, int n, double dt, double helm, double rate,
                            const fw_nomoto_indices *start, fw_nomoto_indices *out,
                            double *rms_rel, fw_error *err);

/* Least squares of one index over m grid points (U in knots, d in degrees):
 * fills ix->coef for the basis terms already set in ix->basis[0..ix->n-1]. */
fw_status fw_ident_regress(fw_nomoto_index *ix, const double *U_kn, const double *d_deg,
                           const double *value, int m, fw_error *err);

#endif
