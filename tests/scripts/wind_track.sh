#!/usr/bin/env bash
# In a wind the own ship keeps its planned line (run_world.c: its one leg steered as a route): the
# Dover crossing, empty sea, 20 kn from 225 deg, an hour at 12 kn on 010 deg: it ends within 100 m of its
# line and 200 m of its planned end, heading within 3 deg of 010 (it crabs to windward), not turned into
# the wind as it did with the rudder amidships (heading 226 after the hour, 13.7 km off).
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sed 's/^name: .*/name: windy/; s/^  fill: 45/  fill: 0\n  behaviour: blind/' \
  "$FAIRWAY_DATA/scenarios/traffic/dover-crossing.yaml" > "$tmp/w.yaml"
printf 'environment:\n  wind: {speed_kn: 20, from_deg: 225}\n' >> "$tmp/w.yaml"
"$FAIRWAY" run "$tmp/w.yaml" --out "$tmp/o" > "$tmp/out" 2>&1 || { cat "$tmp/out"; exit 1; }
"$PYTHON" - "$tmp/o/windy/own.csv" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
e, n, h = float(rows[-1]["east_m"]), float(rows[-1]["north_m"]), float(rows[-1]["heading_deg"])
t = float(rows[-1]["t_s"])
c = math.radians(10.0)
de, dn = e - 18000.0, n + 11000.0
across = de * math.cos(c) - dn * math.sin(c)
end = math.hypot(de - 12 * 1852 / 3600 * t * math.sin(c), dn - 12 * 1852 / 3600 * t * math.cos(c))
print("after %.0f s: %.1f m off the line, %.0f m from the planned end, heading %.2f deg" % (t, across, end, h))
assert abs(across) < 100 and end < 200 and abs(h - 10.0) < 3.0
PY
echo "the own ship keeps its line in a wind"
