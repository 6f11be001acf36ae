/* clock.h - the monotonic wall clock, for timings only (benchmarks, progress,
 * the study database's wall-clock columns); nothing a run writes depends on it. */
#ifndef FW_CLOCK_H
#define FW_CLOCK_H

/* Seconds since an arbitrary fixed point (CLOCK_MONOTONIC). */
double fw_clock_s(void);

#endif
