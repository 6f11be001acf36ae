/* fmt.h - fixed-point numbers written as printf's "%.Nf" writes them, faster.
 *
 * The run's CSV rows are mostly such numbers (targets.csv recorded each
 * second: some 800 000 of them an hour), and printf's exact decimal
 * conversion was most of the records' time.  fw_fmt_fixed rounds |v| * 10^N
 * to an integer in binary and proves, with a fused multiply-add, that the
 * exact product is not within a hair of a half (printf's ties and near
 * ties) and that the integer is exact; only then are the digits its own,
 * else printf writes them.  Either way the bytes are printf's, to the byte.
 */
#ifndef FW_FMT_H
#define FW_FMT_H

#include <stdio.h>

enum { FW_FMT_FIXED_MAX = 32 }; /* room fw_fmt_fixed may use, NUL included */

/* Writes v as "%.Nf" would (0 <= decimals <= 9) at out, which has room for
 * FW_FMT_FIXED_MAX bytes, and returns the length (NUL not counted); -1, out
 * untouched, for the values it leaves to printf (not finite, |v| * 10^N
 * from 1e15 up, within 1e-4 of a tie). */
int fw_fmt_fixed(char *out, double v, int decimals);
/* v as "%.Nf" onto f: fw_fmt_fixed, else fprintf. */
void fw_put_fixed(FILE *f, double v, int decimals);

#endif
