/* fmt.c - see fmt.h. */
#include "core/fmt.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static const double kPow10[10] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};

/* |v| * 10^d below this: the integer is exact in a double and fits uint64 */
static const double kMaxScaled = 1e15;

int fw_fmt_fixed(char *out, double v, int decimals)
{
    if (decimals < 0 || decimals > 9)
        return -1;
    int d = decimals;
    double a = fabs(v), p = kPow10[d];
    double r = nearbyint(a * p);
    /* a * p - r exactly, rounded once: r is the nearest integer to the exact
     * product unless that is (near) a tie, which printf settles */
    double e = fma(a, p, -r);
    if (!(a * p < kMaxScaled) || !(fabs(e) < 0.4999))
        return -1;
    uint64_t n = (uint64_t)r;
    char digits[24];
    int k = 0;
    do { /* least significant first, at least d + 1 digits */
        digits[k++] = (char)('0' + n % 10);
        n /= 10;
    } while (n > 0 || k <= d);
    int len = 0;
    if (signbit(v)) /* printf keeps the sign of a negative rounding to zero */
        out[len++] = '-';
    while (k > d)
        out[len++] = digits[--k];
    if (d > 0)
        out[len++] = '.';
    while (k > 0)
        out[len++] = digits[--k];
    out[len] = '\0';
    return len;
}

void fw_put_fixed(FILE *f, double v, int decimals)
{
    char s[FW_FMT_FIXED_MAX];
    int n = fw_fmt_fixed(s, v, decimals);
    if (n >= 0)
        fwrite(s, 1, (size_t)n, f);
    else
        fprintf(f, "%.*f", decimals, v);
}
