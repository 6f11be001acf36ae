#!/usr/bin/env bash
# A DNV situation's environment is run: baseline 02 with a 1 m/s current setting 090 (and a wave
# height, not modelled, said in run.log) against the same without: until the own ship first acts its
# hull is carried east by current x time (to 1 m); with a visibility of 1 NM the own ship meets the
# target out of sight and acts by rule 19 (run.log says so).
set -euo pipefail
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$PYTHON" - "$FAIRWAY_DATA/scenarios/dnv/traffic_situation_02.json" "$dir" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
json.dump(s, open(sys.argv[2] + "/calm.json", "w"))
s["environment"] = {"currentSpeed": 1.0, "currentDirection": 90.0, "significantWaveHeight": 2.0}
json.dump(s, open(sys.argv[2] + "/current.json", "w"))
s["environment"] = {"visibility": 1.0}
json.dump(s, open(sys.argv[2] + "/fog.json", "w"))
PY
for c in calm current fog; do
  "$FAIRWAY" run "$dir/$c.json" --out "$dir/runs" > "$dir/$c.out" 2>&1 || { cat "$dir/$c.out"; exit 1; }
done
grep -q "waves (2.0 m) are not modelled" "$dir/runs/current/run.log" || { head -3 "$dir/runs/current/run.log"; exit 1; }
grep -q "rule 19" "$dir/runs/fog/run.log" || { echo "no rule 19 in fog:"; head -8 "$dir/runs/fog/run.log"; exit 1; }
"$PYTHON" - "$dir/runs/calm/own.csv" "$dir/runs/current/own.csv" <<'PY'
import csv, sys
calm = list(csv.DictReader(open(sys.argv[1])))
cur = list(csv.DictReader(open(sys.argv[2])))
# before either acts (the rudder amidships in both)
n = next(i for i, r in enumerate(calm) if abs(float(r["rudder_deg"])) > 1e-9 or
         abs(float(cur[i]["rudder_deg"])) > 1e-9)
t = float(calm[n - 1]["t_s"])
de = float(cur[n - 1]["east_m"]) - float(calm[n - 1]["east_m"])
dn = float(cur[n - 1]["north_m"]) - float(calm[n - 1]["north_m"])
print("at %.0f s: carried %.2f m east, %.2f m north (current x time %.0f m)" % (t, de, dn, t))
assert abs(de - t) < 1.0 and abs(dn) < 1.0, (de, dn, t)
PY
echo "ok: a situation's environment is run"
