#!/usr/bin/env python3
"""split_watch.py SCAN DB WALL_S JOBS [GROUP] - bench/split_watch.sh's figures (see there).

GROUP: the batches of one estimate whose relative error and cost are set against crude Monte Carlo
(default 10; the study's batches are cut into groups of it)."""
import math
import re
import sqlite3
import statistics
import sys

scan_file, db, wall_s, jobs = sys.argv[1], sys.argv[2], float(sys.argv[3]), int(sys.argv[4])
NEAR_MISS = 185.2
GROUP = int(sys.argv[5]) if len(sys.argv) > 5 else 10  # batches in one estimate
T95 = {1: 12.71, 2: 4.30, 3: 3.18, 4: 2.78, 5: 2.57, 6: 2.45, 7: 2.36, 8: 2.31, 9: 2.26,
       10: 2.23, 15: 2.13, 20: 2.09, 30: 2.04}


def t95(df):
    return T95.get(df) or T95[max(k for k in T95 if k <= df)]


def threshold(scan, hit):
    """The least D from which every D scanned is an event; checks there is none below."""
    ds = sorted(scan)
    k = next(d for d in ds if all(hit(scan[e]) for e in ds if e >= d))
    if any(hit(scan[e]) for e in ds if e < k):
        sys.exit("not monotone: an event below D = %d" % k)
    if k - 1 not in scan:
        sys.exit("the scan does not reach D = %d" % (k - 1))
    return k


def binom_cdf(k, n, p):
    if p <= 0:
        return 1.0
    if p >= 1:
        return 1.0 if k >= n else 0.0
    return sum(math.exp(math.lgamma(n + 1) - math.lgamma(i + 1) - math.lgamma(n - i + 1)
                        + i * math.log(p) + (n - i) * math.log1p(-p)) for i in range(k + 1))


def clopper_pearson(k, n):
    def solve(f, target):  # f decreasing in p
        lo, hi = 0.0, 1.0
        for _ in range(100):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if f(mid) > target else (lo, mid)
        return (lo + hi) / 2
    lo = 0.0 if k == 0 else solve(lambda p: binom_cdf(k - 1, n, p), 0.975)
    hi = 1.0 if k == n else solve(lambda p: binom_cdf(k, n, p), 0.025)
    return lo, hi


scan = {}
for line in open(scan_file):
    d, h = line.split()
    scan[int(d)] = float(h)
k_c = threshold(scan, lambda h: h <= 0.0)
k_nm = threshold(scan, lambda h: h < NEAR_MISS)
print("Splitting on a fairway case with an exact answer (bench/split_watch.sh)")
print("case: scenarios/watch/headon-watch.yaml, study scenarios/studies/headon-watch.yaml")
print("thresholds (fixed decision delays D, detection at once, every D from 960 to 1070 s run):")
print("  collision from D = %d s (D = %d: %.1f m hull to hull), near miss (< %.1f m) from D = %d s"
      " (D = %d: %.1f m)" % (k_c, k_c - 1, scan[k_c - 1], NEAR_MISS, k_nm, k_nm - 1, scan[k_nm - 1]))
print("  so P(collision) = exp(-%d / detect_s), P(near miss) = exp(-%d / detect_s)" % (k_c - 1, k_nm - 1))
print("sweep: %.0f s wall, %d jobs" % (wall_s, jobs))

con = sqlite3.connect(db)
cells = con.execute("select distinct cell, setting from splits order by cell").fetchall()
for cell, setting in cells:
    d = float(re.search(r"detect_s=([0-9.]+)", setting).group(1))
    exact = {"collision": math.exp(-(k_c - 1) / d), "near miss": math.exp(-(k_nm - 1) / d)}
    rows = con.execute("select p_collision, p_near_miss, runs, sim_s from splits where cell = ? "
                       "and status = 'ok' order by batch", (cell,)).fetchall()
    failed = con.execute("select count(*) from splits where cell = ? and status != 'ok'",
                         (cell,)).fetchone()[0]
    crude = con.execute("select count(*), sum(collision), sum(near_miss), sum(sim_s) from runs "
                        "where setting = ? and status = 'ok'", (setting,)).fetchone()
    B = len(rows)
    runs = [r[2] for r in rows]
    print("\ncell %d: detect_s %g s (%d batches of %s particles, %d failed)"
          % (cell, d, B, con.execute("select particles from splits where cell = ?",
                                     (cell,)).fetchone()[0], failed))
    for j, ev in enumerate(("collision", "near miss")):
        ps = [r[j] for r in rows]
        m, sd = statistics.mean(ps), statistics.stdev(ps)
        half = t95(B - 1) * sd / math.sqrt(B)
        re_all = sd / math.sqrt(B) / m
        print("  P(%s): exact %.4g; splitting, all %d batches: %.4g [%.4g, %.4g] (t 95%%), "
              "relative error %.3f, off the exact by %+.1f %%"
              % (ev, exact[ev], B, m, m - half, m + half, re_all, 100 * (m / exact[ev] - 1)))
        # estimates of g batches each: their relative error and cost against crude Monte Carlo
        g = GROUP
        groups = [ps[i:i + g] for i in range(0, B - B % g, g)]
        if groups:
            re8 = sd / math.sqrt(g) / exact[ev]
            errs = ["%+.0f%%" % (100 * (statistics.mean(x) / exact[ev] - 1)) for x in groups]
            cost8 = g * statistics.mean(runs)
            p = exact[ev]
            crude_runs = (1 - p) / (p * re8 ** 2)
            print("    an estimate of %d batches: relative error %.3f (the batches' sd / sqrt(%d) / "
                  "exact), %.0f runs (%.1f simulated h); crude Monte Carlo for the same relative "
                  "error: %.4g runs: %.0fx fewer; the %d such estimates off the exact by %s"
                  % (g, re8, g, cost8, cost8 * statistics.mean(r[3] / r[2] for r in rows) / 3600,
                     crude_runs, crude_runs / cost8, len(groups), " ".join(errs)))
    n, k_col, k_nm_runs, sim = crude
    for ev, evs, k in (("collision", "collisions", k_col), ("near miss", "near misses", k_nm_runs)):
        lo, hi = clopper_pearson(int(k), int(n))
        print("  crude Monte Carlo: %d runs (%.1f simulated h), %d %s: %.4g [%.4g, %.4g] "
              "(Clopper-Pearson 95%%), exact %.4g"
              % (n, sim / 3600, k, evs, k / n, lo, hi, exact[ev]))
    print("  splitting cost per batch: %.0f runs (median; %d..%d)"
          % (statistics.median(runs), min(runs), max(runs)))
