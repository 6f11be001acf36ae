#!/usr/bin/env python3
"""Pictures of one `fairway run` directory, in the style of the paper's Figures 22-31.

Writes into the run directory (or --out):
  track.png     own and target tracks with hull outlines every --every seconds and
                the own domain ellipse (hull-grown for the closest target) at the
                closest approach
  helm.png      helm order and rudder angle against time, with the policy's mode
  distance.png  centre distance to each target against time, domain size marked

    python3 analysis/plot_run.py runs/paper-1-head-on [--every 60] [--out DIR]
"""
import argparse
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402


def fail(msg):
    print(f"plot_run: {msg}", file=sys.stderr)
    sys.exit(2)


def load(run):
    try:
        own = pd.read_csv(os.path.join(run, "own.csv"))
        with open(os.path.join(run, "summary.json")) as f:
            summary = json.load(f)
        tp = os.path.join(run, "targets.csv")
        tgt = pd.read_csv(tp, dtype={"id": str}) if os.path.exists(tp) else pd.DataFrame()
    except Exception as exc:  # missing or malformed files all mean "not a run directory"
        fail(f"{run}: not a fairway run directory ({exc})")
    return own, tgt, summary


def outline(e, n, heading_deg, length, breadth):
    """Hull outline (pointed bow) as east/north arrays."""
    L, B = length / 2, breadth / 2
    pts = [(-L, -B), (L - B, -B), (L, 0), (L - B, B), (-L, B), (-L, -B)]  # (ahead, starboard)
    h = math.radians(heading_deg)
    xs = [e + a * math.sin(h) + s * math.cos(h) for a, s in pts]
    ys = [n + a * math.cos(h) - s * math.sin(h) for a, s in pts]
    return xs, ys


def ellipse(e, n, heading_deg, a, b):
    t = np.linspace(0, 2 * math.pi, 100)
    ahead, stbd = a * np.cos(t), b * np.sin(t)
    h = math.radians(heading_deg)
    return e + ahead * math.sin(h) + stbd * math.cos(h), n + ahead * math.cos(h) - stbd * math.sin(h)


# the own ship is always orange; targets never are
TARGET_COLORS = ["tab:blue", "tab:green", "tab:purple", "tab:brown", "tab:pink", "tab:gray",
                 "tab:olive", "tab:cyan", "tab:red"]


def plot_track(own, tgt, s, every, path):
    fig, ax = plt.subplots(figsize=(8, 8))
    ax.plot(own.east_m, own.north_m, color="tab:orange", lw=1.5, label="own ship")
    dt = own.t_s.iloc[1] - own.t_s.iloc[0] if len(own) > 1 else 1.0
    step = max(1, int(round(every / dt)))
    for _, r in own.iloc[::step].iterrows():
        ax.fill(*outline(r.east_m, r.north_m, r.heading_deg, s["own_length_m"], s["own_breadth_m"]),
                color="tab:orange", alpha=0.5)
        ax.annotate(f"{r.t_s:.0f}", (r.east_m, r.north_m), fontsize=6, xytext=(4, 4),
                    textcoords="offset points")
    enc = {e["id"]: e for e in s["encounters"]}
    for k, (tid, g) in enumerate(tgt.groupby("id", sort=True) if len(tgt) else []):
        c = TARGET_COLORS[k % len(TARGET_COLORS)]
        e = enc.get(tid, {})
        ax.plot(g.east_m, g.north_m, color=c, lw=1, label=f"{tid} ({e.get('situation', '')})")
        for _, r in g.iloc[::step].iterrows():
            ax.fill(*outline(r.east_m, r.north_m, r.heading_deg, e.get("length_m", 200),
                             e.get("breadth_m", 32)), color=c, alpha=0.5)
    # domain at the closest approach of the closest target
    cid = s.get("closest_target")
    if cid and cid in enc and len(tgt):
        tmin = enc[cid]["t_min_s"]
        o = own.iloc[(own.t_s - tmin).abs().argmin()]
        g = tgt[tgt.id == cid]
        t = g.iloc[(g.t_s - tmin).abs().argmin()]
        ax.plot(*ellipse(o.east_m, o.north_m, o.heading_deg, s["domain_m"] * s["domain_fore_aft_ratio"],
                         s["domain_m"]), "k--", lw=1, label=f"domain {s['domain_m']:.0f} m at t = {tmin:.0f} s")
        ax.plot([o.east_m, t.east_m], [o.north_m, t.north_m], "k:", lw=1)
        ax.annotate(f"{enc[cid]['min_distance_m']:.0f} m", ((o.east_m + t.east_m) / 2,
                    (o.north_m + t.north_m) / 2), fontsize=8)
    ax.set_aspect("equal")
    ax.set_xlabel("east (m)")
    ax.set_ylabel("north (m)")
    fa = s["first_action"]
    act = f"act {fa['t_s']:.0f} s {fa['side']} {fa['helm_deg']:.0f} deg" if fa["acted"] else "no action"
    ax.set_title(f"{s['scenario']}: min {s['min_distance_m']:.0f} m, {act}")
    ax.legend(fontsize=7, loc="best")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_helm(own, s, path):
    fig, ax = plt.subplots(figsize=(9, 4))
    ax.plot(own.t_s, own.helm_deg, label="helm order", lw=1.2)
    ax.plot(own.t_s, own.rudder_deg, label="rudder", lw=1.2)
    ax.axhline(0, color="k", lw=0.5)
    for t, name in ((s["first_action"]["t_s"], "action"), (s["t_return_s"], "return"),
                    (s["t_on_course_s"], "on course")):
        if t is not None:
            ax.axvline(t, color="grey", ls=":", lw=1)
            ax.annotate(name, (t, ax.get_ylim()[1] * 0.9), fontsize=7, rotation=90)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("angle (deg, + starboard)")
    ax.set_title(f"{s['scenario']}: helm order and rudder")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_distance(tgt, s, path):
    fig, ax = plt.subplots(figsize=(9, 4))
    for k, (tid, g) in enumerate(tgt.groupby("id", sort=True) if len(tgt) else []):
        ax.plot(g.t_s, g.range_m, label=tid, lw=1.2, color=TARGET_COLORS[k % len(TARGET_COLORS)])
    ax.axhline(s["domain_m"], color="k", ls="--", lw=1, label=f"domain {s['domain_m']:.0f} m")
    ax.set_yscale("log")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("centre distance (m)")
    ax.set_title(f"{s['scenario']}: distance to each target")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run")
    p.add_argument("--every", type=float, default=120.0, help="outline interval, s (default 120)")
    p.add_argument("--out", help="directory for the PNGs (default: the run directory)")
    a = p.parse_args()
    if not a.every > 0:
        fail("--every must be positive")
    own, tgt, s = load(a.run)
    out = a.out or a.run
    os.makedirs(out, exist_ok=True)
    plot_track(own, tgt, s, a.every, os.path.join(out, "track.png"))
    plot_helm(own, s, os.path.join(out, "helm.png"))
    plot_distance(tgt, s, os.path.join(out, "distance.png"))
    print(f"wrote {out}/track.png, helm.png, distance.png")


if __name__ == "__main__":
    main()
