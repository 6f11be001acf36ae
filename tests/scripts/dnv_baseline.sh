#!/usr/bin/env bash
# DNV's first five baseline situations (scenarios/dnv, maritime-schema 0.2.0, as DNV's generator
# wrote them) run with the C-3 (c3-mmg, the default model): no collision, the domain kept, the
# encounter classed as the situation's title says, and the first action on the side COLREGs
# require: starboard for head-on (rule 14), crossing give-way (15) and crossing stand-on when it
# must act (17(c): not to port for a ship on its own port side); an overtaking own ship may pass
# either side (13); a stand-on ship being overtaken acts only under rule 17(b), here to starboard.
# Asserted on summary.json and encounters.csv; run.log names the model.  Each run's answer,
# situation_output.json (src/run/dnv_out.h), validates against DNV's situation_output.schema.json
# (Debian's python3-jsonschema, draft 2020-12), starts with an event at the situation's start and
# has one at the first action, where the target is of the encounter type the situation names and
# the planned route turns to the side acted on.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
files=()
for i in 1 2 3 4 5; do files+=("$FAIRWAY_DATA/scenarios/dnv/traffic_situation_0$i.json"); done
"$FAIRWAY" run "${files[@]}" --out "$dir/runs" > "$dir/out.txt" 2>&1 || { cat "$dir/out.txt"; exit 1; }
"$PYTHON" - "$dir/runs" <<'PY' || exit 1
import csv, json, math, os, re, sys
import jsonschema
d = sys.argv[1]
schema = json.load(open(os.environ["FAIRWAY_DATA"] + "/scenarios/dnv/situation_output.schema.json"))
validator = jsonschema.Draft202012Validator(schema)
types = {1: "Head-on", 2: "Crossing give-way", 3: "Crossing stand-on", 4: "Overtaking give-way",
         5: "Overtaking stand-on"}
def answer_ok(i, r, fa):
    o = json.load(open(r + "/situation_output.json"))
    errors = [e.message for e in validator.iter_errors(o)]
    ev = o["systemUnderTest"]["eventData"]
    times = all(re.fullmatch(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d(\.\d{3})?Z", e["time"]) for e in ev)
    act = [e for e in ev if e["fairway"]["mode"] == "avoid"]
    if errors or not times or not act:
        print(f"0{i}: schema errors {errors[:3]}, times ok {times}, avoid events {len(act)}")
        return False
    a = act[0]
    w = a["waypoints"]
    # the side of the planned route: the cross product of the first two legs' directions
    (y0, x0), (y1, x1), (y2, x2) = [(p["position"]["lat"], p["position"]["lon"] *
                                     math.cos(math.radians(p["position"]["lat"]))) for p in w[:3]]
    turn = (x1 - x0) * (y2 - y1) - (y1 - y0) * (x2 - x1)  # < 0: clockwise, to starboard
    side = "starboard" if turn < 0 else "port"
    ok = (ev[0]["time"] == "2000-01-01T00:00:00Z" and ev[0]["fairway"]["mode"] == "standby"
          and a["targetShips"][0]["encounterType"] == types[i] and len(w) >= 3
          and side == fa["side"])
    print(f"0{i}: situation_output valid, {len(ev)} events, first avoid at {a['time']}: "
          f"{a['targetShips'][0]['encounterType']}, route of {len(w)} waypoints to {side}")
    return ok
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
          and "own ship model: c3-mmg (fairway's default)" in log and answer_ok(i, r, fa))
    print(f"0{i}: {enc[0]['situation'] if enc else '-'}, first action {fa}, "
          f"min hull {s['min_hull_distance_m']:.0f} m, domain entered {s['domain_entered']}, "
          f"collision {s['collision']}: {'ok' if ok else 'WRONG'}")
    bad += not ok
sys.exit(1 if bad else 0)
PY
echo "the five DNV baselines: no collision, domain kept, first action on the COLREGs side"
