/* turn.c - a ship expected to finish its turn (turn.h). */
#include "geom/turn.h"

#include <math.h>
#include <stddef.h>

#include "core/units.h"

static void turn_path(const fw_predictor *self, const fw_target *now, double dt, int n,
                      double *east, double *north, double *heading)
{
    const fw_turn_pred *p = (const fw_turn_pred *)self;
    /* its drift (course over ground less heading) kept through the turn */
    double psi = now->heading, drift = fw_wrap_pi(now->course - now->heading);
    double e = now->east, no = now->north, run = now->speed * dt;
    double turn = p->rate * dt, left = p->turning ? fw_wrap_pi(p->heading - psi) : 0.0;
    int k = 0;
    if (p->turning && turn > 0.0 && fabs(left) > turn) {
        /* whole steps of the turn: the direction of each step's run (its
         * middle heading) rotated by the step, not recomputed */
        double step = copysign(turn, left), cs = cos(step), ss = sin(step);
        double sm = sin(psi + 0.5 * step + drift), cm = cos(psi + 0.5 * step + drift);
        for (; k < n && fabs(left) > turn; k++) {
            east[k] = e, north[k] = no, heading[k] = psi;
            e += run * sm, no += run * cm;
            psi += step, left -= step;
            double s2 = sm * cs + cm * ss;
            cm = cm * cs - sm * ss, sm = s2;
        }
    }
    if (k < n && p->turning && left != 0.0) { /* the last, part step onto its heading */
        east[k] = e, north[k] = no, heading[k] = psi;
        double mid = psi + 0.5 * left + drift;
        e += run * sin(mid), no += run * cos(mid);
        psi += left;
        k++;
    }
    double se = run * sin(psi + drift), sn = run * cos(psi + drift);
    for (; k < n; k++) { /* straight on */
        east[k] = e, north[k] = no, heading[k] = psi;
        e += se, no += sn;
    }
}

static bool turn_steady(const fw_predictor *self)
{
    return !((const fw_turn_pred *)self)->turning;
}

void fw_turn_pred_init(fw_turn_pred *p)
{
    *p = (fw_turn_pred){.base = {.path = turn_path, .steady = turn_steady}};
}

const fw_turn_pred *fw_turn_pred_of(const fw_predictor *p)
{
    return p && p->path == turn_path ? (const fw_turn_pred *)p : NULL;
}
