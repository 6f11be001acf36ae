#!/usr/bin/env bash
# A run's sumo/ directory replays it.  A blind run with no ships placed at the
# start (nothing fairway orders or takes out): sumo alone on its run.sumocfg
# moves every background ship exactly as the run's FCD recorded it (to the
# FCD's 0.01 m, at the same timestep labels).  Then analysis/replay_gui.py,
# headless, puts every ship of the FCD back where it was and reads the
# positions back.  A run without a sumo/ directory is refused.
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
[ -s "$run/sumo/fcd.xml" ] && [ -s "$run/sumo/run.sumocfg" ] && [ -z "$(ls -A "$run/sumo" | grep "fcd.xml.tmp")" ]
(cd "$run/sumo" && SUMO_HOME=${SUMO_HOME:-/usr/share/sumo} sumo -c run.sumocfg \
   --fcd-output "$dir/alone.xml" --fcd-output.attributes x,y --no-warnings true > "$dir/sumo.out" 2>&1) || { cat "$dir/sumo.out"; exit 1; }
"$PYTHON" - "$run/sumo/fcd.xml" "$dir/alone.xml" <<'PY'
import sys
import xml.etree.ElementTree as ET
def read(path):
    out = {}
    for ts in ET.parse(path).getroot().iter("timestep"):
        t = round(float(ts.get("time")), 2)
        for v in ts.iter("vehicle"):
            out[(t, v.get("id"))] = (float(v.get("x")), float(v.get("y")))
    return out
run, alone = read(sys.argv[1]), read(sys.argv[2])
ours = {k: v for k, v in run.items() if k[1] != "fw_own"}
assert max(t for t, _ in run) == 1800.0 and len({t for t, _ in run}) == 181
missing = [k for k in ours if k not in alone]
assert not missing, f"ships of the run that sumo alone does not have: {missing[:5]}"
extra = {k[1] for k in alone} - {k[1] for k in ours}
assert not extra, f"ships sumo alone has and the run had not: {sorted(extra)[:5]}"
worst = max(max(abs(a - b) for a, b in zip(p, alone[k])) for k, p in ours.items())
ships = {k[1] for k in ours}
assert len(ships) >= 5 and len(ours) >= 300, (len(ships), len(ours))
assert worst <= 0.011, f"sumo alone differs by {worst} m"
print(f"sumo alone on run.sumocfg: {len(ships)} ships at {len(ours)} ship-timesteps where the run had "
      f"them (largest difference {worst:.3f} m)")
PY
"$PYTHON" "$ANALYSIS/replay_gui.py" "$run" --sumo sumo
"$PYTHON" "$ANALYSIS/replay_gui.py" "$dir" --sumo sumo 2> "$dir/err" && exit 1
grep -q "sumo/run.sumocfg: no such file" "$dir/err"
echo "sumo replay ok"
