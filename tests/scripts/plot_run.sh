#!/usr/bin/env bash
# analysis/plot_run.py on a network run and an explicit-target run: the PNGs
# are written; the network's lanes are read from sumo/run.sumocfg (Dover: 10
# lanes: 8 through, 2 ferry; the paper case's generated fw_* edges are not
# lanes); the ships named are the ones within 2 nm or acted for, at most 10.
set -eu
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
sed -e 's/duration_s: 3600/duration_s: 900/' -e 's/targets_csv: false/targets_csv: true/' \
    "$FAIRWAY_DATA/scenarios/traffic/dover-crossing.yaml" > "$dir/dover.yaml"
grep -q "duration_s: 900" "$dir/dover.yaml" && grep -q "targets_csv: true" "$dir/dover.yaml"
"$FAIRWAY" run "$dir/dover.yaml" "$FAIRWAY_DATA/scenarios/paper/3-crossing.yaml" --out "$dir" > /dev/null
for run in dover-crossing paper-3-crossing; do
  "$PYTHON" "$ANALYSIS/plot_run.py" "$dir/$run" > /dev/null
  for f in track helm distance; do [ -s "$dir/$run/$f.png" ]; done
done
"$PYTHON" - "$ANALYSIS" "$dir" <<'PY'
import json, sys
sys.path.insert(0, sys.argv[1])
import plot_run as pr
d = sys.argv[2]
lanes = pr.network_lanes(f"{d}/dover-crossing")
assert len(lanes) == 10, len(lanes)
assert sorted({w for w, _ in lanes}) == [150.0, 1852.0], sorted({w for w, _ in lanes})
assert pr.network_lanes(f"{d}/paper-3-crossing") == []
for run in ("dover-crossing", "paper-3-crossing"):
    s = json.load(open(f"{d}/{run}/summary.json"))
    named = pr.named_targets(s)
    enc = {e["id"]: e for e in s["encounters"]}
    assert len(named) <= pr.NAMED_MAX
    assert all(enc[i]["min_distance_m"] < pr.NAMED_WITHIN or enc[i]["t_act_s"] is not None for i in named)
    rest = [e for e in s["encounters"] if e["id"] not in named]
    assert len(named) == pr.NAMED_MAX or all(e["min_distance_m"] >= pr.NAMED_WITHIN and e["t_act_s"] is None for e in rest)
    print(f"{run}: {len(named)} of {len(enc)} ships named")
assert pr.named_targets(json.load(open(f"{d}/paper-3-crossing/summary.json"))) == ["T1"]
PY
echo "plot run ok"
