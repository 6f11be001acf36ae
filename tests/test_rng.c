/* test_rng.c - fairway's random streams (core/rng.h): Philox4x32-10 against
 * Random123's known answers, the distributions' moments, independence of
 * neighbouring keys, restart at a counter, branches.
 *
 * The statistical checks draw 1e6 values from fixed keys, so they are
 * deterministic; their bounds are set where a fair generator would land
 * outside with probability about 1e-3 (chi-square) or 5 standard errors
 * (moments, correlation), so a pass says the numbers are not visibly off.
 */
#include <math.h>
#include <stdint.h>

#include "core/rng.h"
#include "world/world.h"
#include "test.h"

#define N_DRAWS 1000000

/* Random123 1.14, tests/kat_vectors, the three "philox4x32 10" lines:
 * counter (4 words), key (2 words), expected output (4 words). */
static void test_known_answers(void)
{
    static const uint32_t kat[3][10] = {
        {0x00000000, 0x00000000, 0x00000000, 0x00000000, 0x00000000, 0x00000000,
         0x6627e8d5, 0xe169c58d, 0xbc57ac4c, 0x9b00dbd8},
        {0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff,
         0x408f276d, 0x41c83b0e, 0xa20bc7c6, 0x6d5451fd},
        {0x243f6a88, 0x85a308d3, 0x13198a2e, 0x03707344, 0xa4093822, 0x299f31d0,
         0xd16cfe09, 0x94fdcceb, 0x5001e420, 0x24126ea1},
    };
    for (int v = 0; v < 3; v++) {
        uint32_t out[4];
        fw_philox4x32_10(&kat[v][0], &kat[v][4], out);
        for (int i = 0; i < 4; i++)
            CHECK_MSG(out[i] == kat[v][6 + i], "vector %d word %d: %08x, expected %08x", v, i,
                      out[i], kat[v][6 + i]);
    }
    /* the stream is that generator: seed 0, vessel 0, purpose 0 draws block
     * (0, 0, 0, 0) first, then block (1, 0, 0, 0) */
    fw_rng s = fw_rng_make(0, 0, (fw_purpose)0);
    uint64_t a, b;
    fw_rng_block(&s, &a, &b);
    CHECK(a == 0xe169c58d6627e8d5ull && b == 0x9b00dbd8bc57ac4cull);
    CHECK(s.counter == 1);
    s.counter = 0;
    CHECK(fw_rng_uniform(&s) == (double)(0xe169c58d6627e8d5ull >> 11) * 0x1.0p-53);
    /* the run seed's low word is key word 0 (Random123's third vector) */
    fw_rng p = fw_rng_make(0x299f31d0a4093822ull, 0x13198a2e, (fw_purpose)0x03707344);
    p.counter = 0x85a308d3243f6a88ull;
    fw_rng_block(&p, &a, &b);
    CHECK(a == 0x94fdccebd16cfe09ull && b == 0x24126ea15001e420ull);
}

/* Pearson's chi-square of N_DRAWS uniforms in 100 equal bins. */
static double chi_square_100(fw_rng s)
{
    static long bins[100];
    for (int i = 0; i < 100; i++)
        bins[i] = 0;
    long outside = 0;
    for (long n = 0; n < N_DRAWS; n++) {
        double u = fw_rng_uniform(&s);
        if (u >= 0.0 && u < 1.0)
            bins[(int)(u * 100.0)]++;
        else
            outside++;
    }
    CHECK_MSG(outside == 0, "%ld draws outside [0, 1)", outside);
    double e = N_DRAWS / 100.0, x2 = 0.0;
    for (int i = 0; i < 100; i++)
        x2 += (bins[i] - e) * (bins[i] - e) / e;
    return x2;
}

/* Uniform: chi-square over 100 bins with 99 degrees of freedom, for keys that
 * differ in seed, vessel, purpose and branch.  Bounds: the 0.001 and 0.999
 * quantiles of chi-square(99), 61.1 and 148.2 (Wilson-Hilferty; tables give
 * 148.23 for the upper), so a fair generator fails one key with probability
 * 0.002; too even counts fail too. */
static void test_uniform_chi_square(void)
{
    fw_rng parent = fw_rng_make(1, 0, FW_PURPOSE_SENSING);
    const fw_rng keys[] = {
        parent,
        fw_rng_make(1, 7, FW_PURPOSE_SENSING),
        fw_rng_make(2, 0, FW_PURPOSE_GUST),
        fw_rng_make(0x123456789abcdefull, 0xffffffffu, FW_PURPOSE_BEHAVIOUR),
        fw_rng_branch(&parent, 3),
    };
    for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++) {
        double x2 = chi_square_100(keys[k]);
        printf("  key %zu: chi-square %.1f\n", k, x2);
        CHECK_MSG(x2 > 61.1 && x2 < 148.2, "key %zu: chi-square %.1f", k, x2);
    }
}

/* Normal: mean 0, variance 1, excess kurtosis 0, each within 5 standard
 * errors of N_DRAWS draws (1e-3, sqrt(2/n) = 1.4e-3, sqrt(24/n) = 4.9e-3);
 * and tail mass beyond 3 within 5 standard errors of 0.0027. */
static void test_normal_moments(void)
{
    fw_rng s = fw_rng_make(42, 1, FW_PURPOSE_SENSING);
    double m1 = 0.0, m2 = 0.0, m4 = 0.0;
    long tail = 0, bad = 0;
    for (long n = 0; n < N_DRAWS; n++) {
        double z = fw_rng_normal(&s);
        bad += !isfinite(z);
        m1 += z;
        m2 += z * z;
        m4 += z * z * z * z;
        tail += fabs(z) > 3.0;
    }
    CHECK(bad == 0);
    double mean = m1 / N_DRAWS, var = m2 / N_DRAWS - mean * mean;
    printf("  normal: mean %.5f, variance %.5f, excess kurtosis %.5f, beyond 3: %.5f\n", mean, var,
           m4 / N_DRAWS / (var * var) - 3.0, (double)tail / N_DRAWS);
    CHECK_NEAR(mean, 0.0, 5e-3);
    CHECK_NEAR(var, 1.0, 7e-3);
    CHECK_NEAR(m4 / N_DRAWS / (var * var) - 3.0, 0.0, 0.025);
    double p3 = erfc(3.0 / sqrt(2.0));
    CHECK_NEAR((double)tail / N_DRAWS, p3, 5.0 * sqrt(p3 * (1 - p3) / N_DRAWS));
}

/* Exponential: mean 1 and variance 1 within 5 standard errors (1e-3 and
 * sqrt(8/n) = 2.8e-3); never negative. */
static void test_exponential_moments(void)
{
    fw_rng s = fw_rng_make(42, 1, FW_PURPOSE_WATCH);
    double m1 = 0.0, m2 = 0.0, lo = INFINITY;
    for (long n = 0; n < N_DRAWS; n++) {
        double x = fw_rng_exponential(&s);
        m1 += x;
        m2 += x * x;
        lo = fmin(lo, x);
    }
    double mean = m1 / N_DRAWS;
    printf("  exponential: mean %.5f, variance %.5f\n", mean, m2 / N_DRAWS - mean * mean);
    CHECK_NEAR(mean, 1.0, 5e-3);
    CHECK_NEAR(m2 / N_DRAWS - mean * mean, 1.0, 0.014);
    CHECK(lo >= 0.0);
}

/* Pearson's r of N_DRAWS pairs of uniforms from two streams. */
static double correlation(fw_rng a, fw_rng b)
{
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    for (long n = 0; n < N_DRAWS; n++) {
        double x = fw_rng_uniform(&a), y = fw_rng_uniform(&b);
        sa += x;
        sb += y;
        saa += x * x;
        sbb += y * y;
        sab += x * y;
    }
    double cov = sab / N_DRAWS - sa / N_DRAWS * sb / N_DRAWS;
    double va = saa / N_DRAWS - sa / N_DRAWS * sa / N_DRAWS;
    double vb = sbb / N_DRAWS - sb / N_DRAWS * sb / N_DRAWS;
    return cov / sqrt(va * vb);
}

/* Keys one bit apart (in the seed, the vessel, the purpose) give streams
 * whose draws are uncorrelated: |r| < 0.005 on 1e6 pairs, 5 standard
 * errors. */
static void test_neighbour_keys_uncorrelated(void)
{
    fw_rng s = fw_rng_make(1000, 5, FW_PURPOSE_SENSING);
    double r_seed = correlation(s, fw_rng_make(1000 ^ (1ull << 40), 5, FW_PURPOSE_SENSING));
    double r_vessel = correlation(s, fw_rng_make(1000, 5 ^ 1, FW_PURPOSE_SENSING));
    double r_purpose = correlation(s, fw_rng_make(1000, 5, FW_PURPOSE_SENSING ^ 2));
    printf("  r: seed bit %.5f, vessel bit %.5f, purpose bit %.5f\n", r_seed, r_vessel, r_purpose);
    CHECK_MSG(fabs(r_seed) < 0.005, "seed bit 40: r = %.5f", r_seed);
    CHECK_MSG(fabs(r_vessel) < 0.005, "vessel bit 0: r = %.5f", r_vessel);
    CHECK_MSG(fabs(r_purpose) < 0.005, "purpose bit 1: r = %.5f", r_purpose);
    /* a stream against itself, for the measure's sake */
    CHECK_NEAR(correlation(s, s), 1.0, 1e-12);
}

/* A stream's state is its key and counter: one restarted at counter k (a
 * copy of the struct, or a fresh stream with its counter set) continues
 * exactly, whatever kinds of draw came before. */
static void test_restart_at_counter(void)
{
    enum { N = 3000, K = 1234 };
    static double first[N];
    fw_rng s = fw_rng_make(77, 3, FW_PURPOSE_BEHAVIOUR);
    fw_rng at_k = s;
    for (int n = 0; n < N; n++) {
        if (n == K)
            at_k = s; /* the snapshot */
        first[n] = n % 3 == 0 ? fw_rng_uniform(&s)
                   : n % 3 == 1 ? fw_rng_normal(&s)
                                : fw_rng_exponential(&s);
    }
    fw_rng fresh = fw_rng_make(77, 3, FW_PURPOSE_BEHAVIOUR);
    fresh.counter = K;
    int same_copy = 1, same_fresh = 1;
    for (int n = K; n < N; n++) {
        double c = n % 3 == 0 ? fw_rng_uniform(&at_k)
                   : n % 3 == 1 ? fw_rng_normal(&at_k)
                                : fw_rng_exponential(&at_k);
        double f = n % 3 == 0 ? fw_rng_uniform(&fresh)
                   : n % 3 == 1 ? fw_rng_normal(&fresh)
                                : fw_rng_exponential(&fresh);
        same_copy &= c == first[n];
        same_fresh &= f == first[n];
    }
    CHECK(same_copy);
    CHECK(same_fresh);
    CHECK(s.counter == N && at_k.counter == N);
}

/* Branches: each differs from its parent and from the others (no equal
 * draw among the first 1000 of any two, where equal 53-bit draws would come
 * by chance with probability 1e-10), a branch of a branch too; the parent is
 * not moved by branching; the same branch number gives the same stream. */
static void test_branches(void)
{
    enum { B = 4, N = 1000 };
    fw_rng parent = fw_rng_make(9, 2, FW_PURPOSE_GUST);
    for (int n = 0; n < 500; n++)
        fw_rng_uniform(&parent);
    const fw_rng before = parent;
    fw_rng s[B + 2];
    s[0] = parent;
    for (int b = 1; b <= B; b++)
        s[b] = fw_rng_branch(&parent, (uint32_t)b);
    s[B + 1] = fw_rng_branch(&s[1], 1);
    CHECK(parent.counter == before.counter && parent.key[0] == before.key[0] &&
          parent.key[1] == before.key[1]);
    for (int b = 1; b <= B + 1; b++)
        CHECK(s[b].counter == 0 && s[b].vessel == 2 && s[b].purpose == FW_PURPOSE_GUST);
    static double v[B + 2][N];
    for (int i = 0; i < B + 2; i++)
        for (int n = 0; n < N; n++)
            v[i][n] = fw_rng_uniform(&s[i]);
    int clashes = 0;
    for (int i = 0; i < B + 2; i++)
        for (int j = i + 1; j < B + 2; j++)
            for (int n = 0; n < N; n++)
                for (int m = 0; m < N; m++)
                    clashes += v[i][n] == v[j][m];
    CHECK_MSG(clashes == 0, "%d equal draws between streams", clashes);
    fw_rng again = fw_rng_branch(&before, 3);
    CHECK(again.key[0] == s[3].key[0] && again.key[1] == s[3].key[1]);
    CHECK(fw_rng_uniform(&again) == v[3][0]);
    /* the branch's draws are uniform too (its chi-square is in
     * test_uniform_chi_square) and uncorrelated with the parent's */
    fw_rng p0 = fw_rng_make(9, 2, FW_PURPOSE_GUST);
    double r = correlation(p0, fw_rng_branch(&p0, 1));
    printf("  r: branch against parent %.5f\n", r);
    CHECK_MSG(fabs(r) < 0.005, "branch against parent: r = %.5f", r);
}

/* The world carries the run's seed for its vessels' streams: 1 by default,
 * the def's when given. */
static void test_world_seed(void)
{
    fw_world_def wd = fw_default_world_def();
    CHECK(wd.seed == 1);
    wd.seed = 0x8000000000000001ull;
    fw_world *w = NULL;
    fw_error err = {0};
    CHECK(fw_world_create(&wd, &w, &err) == FW_OK);
    if (w)
        CHECK(fw_world_seed(w) == 0x8000000000000001ull);
    fw_world_destroy(w);
}

/* The world's table of streams: one stream per (vessel, purpose), pointers
 * that survive growth, numbers those of fw_rng_make; a re-keying gives every
 * stream, and one first asked for afterwards, the numbers fw_rng_branch
 * gives, so when an element asks does not matter. */
static void test_world_streams(void)
{
    fw_world_def wd = fw_default_world_def();
    wd.seed = 77;
    fw_world *w = NULL;
    fw_error err = {0};
    CHECK(fw_world_create(&wd, &w, &err) == FW_OK);
    if (!w)
        return;
    CHECK(fw_world_streams(w) == 0);
    fw_rng *first = fw_world_rng(w, 5, FW_PURPOSE_WATCH);
    for (uint32_t v = 100; v < 200; v++) /* past a few blocks of the table */
        CHECK(fw_world_rng(w, v, FW_PURPOSE_SENSING) != NULL);
    CHECK(fw_world_rng(w, 5, FW_PURPOSE_WATCH) == first);
    CHECK(fw_world_streams(w) == 101);
    fw_rng ref = fw_rng_make(77, 5, FW_PURPOSE_WATCH);
    CHECK(fw_rng_uniform(first) == fw_rng_uniform(&ref));
    fw_rng before = *first;
    CHECK(fw_world_rekey(w, 3));
    fw_rng want = fw_rng_branch(&before, 3);
    CHECK(fw_rng_uniform(first) == fw_rng_uniform(&want));
    fw_rng late_ref = fw_rng_make(77, 9, FW_PURPOSE_GUST);
    late_ref = fw_rng_branch(&late_ref, 3);
    CHECK(fw_rng_uniform(fw_world_rng(w, 9, FW_PURPOSE_GUST)) == fw_rng_uniform(&late_ref));
    fw_world_destroy(w);
}

int main(void)
{
    TEST_RUN(test_known_answers);
    TEST_RUN(test_uniform_chi_square);
    TEST_RUN(test_normal_moments);
    TEST_RUN(test_exponential_moments);
    TEST_RUN(test_neighbour_keys_uncorrelated);
    TEST_RUN(test_restart_at_counter);
    TEST_RUN(test_branches);
    TEST_RUN(test_world_seed);
    TEST_RUN(test_world_streams);
    return TEST_EXIT();
}
