#!/usr/bin/env python3
"""Pictures of one `fairway report` directory (drawn from its CSVs only).

Writes into the report directory (or --out):
  rates.png            encounters, domain violations, near misses, manoeuvres per own-ship hour,
                       path lengthening and time lost against domain size, with interval bars
  encounter_types.png  own-ship encounters per hour by type (head-on, overtaking, crossing)
  cpa_hist.png         CPA histograms of the own ship's encounters, one panel per domain size
  traffic.png          traffic-level encounters per 1000 ship-hours by type
  paired.png           paired differences from the reference domain size, with interval bars

    /usr/bin/python3 analysis/plot_study.py REPORT_DIR [--level 0.95] [--out DIR]

`fairway report` runs this itself; run it by hand to redraw after editing the style.
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

# Measures of rates.png and paired.png: (summary.csv name, title, axis label).
RATES = [
    ("encounters_per_h", "Own-ship encounters", "encounters per ship-hour"),
    ("domain_violations_per_h", "Domain violations", "violations per ship-hour"),
    ("near_misses_per_h", "Near misses", "near misses per ship-hour"),
    ("manoeuvres_per_h", "Avoidance manoeuvres", "manoeuvres per ship-hour"),
    ("path_lengthening_m_per_h", "Path lengthening", "metres per ship-hour"),
    ("time_lost_s_per_h", "Time lost", "seconds per ship-hour"),
]
TYPES = [("head_on_per_h", "head-on"), ("overtaking_per_h", "overtaking (either way)"),
         ("crossing_per_h", "crossing (give-way or stand-on)")]
TRAFFIC_TYPES = ["all", "head-on", "overtaking", "crossing"]
DOMAIN_LABEL = "own-ship domain size (metres)"


def fail(msg):
    print(f"plot_study: {msg}", file=sys.stderr)
    sys.exit(2)


def load(d):
    need = {
        "summary.csv": {"density", "domain_m", "measure", "n", "mean", "ci_low", "ci_high"},
        "paired.csv": {"density", "domain_m", "reference_m", "measure", "n", "mean", "ci_low", "ci_high"},
        "traffic.csv": {"density", "domain_m", "type", "n", "mean_per_1000_ship_h", "ci_low", "ci_high"},
        "cpa_hist.csv": {"density", "domain_m", "set", "bin_low_m", "bin_high_m", "count"},
    }
    out = {}
    for name, cols in need.items():
        path = os.path.join(d, name)
        try:
            df = pd.read_csv(path)
        except Exception as exc:  # missing, empty or unparsable all mean the same to the user
            fail(f"{path}: cannot read ({exc})")
        missing = cols - set(df.columns)
        if missing:
            fail(f"{path}: not a fairway report table (no column {', '.join(sorted(missing))})")
        out[name] = df
    return out


def yerr(df, mean="mean"):
    """Asymmetric error bars from ci_low/ci_high; no bar where there is no interval."""
    lo = (df[mean] - df["ci_low"]).to_numpy(dtype=float)
    hi = (df["ci_high"] - df[mean]).to_numpy(dtype=float)
    return np.nan_to_num(np.vstack([lo, hi]), nan=0.0)


def offsets(values, k, n):
    """Small sideways shift of series k of n so that interval bars do not hide each other."""
    v = np.sort(np.unique(values))
    step = np.min(np.diff(v)) if len(v) > 1 else max(abs(v[0]), 1.0)
    return (k - (n - 1) / 2) * 0.04 * step


def series(ax, df, x, mean, label, k, n, **kw):
    df = df.sort_values(x)
    ax.errorbar(df[x] + offsets(df[x], k, n), df[mean], yerr=yerr(df, mean), marker="o", ms=4,
                capsize=3, lw=1.2, label=label, **kw)


def density_label(dens, n):
    return f"density {dens:g}" if n > 1 else None


def empty(ax, text):
    ax.text(0.5, 0.5, text, ha="center", va="center", transform=ax.transAxes, fontsize=9, color="grey")


def finish(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_rates(summary, level, path, paired=None):
    """rates.png, or with `paired` the differences from the reference (paired.png)."""
    data = summary if paired is None else paired
    fig, axes = plt.subplots(2, 3, figsize=(13, 7.5))
    densities = sorted(data["density"].unique())
    for ax, (name, title, unit) in zip(axes.flat, RATES):
        sub = data[data.measure == name]
        for k, dens in enumerate(densities):
            s = sub[sub.density == dens]
            if len(s):
                series(ax, s, "domain_m", "mean", density_label(dens, len(densities)), k, len(densities))
        if paired is not None:
            ax.axhline(0.0, color="k", lw=0.7)
        if not len(sub):
            empty(ax, "no data")
        ax.set_title(title)
        ax.set_xlabel(DOMAIN_LABEL)
        ax.set_ylabel(unit if paired is None else f"difference, {unit}")
        ax.grid(alpha=0.3)
        if len(densities) > 1 and len(sub):
            ax.legend(fontsize=7)
    pct = f"{100 * level:.0f}%"
    if paired is None:
        fig.suptitle(f"Mean over replications with {pct} confidence intervals")
    else:
        ref = ", ".join(f"{r:g} m" for r in sorted(paired["reference_m"].unique())) or "-"
        fig.suptitle(f"Paired differences from the {ref} domain (same traffic per replication), {pct} intervals")
    finish(fig, path)


def plot_types(summary, level, path):
    densities = sorted(summary["density"].unique())
    fig, axes = plt.subplots(1, len(densities), figsize=(6.5 * len(densities), 4.5), squeeze=False)
    for ax, dens in zip(axes.flat, densities):
        for k, (name, label) in enumerate(TYPES):
            s = summary[(summary.measure == name) & (summary.density == dens)]
            series(ax, s, "domain_m", "mean", label, k, len(TYPES))
        ax.set_title(f"Own-ship encounters by type{f', density {dens:g}' if len(densities) > 1 else ''}")
        ax.set_xlabel(DOMAIN_LABEL)
        ax.set_ylabel("encounters per ship-hour")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(f"Mean over replications with {100 * level:.0f}% confidence intervals", fontsize=10)
    finish(fig, path)


def plot_cpa(hist, path):
    own = hist[hist.set == "own"]
    domains = sorted(own["domain_m"].unique())
    densities = sorted(own["density"].unique())
    n = max(len(domains), 1)
    cols = min(4, n)
    rows = math.ceil(n / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4 * cols, 3.2 * rows), squeeze=False)
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    if not domains:
        empty(axes.flat[0], "no own-ship encounters with a CPA")
    for ax, dom in zip(axes.flat, domains):
        for dens in densities:
            s = own[(own.domain_m == dom) & (own.density == dens)].sort_values("bin_low_m")
            if not len(s):
                continue
            edges = np.append(s["bin_low_m"].to_numpy(), s["bin_high_m"].to_numpy()[-1])
            ax.stairs(s["count"].to_numpy(), edges, fill=len(densities) == 1, alpha=0.7,
                      label=density_label(dens, len(densities)))
        ax.axvline(dom, color="k", ls="--", lw=1, label="domain size")
        ax.set_title(f"domain {dom:g} m")
        ax.set_xlabel("CPA: closest centre distance (metres)")
        ax.set_ylabel("encounters")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("Closest approach of the own ship's encounters, pooled over replications")
    finish(fig, path)


def plot_traffic(traffic, level, path):
    densities = sorted(traffic["density"].unique())
    fig, axes = plt.subplots(1, len(densities), figsize=(6.5 * len(densities), 4.5), squeeze=False)
    for ax, dens in zip(axes.flat, densities):
        t = traffic[(traffic.density == dens) & traffic.mean_per_1000_ship_h.notna()]
        for k, typ in enumerate(TRAFFIC_TYPES):
            s = t[t.type == typ]
            if len(s):
                series(ax, s, "domain_m", "mean_per_1000_ship_h", typ, k, len(TRAFFIC_TYPES))
        if not len(t):
            empty(ax, "no traffic-level exposure recorded")
        else:
            ax.legend(fontsize=8)
        ax.set_title(f"Traffic-level encounters{f', density {dens:g}' if len(densities) > 1 else ''}")
        ax.set_xlabel(DOMAIN_LABEL)
        ax.set_ylabel("encounters per 1000 ship-hours")
        ax.grid(alpha=0.3)
    fig.suptitle(f"All ships in the survey area, mean over replications with {100 * level:.0f}% "
                 "confidence intervals", fontsize=10)
    finish(fig, path)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("report", help="a fairway report directory")
    p.add_argument("--level", type=float, default=0.95, help="confidence level of the intervals (for labels)")
    p.add_argument("--out", help="directory for the PNGs (default: the report directory)")
    a = p.parse_args()
    if not 0 < a.level < 1:
        fail("--level must be between 0 and 1")
    t = load(a.report)
    if not len(t["summary.csv"]):
        fail(f"{a.report}/summary.csv: no rows")
    out = a.out or a.report
    os.makedirs(out, exist_ok=True)
    plot_rates(t["summary.csv"], a.level, os.path.join(out, "rates.png"))
    plot_types(t["summary.csv"], a.level, os.path.join(out, "encounter_types.png"))
    plot_cpa(t["cpa_hist.csv"], os.path.join(out, "cpa_hist.png"))
    plot_traffic(t["traffic.csv"], a.level, os.path.join(out, "traffic.png"))
    plot_rates(t["summary.csv"], a.level, os.path.join(out, "paired.png"), paired=t["paired.csv"])
    print(f"wrote {out}/rates.png, encounter_types.png, cpa_hist.png, traffic.png, paired.png")


if __name__ == "__main__":
    main()
