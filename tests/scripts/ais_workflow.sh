#!/usr/bin/env bash
# The AIS workflow of scenarios/ais/README.md end to end: summary, tracks,
# demand (and SUMO running it), the replay scenario; then bad input: exit 2,
# FILE:LINE: FIELD, and no output file.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
ais=$FAIRWAY_DATA/scenarios/ais
file=$ais/aisdk-2026-03-01.csv
fail() { echo "FAIL: $*"; exit 1; }

out=$("$FAIRWAY" ais summary "$file") || fail "summary: exit $?"
for want in "rows: 1222" "kept: 1199 (Class A 1108, Class B 91; without SOG 1, without COG 91)" \
            "skipped, not a ship: 21" "skipped, broken line: 1" "skipped, no position: 1" \
            "ships: 6 (Class A 5, Class B 1)" "ships, cargo: 2" \
            "time: 2026-03-01 10:00:00 to 2026-03-01 10:45:00 UTC (2700 s)"; do
  grep -qxF "$want" <<<"$out" || fail "summary lacks '$want': $out"
done

"$FAIRWAY" ais tracks "$file" --origin 56.5,11.5 --out "$dir/tracks.csv" 2> "$dir/tracks.log" ||
  fail "tracks: $(cat "$dir/tracks.log")"
grep -qxF "duplicates dropped: 1" "$dir/tracks.log" || fail "tracks: $(cat "$dir/tracks.log")"
[ "$(head -1 "$dir/tracks.csv")" = "t_s,id,east_m,north_m,course_deg,speed_kn,type,length_m,breadth_m" ] ||
  fail "tracks header"
[ "$(wc -l < "$dir/tracks.csv")" -eq 1199 ] || fail "tracks: $(wc -l < "$dir/tracks.csv") lines, expected 1198 points + header"

out=$("$FAIRWAY" ais demand "$file" --network channel --origin 56.5,11.5 --out "$dir/demand.yaml") ||
  fail "demand: $out"
grep -qxF "route east: 2 passes, 2.667 per hour" <<<"$out" || fail "demand: $out"
grep -qxF "route west: 3 passes, 4.000 per hour" <<<"$out" || fail "demand: $out"
out=$(cd "$dir" && "$FAIRWAY" traffic --network channel --demand "$dir/demand.yaml" --ships 5 \
        --duration 60 --every 60 2>&1) || fail "SUMO on the AIS demand: $out"
grep -q "east_.*_fill0" "$dir/fairway-traffic.rou.xml" || fail "no AIS streams in the route file"

out=$("$FAIRWAY" run "$ais/ais-crossing.yaml" --out "$dir/runs" 2>&1) || fail "run: $out"
grep -q "^219000102,tanker,180.0,32.0,crossing give-way" "$dir/runs/ais-crossing/encounters.csv" ||
  fail "the tanker is no give-way crossing: $(cat "$dir/runs/ais-crossing/encounters.csv")"

# bad input: a header without MMSI; no output left
sed '1s/,MMSI,/,Mmsi,/' "$file" > "$dir/bad.csv"
out=$("$FAIRWAY" ais tracks "$dir/bad.csv" --origin 56.5,11.5 --out "$dir/bad-tracks.csv" 2>&1)
rc=$?
[ $rc -eq 2 ] || fail "bad header: exit $rc: $out"
grep -qF "bad.csv:1: header: no column 'MMSI' (the mmsi)" <<<"$out" || fail "bad header: $out"
[ -z "$(ls -A "$dir" | grep bad-tracks)" ] || fail "output left behind: $(ls -A "$dir")"
# a scenario with AIS traffic and no origin
grep -v '^origin:' "$ais/ais-crossing.yaml" | sed 's/lat_deg: 56.463971.*/east_m: 10000/; s/lon_deg: 11.662224.*/north_m: -4000/' \
  > "$dir/no-origin.yaml"
cp "$file" "$dir/"
out=$("$FAIRWAY" run "$dir/no-origin.yaml" --out "$dir/bad-runs" 2>&1)
rc=$?
[ $rc -eq 2 ] || fail "no origin: exit $rc: $out"
grep -Eq "no-origin.yaml:[0-9]+: traffic.ais: AIS positions are latitudes and longitudes" <<<"$out" ||
  fail "no origin: $out"
[ ! -e "$dir/bad-runs" ] || fail "run directory left behind"
# a window key that is neither a time nor seconds
sed 's/ais_end: 1800 .*/ais_end: yesterday/' "$ais/ais-crossing.yaml" > "$dir/bad-window.yaml"
out=$("$FAIRWAY" run "$dir/bad-window.yaml" --out "$dir/bad-runs" 2>&1)
rc=$?
[ $rc -eq 2 ] || fail "bad window: exit $rc: $out"
grep -Eq "bad-window.yaml:[0-9]+: traffic.ais_end: expected" <<<"$out" || fail "bad window: $out"
# a geo-referenced network has its own plane: --origin is refused there
out=$("$FAIRWAY" ais demand "$file" --network geo-channel --origin 57,11.5 --out "$dir/geo.yaml" 2>&1)
rc=$?
[ $rc -eq 2 ] || fail "geo network with --origin: exit $rc: $out"
grep -q "network 'geo-channel' is geo-referenced" <<<"$out" || fail "geo network with --origin: $out"
[ ! -e "$dir/geo.yaml" ] || fail "geo network with --origin: a demand was written"
echo "ok: AIS workflow"
