#!/usr/bin/env python3
"""One sheet with the tracks of all 22 Imazu cases from `fairway run` directories.

    python3 analysis/plot_imazu.py RUNS_DIR [--out imazu.png]

RUNS_DIR holds imazu-01 ... imazu-22 (as written by
`fairway run scenarios/imazu/*.yaml --out RUNS_DIR`).  Each panel: own ship
(orange) and targets, closest approach marked, min distance and first action
in the title; a red title marks a domain entry.  Targets appear from their
first detection (avoidance.radius_nm, default 8 nm), so a head-on target
12 nm off at t = 0 starts 8 nm from the own ship in the picture.
"""
import argparse
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402

NM = 1852.0
TARGET_COLORS = ["tab:blue", "tab:green", "tab:purple", "tab:brown"]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("runs")
    p.add_argument("--out", default=None, help="PNG path (default RUNS/imazu.png)")
    a = p.parse_args()
    fig, axes = plt.subplots(4, 6, figsize=(18, 12.5))
    found = 0
    for k, ax in enumerate(axes.flat):
        n = k + 1
        run = os.path.join(a.runs, f"imazu-{n:02d}")
        if n > 22 or not os.path.isdir(run):
            ax.axis("off")
            continue
        try:
            own = pd.read_csv(os.path.join(run, "own.csv"))
            tgt = pd.read_csv(os.path.join(run, "targets.csv"))
            with open(os.path.join(run, "summary.json")) as f:
                s = json.load(f)
        except Exception as exc:  # a half-written or foreign directory
            print(f"plot_imazu: {run}: {exc}", file=sys.stderr)
            sys.exit(2)
        found += 1
        ax.plot(own.east_m / NM, own.north_m / NM, color="tab:orange", lw=1.5)
        ax.plot(own.east_m.iloc[0] / NM, own.north_m.iloc[0] / NM, "o", color="tab:orange", ms=3)
        for j, (tid, g) in enumerate(tgt.groupby("id", sort=True)):
            c = TARGET_COLORS[j % len(TARGET_COLORS)]  # never the own ship's orange
            ax.plot(g.east_m / NM, g.north_m / NM, lw=1, color=c)
            ax.plot(g.east_m.iloc[0] / NM, g.north_m.iloc[0] / NM, "o", ms=3, color=c)
        cid = s.get("closest_target")
        if cid:
            e = next(x for x in s["encounters"] if x["id"] == cid)
            o = own.iloc[(own.t_s - e["t_min_s"]).abs().argmin()]
            g = tgt[tgt.id == cid]
            t = g.iloc[(g.t_s - e["t_min_s"]).abs().argmin()]
            ax.plot([o.east_m / NM, t.east_m / NM], [o.north_m / NM, t.north_m / NM], "k-", lw=1.5)
        fa = s["first_action"]
        act = f"{fa['side'][:4]} {fa['helm_deg']:.0f}° @{fa['t_s']:.0f}s" if fa["acted"] else "no action"
        ax.set_title(f"{n}: min {s['min_distance_m']:.0f} m, {act}", fontsize=9,
                     color="red" if s["domain_entered"] or s["collision"] else "black")
        ax.set_xlim(-6.5, 6.5)
        ax.set_ylim(-6.5, 6.5)
        ax.set_aspect("equal")
        ax.tick_params(labelsize=6)
        ax.grid(alpha=0.3)
    if not found:
        print(f"plot_imazu: no imazu-NN directories in {a.runs}", file=sys.stderr)
        sys.exit(2)
    fig.suptitle("Imazu cases: C-3 (c3-mmg) at 12 kn, 300 m domain; east/north in nm; red: domain entered")
    fig.tight_layout()
    out = a.out or os.path.join(a.runs, "imazu.png")
    fig.savefig(out, dpi=90)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
