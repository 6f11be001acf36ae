/* test.h - the project's tiny test harness.
 *
 * A test program is a main() calling TEST_RUN(fn) for each case; checks record
 * failures with file and line and the program exits non-zero if any failed.
 * Tolerances are explicit in every numeric check.
 */
#ifndef FW_TEST_H
#define FW_TEST_H

#include <math.h>
#include <stdio.h>
#include <string.h>

static int test_failures_ = 0;
static int test_checks_ = 0;

#define CHECK(cond)                                                                         \
    do {                                                                                    \
        test_checks_++;                                                                     \
        if (!(cond)) {                                                                      \
            test_failures_++;                                                               \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond);        \
        }                                                                                   \
    } while (0)

#define CHECK_MSG(cond, ...)                                                                \
    do {                                                                                    \
        test_checks_++;                                                                     \
        if (!(cond)) {                                                                      \
            test_failures_++;                                                               \
            fprintf(stderr, "%s:%d: CHECK failed: %s: ", __FILE__, __LINE__, #cond);        \
            fprintf(stderr, __VA_ARGS__);                                                   \
            fputc('\n', stderr);                                                            \
        }                                                                                   \
    } while (0)

/* |a - b| <= tol */
#define CHECK_NEAR(a, b, tol)                                                               \
    do {                                                                                    \
        double a_ = (a), b_ = (b), t_ = (tol);                                              \
        test_checks_++;                                                                     \
        if (!(fabs(a_ - b_) <= t_)) {                                                       \
            test_failures_++;                                                               \
            fprintf(stderr, "%s:%d: %s = %.9g, expected %s = %.9g within %.3g (off %.3g)\n", \
                    __FILE__, __LINE__, #a, a_, #b, b_, t_, fabs(a_ - b_));                 \
        }                                                                                   \
    } while (0)

/* |a - b| <= rel * |b| */
#define CHECK_REL(a, b, rel)                                                                \
    do {                                                                                    \
        double a_ = (a), b_ = (b), r_ = (rel);                                              \
        test_checks_++;                                                                     \
        if (!(fabs(a_ - b_) <= r_ * fabs(b_))) {                                            \
            test_failures_++;                                                               \
            fprintf(stderr, "%s:%d: %s = %.9g, expected %s = %.9g within %.3g%% (off %.3g%%)\n", \
                    __FILE__, __LINE__, #a, a_, #b, b_, 100 * r_,                           \
                    100 * fabs(a_ - b_) / fabs(b_));                                        \
        }                                                                                   \
    } while (0)

#define CHECK_CONTAINS(haystack, needle)                                                    \
    CHECK_MSG(strstr((haystack), (needle)) != NULL, "'%s' does not contain '%s'",           \
              (haystack), (needle))

#define TEST_RUN(fn)                                                                        \
    do {                                                                                    \
        int before_ = test_failures_;                                                       \
        fn();                                                                               \
        printf("%-40s %s\n", #fn, test_failures_ == before_ ? "ok" : "FAILED");             \
    } while (0)

#define TEST_EXIT()                                                                         \
    (printf("%d checks, %d failed\n", test_checks_, test_failures_), test_failures_ ? 1 : 0)

#endif
