#!/usr/bin/env bash
# Bad DNV situations are refused before anything runs: FILE: $.json.path: problem, exit 2, no
# crash, no output directory.  Each case is baseline 02 with one thing broken (made here with
# Python), plus text that is not JSON, a 50 MB file of nested arrays (refused by its size)
# and 1 MB of them (by Jansson's depth limit).
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$PYTHON" - "$FAIRWAY_DATA/scenarios/dnv/traffic_situation_02.json" "$dir" <<'PY' || exit 1
import copy, json, sys
base, d = json.load(open(sys.argv[1])), sys.argv[2]
def case(name, edit):
    s = copy.deepcopy(base)
    edit(s)
    json.dump(s, open(f"{d}/{name}.json", "w"))
case("no_own", lambda s: s.pop("ownShip"))
case("lat95", lambda s: s["targetShips"][0]["waypoints"][1]["position"].update(lat=95))
case("negative_speed", lambda s: s["targetShips"][0]["waypoints"][1]["leg"].update(sog=-3))
case("version", lambda s: (s.pop("schemaVersion"), s.update(version="9.1.0")))
case("no_version", lambda s: s.pop("schemaVersion"))
case("no_targets", lambda s: s.pop("targetShips"))
case("one_waypoint", lambda s: s["ownShip"]["waypoints"].pop())
case("own_too_fast", lambda s: s["ownShip"]["waypoints"][1]["leg"].update(sog=45))
case("id_text", lambda s: s["targetShips"][0]["static"].update(id="two"))
case("wind_no_dir", lambda s: s.update(environment={"windSpeed": 10}))
case("wind_negative", lambda s: s.update(environment={"windSpeed": -1, "windDirection": 90}))
case("visibility_0", lambda s: s.update(environment={"visibility": 0}))
case("turn_short", lambda s: s["targetShips"][0].update(fairway={"turns": [[0, 90, 10, 0.5]]}))
case("turn_order", lambda s: s["targetShips"][0].update(
    fairway={"turns": [[5, 90, 10, 0.5, 120], [5, 90, 10, 0, 0]]}))
case("turn_rate", lambda s: s["targetShips"][0].update(fairway={"turns": [[5, 90, 10, 95, 120]]}))
open(f"{d}/invalid.json", "w").write('{"schemaVersion": "0.2.0", "ownShip": {\n  "static": }\n')
with open(f"{d}/nested.json", "w") as f:  # 50 MB of nested arrays
    f.write("[" * (25 << 20) + "]" * (25 << 20))
with open(f"{d}/deep.json", "w") as f:  # 1 MB: under the size limit, beyond the depth limit
    f.write("[" * (1 << 19) + "]" * (1 << 19))
PY
bad=0
check() { # NAME PATTERN
  out=$("$FAIRWAY" run "$dir/$1.json" --out "$dir/runs" 2>&1)
  rc=$?
  if [ "$rc" -ne 2 ] || ! grep -Eq -- "^fairway: $dir/$1.json(:[0-9]+)?: $2" <<<"$out" || [ -e "$dir/runs" ]; then
    echo "WRONG $1: exit $rc: $out"; bad=1
  else
    echo "ok $1: $out"
  fi
}
check no_own '\$\.ownShip: missing'
check lat95 '\$\.targetShips\[0\]\.waypoints\[1\]\.position\.lat: 95 is not in \[-90, 90\]'
check negative_speed '\$\.targetShips\[0\]\.waypoints\[1\]\.leg\.sog: -3 is not in \[0, 60\]'
check version "\\\$\\.version: '9\\.1\\.0' is not a version fairway reads"
check no_version '\$: no version'
check no_targets '\$: no targetShips'
check one_waypoint '\$\.ownShip\.waypoints: 1 elements, at least 2 needed'
check own_too_fast '\$\.ownShip: 45 kn is beyond c3-mmg'
check id_text '\$\.targetShips\[0\]\.static\.id: '
check wind_no_dir '\$\.environment: a wind speed needs its direction'
check wind_negative '\$\.environment\.windSpeed: -1 is not in'
check visibility_0 '\$\.environment\.visibility: 0 is not in'
check turn_short '\$\.targetShips\[0\]\.fairway\.turns\[0\]: 4 elements, at least 5 needed'
check turn_order '\$\.targetShips\[0\]\.fairway\.turns\[1\]\[0\]: 5 s: not after the turn before \(5 s\)'
check turn_rate '\$\.targetShips\[0\]\.fairway\.turns\[0\]\[3\]: 95 is not in \[0, 90\]'
check invalid '\$: invalid JSON'
check nested '\$: more than 8388608 bytes'
check deep '\$: invalid JSON'
exit $bad
