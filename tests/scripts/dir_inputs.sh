#!/usr/bin/env bash
# Nesting 50,000 levels deep is refused with FILE:LINE by every loader.
# A directory where a file is expected gets "PATH: is a directory, expected a
# YAML file" with exit 2: a ship, a scenario, a trial, a scenario's ship and a
# study's scenario.  Speeds beyond a ship's Nomoto knowledge base are warned
# about by run (and the run goes on); beyond its x1.5 margin, or 40 kn, they
# are refused.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
mkdir "$dir/d.yaml"
expect() { # expect RC PATTERN ARGS...
  local want=$1 pattern=$2; shift 2
  out=$("$FAIRWAY" "$@" 2>&1)
  rc=$?
  [ $rc -eq "$want" ] && grep -q -- "$pattern" <<<"$out" || { echo "exit $rc: $* -> $out"; exit 1; }
}
msg="$dir/d.yaml: is a directory, expected a YAML file"
expect 2 "$msg" ship "$dir/d.yaml"
expect 2 "$msg" run "$dir/d.yaml" --out "$dir/runs"
expect 2 "$msg" calibrate --ship c3 --trial "$dir/d.yaml"
sed "s|ship: c3-mmg|ship: $dir/d.yaml|" "$FAIRWAY_DATA/scenarios/traffic/strait-crossing.yaml" > "$dir/s.yaml"
expect 2 "$msg" run "$dir/s.yaml" --out "$dir/runs"
sed "s|scenario: base.yaml|scenario: $dir/d.yaml|" "$FAIRWAY_DATA/tests/data/study/small.yaml" > "$dir/study.yaml"
expect 2 "$msg" sweep "$dir/study.yaml" --db "$dir/x.db"
[ ! -e "$dir/runs" ] && [ ! -e "$dir/x.db" ] || { echo "output created: $(ls "$dir")"; exit 1; }
# 50,000 levels of nesting: a located error from every loader, not a stack overflow
{ printf 'name: '; head -c 50000 /dev/zero | tr '\0' '['; } > "$dir/deep.yaml"
{ printf 'name: x\nscenario: '; for _ in $(seq 1 2000); do printf '{a: '; done; } > "$dir/deepmap.yaml"
expect 2 "$dir/deep.yaml:1: nested deeper than 64 levels" ship "$dir/deep.yaml"
expect 2 "$dir/deep.yaml:1: nested deeper than 64 levels" run "$dir/deep.yaml" --out "$dir/runs"
expect 2 "$dir/deepmap.yaml:2: nested deeper than 64 levels" sweep "$dir/deepmap.yaml" --db "$dir/x.db"
[ ! -e "$dir/runs" ] && [ ! -e "$dir/x.db" ] || { echo "output created: $(ls "$dir")"; exit 1; }
# 22 kn: outside c3-mmg's knowledge base (4-20 kn), within its x1.5 margin:
# warned about on stderr, in run.log and in summary.json, and the run goes on
sed -e 's/speed_kn: 12/speed_kn: 22/' -e 's/duration_s: 3600/duration_s: 60/' \
    "$FAIRWAY_DATA/scenarios/traffic/strait-crossing.yaml" > "$dir/fast.yaml"
expect 0 "warning: $dir/fast.yaml: own_ship.speed_kn: 22 kn is outside 4-20 kn, the speeds c3-mmg's Nomoto knowledge base was fitted over" \
  run "$dir/fast.yaml" --out "$dir/runs"
grep -q "warning: own speed 22.00 kn is outside 4.00-20.00 kn" "$dir"/runs/*/run.log ||
  { echo "run.log: no knowledge-base speed warning"; exit 1; }
grep -q '"knowledge_base_speeds": {"fitted_min_kn": 4.00, "fitted_max_kn": 20.00, .*"outside_s": 61.0, "warning": "own speed' \
  "$dir"/runs/*/summary.json || { echo "summary.json: no knowledge-base speed warning"; exit 1; }
# 35 kn: within what scenarios accept, beyond the margin (2.7-30 kn): refused
sed -e 's/speed_kn: 12/speed_kn: 35/' "$FAIRWAY_DATA/scenarios/traffic/strait-crossing.yaml" > "$dir/faster.yaml"
expect 2 "faster.yaml:[0-9]*: own_ship.speed_kn: 35 kn is beyond c3-mmg's Nomoto knowledge base, fitted over 4-20 kn, by more than its x1.5 margin (2.7-30.0 kn)" \
  run "$dir/faster.yaml" --out "$dir/runs2"
expect 0 "warning: --own speed: 35 kn is outside 4-20 kn" helm --ship c3-mmg --own 0,0,0,35 --target 0,5000,180,10
expect 2 "speed 45 kn is above 40 kn" helm --ship c3-mmg --own 0,0,0,45
expect 2 "--speed: 60 kn is above 40 kn" manoeuvre turning --ship c3 --speed 60 --rudder 35
expect 2 "--speed: 45 kn is above 40 kn" manoeuvre zigzag --ship c3 --speed 45 --angle 10
echo "ok: directories refused, speeds checked"
