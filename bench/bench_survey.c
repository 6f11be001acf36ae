/* bench_survey - time per fw_survey_step with 100, 1000 and 5000 ships, the
 * cell grid against testing every pair, on the same steps of the same traffic.
 *
 * Traffic: a square sized for a busy strait's density (0.1 ships per km^2:
 * about 35 ships within 6 nm, what the crossing network holds at four times
 * its demand), 80 % of the ships along four lane directions, the rest
 * anywhere, 2-10 m/s; each 1 s step a ship may turn (0.2 %), leaves when it
 * crosses the edge or by chance (0.05 %), and newcomers keep the count.
 * Default survey settings (2000 m, 1000 m, 1000 s, hysteresis 500 m).
 * Per run: WARMUP steps, then STEPS steps each timed for both surveys (fed
 * in alternating order); per run the medians and their ratio; printed: the
 * medians over RUNS runs (different seeds, the sizes interleaved).  The two
 * surveys' records are compared at the end of every run ("same"). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "core/units.h"
#include "survey/survey.h"

enum { WARMUP = 60, STEPS = 120, RUNS = 7 };
static const double kDensity = 0.1e-6; /* ships per m^2 */

static uint64_t rng;
static double urand(void)
{
    rng += 0x9e3779b97f4a7c15ULL;
    uint64_t z = rng;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return (double)((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}

typedef struct ship {
    char id[16];
    double e, n, h, v;
} ship;

static int next_id;

static void spawn(ship *s, double half)
{
    snprintf(s->id, sizeof s->id, "v%d", next_id++);
    s->e = (2 * urand() - 1) * half;
    s->n = (2 * urand() - 1) * half;
    s->h = urand() < 0.8 ? floor(urand() * 4) * FW_PI / 2 + 0.1 * (urand() - 0.5)
                         : 2 * FW_PI * urand();
    s->v = 2.0 + 8.0 * urand();
}

static void advance(ship *s, int n, double half)
{
    for (int i = 0; i < n; i++) {
        if (urand() < 0.002)
            s[i].h += (urand() - 0.5) * FW_PI;
        s[i].e += s[i].v * sin(s[i].h);
        s[i].n += s[i].v * cos(s[i].h);
        if (fabs(s[i].e) > half || fabs(s[i].n) > half || urand() < 0.0005)
            spawn(&s[i], half);
    }
}

static bool same(const fw_survey *a, const fw_survey *b)
{
    int na, nb;
    const fw_survey_record *ra = fw_survey_records(a, &na), *rb = fw_survey_records(b, &nb);
    if (na != nb)
        return false;
    for (int i = 0; i < na; i++)
        if (strcmp(ra[i].ship_a, rb[i].ship_a) || strcmp(ra[i].ship_b, rb[i].ship_b) ||
            ra[i].t_first != rb[i].t_first || ra[i].min_dist != rb[i].min_dist ||
            ra[i].type != rb[i].type)
            return false;
    return true;
}

/* One run: out = median us per step of grid and all pairs (0 without),
 * records, the two agree. */
static int one_run(int n, int run, bool brute, double out[4])
{
    double half = 0.5 * sqrt(n / kDensity);
    ship *s = malloc(sizeof *s * (size_t)n);
    fw_target *in = malloc(sizeof *in * (size_t)n);
    static double tg[STEPS], tb[STEPS];
    fw_survey_def d = fw_default_survey_def(), db = d;
    db.brute_force = true;
    fw_survey *g = NULL, *b = NULL;
    fw_error err = {0};
    if (!s || !in || fw_survey_create(&d, &g, &err) || fw_survey_create(&db, &b, &err)) {
        fprintf(stderr, "bench_survey: %s\n", err.msg[0] ? err.msg : "out of memory");
        return 1;
    }
    rng = 1000003ULL * (uint64_t)(run + 1) + (uint64_t)n;
    next_id = 0;
    for (int i = 0; i < n; i++)
        spawn(&s[i], half);
    for (int k = 0; k < WARMUP + STEPS; k++) {
        for (int i = 0; i < n; i++)
            in[i] = fw_target_named(s[i].id, (fw_target){ .east = s[i].e, .north = s[i].n,
                                     .course = s[i].h, .heading = s[i].h, .speed = s[i].v, .length = 150,
                                     .breadth = 25, .own = i == 0});
        double dt[2] = {0.0, 0.0};
        for (int j = 0; j < 1 + brute; j++) {
            /* alternate which goes first */
            fw_survey *sv = brute && (k + j) % 2 ? b : g;
            double t0 = bench_now();
            if (fw_survey_step(sv, k, in, n, &err)) {
                fprintf(stderr, "bench_survey: %s\n", err.msg);
                return 1;
            }
            dt[sv == b] = 1e6 * (bench_now() - t0);
        }
        if (k >= WARMUP) {
            tg[k - WARMUP] = dt[0];
            tb[k - WARMUP] = dt[1];
        }
        advance(s, n, half);
    }
    fw_survey_totals tot;
    fw_survey_finish(g, &tot);
    fw_survey_finish(b, NULL);
    out[0] = bench_median(tg, STEPS);
    out[1] = bench_median(tb, STEPS);
    out[2] = tot.n;
    out[3] = !brute || same(g, b);
    fw_survey_destroy(g);
    fw_survey_destroy(b);
    free(s);
    free(in);
    return 0;
}

enum { NSIZES = 4 };

int main(void)
{
    /* all pairs at 20000 ships would take minutes: the grid alone there */
    const int sizes[NSIZES] = {100, 1000, 5000, 20000};
    const bool brute[NSIZES] = {true, true, true, false};
    printf("# fairway bench_survey: fw_survey_step, cell grid vs all pairs, same steps\n");
    printf("# density %.2f ships/km^2, 1 s steps, %d timed after %d warm-up, median of %d runs\n",
           kDensity * 1e6, STEPS, WARMUP, RUNS);
    printf("%6s %8s %10s %10s %12s %13s %7s %9s %5s\n", "ships", "side_km", "grid_us",
           "pairs_us", "grid_ns/ship", "pairs_ns/ship", "ratio", "records", "same");
    /* runs outermost, sizes inside: every size sees the same spells of a
     * shared machine's load */
    static double g[NSIZES][RUNS], b[NSIZES][RUNS], ratio[NSIZES][RUNS], rec[NSIZES];
    bool all_same = true;
    for (int run = 0; run < RUNS; run++)
        for (int i = 0; i < NSIZES; i++) {
            double o[4];
            if (one_run(sizes[i], run, brute[i], o))
                return 1;
            g[i][run] = o[0];
            b[i][run] = o[1];
            ratio[i][run] = o[1] / o[0];
            rec[i] += o[2] / RUNS;
            all_same &= o[3] != 0.0;
        }
    double per_ship[NSIZES];
    for (int i = 0; i < NSIZES; i++) {
        double mg = bench_median(g[i], RUNS), mb = bench_median(b[i], RUNS);
        per_ship[i] = 1e3 * mg / sizes[i];
        printf("%6d %8.1f %10.1f ", sizes[i], sqrt(sizes[i] / kDensity) / 1e3, mg);
        if (brute[i])
            printf("%10.1f %12.1f %13.1f %7.1f", mb, per_ship[i], 1e3 * mb / sizes[i],
                   bench_median(ratio[i], RUNS));
        else
            printf("%10s %12.1f %13s %7s", "-", per_ship[i], "-", "-");
        printf(" %9.0f %5s\n", rec[i], brute[i] ? (all_same ? "yes" : "NO") : "-");
    }
    if (!all_same)
        return 1;
    /* linear cost = a flat ns per ship; the step from 1000 to 5000 ships is
     * the step's data (about 1 MB at 5000) leaving the per-core L2 */
    printf("# grid ns per ship: 1000 -> 5000 ships x%.2f, 5000 -> 20000 x%.2f (flat = linear); "
           "all pairs x%.2f for 1000 -> 5000\n", per_ship[2] / per_ship[1],
           per_ship[3] / per_ship[2],
           bench_median(b[2], RUNS) / sizes[2] / (bench_median(b[1], RUNS) / sizes[1]));
    return 0;
}
