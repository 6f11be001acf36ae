#!/usr/bin/env bash
# A run's sumo/ directory replays it: sumo alone runs its run.sumocfg (the
# same streams of ships to the run's end), and analysis/replay_gui.py,
# headless, puts every ship of the run's FCD back where it was and reads the
# positions back (to 0.01 m).  A run without a sumo/ directory is refused.
set -eu
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
sed -e 's/fill: 45/fill: 0/' -e 's/behaviour: colregs/behaviour: blind/' \
    -e 's/duration_s: 3600/duration_s: 1800/' -e 's/targets_csv: false/targets_csv: false\n  fcd: true/' \
    "$FAIRWAY_DATA/scenarios/traffic/dover-crossing.yaml" > "$dir/replay.yaml"
grep -q "fcd: true" "$dir/replay.yaml" && grep -q "fill: 0" "$dir/replay.yaml" &&
  grep -q "behaviour: blind" "$dir/replay.yaml" && grep -q "duration_s: 1800" "$dir/replay.yaml"
"$FAIRWAY" run "$dir/replay.yaml" --out "$dir" > /dev/null
run="$dir/dover-crossing"
[ -s "$run/sumo/fcd.xml" ] && [ -s "$run/sumo/run.sumocfg" ] && [ ! -e "$run/sumo/fcd.xml.tmp" ]
(cd "$run/sumo" && SUMO_HOME=${SUMO_HOME:-/usr/share/sumo} sumo -c run.sumocfg \
   --fcd-output "$dir/alone.xml" --fcd-output.attributes x,y --no-warnings true > "$dir/sumo.out" 2>&1) || { cat "$dir/sumo.out"; exit 1; }
"$PYTHON" - "$run/sumo/fcd.xml" "$dir/alone.xml" <<'PY'
import sys
import xml.etree.ElementTree as ET
def read(path):
    out = {}
    for ts in ET.parse(path).getroot().iter("timestep"):
        out[round(float(ts.get("time")), 2)] = {v.get("id") for v in ts.iter("vehicle")}
    return out
run, alone = read(sys.argv[1]), read(sys.argv[2])
# the same network, routes and seed: the same streams of ships over the same
# half hour (not the same ships: the own ship draws from SUMO's random numbers)
assert max(run) == max(alone) + 1 and len(run) == 181, (max(run), max(alone), len(run))
ours = set().union(*run.values()) - {"fw_own"}
theirs = set().union(*alone.values())
assert len(ours) >= 5 and len(theirs) >= 5, (len(ours), len(theirs))
assert {s.split(".")[0] for s in ours} == {s.split(".")[0] for s in theirs}
print(f"sumo alone on run.sumocfg: {len(theirs)} ships (the run: {len(ours)})")
PY
"$PYTHON" "$ANALYSIS/replay_gui.py" "$run" --sumo sumo
"$PYTHON" "$ANALYSIS/replay_gui.py" "$dir" --sumo sumo 2> "$dir/err" && exit 1
grep -q "sumo/run.sumocfg: no such file" "$dir/err"
echo "sumo replay ok"
