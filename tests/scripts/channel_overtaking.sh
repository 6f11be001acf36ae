#!/usr/bin/env bash
# The own ship overtaking close in a channel keeps clear without turning
# towards the ship it passes (issue 27 item 5, rule 13):
# tests/data/route/channel-overtaking.yaml, c3-mmg at 6 kn on networks/bend's
# east-going edges overtaking a 2 kn ship 125 m to port of its route.
# Deterministic (one SUMO seed, an explicit target, no traffic).  Asserted:
# no helm to port beyond the autopilot's steadying (-10 deg), the ordered
# helm changes sign at most 4 times, the hull centre within its side of the
# channel on the first leg (y = -500 to 0 m less half the ship's 42.8 m
# breadth, to 1 m), the hulls at least 120 m apart, no collision.  Before,
# the least helm's side was taken: port 10 deg, then port 25 deg from the
# channel's edge every other step (38 sign changes), towards the ship and
# across its bow, hulls 71 m apart (a 3 kn ship 175 m to port: collision).
set -u
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
scn=$FAIRWAY_DATA/tests/data/route/channel-overtaking.yaml
"$FAIRWAY" run "$scn" --out "$tmp/runs" > "$tmp/out.txt" 2>&1 ||
  { echo "run failed"; cat "$tmp/out.txt"; exit 1; }
"$PYTHON" - "$tmp/runs/channel-overtaking" <<'PY' || exit 1
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1] + "/own.csv")))
helm = [float(r["helm_deg"]) for r in rows]
flips, last = 0, 0
for h in helm:
    s = 1 if h > 0.05 else -1 if h < -0.05 else 0
    flips += bool(s and last and s != last)
    last = s or last
ys = [float(r["north_m"]) for r in rows if float(r["east_m"]) < 9800.0]
s = json.load(open(sys.argv[1] + "/summary.json"))
half = 0.5 * s["own_breadth_m"]
print("helm %.1f to %.1f deg, %d sign changes; first leg: hull centre y %.1f to %.1f m (its side "
      "of the channel: %.1f to %.1f m); hulls %.0f m apart at the closest, collision %s"
      % (min(helm), max(helm), flips, min(ys), max(ys), -500 + half, -half,
         s["min_hull_distance_m"], s["collision"]))
assert min(helm) > -10.0 and flips <= 4
assert min(ys) >= -500.0 + half - 1.0 and max(ys) <= -half + 1.0
assert s["min_hull_distance_m"] >= 120.0 and not s["collision"]
PY
echo "ok: the own ship overtaking close in a channel keeps clear, not towards the ship it passes"
