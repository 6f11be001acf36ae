/* windage.c - Blendermann (1994) wind coefficients (windage.h). */
#include "ship/windage.h"

#include <math.h>
#include <string.h>

#include "core/units.h"

/* Blendermann (1994) via Fossen (2011) ch. 10 and MSS blendermann94.m: CD_t,
 * CD_lAF (bow), CD_lAF (stern), delta, kappa. */
const fw_blendermann fw_blendermann_table[FW_WT_COUNT] = {
    [FW_WT_CAR_CARRIER] = {"car_carrier", 0.95, 0.55, 0.60, 0.80, 1.2},
    [FW_WT_CARGO_LOADED] = {"cargo_loaded", 0.85, 0.65, 0.55, 0.40, 1.7},
    [FW_WT_CARGO_CONTAINERS_ON_DECK] = {"cargo_containers_on_deck", 0.85, 0.55, 0.50, 0.40, 1.4},
    [FW_WT_CONTAINER_LOADED] = {"container_loaded", 0.90, 0.55, 0.55, 0.40, 1.4},
    [FW_WT_DESTROYER] = {"destroyer", 0.85, 0.60, 0.65, 0.65, 1.1},
    [FW_WT_DIVING_SUPPORT] = {"diving_support", 0.90, 0.60, 0.80, 0.55, 1.7},
    /* the table gives ranges for the drilling vessel: their middles, as MSS */
    [FW_WT_DRILLING] = {"drilling", 1.00, 0.85, 0.925, 0.10, 1.7},
    [FW_WT_FERRY] = {"ferry", 0.90, 0.45, 0.50, 0.80, 1.1},
    [FW_WT_FISHING] = {"fishing", 0.95, 0.70, 0.70, 0.40, 1.1},
    [FW_WT_LNG_TANKER] = {"lng_tanker", 0.70, 0.60, 0.65, 0.50, 1.1},
    [FW_WT_OFFSHORE_SUPPLY] = {"offshore_supply", 0.90, 0.55, 0.80, 0.55, 1.2},
    [FW_WT_PASSENGER_LINER] = {"passenger_liner", 0.90, 0.40, 0.40, 0.80, 1.2},
    [FW_WT_RESEARCH] = {"research", 0.85, 0.55, 0.65, 0.60, 1.4},
    [FW_WT_SPEED_BOAT] = {"speed_boat", 0.90, 0.55, 0.60, 0.60, 1.1},
    [FW_WT_TANKER_LOADED] = {"tanker_loaded", 0.70, 0.90, 0.55, 0.40, 3.1},
    [FW_WT_TANKER_BALLAST] = {"tanker_ballast", 0.70, 0.75, 0.55, 0.40, 2.2},
    [FW_WT_TENDER] = {"tender", 0.85, 0.55, 0.55, 0.65, 1.1},
};

bool fw_windage_type_parse(const char *name, fw_windage_type *out)
{
    for (int i = 0; i < FW_WT_COUNT; i++)
        if (strcmp(name, fw_blendermann_table[i].name) == 0) {
            *out = (fw_windage_type)i;
            return true;
        }
    return false;
}

void fw_windage_coeffs(const fw_windage *w, double gamma, double *CX, double *CY, double *CN)
{
    const fw_blendermann *b = &fw_blendermann_table[w->type];
    double g = fw_wrap_pi(gamma), ag = fabs(g);
    double CD_lAF = ag <= 0.5 * FW_PI ? b->CD_lAF_bow : b->CD_lAF_stern;
    double CD_l = CD_lAF * w->A_F / w->A_L;
    double s2 = sin(2.0 * g);
    double D = 1.0 - 0.5 * b->delta * (1.0 - CD_l / b->CD_t) * s2 * s2;
    *CX = -CD_lAF * cos(g) / D;
    *CY = -b->CD_t * sin(g) / D;
    *CN = *CY * (w->s_L / w->Loa - 0.18 * (ag - 0.5 * FW_PI));
}

void fw_windage_force(const fw_windage *w, double V, double gamma, double *X, double *Y,
                      double *N)
{
    double CX, CY, CN;
    fw_windage_coeffs(w, gamma, &CX, &CY, &CN);
    double q = 0.5 * FW_AIR_DENSITY * V * V;
    *X = q * w->A_F * CX;
    *Y = q * w->A_L * CY;
    *N = q * w->A_L * w->Loa * CN;
}

void fw_apparent_wind(double speed, double from, double psi, double ve, double vn, double *V,
                      double *gamma)
{
    /* the air's velocity over the ship, east and north: the wind's (towards
     * from + 180 deg) less the ship's */
    double ae = -speed * sin(from) - ve, an = -speed * cos(from) - vn;
    double s = sin(psi), c = cos(psi);
    double ax = ae * s + an * c, ay = ae * c - an * s; /* body: forward, starboard */
    *V = hypot(ax, ay);
    /* it comes from the opposite of where it goes */
    *gamma = atan2(-ay, -ax);
}
