#!/usr/bin/env bash
# In a current the own ship keeps its planned line over ground (run_world.c: its one leg steered as a
# route): the Dover crossing, empty sea, 2 kn setting towards 100 deg (straight across its 010 track),
# an hour at 12 kn: it ends within 100 m of its line, heading within 1 deg of 010 less the crab angle
# asin(2 / 12) = 9.6 deg, never more than 300 m off (112 m while it first turns into the set).  With
# the rudder amidships until something made it act, it held 010 and was set 2.5 km off its line.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sed 's/^name: .*/name: set/; s/^  fill: 45/  fill: 0\n  behaviour: blind/' \
  "$FAIRWAY_DATA/scenarios/traffic/dover-crossing.yaml" > "$tmp/c.yaml"
printf 'environment:\n  current: {speed_kn: 2, towards_deg: 100}\n' >> "$tmp/c.yaml"
"$FAIRWAY" run "$tmp/c.yaml" --out "$tmp/o" > "$tmp/out" 2>&1 || { cat "$tmp/out"; exit 1; }
"$PYTHON" - "$tmp/o/set/own.csv" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
c = math.radians(10.0)
def across(r):
    return (float(r["east_m"]) - 18000.0) * math.cos(c) - (float(r["north_m"]) + 11000.0) * math.sin(c)
worst = max(abs(across(r)) for r in rows)
h, t = float(rows[-1]["heading_deg"]), float(rows[-1]["t_s"])
crab = math.degrees(math.asin(2.0 / 12.0))
print("after %.0f s: %.1f m off the line (at most %.0f m), heading %.2f deg (010 less the crab %.2f: %.2f)"
      % (t, across(rows[-1]), worst, h, crab, 10.0 - crab))
assert abs(across(rows[-1])) < 100 and worst < 300 and abs(h - (10.0 - crab)) < 1.0
PY
echo "the own ship keeps its line in a current"
