/* clock.h - the monotonic wall clock, for timings only (benchmarks, progress,
 * the study database's wall-clock columns); nothing a run writes depends on it. */
#ifndef FW_CLOCK_H
#define FW_CLOCK_H

/* Seconds since an arbitrary fixed point (CLOCK_MONOTONIC). */
double fw_clock_s(void);

/* CPU seconds this process has used (CLOCK_PROCESS_CPUTIME_ID: a system
 * call, ~0.2 us; for --profile, not for every step of every run). */
double fw_cpu_s(void);

#endif
