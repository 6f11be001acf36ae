#!/usr/bin/env bash
# DNV's first five baseline situations (scenarios/dnv, maritime-schema 0.2.0, as DNV's generator
# wrote them) run with the C-3 (c3-mmg, the default model): no collision, the domain kept, the
# encounter classed as the situation's title says, and the first action on the side COLREGs
# require: starboard for head-on (rule 14), crossing give-way (15) and crossing stand-on when it
# must act (17(c): not to port for a ship on its own port side); an overtaking own ship may pass
# either side (13); a stand-on ship being overtaken acts only under rule 17(b), here to starboard.
# Asserted on summary.json and encounters.csv; run.log names the model.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
files=()
for i in 1 2 3 4 5; do files+=("$FAIRWAY_DATA/scenarios/dnv/traffic_situation_0$i.json"); done
"$FAIRWAY" run "${files[@]}" --out "$dir/runs" > "$dir/out.txt" 2>&1 || { cat "$dir/out.txt"; exit 1; }
"$PYTHON" - "$dir/runs" <<'PY' || exit 1
import csv, json, sys
d = sys.argv[1]
# situation, its encounter class, the side of the first action (None: either)
want = {1: ("head-on", "starboard"), 2: ("crossing give-way", "starboard"),
        3: ("crossing stand-on", "starboard"), 4: ("overtaking", None),
        5: ("being overtaken", "starboard")}
bad = 0
for i, (cls, side) in want.items():
    r = f"{d}/traffic_situation_0{i}"
    s = json.load(open(r + "/summary.json"))
    enc = list(csv.DictReader(open(r + "/encounters.csv")))
    log = open(r + "/run.log").read()
    fa = s["first_action"]
    ok = (s["status"] == "ok" and not s["collision"] and not s["domain_entered"]
          and s["colregs_ok"] and len(enc) == 1 and enc[0]["situation"] == cls
          and fa and fa.get("acted") and (side is None or fa["side"] == side)
          and "own ship model: c3-mmg (fairway's default)" in log)
    print(f"0{i}: {enc[0]['situation'] if enc else '-'}, first action {fa}, "
          f"min hull {s['min_hull_distance_m']:.0f} m, domain entered {s['domain_entered']}, "
          f"collision {s['collision']}: {'ok' if ok else 'WRONG'}")
    bad += not ok
sys.exit(1 if bad else 0)
PY
echo "the five DNV baselines: no collision, domain kept, first action on the COLREGs side"
