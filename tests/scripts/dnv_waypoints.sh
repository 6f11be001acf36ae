#!/usr/bin/env bash
# A DNV target follows its waypoints: baseline 01's target given a bend (a waypoint 1 nm east of
# its track half way) and a speed per leg (12.1 kn, then 8 kn) passes through the bend within 1 m
# (targets.csv's lat/lon against the file's), at each leg's speed, and goes on along its last
# leg after the last waypoint; --ship names the own ship's model in run.log.  The own ship given
# a second leg follows its waypoints as a route (avoid/route.h): run.log lists both legs.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$PYTHON" - "$FAIRWAY_DATA/scenarios/dnv/traffic_situation_01.json" "$dir/bend.json" <<'PY' || exit 1
import json, math, sys
s = json.load(open(sys.argv[1]))
w = s["targetShips"][0]["waypoints"]
a, b = w[0]["position"], w[1]["position"]
mid = {"lat": (a["lat"] + b["lat"]) / 2,
       "lon": (a["lon"] + b["lon"]) / 2 + 1852.0 / (111320.0 * math.cos(math.radians(a["lat"])))}
w.insert(1, {"position": mid, "leg": {"sog": 12.1}})
w[2]["leg"]["sog"] = 8.0
o = s["ownShip"]["waypoints"]  # the own ship: a second leg, 30 deg to starboard, at 12 kn
e = o[1]["position"]
o.append({"position": {"lat": e["lat"] + 1852.0 * math.cos(math.radians(30)) / 110574.0,
                       "lon": e["lon"] + 1852.0 * 0.5 / (111320.0 * math.cos(math.radians(e["lat"])))},
          "leg": {"sog": 12.0}})
json.dump(s, open(sys.argv[2], "w"), indent=1)
PY
"$FAIRWAY" run "$dir/bend.json" --ship c3 --out "$dir/runs" > "$dir/out.txt" 2>&1 || { cat "$dir/out.txt"; exit 1; }
"$PYTHON" - "$dir/bend.json" "$dir/runs/bend" <<'PY' || exit 1
import csv, json, math, sys
s = json.load(open(sys.argv[1]))
wp = s["targetShips"][0]["waypoints"]
rows = [r for r in csv.DictReader(open(sys.argv[2] + "/targets.csv")) if r["id"] == "2"]
log = open(sys.argv[2] + "/run.log").read()
lat0 = wp[1]["position"]["lat"]
def xy(lat, lon):  # metres about waypoint 1 (equirectangular: mm over these few metres)
    k = 111320.0
    return ((lon - wp[1]["position"]["lon"]) * k * math.cos(math.radians(lat0)),
            (lat - lat0) * 110574.0)
p = [xy(float(r["lat_deg"]), float(r["lon_deg"])) for r in rows]
def seg(a, b):  # distance from waypoint 1 (the origin) to segment ab
    dx, dy = b[0] - a[0], b[1] - a[1]
    t = max(0.0, min(1.0, -(a[0] * dx + a[1] * dy) / (dx * dx + dy * dy or 1)))
    return math.hypot(a[0] + t * dx, a[1] + t * dy)
miss = min(seg(p[i], p[i + 1]) for i in range(len(p) - 1))
k = min(range(len(p)), key=lambda i: math.hypot(*p[i]))
v1, v2 = float(rows[k - 20]["speed_kn"]), float(rows[k + 20]["speed_kn"])
own_end = open(sys.argv[2] + "/own.csv").read().splitlines()[-1].split(",")[0]
end = float(rows[-1]["t_s"]) == float(own_end)
ok = (miss < 1.0 and abs(v1 - 12.1) < 1e-9 and abs(v2 - 8.0) < 1e-9 and end
      and "own ship model: c3 (--ship)" in log and "a route steered leg by leg" in log
      and "route: leg 2 of 2" in log)
print(f"bend passed within {miss:.3f} m; {v1} kn before, {v2} kn after; "
      f"present to the end: {end}; model in run.log: {'own ship model: c3 (--ship)' in log}")
sys.exit(0 if ok else 1)
PY
echo "a DNV target follows its waypoints at each leg's speed"
