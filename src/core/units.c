#include "core/units.h"

#include <math.h>

double fw_wrap_pi(double a)
{
    a = fmod(a + FW_PI, 2.0 * FW_PI);
    if (a <= 0.0)
        a += 2.0 * FW_PI;
    return a - FW_PI;
}

double fw_wrap_2pi(double a)
{
    a = fmod(a, 2.0 * FW_PI);
    if (a < 0.0)
        a += 2.0 * FW_PI;
    return a;
}

double fw_heading_deg(double psi_rad)
{
    double d = fw_rad_to_deg(fw_wrap_2pi(psi_rad));
    return d >= 360.0 ? d - 360.0 : d;
}
