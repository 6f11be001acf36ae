/* decide_scenes.c - see decide_scenes.h. */
#include "decide_scenes.h"

#include <math.h>
#include <stdio.h>

#include "core/units.h"

static unsigned long long rng;

void decide_seed(unsigned long long seed) { rng = seed; }

double decide_uniform(void)
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

/* A target turning at a constant rate: a predictor other than constant velocity. */
typedef struct turning {
    fw_predictor base;
    double rate; /* rad/s */
} turning;

static void turning_path(const fw_predictor *self, const fw_target *t, double dt, int n,
                         double *east, double *north, double *course)
{
    double rate = ((const turning *)self)->rate, e = t->east, nn = t->north, c = t->course;
    for (int k = 0; k < n; k++) {
        east[k] = e, north[k] = nn, course[k] = c;
        e += t->speed * dt * sin(c + 0.5 * rate * dt);
        nn += t->speed * dt * cos(c + 0.5 * rate * dt);
        c += rate * dt;
    }
}

static const turning kTurnPort = {{turning_path, NULL}, -0.004},
                     kTurnStbd = {{turning_path, NULL}, 0.003};

void decide_scene(const fw_own_state *own, bool dense, fw_target *tg, int n)
{
    for (int i = 0; i < n; i++) {
        double tm = 100 + 500 * decide_uniform(), off = 1600 * (decide_uniform() - 0.5);
        double course = 2 * FW_PI * decide_uniform(), v = fw_kn_to_ms(5 + 10 * decide_uniform());
        /* the aim point on the own ship's straight track, tm s ahead */
        double along = own->U * tm + 1600 * (decide_uniform() - 0.5);
        double me = own->east + along * sin(own->psi) + off * cos(own->psi);
        double mn = own->north + along * cos(own->psi) - off * sin(own->psi);
        if (!dense && i % 10 != 0) {
            double rr = 3 * FW_NMILE * sqrt(decide_uniform()), b = 2 * FW_PI * decide_uniform();
            me = own->east + rr * sin(b) + v * sin(course) * tm;
            mn = own->north + rr * cos(b) + v * cos(course) * tm;
        }
        double u = decide_uniform();
        tg[i] = (fw_target){.east = me - v * sin(course) * tm, .north = mn - v * cos(course) * tm,
                            .course = course, .heading = course, .speed = v, .length = 100 + 200 * decide_uniform(),
                            .breadth = 30,
                            .pred = u < 0.07 ? &kTurnPort.base
                                    : u < 0.14 ? &kTurnStbd.base : NULL};
        snprintf(tg[i].id, sizeof tg[i].id, "t%d", i);
    }
}

fw_own_state decide_own(bool turning_now)
{
    fw_own_state o = {.east = 2000 * (decide_uniform() - 0.5), .north = 2000 * (decide_uniform() - 0.5),
                      .psi = 2 * FW_PI * decide_uniform(), .U = fw_kn_to_ms(6 + 8 * decide_uniform())};
    if (turning_now) {
        o.r = fw_deg_to_rad(0.6 * (decide_uniform() - 0.5));
        o.rdot = fw_deg_to_rad(0.02 * (decide_uniform() - 0.5));
        o.delta = fw_deg_to_rad(40 * (decide_uniform() - 0.5));
        o.beta = fw_deg_to_rad(4 * (decide_uniform() - 0.5));
        o.U0 = o.U * (1.0 + 0.2 * decide_uniform());
    }
    return o;
}
