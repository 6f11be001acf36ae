#include "ship/ship.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const fw_nomoto_basis_names[FW_NB_COUNT] = {
    "1", "U", "d", "ln_d", "U*ln_d", "U*d", "d^2", "U^2", "1/U", "ln_d/U", "d/U",
};

bool fw_ship_path(const char *name_or_path, char *out, unsigned outsz)
{
    size_t len = strlen(name_or_path);
    bool is_path = strchr(name_or_path, '/') != NULL ||
                   (len > 5 && strcmp(name_or_path + len - 5, ".yaml") == 0);
    int n = is_path ? snprintf(out, outsz, "%s", name_or_path)
                    : snprintf(out, outsz, "%s/scenarios/ships/%s.yaml", fw_data_root(),
                               name_or_path);
    return n >= 0 && (unsigned)n < outsz;
}

double fw_ship_mass(const fw_ship *s) { return s->rho * s->volume; }

double fw_ship_f_alpha(const fw_ship *s)
{
    return 6.13 * s->aspect_ratio / (s->aspect_ratio + 2.25);
}

static double basis_value(fw_nomoto_basis b, double U, double d)
{
    switch (b) {
    case FW_NB_ONE: return 1.0;
    case FW_NB_U: return U;
    case FW_NB_D: return d;
    case FW_NB_LN_D: return log(d);
    case FW_NB_U_LN_D: return U * log(d);
    case FW_NB_U_D: return U * d;
    case FW_NB_D2: return d * d;
    case FW_NB_U2: return U * U;
    case FW_NB_INV_U: return 1.0 / U;
    case FW_NB_LN_D_U: return log(d) / U;
    case FW_NB_D_U: return d / U;
    case FW_NB_COUNT: break;
    }
    return 0.0;
}

double fw_nomoto_index_eval(const fw_nomoto_index *ix, double U_kn, double d_deg)
{
    double v = 0.0;
    for (int i = 0; i < ix->n; i++)
        v += ix->coef[i] * basis_value(ix->basis[i], U_kn, d_deg);
    return v;
}

const fw_nomoto_kb *fw_ship_kb(const fw_ship *ship, double helm)
{
    return helm < 0.0 && ship->nomoto_port.present ? &ship->nomoto_port : &ship->nomoto;
}
