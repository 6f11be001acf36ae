#!/usr/bin/env bash
# A run placed by latitude and longitude exports as GeoJSON (RFC 7946:
# longitude first) whose coordinates are the CSVs' lat/lon; a run in metres
# only is refused with exit 2 and no file.
set -eu
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$FAIRWAY" run "$FAIRWAY_DATA/tests/data/geo_twin.yaml" "$FAIRWAY_DATA/scenarios/paper/3-crossing.yaml" \
  --out "$dir" > /dev/null
"$PYTHON" "$ANALYSIS/export_geojson.py" "$dir/geo-twin" > /dev/null
"$PYTHON" - "$dir/geo-twin" <<'PY'
import csv, json, sys
run = sys.argv[1]
doc = json.load(open(f"{run}/tracks.geojson"))
assert doc["type"] == "FeatureCollection"
lines = {f["properties"]["id"]: f for f in doc["features"] if f["geometry"]["type"] == "LineString"}
own = list(csv.DictReader(open(f"{run}/own.csv")))
c = lines["own"]["geometry"]["coordinates"]
assert len(c) == len(own), (len(c), len(own))
for (lon, lat), r in zip(c, own):
    assert abs(lon - float(r["lon_deg"])) < 1e-9 and abs(lat - float(r["lat_deg"])) < 1e-9
assert "T1" in lines and lines["T1"]["properties"]["role"] == "target"
cpa = [f for f in doc["features"] if f["properties"]["role"] == "cpa"]
rows = list(csv.DictReader(open(f"{run}/targets.csv")))
assert abs(cpa[0]["properties"]["range_m"] - min(float(r["range_m"]) for r in rows)) < 1e-9
print(f"{len(doc['features'])} features, own track {len(c)} points")
PY
if "$PYTHON" "$ANALYSIS/export_geojson.py" "$dir/paper-3-crossing" 2> "$dir/err"; then
  echo "a run without lat/lon was exported"; exit 1
fi
grep -q "missing columns lat_deg, lon_deg (the scenario needs an origin" "$dir/err"
[ ! -e "$dir/paper-3-crossing/tracks.geojson" ]
echo "geojson export ok"
