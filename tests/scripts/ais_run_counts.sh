#!/usr/bin/env bash
# An AIS run says what the reading met (issue 28): two ships on one MMSI (two
# reports of 219000001 at 10:00:30, 5.5 km apart: one was dropped as a
# duplicate and the run said nothing) and a report the plane cannot hold (90
# deg of longitude from the origin: it stopped the whole read with "-78.5, 0
# cannot be converted") are counted in run.log and summary.json.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
cat > "$dir/reports.csv" <<'CSV'
# Timestamp,Type of mobile,MMSI,Latitude,Longitude,SOG,COG
01/03/2026 10:00:00,Class A,219000001,56.500000,11.500000,10.0,0.0
01/03/2026 10:00:30,Class A,219000001,56.501000,11.500000,10.0,0.0
01/03/2026 10:00:30,Class A,219000001,56.550000,11.500000,10.0,0.0
01/03/2026 10:00:30,Class A,219000001,56.501000,11.500000,10.0,0.0
01/03/2026 10:00:40,Class A,219000002,0.000000,101.500000,10.0,0.0
01/03/2026 10:01:00,Class A,219000001,56.502000,11.500000,10.0,0.0
CSV
sed -e 's/^  ais: .*/  ais: reports.csv/' -e 's/^  ais_end: .*/  ais_end: 120/' \
    -e 's/^  duration_s: .*/  duration_s: 30/' \
    "$FAIRWAY_DATA/scenarios/ais/ais-crossing.yaml" > "$dir/s.yaml"
grep -q "ais: reports.csv" "$dir/s.yaml" || fail "scenario not made"
out=$("$FAIRWAY" run "$dir/s.yaml" --out "$dir/runs" 2>&1) || fail "run: $out"
log="$dir/runs/ais-crossing/run.log"
sum="$dir/runs/ais-crossing/summary.json"
grep -q "traffic: 1 AIS reports at an instant their MMSI already had, more than 50 m from it, dropped: two ships on one MMSI (1 MMSIs, the first 219000001)" "$log" \
  || fail "run.log: $(grep traffic: "$log")"
grep -q "traffic: 1 AIS reports skipped: the plane cannot hold them (the first at $dir/reports.csv:6)" "$log" \
  || fail "run.log: $(grep traffic: "$log")"
grep -q '"ais": {"duplicates_dropped": 2, "two_ships_one_mmsi": 1, "mmsis_shared": 1, "first_mmsi_shared": 219000001, "not_projected": 1}' "$sum" \
  || fail "summary.json: $(grep ais "$sum")"
python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$sum" || fail "summary.json is not JSON"
echo "ok: AIS counts in run.log and summary.json"
