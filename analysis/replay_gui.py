#!/usr/bin/env python3
"""Replay one `fairway run` in sumo-gui: every ship where it was, the own ship included.

A run with `outputs: fcd: true` in its scenario leaves, in RUN_DIR/sumo/, the
floating car data of every ship SUMO had (fcd.xml, SUMO's FCD layout: x/y the
front bumper) beside run.sumocfg (the run's network, ship types, step and
seed).  This opens sumo-gui on run.sumocfg without its routes and, through
SUMO's TraCI (Debian's sumo-tools), puts every ship of each FCD timestep where
the file says (moveToXY, never onto a lane), so what is watched is what the run
computed: the own ship's manoeuvres and every ship the traffic slowed.  Ships
come and go as they did; the own ship is drawn signal orange at its own size
(summary.json), the others with their SUMO types.

    python3 analysis/replay_gui.py runs/NAME [--delay MS] [--keep]
    python3 analysis/replay_gui.py runs/NAME --sumo sumo      # no window: a check

With --sumo sumo (no display needed) the replay runs headless and, at every
timestep, reads each ship's position back from SUMO; it prints the number of
timesteps and ships and the largest difference from the file (0.01 m or less:
exit 0; more: exit 1).  Exit 2: the run has no fcd.xml or no run.sumocfg.
"""
import argparse
import contextlib
import io
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

SUMO_TOOLS = os.path.join(os.environ.get("SUMO_HOME", "/usr/share/sumo"), "tools")
OWN_TYPE = "fw_own_type"  # the own ship's SUMO type (src/traffic/traffic.h)
ROUTE = "fw_replay_route"


def fail(msg, code=2):
    print(f"replay_gui: {msg}", file=sys.stderr)
    sys.exit(code)


def timesteps(path):
    """(time, [(id, x, y, angle, type, speed)]) per timestep, streamed."""
    try:
        for _, el in ET.iterparse(path, events=("end",)):
            if el.tag != "timestep":
                continue
            ships = [(v.get("id"), float(v.get("x")), float(v.get("y")), float(v.get("angle")),
                      v.get("type"), float(v.get("speed"))) for v in el.iter("vehicle")]
            yield float(el.get("time")), ships
            el.clear()
    except (ET.ParseError, TypeError, ValueError) as e:
        fail(f"{path}: {e}")


def period(path):
    """The file's first timestep, and the seconds between its first two (1 if it has one)."""
    t = [tm for tm, _ in zip((tm for tm, _ in timesteps(path)), range(2))]
    return t[0] if t else 0.0, t[1] - t[0] if len(t) == 2 else 1.0


def own_size(run):
    try:
        with open(os.path.join(run, "summary.json")) as f:
            s = json.load(f)
        return float(s["own_length_m"]), float(s["own_breadth_m"])
    except (OSError, KeyError, ValueError):
        return 200.0, 32.0


def add_ship(traci, sid, vtype, own, known):
    if vtype not in known:
        traci.vehicletype.copy("DEFAULT_VEHTYPE", vtype)
        traci.vehicletype.setVehicleClass(vtype, "ship")
        traci.vehicletype.setShapeClass(vtype, "ship")
        if vtype == OWN_TYPE:
            traci.vehicletype.setLength(vtype, own[0])
            traci.vehicletype.setWidth(vtype, own[1])
            traci.vehicletype.setColor(vtype, (255, 80, 0, 255))
        known.add(vtype)
    traci.vehicle.add(sid, ROUTE, typeID=vtype, depart="now")


def replay(traci, fcd, own, check):
    """Returns (timesteps, ships seen, largest position difference in m)."""
    known = set(traci.vehicletype.getIDList())
    edge = next(e for e in traci.edge.getIDList() if not e.startswith(":"))
    traci.route.add(ROUTE, [edge])
    present, seen, worst, n = set(), set(), 0.0, 0
    for tm, ships in timesteps(fcd):
        now = {s[0] for s in ships}
        for sid in present - now:
            traci.vehicle.remove(sid)
        for sid, x, y, angle, vtype, speed in ships:
            if sid not in present:
                add_ship(traci, sid, vtype, own, known)
            traci.vehicle.moveToXY(sid, "", -1, x, y, angle, keepRoute=2, matchThreshold=1e-3)
            traci.vehicle.setSpeed(sid, speed)
        present = now
        seen |= now
        traci.simulationStep()  # one step of the file's period: the ships go where set
        n += 1
        if check:
            for sid, x, y, *_ in ships:
                px, py = traci.vehicle.getPosition(sid)
                worst = max(worst, abs(px - x), abs(py - y))
    return n, len(seen), worst


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run", help="a fairway run directory (RUN_DIR)")
    ap.add_argument("--sumo", default="sumo-gui", help="sumo-gui (default) or sumo (headless)")
    ap.add_argument("--delay", type=float, default=30.0, help="ms per replayed timestep")
    ap.add_argument("--keep", action="store_true", help="leave the window open at the end")
    a = ap.parse_args()
    cfg = os.path.join(a.run, "sumo", "run.sumocfg")
    fcd = os.path.join(a.run, "sumo", "fcd.xml")
    for f, why in ((cfg, "a SUMO run"), (fcd, "outputs: fcd: true in its scenario")):
        if not os.path.isfile(f):
            fail(f"{f}: no such file (the run needs {why})")
    sys.path.append(SUMO_TOOLS)
    try:
        import traci
    except ImportError:
        fail(f"no traci in {SUMO_TOOLS} (Debian's sumo-tools)")
    gui = os.path.basename(a.sumo).startswith("sumo-gui")
    if gui and not os.environ.get("DISPLAY"):
        fail("sumo-gui needs a display ($DISPLAY is not set); --sumo sumo replays without one")
    os.environ.setdefault("SUMO_HOME", os.path.dirname(SUMO_TOOLS))
    begin, dt = period(fcd)
    cmd = [a.sumo, "-c", cfg, "--route-files", "", "--begin", repr(begin), "--step-length", repr(dt),
           "--no-step-log", "true", "--no-warnings", "true", "--log", os.devnull]
    if gui:
        cmd += ["--start", "true", "--delay", repr(a.delay),
                "--quit-on-end", "false" if a.keep else "true"]
    with contextlib.redirect_stdout(io.StringIO()):  # TraCI's "Retrying in 1 seconds"
        traci.start(cmd, stdout=subprocess.DEVNULL)
    try:
        n, ships, worst = replay(traci, fcd, own_size(a.run), check=not gui)
    finally:
        traci.close(wait=not a.keep)
    print(f"replayed {n} timesteps, {ships} ships" +
          ("" if gui else f", largest position difference {worst:.3f} m"))
    sys.exit(0 if gui or worst <= 0.01 else 1)


if __name__ == "__main__":
    main()
