#!/usr/bin/env bash
# Background ships that alter course (traffic.give_way: course, src/world/steer.h) in SUMO's Dover
# traffic, an hour, seed 1: ships alter course (to starboard by 20 deg or more; close quarters may
# turn one to port), come back to their
# lanes and are given back to SUMO, and nothing happens that no ship can do (the traffic monitors
# count no sideways jump, teleport or hull overlap); run.log says each alteration and each return.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
base=$FAIRWAY_DATA/scenarios/traffic/dover-crossing.yaml
sed 's/^  density: 1$/  density: 1\n  give_way: course/; s/^name: .*/name: gw/' "$base" > "$dir/gw.yaml"
"$FAIRWAY" run "$dir/gw.yaml" --out "$dir/runs" > "$dir/out.txt" 2>&1 || { cat "$dir/out.txt"; exit 1; }
"$PYTHON" - "$dir/runs/gw" <<'PY' || exit 1
import json, re, sys
d = sys.argv[1]
s = json.load(open(d + "/summary.json"))
c, m = s["course_alterations"], s["monitors"]
log = open(d + "/run.log").read()
alters = [float(a) * (1 if side == "starboard" else -1)
          for a, side in re.findall(r"alters (\d+) deg to (starboard|port)", log)]
backs = len(re.findall(r"back on its lane", log))
ok = (c["n"] >= 3 and c["n"] == len(alters) and c["rejoined"] == backs >= 2
      and all(abs(a) <= 180 for a in alters) and 20 <= c["max_deg"] <= 180
      and m["sideways"] == 0 and m["teleport"] == 0 and m["overlap"] == 0
      and m["max_lateral_mps"] < 2.0)
print("alterations", c, "monitors", m)
sys.exit(0 if ok else 1)
PY
echo "background ships alter course and come back"
