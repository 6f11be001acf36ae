#!/usr/bin/env bash
# The own ship overtaken close in a channel keeps within it (issue 27 item 5):
# tests/data/route/channel-overtaken.yaml, c3-mmg at 10 kn on networks/bend's
# east-going edges (its route on the starboard lane's centre line, y = -375
# m), a 16 kn ship that does not keep clear coming up 150 m to port of its
# line, inside the 300 m domain.  Deterministic (one SUMO seed,
# an explicit target).  Asserted: the hull stays within its side of the
# channel on the first leg (y = -500 to 0 m, the lanes' edges from the
# network's 2 x 250 m lanes, less half the ship's 42.8 m breadth, to 1 m),
# the run says the domain cannot be kept within the route's band (it cannot:
# a 150 m pass with 250 m of lane), and there is no collision.  Before the
# band was the helm search's, the own ship stood on, then acted (rule 17(b))
# 22 deg to starboard and left the channel by 1332 m.
set -u
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
scn=$FAIRWAY_DATA/tests/data/route/channel-overtaken.yaml
"$FAIRWAY" run "$scn" --out "$tmp/runs" > "$tmp/out.txt" 2>&1 ||
  { echo "run failed"; cat "$tmp/out.txt"; exit 1; }
run=$tmp/runs/channel-overtaken
grep -q "the domain cannot be kept within the route's band" "$run/run.log" ||
  { echo "no 'domain cannot be kept' in run.log:"; cat "$run/run.log"; exit 1; }
"$PYTHON" - "$run" <<'PY' || exit 1
import csv, json, sys
rows = [r for r in csv.DictReader(open(sys.argv[1] + "/own.csv")) if float(r["east_m"]) < 9800.0]
ys = [float(r["north_m"]) for r in rows]
s = json.load(open(sys.argv[1] + "/summary.json"))
half = 0.5 * s["own_breadth_m"]
print("first leg: hull centre y from %.1f to %.1f m (its side of the channel: %.1f to %.1f m); "
      "closest %.0f m, collision %s" % (min(ys), max(ys), -500 + half, -half,
                                         s["min_distance_m"], s["collision"]))
assert len(rows) > 600 and min(ys) >= -500.0 + half - 1.0 and max(ys) <= -half + 1.0
assert not s["collision"]
PY
echo "ok: the own ship overtaken close keeps within its channel"
