#!/usr/bin/env bash
# Names and numbers in scenario and study files (issue 28): an empty name, a
# name with a line break (said, not quoted, so the message stays one line), an
# id fairway reserves (a target fw_own: its own SUMO edge), each refused at
# load with FILE:LINE: FIELD and exit 2; a number out of range quoted as the
# file has it (80.000001, not 80), and an own ship at latitude 90 not reported
# as 90.0001.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
base=$FAIRWAY_DATA/scenarios/paper/1-head-on.yaml
expect() { # expect PATTERN ARGS... (exit 2, one line of message)
  local pattern=$1; shift
  out=$("$@" 2>&1)
  rc=$?
  [ $rc -eq 2 ] && grep -Eq -- "$pattern" <<<"$out" || { echo "exit $rc: $* -> $out"; exit 1; }
  [ "$(wc -l <<<"$out")" -eq 1 ] || { echo "not one line: $out"; exit 1; }
  [ ! -e "$dir/runs" ] || { echo "a run directory was left"; exit 1; }
}
sed 's/^name: .*/name: ""/' "$base" > "$dir/a.yaml"
expect "a.yaml:15: name: is empty: use letters" "$FAIRWAY" run "$dir/a.yaml" --out "$dir/runs"
sed 's/^name: .*/name: "two\\nlines"/' "$base" > "$dir/b.yaml"
expect "b.yaml:15: name: contains a line break or other control character" \
  "$FAIRWAY" run "$dir/b.yaml" --out "$dir/runs"
sed 's/{id: T1,/{id: fw_own,/' "$base" > "$dir/c.yaml"
expect "c.yaml:27: traffic.targets\[0\].id: 'fw_own': names beginning 'fw_' are fairway's own" \
  "$FAIRWAY" run "$dir/c.yaml" --out "$dir/runs"
sed 's/^name: .*/name: geo\norigin: {lat_deg: 80.000001, lon_deg: 0}/' "$base" > "$dir/d.yaml"
expect "d.yaml:16: origin.lat_deg: 80.000001 is out of range \[-80, 80\]" \
  "$FAIRWAY" run "$dir/d.yaml" --out "$dir/runs"
sed -e 's/^name: .*/name: geo\norigin: {lat_deg: 80, lon_deg: 0}/' \
    -e 's/^  east_m: 0$/  lat_deg: 90/' -e 's/^  north_m: 0$/  lon_deg: 0/' "$base" > "$dir/e.yaml"
grep -q "^  lat_deg: 90$" "$dir/e.yaml" || { echo "e.yaml not made"; exit 1; }
expect "e.yaml:[0-9]+: own_ship.lat_deg: 90, 0 is more than 1000 km from the origin" \
  "$FAIRWAY" run "$dir/e.yaml" --out "$dir/runs"
# options too: the number as typed ("--speed: 40 kn is above 40 kn" before)
expect "^fairway: --speed: 40.0000001 kn is above 40 kn" \
  "$FAIRWAY" manoeuvre turning --ship c3 --speed 40.0000001 --rudder 35
expect "^fairway: --radius 100.0000001: must be in \(0, 100\] nm" "$FAIRWAY" traffic --radius 100.0000001
expect "^fairway: origin 80.0000001, 11.5: latitude must be within 80 deg" \
  "$FAIRWAY" ais tracks "$FAIRWAY_DATA/scenarios/ais/aisdk-2026-03-01.csv" --origin 80.0000001,11.5
expect "^fairway: --own: speed 40.0000001 kn is above 40 kn" \
  "$FAIRWAY" helm --ship c3 --own 0,0,0,40.0000001 --target 100,200,180,10
cp "$FAIRWAY_DATA/tests/data/study/"*.yaml "$dir/"
sed -i 's/^name: .*/name: ""/' "$dir/small.yaml"
expect "small.yaml:2: name: is empty: use letters, digits, '-' or '_' \(it names the runs\)" \
  "$FAIRWAY" sweep "$dir/small.yaml" --db "$dir/runs"
# a comma in a path SUMO reads: SUMO splits file options at commas ("network
# file ... cannot be read"); refused naming the path, nothing left behind
comma() { # comma PATTERN ARGS... (exit 2; the run's table header may precede)
  local pattern=$1; shift
  out=$("$@" 2>&1)
  rc=$?
  [ $rc -eq 2 ] && grep -Eq -- "$pattern" <<<"$out" || { echo "exit $rc: $* -> $out"; exit 1; }
}
cp "$FAIRWAY_DATA/tests/data/study/small.yaml" "$dir/small.yaml"
comma "fairway: the run directory: '$dir/o,ut' has a comma: SUMO splits its file options at commas" \
  "$FAIRWAY" run "$base" --out "$dir/o,ut"
[ -z "$(ls -A "$dir/o,ut" 2>/dev/null)" ] || { echo "left in --out: $(ls -A "$dir/o,ut")"; exit 1; }
comma "fairway: --keep: '$dir/k,eep' has a comma" \
  "$FAIRWAY" sweep "$dir/small.yaml" --db "$dir/s.db" --keep "$dir/k,eep"
[ ! -e "$dir/s.db" ] || { echo "the sweep began"; exit 1; }
mkdir -p "$dir/t,mp"
comma "fairway: the work directory \(TMPDIR\): '$dir/t,mp' has a comma" \
  env TMPDIR="$dir/t,mp" "$FAIRWAY" sweep "$dir/small.yaml" --db "$dir/s.db"
[ ! -e "$dir/s.db" ] || { echo "the sweep made its database first"; exit 1; }
mkdir -p "$dir/d,ata"
cp -r "$FAIRWAY_DATA/networks" "$FAIRWAY_DATA/scenarios" "$dir/d,ata/"
comma "fairway: FAIRWAY_DATA: '$dir/d,ata' has a comma" \
  env FAIRWAY_DATA="$dir/d,ata" "$FAIRWAY" run "$FAIRWAY_DATA/scenarios/traffic/dover-crossing.yaml" \
  --out "$dir/o2"
# fairway traffic's route file, which SUMO reads: refused before it is written
comma "fairway: --routes: '$dir/r,b.rou.xml' has a comma" \
  "$FAIRWAY" traffic --network channel --duration 10 --routes "$dir/r,b.rou.xml" --log "$dir/t.log"
[ ! -e "$dir/r,b.rou.xml" ] && [ ! -e "$dir/t.log" ] || { echo "traffic wrote its files"; exit 1; }
echo "ok: names and numbers refused as written"
