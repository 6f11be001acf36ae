/* ramp.h - a ship whose speed changes at a rate: how far it runs, and how
 * close it comes to another ship meanwhile.
 *
 * A background ship told a new speed does not have it at once: SUMO takes
 * it there at its type's acceleration or deceleration (networks/ships.add.xml:
 * accel 0.05 m/s^2 and decel 0.1 m/s^2 for every type but ferries, 0.08 and
 * 0.15, and small craft, 0.2 and 0.3), and fairway steers the ships it takes
 * at the same rates (world/steer.h).  A tanker resuming 13.9 kn from 2 kn
 * needs two minutes and 450 m to get there: judged at its new speed from
 * the start, it passes ahead of a ship it will in fact meet (strait-domain
 * seed 3, replication 0).
 *
 * The ship runs straight on its course (unit vector hx, hy: east and north
 * components), from speed u to v at acc (v > u) or dec (v < u), then holds v.
 * SI throughout. */
#ifndef FW_GEOM_RAMP_H
#define FW_GEOM_RAMP_H

/* m: how far it runs in t s (t >= 0).  Inline: a steered ship's look
 * ahead takes it 60 times a course it judges (world/steer_look.c). */
static inline double fw_ramp_run(double u, double v, double acc, double dec, double t)
{
    double a = v >= u ? acc : -dec, tr = (v - u) / a;
    if (t <= tr)
        return u * t + 0.5 * a * t * t;
    return 0.5 * (u + v) * tr + v * (t - tr);
}

/* The closest approach of that ship, at the origin now, and a ship at (dx,
 * dy) moving at (vx, vy): its time *tcpa (0 when they are opening now and
 * the change of speed does not close them) and the distance squared *d2.
 * While the speed changes the two are taken between points step s apart
 * (a straight line between: at 0.05 m/s^2 and 5 s, at most 0.16 m from the
 * curve); once at v, exactly.  With u == v, fw_cpa_sq's answer for the
 * relative motion (geom.h), tcpa negative when opening. */
void fw_cpa_ramp_sq(double dx, double dy, double vx, double vy, double hx, double hy, double u,
                    double v, double acc, double dec, double step, double *tcpa, double *d2);

#endif
