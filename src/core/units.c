#include "core/units.h"

#include <math.h>

double fw_heading_deg(double psi_rad)
{
    double d = fw_rad_to_deg(fw_wrap_2pi(psi_rad));
    return d >= 360.0 ? d - 360.0 : d;
}
