/* Identification: Nomoto indices fitted to MMG turning tests (small grid). */
#include <math.h>
#include <stdlib.h>

#include "core/units.h"
#include "nomoto/identify.h"
#include "test.h"

static fw_ship c3;

static void test_fit_recovers_known_indices(void)
{
    /* a synthetic history from known indices is fitted back exactly */
    fw_nomoto_indices truth = {.K = 0.02, .T1 = 12, .T2 = 70, .T3 = 80}, fit;
    double r[400], rms;
    fw_ident_response(&truth, fw_deg_to_rad(20), c3.rudder_rate, 1.0, 400, r);
    CHECK(fw_ident_fit(r, 400, 1.0, fw_deg_to_rad(20), c3.rudder_rate, &fit, &rms, NULL) == FW_OK);
    CHECK_REL(fit.K, truth.K, 1e-4);
    CHECK_REL(fit.T1, truth.T1, 1e-3);
    CHECK_REL(fit.T2, truth.T2, 1e-3);
    CHECK_REL(fit.T3, truth.T3, 1e-3);
    CHECK(rms < 1e-5);
}

static void test_fit_mmg_histories(void)
{
    /* floor: each MMG history reproduced within 5% RMS of its steady rate */
    static const double grid[][2] = {{20.12, 10}, {20.12, 30}, {14.55, -20}};
    enum { N = 700 };
    double *r = malloc(sizeof(double) * N);
    for (size_t i = 0; i < sizeof grid / sizeof grid[0]; i++) {
        fw_error err = {0};
        double helm = fw_deg_to_rad(grid[i][1]);
        CHECK_MSG(fw_ident_turning(&c3, fw_kn_to_ms(grid[i][0]), helm, 1.0, N, r, &err) == FW_OK,
                  "%s", err.msg);
        fw_nomoto_indices fit;
        double rms;
        CHECK(fw_ident_fit(r, N, 1.0, helm, c3.rudder_rate, &fit, &rms, &err) == FW_OK);
        CHECK_MSG(rms < 0.05, "%.2f kn %.0f deg: RMS %.1f%%", grid[i][0], grid[i][1], 100 * rms);
        CHECK(fit.K > 0 && fit.T1 > 0 && fit.T2 >= fit.T1);
        printf("  %.2f kn %+3.0f deg: K %.5f T1 %.1f T2 %.1f T3 %.1f rms %.2f%%\n", grid[i][0],
               grid[i][1], fit.K, fit.T1, fit.T2, fit.T3, 100 * rms);
    }
    free(r);
}

static void test_regression_reproduces_paper(void)
{
    /* regressing the paper's own equations sampled on its grid returns them */
    double U[21], d[21], v[21];
    int m = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 7; j++, m++) {
            U[m] = (double[]){14.55, 20.12, 26.7}[i];
            d[m] = 5 + 5 * j;
        }
    const fw_nomoto_index *src[4] = {&c3.nomoto.K, &c3.nomoto.T1, &c3.nomoto.T2, &c3.nomoto.T3};
    for (int x = 0; x < 4; x++) {
        fw_nomoto_index ix = *src[x];
        for (int i = 0; i < m; i++)
            v[i] = fw_nomoto_index_eval(src[x], U[i], d[i]);
        CHECK(fw_ident_regress(&ix, U, d, v, m, NULL) == FW_OK);
        for (int k = 0; k < ix.n; k++)
            CHECK_NEAR(ix.coef[k], src[x]->coef[k], 1e-6 * fmax(1.0, fabs(src[x]->coef[k])));
    }
}

int main(void)
{
    fw_error err = {0};
    if (fw_ship_load("c3", &c3, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    TEST_RUN(test_fit_recovers_known_indices);
    TEST_RUN(test_fit_mmg_histories);
    TEST_RUN(test_regression_reproduces_paper);
    return TEST_EXIT();
}
