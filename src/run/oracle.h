/* oracle.h - the best a fixed manoeuvre can do in a scenario with explicit targets.
 *
 * The yardstick for "keeps the domain wherever 35 deg of helm can": the own
 * ship (the scenario's MMG ship, straight running at its speed) puts the helm
 * hard over to one side at t_act, holds it until the heading has changed by a
 * given angle, then holds that heading; the targets keep course and speed.
 * Over both sides and alterations of 15 to 180 deg (and keeping course) the
 * oracle reports the manoeuvre whose smallest normalised domain radius over
 * all targets is largest.  If even that is below 1, no such manoeuvre keeps
 * the domain, and the case is named as one where 35 deg cannot.
 */
#ifndef FW_ORACLE_H
#define FW_ORACLE_H

#include "scenario/scenario.h"

typedef struct fw_oracle_def {
    double t_act;     /* s, when the helm goes over (0: at the start) */
    double helm;      /* rad, 0 = the ship's maximum rudder angle */
    double step;      /* s, 1 */
    double after;     /* s, how long after t_act to follow (0 = to the scenario's end) */
} fw_oracle_def;

fw_oracle_def fw_default_oracle_def(void);

typedef struct fw_oracle_result {
    double best_lambda;  /* smallest normalised domain radius on the best manoeuvre */
    double best_dist;    /* m, smallest centre distance on it */
    int side;            /* +1 starboard, -1 port, 0 keep course */
    double alteration;   /* rad, heading change of the best manoeuvre */
    int manoeuvres;      /* how many were tried */
} fw_oracle_result;

fw_status fw_oracle_best(const fw_scenario *s, const fw_oracle_def *def, fw_oracle_result *out,
                         fw_error *err);

#endif
