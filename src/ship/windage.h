/* windage.h - a ship above the water: its windage particulars and the wind
 * force coefficients of Blendermann (1994) for its ship type.
 *
 * Model: W. Blendermann, "Parameter identification of wind loads on ships",
 * J. Wind Eng. Ind. Aerodyn. 51 (1994) 339-351, as given by Fossen, Handbook
 * of Marine Craft Hydrodynamics and Motion Control (2011, 2021), ch. 10, and
 * coded in cybergalactic/MSS GNC/blendermann94.m (the table below is its
 * BDATA, per ship type: CD_t, CD_lAF at the bow and the stern, delta, kappa;
 * kappa is for the roll moment, which a 3-DOF model does not use).  Chosen
 * over Fujiwara et al. (1998) because it needs only the areas and the
 * centroid a ship file can give, and its coefficients at 0, 90 and 180 deg
 * are the table's own numbers (tests/test_wind.c checks them, to 1e-12).
 *
 * gamma: the apparent wind's angle off the bow, the direction it comes FROM,
 * positive from starboard (0 head wind, +90 deg on the starboard beam, 180
 * deg from astern).  Forces in body axes (x forward, y starboard, N positive
 * turning the bow to starboard), with the wind relative to the moving ship:
 *   X = 0.5 rho_a V^2 A_F C_X,  Y = 0.5 rho_a V^2 A_L C_Y,
 *   N = 0.5 rho_a V^2 A_L Loa C_N,
 *   C_X = -CD_lAF cos(gamma) / D,  C_Y = -CD_t sin(gamma) / D,
 *   D = 1 - delta/2 (1 - CD_l/CD_t) sin^2(2 gamma),  CD_l = CD_lAF A_F / A_L,
 *   C_N = C_Y (s_L/Loa - 0.18 (|gamma| - pi/2)),
 * CD_lAF the bow value for |gamma| <= 90 deg, the stern value beyond.  The
 * signs are Blendermann's with the side force made leeward (a wind from
 * starboard pushes to port: C_Y < 0) and the moment the side force times its
 * lever s_L/Loa - 0.18 (|gamma| - 90 deg) forward of midship (a bow wind's
 * centre of pressure forward, a stern wind's aft); |gamma| keeps C_N odd in
 * gamma, as the hull's symmetry requires (MSS's code writes gamma - pi/2,
 * meant for 0..180 deg).  rho_a: 1.225 kg/m^3 (ISA sea level, 15 C).
 */
#ifndef FW_SHIP_WINDAGE_H
#define FW_SHIP_WINDAGE_H

#include <stdbool.h>

/* kg/m^3, the ISA sea-level air density */
#define FW_AIR_DENSITY 1.225

/* Blendermann's ship types (MSS blendermann94.m's order). */
typedef enum fw_windage_type {
    FW_WT_CAR_CARRIER,
    FW_WT_CARGO_LOADED,
    FW_WT_CARGO_CONTAINERS_ON_DECK,
    FW_WT_CONTAINER_LOADED,
    FW_WT_DESTROYER,
    FW_WT_DIVING_SUPPORT,
    FW_WT_DRILLING,
    FW_WT_FERRY,
    FW_WT_FISHING,
    FW_WT_LNG_TANKER,
    FW_WT_OFFSHORE_SUPPLY,
    FW_WT_PASSENGER_LINER,
    FW_WT_RESEARCH,
    FW_WT_SPEED_BOAT,
    FW_WT_TANKER_LOADED,
    FW_WT_TANKER_BALLAST,
    FW_WT_TENDER,
    FW_WT_COUNT
} fw_windage_type;

/* One row of Blendermann's table. */
typedef struct fw_blendermann {
    const char *name;       /* as a ship file spells it: container_loaded */
    double CD_t;            /* transverse drag, beam wind */
    double CD_lAF_bow;      /* longitudinal drag on A_F, head wind */
    double CD_lAF_stern;    /* longitudinal drag on A_F, stern wind */
    double delta;           /* cross-force parameter */
    double kappa;           /* roll-moment factor (unused in 3 DOF) */
} fw_blendermann;

extern const fw_blendermann fw_blendermann_table[FW_WT_COUNT];

/* A ship's windage (ship file `windage:`); present false: none given. */
typedef struct fw_windage {
    bool present;
    fw_windage_type type;
    double A_F;   /* m^2, frontal projected area above the waterline */
    double A_L;   /* m^2, lateral projected area above the waterline */
    double s_L;   /* m, the centroid of A_L forward of midship (aft < 0) */
    double Loa;   /* m, length overall (Blendermann's reference length) */
} fw_windage;

/* The type named `name`; false when there is none. */
bool fw_windage_type_parse(const char *name, fw_windage_type *out);

/* Blendermann's C_X, C_Y, C_N at apparent-wind angle gamma (rad, above). */
void fw_windage_coeffs(const fw_windage *w, double gamma, double *CX, double *CY, double *CN);

/* The wind's force and moment on the hull (N, N, N m; body axes) for the
 * apparent wind's speed V (m/s) and angle gamma (rad). */
void fw_windage_force(const fw_windage *w, double V, double gamma, double *X, double *Y,
                      double *N);

/* The apparent wind in body axes: speed *V and angle *gamma, for a true wind
 * of `speed` m/s blowing FROM `from` (rad, navigational) and a ship on
 * heading psi moving over ground at (ve, vn) m/s east, north. */
void fw_apparent_wind(double speed, double from, double psi, double ve, double vn, double *V,
                      double *gamma);

#endif
