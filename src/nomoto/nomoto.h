/* nomoto.h - Nomoto's second-order steering model from a ship's knowledge base.
 *
 *     T1 T2 r'' + (T1 + T2) r' + r = K delta + K T3 delta'      (paper eq 8)
 *
 * Indices come from the regressions in the ship file (paper eqs 10-13, U in
 * knots, |delta| in degrees).  The response is solved exactly for inputs that
 * are linear in time (a rudder ramp) or constant, in a form that stays exact
 * and well conditioned as T1 -> T2 (see nomoto.c), so eq 9 and its T1 = T2
 * limit are one code path.  Angles and rates here are in any one unit (the
 * model is linear); the track module uses radians.
 */
#ifndef FW_NOMOTO_H
#define FW_NOMOTO_H

#include <stdbool.h>

#include "core/error.h"
#include "ship/ship.h"

typedef struct fw_nomoto_indices {
    double K;   /* 1/s */
    double T1;  /* s */
    double T2;  /* s */
    double T3;  /* s */
    double U_kn, d_deg;        /* where they were evaluated (d after clamping) */
    bool speed_in_range;       /* U inside the knowledge base's fitted speeds */
    bool rudder_in_range;      /* |helm| inside its fitted rudder angles */
} fw_nomoto_indices;

/* Indices at speed U (knots) and helm magnitude |helm_deg|.  ln(d) needs d > 0
 * and the regressions are meaningless near zero rudder, so d is clamped up to
 * max(kb->rudder_min_deg, 1 deg): a zero-helm (steady) prediction uses the
 * indices of the smallest fitted angle.  U below 1 kn is clamped to 1 kn (1/U
 * terms).  Outside the fitted range the regressions are extrapolated, as the
 * paper does at 10 kn; the flags say so.  FW_ERUN if the result is not a
 * stable system (K <= 0, T1 <= 0 or T2 <= 0). */
fw_status fw_nomoto_indices_at(const fw_nomoto_kb *kb, double U_kn, double helm_deg,
                               fw_nomoto_indices *out, fw_error *err);

/* A speed against the knowledge base's fitted speeds.  Outside them the
 * regressions are extrapolated (the paper does so at 10 kn from 14.55): a
 * warning.  Beyond FW_KB_SPEED_MARGIN times the range (below speed_min /
 * margin or above speed_max x margin) the extrapolation is refused: eqs
 * 10-13 have 1/U and U^2 terms that run away there. */
#define FW_KB_SPEED_MARGIN 1.5
typedef enum fw_kb_speed { FW_KB_SPEED_IN, FW_KB_SPEED_OUTSIDE, FW_KB_SPEED_REFUSED } fw_kb_speed;
fw_kb_speed fw_nomoto_kb_speed(const fw_nomoto_kb *kb, double U_kn);

/* Paper eq 9: turning rate t seconds after a rudder step delta from rest. */
double fw_nomoto_step_rate(const fw_nomoto_indices *ix, double delta, double t);

/* Exact solution of eq 8 over one interval where the rudder is delta0 + rho*t
 * (rho = rudder rate during a ramp, 0 when held), from r(0) = r0, r'(0) = v0.
 * Gives r, r' and the heading change (integral of r) at time t. */
typedef struct fw_nomoto_piece {
    double T1, T2;
    double c0, b;   /* particular solution r_p = c0 + b t */
    double h0, h1;  /* homogeneous part and its slope at t = 0 */
    double h2;      /* its second derivative at t = 0 */
} fw_nomoto_piece;

void fw_nomoto_piece_init(fw_nomoto_piece *p, const fw_nomoto_indices *ix, double delta0,
                          double rho, double r0, double v0);
void fw_nomoto_piece_eval(const fw_nomoto_piece *p, double t, double *r, double *rdot,
                          double *turned);

/* (exp(-t/T1) - exp(-t/T2)) / (T1 - T2), continuous through T1 = T2 where it
 * is t exp(-t/T) / T^2.  Exposed for tests. */
double fw_nomoto_phi(double T1, double T2, double t);

#endif
