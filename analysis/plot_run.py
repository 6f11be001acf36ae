#!/usr/bin/env python3
"""Pictures of one `fairway run` directory, in the style of the paper's Figures 22-31.

Writes into the run directory (or --out):
  track.png     own and target tracks in nautical miles with hull outlines every
                --every seconds and the own domain ellipse at the closest
                approach; with a network its lanes (from sumo/run.sumocfg), the
                ships that came within 2 nm or that the own ship acted for named
                (the 10 closest), every other ship in sight a thin grey track;
                a caption line with the run's settings and outcome
  helm.png      helm order and rudder angle against time, with the policy's mode
  distance.png  centre distance to each target against time, domain size marked

    python3 analysis/plot_run.py runs/paper-1-head-on [--every 60] [--out DIR]
"""
import argparse
import json
import math
import os
import sys
import xml.etree.ElementTree as ET

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
TARGET_COLORS = ["tab:blue", "tab:green", "tab:purple", "tab:brown", "tab:pink",
                 "tab:olive", "tab:cyan", "tab:red", "navy", "darkgoldenrod"]  # 10: NAMED_MAX


NM = 1852.0
NAMED_WITHIN = 2 * NM  # ships that came this close, or that the own ship acted for, are named
NAMED_MAX = 10


def network_lanes(run):
    """[(width_m, [(x, y), ...])] of the run's network lanes (sumo/run.sumocfg's net-file),
    leaving out fairway's generated target and own-ship edges (fw_*) and SUMO's
    internal ones; [] without a network."""
    cfg = os.path.join(run, "sumo", "run.sumocfg")
    try:
        net = ET.parse(cfg).getroot().find("net-file").get("value")
        root = ET.parse(os.path.join(os.path.dirname(cfg), net)).getroot()
    except (OSError, ET.ParseError, AttributeError):
        return []
    lanes = []
    for e in root.iter("edge"):
        if e.get("function") == "internal" or e.get("id", "").startswith("fw_"):
            continue
        for ln in e.iter("lane"):
            pts = [tuple(map(float, p.split(","))) for p in ln.get("shape", "").split()]
            lanes.append((float(ln.get("width", "3.2")), pts))
    return lanes


def draw_lanes(ax, lanes):
    """Each lane as a band of its width, pale (SUMO's x/y are the plane's east/north)."""
    for w, pts in lanes:
        for (x0, y0), (x1, y1) in zip(pts, pts[1:]):
            d = math.hypot(x1 - x0, y1 - y0)
            if d == 0:
                continue
            ox, oy = -(y1 - y0) / d * w / 2, (x1 - x0) / d * w / 2
            xs = [x0 + ox, x1 + ox, x1 - ox, x0 - ox]
            ys = [y0 + oy, y1 + oy, y1 - oy, y0 - oy]
            ax.fill([v / NM for v in xs], [v / NM for v in ys], color="0.93", ec="0.8", lw=0.5,
                    zorder=0)


def named_targets(s):
    """The ids to name: acted for or within NAMED_WITHIN, the NAMED_MAX closest."""
    enc = [e for e in s["encounters"]
           if e.get("t_act_s") is not None or e["min_distance_m"] < NAMED_WITHIN]
    enc.sort(key=lambda e: e["min_distance_m"])
    return [e["id"] for e in enc[:NAMED_MAX]]


def caption(s, own):
    speed = own.speed_kn.iloc[0] if "speed_kn" in own and len(own) else float("nan")
    parts = [f"own ship {s['own_length_m']:.0f} x {s['own_breadth_m']:.0f} m at {speed:.1f} kn",
             f"domain {s['domain_m']:.0f} m (fore-aft x{s['domain_fore_aft_ratio']:g}, "
             f"{s.get('domain_reading', 'ellipse')})",
             f"traffic {s.get('traffic_behaviour') or 'scripted'}",
             f"{s['t_end_s']:.0f} s", f"min hull {s['min_hull_distance_m']:.0f} m"
             if s.get("min_hull_distance_m") is not None else "no hull distance",
             f"collision {'yes' if s['collision'] else 'no'}",
             f"domain entered {'yes' if s['domain_entered'] else 'no'}"]
    return ", ".join(parts)


def view_box(own, tgt, named, margin):
    """The own track and the named ships' tracks, with margin (m) round them."""
    xs, ys = list(own.east_m), list(own.north_m)
    if len(tgt) and named:
        g = tgt[tgt.id.isin(named)]
        xs += list(g.east_m)
        ys += list(g.north_m)
    return min(xs) - margin, max(xs) + margin, min(ys) - margin, max(ys) + margin


def plot_track(run, own, tgt, s, every, path):
    fig, ax = plt.subplots(figsize=(8, 8.4))
    lanes = network_lanes(run)
    draw_lanes(ax, lanes)
    ax.plot(own.east_m / NM, own.north_m / NM, color="tab:orange", lw=1.5, label="own ship")
    dt = own.t_s.iloc[1] - own.t_s.iloc[0] if len(own) > 1 else 1.0
    step = max(1, int(round(every / dt)))
    for _, r in own.iloc[::step].iterrows():
        xs, ys = outline(r.east_m, r.north_m, r.heading_deg, s["own_length_m"], s["own_breadth_m"])
        ax.fill(np.array(xs) / NM, np.array(ys) / NM, color="tab:orange", alpha=0.5)
        ax.annotate(f"{r.t_s:.0f}", (r.east_m / NM, r.north_m / NM), fontsize=6, xytext=(4, 4),
                    textcoords="offset points")
    enc = {e["id"]: e for e in s["encounters"]}
    named = named_targets(s)
    k = 0
    for tid, g in (tgt.groupby("id", sort=True) if len(tgt) else []):
        e = enc.get(tid, {})
        if tid not in named:  # every other ship in sight: its track only, unnamed
            ax.plot(g.east_m / NM, g.north_m / NM, color="0.6", lw=0.6, zorder=1)
            continue
        c = TARGET_COLORS[k % len(TARGET_COLORS)]
        k += 1
        ax.plot(g.east_m / NM, g.north_m / NM, color=c, lw=1,
                label=f"{tid} ({e.get('situation', '')}, {e['min_distance_m']:.0f} m)")
        for _, r in g.iloc[::step].iterrows():
            xs, ys = outline(r.east_m, r.north_m, r.heading_deg, e.get("length_m", 200),
                             e.get("breadth_m", 32))
            ax.fill(np.array(xs) / NM, np.array(ys) / NM, color=c, alpha=0.5)
    if len(tgt) and len(named) < tgt.id.nunique():
        ax.plot([], [], color="0.6", lw=0.6, label=f"{tgt.id.nunique() - len(named)} other ships in sight")
    # domain at the closest approach of the closest target
    cid = s.get("closest_target")
    if cid and cid in enc and len(tgt):
        tmin = enc[cid]["t_min_s"]
        o = own.iloc[(own.t_s - tmin).abs().argmin()]
        g = tgt[tgt.id == cid]
        t = g.iloc[(g.t_s - tmin).abs().argmin()]
        fa_ratio = s["domain_fore_aft_ratio"]
        if s.get("domain_reading") == "transverse":
            # the paper's reading: about the target, in its frame, beyond its hull (src/geom/geom.h)
            e = enc[cid]
            ex, ey = ellipse(t.east_m, t.north_m, t.heading_deg,
                             s["domain_m"] * fa_ratio + e.get("length_m", 200) / 2,
                             s["domain_m"] + e.get("breadth_m", 32) / 2)
            what = f"domain {s['domain_m']:.0f} m beyond {cid}'s hull (transverse)"
        else:
            ex, ey = ellipse(o.east_m, o.north_m, o.heading_deg, s["domain_m"] * fa_ratio, s["domain_m"])
            what = f"domain {s['domain_m']:.0f} m"
        ax.plot(ex / NM, ey / NM, "k--", lw=1, label=f"{what} at t = {tmin:.0f} s")
        ax.plot([o.east_m / NM, t.east_m / NM], [o.north_m / NM, t.north_m / NM], "k:", lw=1)
        ax.annotate(f"{enc[cid]['min_distance_m']:.0f} m", ((o.east_m + t.east_m) / 2 / NM,
                    (o.north_m + t.north_m) / 2 / NM), fontsize=8)
    x0, x1, y0, y1 = view_box(own, tgt, named, margin=0.5 * NM if not lanes else 1.0 * NM)
    ax.set_xlim(x0 / NM, x1 / NM)
    ax.set_ylim(y0 / NM, y1 / NM)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("east (nm)")
    ax.set_ylabel("north (nm)")
    fa = s["first_action"]
    act = f"act {fa['t_s']:.0f} s {fa['side']} {fa['helm_deg']:.0f} deg" if fa["acted"] else "no action"
    ax.set_title(f"{s['scenario']}: min {s['min_distance_m']:.0f} m, {act}")
    if len(tgt) == 0 and s["encounters"]:
        ax.text(0.5, 0.02, "targets.csv not written (outputs: targets_csv: false): own ship only",
                transform=ax.transAxes, ha="center", fontsize=8, color="0.3")
    ax.legend(fontsize=7, loc="best")
    ax.grid(alpha=0.3)
    fig.text(0.5, 0.01, caption(s, own), ha="center", fontsize=7, color="0.25")
    fig.tight_layout(rect=(0, 0.03, 1, 1))
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
    plot_track(a.run, own, tgt, s, a.every, os.path.join(out, "track.png"))
    plot_helm(own, s, os.path.join(out, "helm.png"))
    plot_distance(tgt, s, os.path.join(out, "distance.png"))
    print(f"wrote {out}/track.png, helm.png, distance.png")


if __name__ == "__main__":
    main()
