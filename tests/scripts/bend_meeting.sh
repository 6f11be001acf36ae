# bend_meeting.sh - ships meeting round a bend are meeting ships (rules 9 and
# 14), not crossing ones: an hour of networks/bend at density 3 as a channel
# (tests/data/bend_meeting.yaml).  The traffic survey classes every pair of an
# east-going and a west-going ship head-on, those first seen within 2.5 km of
# the bend included, and no pair of one stream crossing; no background ship
# gives way to one coming the other way (each keeps its lane, to starboard);
# nothing moves sideways.  On main before (90f678e: classification by
# bearings and headings alone, which differ by the bend's 30 deg from
# reciprocal): 62 of 514 meeting pairs classed crossing, every one first seen
# at the bend, 7 pairs of one stream crossing, 456 orders between the streams
# in the hour.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$FAIRWAY" run "$FAIRWAY_DATA/tests/data/bend_meeting.yaml" --out "$tmp" > /dev/null 2>&1 ||
  { echo "run failed"; cat "$tmp"/*/run.log; exit 1; }
"$PYTHON" - "$tmp/bend-meeting" <<'PY'
import csv, json, math, re, sys
d = sys.argv[1]
pos = {}
for r in csv.DictReader(open(d + "/targets.csv")):
    pos[(r["id"], float(r["t_s"]))] = (float(r["east_m"]), float(r["north_m"]))
def stream(s):
    return "east" if s.startswith("east") else "west" if s.startswith("west") else None
meet = bend = 0
bad = []
same_crossing = []
for r in csv.DictReader(open(d + "/traffic_encounters.csv")):
    a, b = stream(r["ship_a"]), stream(r["ship_b"])
    if not a or not b:
        continue
    if a == b:
        if r["type"] == "crossing":
            same_crossing.append((r["ship_a"], r["ship_b"], r["t_first_s"]))
        continue
    meet += 1
    t = 5 * math.floor(float(r["t_first_s"]) / 5)
    p = pos.get((r["ship_a"], t))
    near = p is not None and math.hypot(p[0] - 10000.0, p[1]) < 2500.0
    bend += near
    if r["type"] != "head-on":
        bad.append((r["ship_a"], r["ship_b"], r["t_first_s"], r["type"], near))
orders = 0
for line in open(d + "/run.log"):
    m = re.search(r"traffic: (\S+) (gives way to|acts \(rule 17\(b\)\) for) (\S+)", line)
    if m and {stream(m.group(1)), stream(m.group(3))} == {"east", "west"}:
        orders += 1
mon = json.load(open(d + "/summary.json"))["monitors"]
print("meeting pairs", meet, "first seen at the bend", bend, "not head-on", len(bad),
      "one stream's pairs crossing", len(same_crossing), "orders between the streams", orders,
      "sideways", mon["sideways"], "largest sideways %.2f m/s" % mon["max_lateral_mps"])
assert meet >= 300 and bend >= 20, (meet, bend)
assert not bad, bad[:5]
assert not same_crossing, same_crossing[:5]
assert orders == 0, orders
assert mon["sideways"] == 0 and mon["teleport"] == 0, mon
PY
echo "ok: ships meet round the bend head-on"
