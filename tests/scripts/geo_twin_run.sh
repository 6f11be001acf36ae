#!/usr/bin/env bash
# The paper's case 3 in metres and its twin placed by latitude and longitude
# (tests/data/geo_twin.yaml) give the same own-ship and target tracks to
# 0.1 m; the twin's CSVs carry lat_deg and lon_deg that map back onto them.
set -eu
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$FAIRWAY" run "$FAIRWAY_DATA/scenarios/paper/3-crossing.yaml" "$FAIRWAY_DATA/tests/data/geo_twin.yaml" \
  --out "$dir" > /dev/null
"$PYTHON" - "$dir/paper-3-crossing" "$dir/geo-twin" <<'PY'
import csv, sys
a, b = sys.argv[1], sys.argv[2]
for name in ("own.csv", "targets.csv"):
    ra = list(csv.DictReader(open(f"{a}/{name}")))
    rb = list(csv.DictReader(open(f"{b}/{name}")))
    assert len(ra) == len(rb) > 10, (name, len(ra), len(rb))
    assert "lat_deg" in rb[0] and "lat_deg" not in ra[0], name
    worst = max(max(abs(float(x["east_m"]) - float(y["east_m"])),
                    abs(float(x["north_m"]) - float(y["north_m"]))) for x, y in zip(ra, rb))
    assert worst <= 0.1, (name, worst)
    lat = [float(r["lat_deg"]) for r in rb]
    assert 50.9 < min(lat) and max(lat) < 51.2, (min(lat), max(lat))
    print(f"{name}: {len(ra)} rows, largest difference {worst:.3f} m")
PY
echo "twin runs agree"
