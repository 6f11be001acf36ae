#!/usr/bin/env bash
# Bad traffic input is refused before anything runs, with FILE:LINE: FIELD and
# exit 2, and no run directory is left: an unknown behaviour or give_way, a density below
# zero, an unknown return, domain reading or own-ship dynamics, and a network whose demand names
# an edge the network does not have (a copy of the data root with one edge
# renamed).
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
base=$FAIRWAY_DATA/scenarios/traffic/dover-crossing.yaml
expect() { # expect PATTERN ARGS... (exit 2)
  local pattern=$1; shift
  out=$("$@" 2>&1)
  rc=$?
  [ $rc -eq 2 ] && grep -Eq -- "$pattern" <<<"$out" || { echo "exit $rc: $* -> $out"; exit 1; }
  [ ! -e "$dir/runs" ] || { echo "a run directory was left: $(ls -R "$dir/runs")"; exit 1; }
}
sed 's/^  density: 1$/  density: 1\n  behaviour: polite/' "$base" > "$dir/a.yaml"
expect "a.yaml:[0-9]+: traffic.behaviour: 'polite': expected colregs or blind" \
  "$FAIRWAY" run "$dir/a.yaml" --out "$dir/runs"
sed 's/^  density: 1$/  density: 1\n  give_way: sideways/' "$base" > "$dir/a2.yaml"
expect "a2.yaml:[0-9]+: traffic.give_way: 'sideways': expected speed or course" \
  "$FAIRWAY" run "$dir/a2.yaml" --out "$dir/runs"
sed 's/^  density: 1$/  density: -0.5/' "$base" > "$dir/b.yaml"
expect "b.yaml:[0-9]+: traffic.density: -0.5 is out of range" "$FAIRWAY" run "$dir/b.yaml" --out "$dir/runs"
sed 's/^  radius_nm: 6 .*/  radius_nm: 6\n  return: home/' "$base" > "$dir/c.yaml"
expect "c.yaml:[0-9]+: avoidance.return: 'home': expected track or heading" \
  "$FAIRWAY" run "$dir/c.yaml" --out "$dir/runs"
sed 's/^  radius_nm: 6 .*/  radius_nm: 6\n  domain_from: bow/' "$base" > "$dir/e.yaml"
expect "e.yaml:[0-9]+: avoidance.domain_from: 'bow': expected hull or centre" \
  "$FAIRWAY" run "$dir/e.yaml" --out "$dir/runs"
sed 's/^  radius_nm: 6 .*/  radius_nm: 6\n  domain_reading: circle/' "$base" > "$dir/f.yaml"
expect "f.yaml:[0-9]+: avoidance.domain_reading: 'circle': expected ellipse or transverse" \
  "$FAIRWAY" run "$dir/f.yaml" --out "$dir/runs"
sed 's/^  ship: c3-mmg\(.*\)$/  ship: c3-mmg\1\n  dynamics: euler/' "$base" > "$dir/g.yaml"
grep -q "dynamics: euler" "$dir/g.yaml" || { echo "g.yaml not made"; exit 1; }
expect "g.yaml:[0-9]+: own_ship.dynamics: 'euler': expected mmg or nomoto" \
  "$FAIRWAY" run "$dir/g.yaml" --out "$dir/runs"
mkdir -p "$dir/root/scenarios"
cp -r "$FAIRWAY_DATA/networks" "$dir/root/" && cp -r "$FAIRWAY_DATA/scenarios/ships" "$dir/root/scenarios/"
sed -i 's/edges: \[SW\]/edges: [SW, NOPE]/' "$dir/root/networks/dover/demand.yaml"
expect "demand.yaml:[0-9]+: streams\[1\].edges: edge 'NOPE' is not in .*dover.edg.xml" \
  env FAIRWAY_DATA="$dir/root" "$FAIRWAY" run "$base" --out "$dir/runs"
echo "bad traffic input refused: behaviour, density, return, domain_from, domain_reading, dynamics, demand edge"
