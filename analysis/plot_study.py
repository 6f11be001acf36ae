#!/usr/bin/env python3
"""Pictures of one `fairway report` directory (drawn from its CSVs only).

Writes into the report directory (or --out):
  rates.png            encounters, domain violations, near misses, collisions, runs with a
                       collision, manoeuvres per own-ship hour, path lengthening and time lost
                       against domain size, with interval bars (each measure's own interval:
                       summary.csv's method column)
  encounter_types.png  own-ship encounters per hour by type (head-on, overtaking, crossing)
  cpa_hist.png         CPA histograms of the own ship's encounters, one panel per domain size
  traffic.png          traffic-level encounters per 1000 ship-hours by type
  paired.png           paired differences from the reference domain size, with interval bars
  behaviour.png        colregs - blind background traffic (a study that swept it), paired

Domain sizes are discrete settings: markers with interval bars, no lines between them.  A
series is one density and background behaviour.  A measure that is 0 everywhere with no
interval above 0 gets no invented axis range: the panel says so.

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
    ("near_misses_per_h", "Near misses (hull to hull)", "near misses per ship-hour"),
    ("min_hull_m", "Least hull distance of a run", "metres, hull to hull"),
    ("collisions_per_h", "Collisions (hull contact)", "collisions per ship-hour"),
    ("collision_run_fraction", "Runs with a collision", "share of runs"),
    ("manoeuvres_per_h", "Avoidance manoeuvres", "manoeuvres per ship-hour"),
    ("path_lengthening_m_per_h", "Path lengthening", "metres per ship-hour"),
    ("time_lost_s_per_h", "Time lost", "seconds per ship-hour"),
    ("closeness", "Closeness (1 at contact)", "1 - least hull distance / 1 nm"),
]
# Measures of the domain itself: a larger domain is broken sooner, so they are
# not compared across domain sizes (fairway report leaves them out of paired.csv).
PER_DOMAIN = {"domain_violations_per_h", "domain_violation_fraction"}
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
        "behaviour.csv": {"density", "domain_m", "measure", "n", "mean", "ci_low", "ci_high"},
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
        if "behaviour" not in df.columns:
            df["behaviour"] = ""
        df["behaviour"] = df["behaviour"].fillna("").astype(str)
        if "fore_aft_ratio" not in df.columns:
            df["fore_aft_ratio"] = np.nan
        df["fore_aft_ratio"] = df["fore_aft_ratio"].fillna(1.0)
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
    """Markers with interval bars at each domain size: the sizes are settings, not a continuum."""
    df = df.sort_values(x)
    ax.errorbar(df[x] + offsets(df[x], k, n), df[mean], yerr=yerr(df, mean), marker="o", ms=5,
                capsize=3, ls="none", elinewidth=1.2, label=label, **kw)
    ax.set_xticks(sorted(df[x].unique()))


def settings(df):
    """The series of a table: its (density, behaviour, domain shape) triples."""
    return sorted(set(zip(df["density"], df["behaviour"], df["fore_aft_ratio"])))


def pick(df, key):
    """The rows of one series."""
    return df[(df.density == key[0]) & (df.behaviour == key[1]) & (df.fore_aft_ratio == key[2])]


def setting_label(key, keys):
    dens, beh, ratio = key
    parts = []
    if len({k[0] for k in keys}) > 1:
        parts.append(f"density {dens:g}")
    if len({k[1] for k in keys}) > 1:
        parts.append(f"{beh} traffic")
    if len({k[2] for k in keys}) > 1:
        parts.append(f"fore-aft {ratio:g}:1")
    return ", ".join(parts) or None


def all_zero(sub):
    """Every mean and every interval end 0 (or absent): nothing to scale an axis on."""
    vals = pd.concat([sub["mean"], sub["ci_low"], sub["ci_high"]]).dropna()
    return len(sub) > 0 and (vals == 0).all()


def empty(ax, text):
    ax.text(0.5, 0.5, text, ha="center", va="center", transform=ax.transAxes, fontsize=9, color="grey")


def finish(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_rates(summary, level, path, paired=None, title_override=None):
    """rates.png, or with `paired` the differences from the reference (paired.png)."""
    data = summary if paired is None else paired
    fig, axes = plt.subplots(2, 5, figsize=(21, 7.5))
    keys = settings(data)
    for ax, (name, title, unit) in zip(axes.flat, RATES):
        sub = data[data.measure == name]
        for k, key in enumerate(keys):
            s = pick(sub, key)
            if len(s):
                series(ax, s, "domain_m", "mean", setting_label(key, keys), k, len(keys))
        if paired is not None:
            ax.axhline(0.0, color="k", lw=0.7)
        if not len(sub) and paired is not None and name in PER_DOMAIN:
            empty(ax, "not compared across domain sizes")
        elif not len(sub):
            empty(ax, "no data")
        elif all_zero(sub):
            # no range to show: one tick at 0 rather than matplotlib's invented +-0.05
            ax.set_yticks([0.0])
            empty(ax, "0 in every setting")
        ax.set_title(title)
        ax.set_xlabel(DOMAIN_LABEL)
        ax.set_ylabel(unit if paired is None else f"difference, {unit}")
        ax.grid(alpha=0.3)
        if len(keys) > 1 and len(sub) and not all_zero(sub):
            ax.legend(fontsize=7)
    pct = f"{100 * level:.0f}%"
    if paired is None:
        fig.suptitle(f"Each measure with its {pct} interval (method per measure: summary.csv)")
    elif title_override:
        fig.suptitle(title_override)
    else:
        ref = ", ".join(f"{r:g} m" for r in sorted(paired["reference_m"].unique())) or "-"
        fig.suptitle(f"Paired differences from the {ref} domain (same traffic per replication), {pct} intervals")
    finish(fig, path)


def plot_types(summary, level, path):
    keys = settings(summary)
    fig, axes = plt.subplots(1, len(keys), figsize=(6.5 * len(keys), 4.5), squeeze=False)
    for ax, key in zip(axes.flat, keys):
        for k, (name, label) in enumerate(TYPES):
            s = pick(summary[summary.measure == name], key)
            series(ax, s, "domain_m", "mean", label, k, len(TYPES))
        lab = setting_label(key, keys)
        ax.set_title(f"Own-ship encounters by type{f', {lab}' if lab else ''}")
        ax.set_xlabel(DOMAIN_LABEL)
        ax.set_ylabel("encounters per ship-hour")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(f"Mean over replications with {100 * level:.0f}% confidence intervals", fontsize=10)
    finish(fig, path)


def plot_cpa(hist, path):
    own = hist[hist.set == "own"]
    domains = sorted(own["domain_m"].unique())
    keys = settings(own)
    n = max(len(domains), 1)
    cols = min(4, n)
    rows = math.ceil(n / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4 * cols, 3.2 * rows), squeeze=False)
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    if not domains:
        empty(axes.flat[0], "no own-ship encounters with a CPA")
    for ax, dom in zip(axes.flat, domains):
        for key in keys:
            s = pick(own[own.domain_m == dom], key).sort_values("bin_low_m")
            if not len(s):
                continue
            edges = np.append(s["bin_low_m"].to_numpy(), s["bin_high_m"].to_numpy()[-1])
            ax.stairs(s["count"].to_numpy(), edges, fill=len(keys) == 1, alpha=0.7,
                      label=setting_label(key, keys))
        ax.axvline(dom, color="k", ls="--", lw=1, label="domain size")
        ax.set_title(f"domain {dom:g} m")
        ax.set_xlabel("CPA: closest centre distance (metres)")
        ax.set_ylabel("encounters")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("Closest approach of the own ship's encounters, pooled over replications")
    finish(fig, path)


def plot_traffic(traffic, level, path):
    keys = settings(traffic)
    fig, axes = plt.subplots(1, len(keys), figsize=(6.5 * len(keys), 4.5), squeeze=False)
    for ax, key in zip(axes.flat, keys):
        lab = setting_label(key, keys)
        t = pick(traffic[traffic.mean_per_1000_ship_h.notna()], key)
        for k, typ in enumerate(TRAFFIC_TYPES):
            s = t[t.type == typ]
            if len(s):
                series(ax, s, "domain_m", "mean_per_1000_ship_h", typ, k, len(TRAFFIC_TYPES))
        if not len(t):
            empty(ax, "no traffic-level exposure recorded")
        else:
            ax.legend(fontsize=8)
        ax.set_title(f"Traffic-level encounters{f', {lab}' if lab else ''}")
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
    wrote = "rates.png, encounter_types.png, cpa_hist.png, traffic.png, paired.png"
    if len(t["behaviour.csv"]):
        plot_rates(t["summary.csv"], a.level, os.path.join(out, "behaviour.png"),
                   paired=t["behaviour.csv"],
                   title_override=f"colregs - blind background traffic (paired by replication), "
                                  f"{100 * a.level:.0f}% intervals (counts: exact conditional)")
        wrote += ", behaviour.png"
    print(f"wrote {out}/{wrote}")


if __name__ == "__main__":
    main()
