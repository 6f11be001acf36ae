/* bench_reactions - the cost of reactive traffic: time per world step with
 * 50 and 200 background ships, behaviour colregs against blind, same traffic.
 *
 * The world: the kinematic source (no SUMO, so the figure is fairway's own
 * cost) with N ships on random straight courses at 5-20 kn inside a square
 * around the own ship (the C-3, Nomoto dynamics, no controller: the
 * avoidance policy's cost is bench_helm's), sized so that about N ships are
 * within the own ship's 6 nm sight (the strait holds 60-100 at density 2).
 * Per configuration RUNS runs of STEPS steps (different seeds, colregs and
 * blind interleaved on the same seed); printed: the median time per step of
 * each, their ratio (colregs / blind, measured in the same run), and the
 * orders given.  Results: bench/results/reactions.txt. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"
#include "core/units.h"
#include "traffic/source.h"
#include "world/world.h"

enum { STEPS = 600, RUNS = 5, MAX_SHIPS = 400 };

static uint64_t rng;
static double urand(void)
{
    rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rng >> 11) * (1.0 / 9007199254740992.0);
}

/* Seconds per step of one world, and the orders it gave. */
static double one(const fw_ship *ship, const fw_kin_ship *ships, int n, fw_behaviour b,
                  int *orders)
{
    fw_error err = {0};
    fw_kinematic_def kd = fw_default_kinematic_def();
    kd.ships = ships;
    kd.n = n;
    fw_world_def wd = fw_default_world_def();
    wd.reactions.behaviour = b;
    fw_world *w = NULL;
    fw_vessel_def vd = fw_default_vessel_def();
    vd.ship = ship;
    vd.dynamics = FW_DYN_NOMOTO;
    vd.speed = fw_kn_to_ms(12);
    if (fw_kinematic_source_create(&kd, &wd.source, &err) || fw_world_create(&wd, &w, &err) ||
        fw_world_add_vessel(w, &vd, NULL, &err) || fw_world_start(w, &err)) {
        fprintf(stderr, "bench_reactions: %s\n", err.msg);
        exit(1);
    }
    double t0 = bench_now();
    for (int k = 0; k < STEPS; k++)
        if (fw_world_step(w, 1.0, &err)) {
            fprintf(stderr, "bench_reactions: %s\n", err.msg);
            exit(1);
        }
    double dt = (bench_now() - t0) / STEPS;
    fw_world_reactions(w, orders);
    fw_world_destroy(w);
    return dt;
}

int main(int argc, char **argv)
{
    (void)argv;
    if (argc > 1) {
        fprintf(stderr, "usage: bench_reactions (no arguments; prints medians of %d runs)\n", RUNS);
        return 2;
    }
    fw_ship ship;
    fw_error err = {0};
    if (fw_ship_load("c3", &ship, &err)) {
        fprintf(stderr, "bench_reactions: %s\n", err.msg);
        return 1;
    }
    static fw_kin_ship ships[MAX_SHIPS];
    static const int counts[] = {50, 200};
    printf("%8s %14s %14s %8s %12s\n", "ships", "blind_us", "colregs_us", "ratio", "orders_per_h");
    for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
        int n = counts[c];
        double tb[RUNS], tc[RUNS], ratio[RUNS], orders = 0.0;
        /* n ships within 6 nm: a disc of that radius, and the square around it */
        double half = 6.0 * FW_NMILE * sqrt(FW_PI) / 2.0;
        for (int r = 0; r < RUNS; r++) {
            rng = 1000003ULL * (uint64_t)(r + 1) + (uint64_t)n;
            for (int i = 0; i < n; i++) {
                double e, no;
                do {
                    e = half * (2 * urand() - 1), no = half * (2 * urand() - 1);
                } while (hypot(e, no) < 2 * FW_NMILE); /* none on top of the own ship */
                ships[i] = (fw_kin_ship){.start = {.east = e, .north = no,
                                                   .course = 2 * FW_PI * urand(),
                                                   .speed = fw_kn_to_ms(5 + 15 * urand()),
                                                   .length = 100 + 200 * urand(), .breadth = 30}};
                snprintf(ships[i].start.id, sizeof ships[i].start.id, "s%03d", i);
            }
            int ob, oc;
            tb[r] = one(&ship, ships, n, FW_BEHAVIOUR_BLIND, &ob);
            tc[r] = one(&ship, ships, n, FW_BEHAVIOUR_COLREGS, &oc);
            ratio[r] = tc[r] / tb[r];
            orders += oc * 3600.0 / STEPS / RUNS;
        }
        printf("%8d %14.1f %14.1f %8.2f %12.0f\n", n, 1e6 * bench_median(tb, RUNS),
               1e6 * bench_median(tc, RUNS), bench_median(ratio, RUNS), orders);
    }
    return 0;
}
