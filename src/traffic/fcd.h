/* fcd.h - the floating car data of a run, every ship SUMO has, in SUMO's own
 * FCD layout (what --fcd-output writes: <fcd-export><timestep time><vehicle
 * id x y angle type speed/>): x/y the front bumper in the network's
 * coordinates, angle navigational degrees, speed m/s.  Internal to
 * src/traffic.
 *
 * fairway writes it, not SUMO: SUMO 1.15 (Debian's) dies in its FCD output
 * on a vehicle that moveToXY put off every lane (it reads that vehicle's
 * lane, which is null), and the own ship is such a vehicle most of the time
 * (measured: a segmentation fault at the first step, with sumo through TraCI
 * and with libsumo alike, whatever --fcd-output.attributes says).  The
 * values are the ones SUMO's getters give, so SUMO's tools that read FCD
 * (traceExporter.py, plot_trajectories.py) read this file.
 */
#ifndef FW_TRAFFIC_FCD_H
#define FW_TRAFFIC_FCD_H

#include <stdbool.h>
#include <stdio.h>

#include "core/error.h"
#include "traffic/backend.h"

typedef struct fw_fcd fw_fcd;

/* One character into an XML attribute value, escaped (& < "): the FCD's and
 * run.sumocfg's (sumofiles.c). */
void fw_xml_putc(int c, FILE *f);

/* Starts path (under a temporary name until fw_fcd_close). */
fw_status fw_fcd_open(const char *path, fw_fcd **out, fw_error *err);
/* One timestep: the ships in v. */
fw_status fw_fcd_step(fw_fcd *f, double time, const fw_sumo_raw *v, int n, fw_error *err);
/* Ends the file and gives it its name (keep), or removes it; frees f.  Safe
 * on NULL. */
fw_status fw_fcd_close(fw_fcd *f, bool keep, fw_error *err);

#endif
