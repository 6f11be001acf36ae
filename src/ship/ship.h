/* ship.h - a ship as data: particulars, MMG coefficients, Nomoto knowledge base.
 *
 * Ship definitions come from YAML files (scenarios/ships/NAME.yaml), never from
 * constants in C.  Everything here is SI (m, kg, s, rad) or non-dimensional in
 * the MMG scaling (forces by 0.5 rho L d U^2, moments by 0.5 rho L^2 d U^2).
 * The Nomoto knowledge base keeps the paper's interface units (U in knots,
 * rudder angle in degrees) because its regression coefficients are fitted in
 * them; fw_nomoto_index_eval() is the only place that evaluates them.
 */
#ifndef FW_SHIP_H
#define FW_SHIP_H

#include <stdbool.h>

#include "core/error.h"
#include "core/files.h" /* fw_data_root */
#include "ship/windage.h"

/* Basis terms of the Nomoto index regressions (paper equations 10 to 13).
 * U is the speed in knots and d the rudder angle magnitude in degrees. */
typedef enum fw_nomoto_basis {
    FW_NB_ONE,      /* "1"      */
    FW_NB_U,        /* "U"      */
    FW_NB_D,        /* "d"      */
    FW_NB_LN_D,     /* "ln_d"   */
    FW_NB_U_LN_D,   /* "U*ln_d" */
    FW_NB_U_D,      /* "U*d"    */
    FW_NB_D2,       /* "d^2"    */
    FW_NB_U2,       /* "U^2"    */
    FW_NB_INV_U,    /* "1/U"    */
    FW_NB_LN_D_U,   /* "ln_d/U" */
    FW_NB_D_U,      /* "d/U"    */
    FW_NB_COUNT
} fw_nomoto_basis;

extern const char *const fw_nomoto_basis_names[FW_NB_COUNT];

/* One index as sum(coef[i] * basis_i(U, d)) over the terms present. */
typedef struct fw_nomoto_index {
    int n;
    fw_nomoto_basis basis[FW_NB_COUNT];
    double coef[FW_NB_COUNT];
} fw_nomoto_index;

typedef struct fw_nomoto_kb {
    bool present;
    fw_nomoto_index K;  /* 1/s: K*delta in deg/s for delta in deg */
    fw_nomoto_index T1; /* s */
    fw_nomoto_index T2; /* s */
    fw_nomoto_index T3; /* s */
    double speed_min_kn, speed_max_kn;  /* range the regression was fitted over */
    double rudder_min_deg, rudder_max_deg;
    /* What Nomoto's yaw equation leaves out of the track (optional, 0 = none):
     * in a turn the hull slides outwards at the drift angle beta (course over
     * ground = heading - beta) and slows down.  Steady values follow the
     * non-dimensional yaw rate r' = r L / U: beta = drift r', U = U0 (1 -
     * speed_loss |r'| - speed_loss_drift |beta r'|); both approach them with
     * first-order lags.  Without them a 20 deg turn of the C-3 at 10 kn is
     * predicted 110 m off after 3 minutes.  The beta r' term is the surge
     * equation's centripetal one (m + m_y) v r, which makes the loss grow
     * with the square of the turn (small at 10 deg, large at 35); alone,
     * |r'| over-predicts the loss of small helms (40 m off after 3 minutes
     * at 10 kn and 10 deg for the c3-paper-mmg ship, 7 m with both).  With
     * both, speed_loss may be negative: a propeller in the oblique inflow of
     * a turn can gain thrust (the MMG wake model's C_2 below 1). */
    double drift;        /* rad of drift per unit r' */
    double drift_lag_s;  /* s */
    double speed_loss;   /* fraction of U0 lost per unit |r'| */
    double speed_loss_drift; /* fraction of U0 lost per unit |beta r'| (beta in rad) */
    double speed_lag_s;  /* s */
} fw_nomoto_kb;

typedef struct fw_ship {
    char name[64];
    char file[512]; /* where it was loaded from */

    /* particulars */
    double L;       /* m, length between perpendiculars */
    double Loa;     /* m, length overall (hull outline, SUMO length) */
    double B;       /* m, breadth */
    double d;       /* m, mean draft */
    double Cb;      /* block coefficient */
    double volume;  /* m^3, displacement volume */
    double x_G;     /* m, centre of gravity forward of midship */
    double k_zz;    /* yaw radius of gyration / L */
    double rho;     /* kg/m^3, water density */
    double rudder_rate; /* rad/s, steering gear rate limit */
    double rudder_max;  /* rad, maximum rudder angle */

    /* hull, non-dimensional */
    double m_x, m_y, J_z, R_0;
    double X_vv, X_vr, X_rr, X_vvvv;
    double Y_v, Y_r, Y_vvv, Y_vvr, Y_vrr, Y_rrr;
    double N_v, N_r, N_vvv, N_vvr, N_vrr, N_rrr;

    /* propeller */
    double D_P;   /* m */
    double t_P, w_P0, x_P; /* x_P non-dimensional (x_P / L) */
    double k0, k1, k2;     /* K_T = k0 + k1 J + k2 J^2 */
    double C_1, C_2_plus, C_2_minus;

    /* rudder */
    double A_R;   /* m^2 */
    double H_R;   /* m, rudder span */
    double aspect_ratio; /* Lambda, for f_alpha */
    double t_R, a_H, x_H, x_R; /* x_H, x_R non-dimensional */
    double eps, kappa, l_R;    /* l_R non-dimensional */
    double gamma_R_plus, gamma_R_minus;

    fw_nomoto_kb nomoto;
    /* port turns (helm < 0) when present: a single-screw ship turns faster to
     * one side at small helm (c3-paper at 10 kn, 5 deg: 29 %), and `identify
     * --sides both` fits the sides apart; absent, nomoto serves both */
    fw_nomoto_kb nomoto_port;

    /* above the water (ship file `windage:`, ship/windage.h); absent: a
     * wind that is not calm is refused (env/env.h fw_env_check_vessel) */
    fw_windage windage;
} fw_ship;

/* The knowledge base for a helm of this sign (> 0 starboard). */
const fw_nomoto_kb *fw_ship_kb(const fw_ship *ship, double helm);

/* Loads a ship by name (searched as scenarios/ships/NAME.yaml under the data
 * root) or by path (anything containing '/' or ending in .yaml).  Every field
 * is checked; errors name file, line and field and return FW_EINPUT. */
fw_status fw_ship_load(const char *name_or_path, fw_ship *ship, fw_error *err);

/* Resolves a ship name to its file path (without checking it exists);
 * false when the path does not fit in out. */
bool fw_ship_path(const char *name_or_path, char *out, unsigned outsz);

/* Derived quantities. */
double fw_ship_mass(const fw_ship *s);             /* kg */
double fw_ship_f_alpha(const fw_ship *s);          /* rudder lift gradient */

/* Evaluates one Nomoto index at U (knots) and rudder magnitude d (degrees). */
double fw_nomoto_index_eval(const fw_nomoto_index *ix, double U_kn, double d_deg);



/* Named access to a ship's numeric fields, as they are spelt in ship files
 * (e.g. "N_r", "A_R").  Returns NULL for an unknown name.  *section gets the
 * file section holding the field; *scale the factor from file units to SI. */
double *fw_ship_field(fw_ship *ship, const char *key, const char **section, double *scale);
#endif
