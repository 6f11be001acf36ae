/* test_watch_redraw.c - the watch under splitting (world/watch.h): a branch
 * draws the time to detect afresh for the ships not yet detected, with the
 * law they had (the exponential law is memoryless), and the unseen approach
 * that splitting's score climbs. */
#include <math.h>
#include <stdio.h>

#include "test.h"
#include "world/watch.h"

static fw_rng *one_stream(void *ctx, uint32_t key, fw_purpose purpose)
{
    (void)key;
    (void)purpose;
    return ctx;
}

/* 4000 encounters met at t = 0, mean 100 s; at 150 s those not yet detected
 * (e^-1.5 of them) draw afresh from another stream: of them 1 - 1/e are
 * detected 100 s later, within 4 standard errors, as without the redraw;
 * those detected before stay detected; the draws differ from the parent's
 * (the same 4000 without the redraw detect others at 250 s). */
static void test_redraw_law(void)
{
    enum { N = 4000 };
    fw_error err = {0};
    fw_watch_def d = fw_default_watch_def();
    d.detect = 100.0;
    fw_watch *w[2] = {NULL, NULL};
    fw_rng s[2] = {fw_rng_make(7, 0, FW_PURPOSE_WATCH), fw_rng_make(7, 0, FW_PURPOSE_WATCH)};
    for (int k = 0; k < 2; k++) {
        CHECK(fw_watch_create(&d, &w[k], &err) == FW_OK);
        fw_watch_set_rng(w[k], one_stream, &s[k]);
    }
    fw_target b = {.id = "other", .east = 1000.0};
    int seen150[N], pending = 0, later = 0, differ = 0, kept = 1;
    for (int i = 0; i < N; i++) {
        fw_target a = {.east = 0.0};
        snprintf(a.id, sizeof a.id, "s%d", i);
        for (int k = 0; k < 2; k++)
            CHECK(fw_watch_noticed(w[k], &a, &b, 0.0) == 0);
        seen150[i] = fw_watch_noticed(w[0], &a, &b, 150.0);
        CHECK(fw_watch_noticed(w[1], &a, &b, 150.0) == seen150[i]);
        pending += !seen150[i];
    }
    s[1] = fw_rng_make(8, 0, FW_PURPOSE_WATCH); /* the branch's stream */
    CHECK(fw_watch_redraw(w[1], 150.0) == pending);
    for (int i = 0; i < N; i++) {
        fw_target a = {.east = 0.0};
        snprintf(a.id, sizeof a.id, "s%d", i);
        int p = fw_watch_noticed(w[0], &a, &b, 250.0), q = fw_watch_noticed(w[1], &a, &b, 250.0);
        if (seen150[i])
            kept &= q;
        else
            later += q, differ += p != q;
    }
    double f = later / (double)pending, want = 1.0 - exp(-1.0);
    printf("redraw at 150 s: %d of %d not yet detected, %.4f of them detected by 250 s (%.4f), "
           "%d differ from the parent\n", pending, N, f, want, differ);
    CHECK(fabs(pending / (double)N - exp(-1.5)) < 4.0 * sqrt(exp(-1.5) * (1 - exp(-1.5)) / N));
    CHECK(fabs(f - want) < 4.0 * sqrt(want * (1 - want) / pending));
    CHECK(kept && differ > pending / 4);
    for (int k = 0; k < 2; k++)
        fw_watch_destroy(w[k]);
}

/* The unseen approach: a ship met 2000 m off, hidden until 100 s, is 1 - r
 * / 2000 at its nearest while hidden, and no more after: 1500 m at 50 s ->
 * 0.25, 1000 m at 200 s (detected) leaves 0.25.  A lapsed ship's approach
 * counts to the end. */
static void test_unseen(void)
{
    fw_error err = {0};
    fw_watch_def d = fw_default_watch_def();
    d.delay = 100.0;
    fw_watch *w = NULL;
    fw_rng s = fw_rng_make(1, 0, FW_PURPOSE_WATCH);
    CHECK(fw_watch_create(&d, &w, &err) == FW_OK);
    fw_watch_set_rng(w, one_stream, &s);
    fw_target a = {.id = "own"}, b = {.id = "b", .north = 2000.0};
    CHECK(fw_watch_unseen(w) == 0.0);
    CHECK(fw_watch_noticed(w, &a, &b, 0.0) == 0);
    b.north = 1500.0;
    CHECK(fw_watch_noticed(w, &a, &b, 50.0) == 0);
    CHECK_NEAR(fw_watch_unseen(w), 0.25, 1e-12);
    b.north = 1000.0;
    CHECK(fw_watch_noticed(w, &a, &b, 200.0) == 1);
    CHECK_NEAR(fw_watch_unseen(w), 0.25, 1e-12);
    CHECK(fw_watch_redraw(w, 200.0) == 0); /* nothing drawn: a fixed delay */
    fw_watch_destroy(w);
    d = fw_default_watch_def();
    d.lapse = 1.0;
    CHECK(fw_watch_create(&d, &w, &err) == FW_OK);
    fw_watch_set_rng(w, one_stream, &s);
    b.north = 2000.0;
    CHECK(fw_watch_noticed(w, &a, &b, 0.0) == 0);
    b.north = 100.0;
    CHECK(fw_watch_noticed(w, &a, &b, 150.0) == 0);
    CHECK_NEAR(fw_watch_unseen(w), 0.95, 1e-12);
    fw_watch_destroy(w);
}

int main(void)
{
    TEST_RUN(test_redraw_law);
    TEST_RUN(test_unseen);
    return TEST_EXIT();
}
