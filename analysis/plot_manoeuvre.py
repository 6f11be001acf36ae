#!/usr/bin/env python3
"""Plots of standard manoeuvres from `fairway manoeuvre ... --csv` time histories.

For each turning-circle CSV: one sheet in the style of the paper's Figures 2 to 9
(trajectory, turning rate, heading change, speed), with the sea-trial values
marked when a trial file is given.  For each zig-zag CSV: heading and rudder
against time.  Writes one PNG per CSV into --out.

    python3 analysis/plot_manoeuvre.py out/manoeuvres/*.csv --trial c3 --out out/manoeuvres
"""
import argparse
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

COLUMNS = ["t_s", "east_m", "north_m", "heading_deg", "u_mps", "v_mps", "r_degps",
           "rudder_deg", "helm_deg", "propeller_rps"]
KNOT = 1852.0 / 3600.0


def fail(msg):
    print(f"plot_manoeuvre: {msg}", file=sys.stderr)
    sys.exit(2)


def read_history(path):
    try:
        df = pd.read_csv(path)
    except Exception as exc:  # pandas raises many kinds; all mean the same to a user
        fail(f"{path}: cannot read CSV: {exc}")
    missing = [c for c in COLUMNS if c not in df.columns]
    if missing:
        fail(f"{path}: missing columns {', '.join(missing)}")
    if df.empty:
        fail(f"{path}: no rows")
    return df


def read_trial(name):
    """Trial rows keyed by (side, speed) from scenarios/ships/NAME-trial.yaml or a path."""
    if not name:
        return {}
    try:
        import yaml
    except ImportError:
        fail("python3-yaml is needed for --trial")
    path = name
    if not os.path.exists(path):
        root = os.environ.get("FAIRWAY_DATA",
                              os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
        path = os.path.join(root, "scenarios", "ships", f"{name}-trial.yaml")
    try:
        with open(path) as f:
            data = yaml.safe_load(f)
    except OSError as exc:
        fail(f"{path}: {exc.strerror}")
    rows = {}
    for row in data.get("turns", []):
        rows[(row["side"], round(float(row["speed_kn"]), 2))] = row
    return rows


def turning_sheet(df, title, trial_row, out_png):
    psi0 = df["heading_deg"].iloc[0]
    side = 1.0 if df["rudder_deg"].iloc[-1] > 0 else -1.0
    heading = np.unwrap(np.radians(df["heading_deg"] - psi0))
    change = np.degrees(side * heading)
    speed_kn = np.hypot(df["u_mps"], df["v_mps"]) / KNOT
    fig, ax = plt.subplots(2, 2, figsize=(12, 10))
    fig.suptitle(title)

    a = ax[0, 0]
    a.plot(side * df["east_m"], df["north_m"], label="fairway (midship)")
    for level, marker in ((90.0, "o"), (180.0, "s")):
        i = int(np.searchsorted(change, level))
        if i < len(df):
            a.plot(side * df["east_m"].iloc[i], df["north_m"].iloc[i], marker, color="C0")
    if trial_row:
        a.plot([trial_row.get("transfer_m", np.nan)], [trial_row.get("advance_m", np.nan)],
               "o", mfc="none", color="C3", ms=10, label="sea trial: advance, transfer")
        if "tactical_diameter_m" in trial_row:
            a.axvline(trial_row["tactical_diameter_m"], color="C3", ls="--",
                      label="sea trial: tactical diameter")
    a.set_xlabel("transfer (m, to the turning side)")
    a.set_ylabel("advance (m)")
    a.set_aspect("equal", adjustable="datalim")
    a.grid(True)
    a.legend(loc="lower right")
    a.set_title("trajectory")

    a = ax[0, 1]
    a.plot(df["t_s"], side * df["r_degps"], label="fairway")
    if trial_row and "steady_rate_degps" in trial_row:
        a.axhline(trial_row["steady_rate_degps"], color="C3", ls="--", label="sea trial, steady")
    a.set_xlabel("time (s)")
    a.set_ylabel("turning rate (deg/s)")
    a.grid(True)
    a.legend()
    a.set_title("turning rate")

    a = ax[1, 0]
    a.plot(df["t_s"], change)
    a.set_xlabel("time (s)")
    a.set_ylabel("heading change (deg)")
    a.grid(True)
    a.set_title("heading")

    a = ax[1, 1]
    a.plot(df["t_s"], speed_kn)
    a.set_xlabel("time (s)")
    a.set_ylabel("speed (kn)")
    a.grid(True)
    a.set_title("speed")
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)
    plt.close(fig)


def zigzag_sheet(df, title, out_png):
    psi0 = df["heading_deg"].iloc[0]
    heading = np.degrees(np.unwrap(np.radians(df["heading_deg"] - psi0)))
    fig, ax = plt.subplots(figsize=(11, 5))
    ax.plot(df["t_s"], heading, label="heading change (deg)")
    ax.plot(df["t_s"], df["rudder_deg"], label="rudder (deg)")
    ax.plot(df["t_s"], df["helm_deg"], ls=":", label="helm order (deg)")
    ax.set_xlabel("time (s)")
    ax.grid(True)
    ax.legend()
    ax.set_title(title)
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv", nargs="+", help="time histories written by fairway manoeuvre --csv")
    ap.add_argument("--trial", help="ship name (scenarios/ships/NAME-trial.yaml) or trial file")
    ap.add_argument("--out", default=".", help="directory for the PNG files")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    trial = read_trial(args.trial)
    for path in args.csv:
        df = read_history(path)
        base = os.path.splitext(os.path.basename(path))[0]
        out_png = os.path.join(args.out, base + ".png")
        m = re.match(r"turning_(starboard|port)_([0-9.]+)kn", base)
        if m:
            row = trial.get((m.group(1), round(float(m.group(2)), 2)))
            title = f"35 deg {m.group(1)} turning circle at {m.group(2)} kn"
            turning_sheet(df, title, row, out_png)
        elif base.startswith("zigzag"):
            zigzag_sheet(df, base.replace("_", " "), out_png)
        else:  # a CSV with another name: decide from the helm history
            if (df["helm_deg"].diff().abs() > 0).sum() > 1:
                zigzag_sheet(df, base, out_png)
            else:
                turning_sheet(df, base, None, out_png)
        print(out_png)


if __name__ == "__main__":
    main()
