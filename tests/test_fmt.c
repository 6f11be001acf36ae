/* test_fmt.c - fw_fmt_fixed writes what printf's "%.Nf" writes, byte for byte:
 * the run's CSV columns (positions, headings, speeds, times), exact ties and
 * near ties, signs and zeros, huge and non-finite values. */
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>

#include "core/fmt.h"
#include "test.h"

static uint64_t rng = 12345;
static double urand(void)
{
    rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rng >> 11) / 9007199254740992.0;
}

static int fast = 0; /* values fw_fmt_fixed wrote itself */

/* v through fw_put_fixed, fw_fmt_fixed and printf; 1 if they differ (the
 * first few printed). */
static int differs(double v, int d)
{
    char a[FW_FMT_FIXED_MAX], b[400], *c = NULL;
    size_t nc = 0;
    int n = fw_fmt_fixed(a, v, d);
    snprintf(b, sizeof b, "%.*f", d, v);
    FILE *f = open_memstream(&c, &nc);
    fw_put_fixed(f, v, d);
    fclose(f);
    fast += n >= 0;
    bool same = (n < 0 || (n == (int)strlen(b) && strcmp(a, b) == 0)) && strcmp(c, b) == 0;
    if (!same)
        strcpy(a, c);
    free(c);
    static int shown = 0;
    if (!same && shown++ < 10)
        fprintf(stderr, "%.17g with %d decimals: '%s', printf '%s'\n", v, d, a, b);
    return !same;
}

static void test_run_columns(void)
{
    /* the magnitudes of the CSV columns, 1 to 7 decimals, both signs */
    const double scale[] = {1.0, 30.0, 360.0, 3600.0, 2.0e4, 1.0e5, 1.0e6, 1.0e7};
    int bad = 0, n = 0;
    fast = 0;
    for (int k = 0; k < 400000; k++) {
        double v = (urand() - 0.3) * scale[k % 8];
        for (int d = 1; d <= 7; d++, n++)
            bad += differs(v, d);
    }
    CHECK_MSG(bad == 0, "%d of %d differ", bad, n);
    /* and the fast path is the usual one (near ties are some 1e-4 of all) */
    CHECK_MSG(fast > n - n / 1000, "only %d of %d written without printf", fast, n);
}

static void test_ties_and_edges(void)
{
    int bad = 0;
    /* exact binary ties (x.5 / 10^d with a short binary expansion) and their
     * neighbours one ulp either side */
    for (int i = -4000; i <= 4000; i++) {
        double t = (double)i / 8.0; /* 0.125, 0.375, ...: ties at 2 decimals */
        for (int d = 0; d <= 4; d++) {
            bad += differs(t, d);
            bad += differs(nextafter(t, INFINITY), d);
            bad += differs(nextafter(t, -INFINITY), d);
        }
    }
    /* decimal near-ties the binary cannot hold: 0.005, 1.015, 2.675, ... */
    for (int i = 0; i < 20000; i++) {
        double t = ((double)i + 0.5) / 100.0;
        bad += differs(t, 2) + differs(-t, 2) + differs(t * 10.0, 1) + differs(t / 10.0, 3);
    }
    const double odd[] = {0.0, -0.0, 1e-300, -1e-300, 0.5, -0.5, 1.5, 2.5, 9.9999999,
                          -9.99999999, 999999.9999999, 1e14, 1e15, 1e16, -3e17, 1e300,
                          INFINITY, -INFINITY, NAN, 4503599627370495.5, 0.049999999999999996};
    for (size_t i = 0; i < sizeof odd / sizeof *odd; i++)
        for (int d = 0; d <= 9; d++)
            bad += differs(odd[i], d);
    CHECK_MSG(bad == 0, "%d edge values differ", bad);
    char s[FW_FMT_FIXED_MAX];
    CHECK(fw_fmt_fixed(s, -0.001, 2) == 5 && strcmp(s, "-0.00") == 0);
    CHECK(fw_fmt_fixed(s, 3600.0, 1) == 6 && strcmp(s, "3600.0") == 0);
    CHECK(fw_fmt_fixed(s, NAN, 2) == -1 && fw_fmt_fixed(s, 1e300, 2) == -1);
    CHECK(fw_fmt_fixed(s, 0.125, 2) == -1); /* a tie: printf's to settle */
}

int main(void)
{
    TEST_RUN(test_run_columns);
    TEST_RUN(test_ties_and_edges);
    return TEST_EXIT();
}
