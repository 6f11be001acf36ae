#!/usr/bin/env bash
# The own ship follows a route given as a network's edges (issue 27 item 5):
# tests/data/route/net-bend.yaml, networks/bend's east-going edges WB and BE
# at 10 then 12 kn, nothing else on the water.  The route's legs are the
# starboard lane's centre line (rule 9(a): SUMO's lane 0, y = -375 m, then
# 060 deg from where the two edges' lane-0 lines cross, x = 10100.5 m; on
# the edges' centre line, y = -250 m, before); the track stays within 100 m
# of them and, on the first leg, within its starboard lane; the same
# route named as the demand's stream `east` sails the same track.  Then the
# bad inputs: FILE:LINE: FIELD, exit 2, no output directory: edges that are
# not the network's or do not join, speeds that do not match, no network, an
# unknown stream, a waypoint of own_ship.route 1 nm and more off the network,
# a network directory whose nodes or edges file holds none.
set -u
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
scn=$FAIRWAY_DATA/tests/data/route/net-bend.yaml
"$FAIRWAY" run "$scn" --out "$tmp/runs" > "$tmp/out.txt" 2>&1 ||
  { echo "run failed"; cat "$tmp/out.txt"; exit 1; }
log=$tmp/runs/net-route-bend/run.log
grep -q "route: leg 1 of 2 from (0.0, -375.0) m, 090 deg, 10100 m at 10.0 kn" "$log" &&
  grep -q "route: leg 2 of 2 from (10100.5, -375.0) m, 060 deg, 10100 m at 12.0 kn" "$log" ||
  { echo "legs not the starboard lane's line:"; grep "route:" "$log"; exit 1; }
"$PYTHON" - "$tmp/runs/net-route-bend/own.csv" <<'PY' || exit 1
import csv, math, sys
a = math.radians(60)
P = [(0.0, -375.0), (10100.5, -375.0), (10100.5 + 10100.0 * math.sin(a), -375.0 + 10100.0 * math.cos(a))]
def dseg(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    t = max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy)))
    return math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy)
rows = list(csv.DictReader(open(sys.argv[1])))
off = [min(dseg((float(r["east_m"]), float(r["north_m"])), P[i], P[i + 1]) for i in range(2)) for r in rows]
end = math.hypot(float(rows[-1]["east_m"]) - P[2][0], float(rows[-1]["north_m"]) - P[2][1])
# first leg (before the bend's wheel-over): the starboard lane WB_0, y = -500 to -250 m
ys = [float(r["north_m"]) for r in rows if float(r["east_m"]) < 9000.0]
print("track at most %.1f m off the route's line (at t = %s s); %.0f m from its end at %s s; "
      "first leg y %.1f to %.1f m" % (max(off), rows[off.index(max(off))]["t_s"], end,
                                      rows[-1]["t_s"], min(ys), max(ys)))
assert max(off) < 100.0 and end < 500.0 and min(ys) > -500.0 and max(ys) < -250.0
PY
sed 's/    edges: \[WB, BE\]/    stream: east/' "$scn" > "$tmp/stream.yaml"
"$FAIRWAY" run "$tmp/stream.yaml" --out "$tmp/runs2" > /dev/null 2>&1 &&
  cmp -s "$tmp/runs/net-route-bend/own.csv" "$tmp/runs2/net-route-bend/own.csv" ||
  { echo "stream east: not the same track"; exit 1; }

bad() { # FILE PATTERN: refused with it, nothing written
  local rc=0
  "$FAIRWAY" run "$1" --out "$tmp/bad" > "$tmp/bad.txt" 2>&1 || rc=$?
  [ "$rc" -eq 2 ] && grep -q -- "$2" "$tmp/bad.txt" && [ ! -e "$tmp/bad" ] ||
    { echo "rc $rc, wanted 2 and '$2':"; cat "$tmp/bad.txt"; exit 1; }
}
case_() { # NAME SED-EXPRESSION: a copy of the scenario with one thing changed
  sed "$2" "$scn" > "$tmp/$1.yaml"
}
case_ noedge 's/edges: \[WB, BE\]/edges: [WB, XX]/'
bad "$tmp/noedge.yaml" "noedge.yaml:10: own_ship.network_route.edges: no edge 'XX' in network 'bend'"
case_ nojoin 's/edges: \[WB, BE\]/edges: [WB, EB]/'
bad "$tmp/nojoin.yaml" "nojoin.yaml:10: own_ship.network_route.edges: edge 'EB' begins at junction 'E', not where 'WB' ends ('B')"
case_ speeds 's/speeds_kn: \[10, 12\]/speeds_kn: [10]/'
bad "$tmp/speeds.yaml" "speeds.yaml:11: own_ship.network_route.speeds_kn: 1 speeds for 2 edges"
case_ fast 's/speeds_kn: \[10, 12\]/speeds_kn: [10, 35]/'
bad "$tmp/fast.yaml" "fast.yaml:11: own_ship.network_route.speeds_kn\[1\]: 35 kn is beyond c3-mmg's Nomoto knowledge base"
case_ nonet '/  network: bend/d'
bad "$tmp/nonet.yaml" "nonet.yaml:9: own_ship.network_route: the route is a network's edges: the scenario needs traffic.network"
case_ nostream 's/    edges: \[WB, BE\]/    stream: north/'
bad "$tmp/nostream.yaml" "nostream.yaml:10: own_ship.network_route.stream: 'north' is not a stream of"
# own_ship.route on the network: the last waypoint 9 km north of the bend's end,
# 3550 m beyond the lanes' box (north -500 to 5450 m), refused at its line
sed -e 's/  network_route:/  route:/' -e 's/    edges: \[WB, BE\]/    - {east_m: 0, north_m: -250, speed_kn: 10}\n    - {east_m: 10000, north_m: -250, speed_kn: 12}\n    - {east_m: 18660, north_m: 9000}/' \
    -e '/speeds_kn/d' "$scn" > "$tmp/offnet.yaml"
bad "$tmp/offnet.yaml" "offnet.yaml:12: own_ship.route\[2\]: waypoint 2 (18660, 9000 m) is 3550 m outside network 'bend' (its lanes span east -125 to 18973 m, north -500 to 5450 m): more than 1852 m (1 nm) off it"
sed -i 's/north_m: 9000/north_m: 7000/' "$tmp/offnet.yaml"
"$FAIRWAY" run "$tmp/offnet.yaml" --out "$tmp/near" > /dev/null 2>&1 ||
  { echo "a waypoint 1550 m off the network refused"; exit 1; }
# a network of the user's own whose nodes or edges file holds none
mkdir -p "$tmp/net/mine"
for f in nod edg typ; do cp "$FAIRWAY_DATA/networks/bend/bend.$f.xml" "$tmp/net/mine/mine.$f.xml"; done
cp "$FAIRWAY_DATA/networks/bend/demand.yaml" "$tmp/net/mine/"
sed 's|  network: bend|  network: net/mine|' "$scn" > "$tmp/mine.yaml"
printf '<nodes>\n  <!-- none -->\n</nodes>\n' > "$tmp/net/mine/mine.nod.xml"
bad "$tmp/mine.yaml" "mine.yaml:13: traffic.network: network 'mine': .*/net/mine/mine.nod.xml has no <node> element (its nodes"
cp "$FAIRWAY_DATA/networks/bend/bend.nod.xml" "$tmp/net/mine/mine.nod.xml"
printf '<edges>\n</edges>\n' > "$tmp/net/mine/mine.edg.xml"
bad "$tmp/mine.yaml" "mine.yaml:13: traffic.network: network 'mine': .*/net/mine/mine.edg.xml has no <edge> element (its edges"
# a curved edge (a user's network): one edge whose shape is a 40 deg arc to
# port of radius 5 km, a point a degree.  The starboard lane's line (radius
# 5375 m) is cut to the fewest waypoints within 10 m of it: 7, every 6.7 deg, on that
# line (Douglas-Peucker, which halves an arc, gave 9 every 5 deg, and the
# follower then settled 87 m outside the legs).  The ship within 100 m of
# the legs.  A 270 deg arc needs too many waypoints even at 40 m (a quarter
# of the starboard lane's 250 m is the most allowed): refused.
arc() { # DIR DEGREES
  mkdir -p "$1"
  cp "$FAIRWAY_DATA/networks/bend/bend.typ.xml" "$1/$(basename "$1").typ.xml"
  "$PYTHON" - "$1" "$2" <<'PY'
import math, os, sys
d, deg = sys.argv[1], float(sys.argv[2])
n = os.path.basename(d)
pts = [(5000 * math.sin(math.radians(k)), 5000 - 5000 * math.cos(math.radians(k))) for k in range(int(deg) + 1)]
open(f"{d}/{n}.nod.xml", "w").write('<nodes>\n  <node id="A" x="0" y="0"/>\n  <node id="B" x="%.3f" y="%.3f"/>\n</nodes>\n' % pts[-1])
shape = " ".join("%.3f,%.3f" % p for p in pts)
open(f"{d}/{n}.edg.xml", "w").write('<edges>\n  <edge id="AB" from="A" to="B" type="fairway" shape="%s"/>\n</edges>\n' % shape)
open(f"{d}/demand.yaml", "w").write("streams:\n  - {id: along, edges: [AB], per_hour: 1, types: fw_seagoing}\n")
PY
}
arc "$tmp/net/arc" 40
sed -e 's|  network: bend|  network: net/arc|' -e 's/edges: \[WB, BE\]/edges: [AB]/' \
    -e 's/speeds_kn: \[10, 12\]/speeds_kn: 10/' -e 's/duration_s: 3600/duration_s: 690/' "$scn" > "$tmp/arc.yaml"
"$FAIRWAY" run "$tmp/arc.yaml" --out "$tmp/arcrun" > "$tmp/out.txt" 2>&1 ||
  { echo "arc run failed"; cat "$tmp/out.txt"; exit 1; }
"$PYTHON" - "$tmp/arcrun/net-route-bend" <<'PY' || exit 1
import csv, math, re, sys
d = sys.argv[1]
legs = [tuple(map(float, m.groups())) for m in
        re.finditer(r"route: leg \d+ of \d+ from \(([-\d.]+), ([-\d.]+)\) m, (\d+) deg, (\d+) m", open(d + "/run.log").read())]
P = [(e, n) for e, n, c, l in legs]
e, n, c, l = legs[-1]
P.append((e + l * math.sin(math.radians(c)), n + l * math.cos(math.radians(c))))
# the starboard lane's centre line: the arc 375 m to starboard of the edge's shape, radius 5375 m
r = [math.hypot(x, y - 5000) for x, y in P]
def dseg(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    t = max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy)))
    return math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy)
rows = list(csv.DictReader(open(d + "/own.csv")))
off = max(min(dseg((float(q["east_m"]), float(q["north_m"])), P[i], P[i + 1]) for i in range(len(P) - 1)) for q in rows)
print("40 deg arc: %d waypoints at radius %.1f-%.1f m (starboard lane's line 5375 m), track at most %.1f m off the legs"
      % (len(P), min(r), max(r), off))
assert len(P) == 7 and 5375 - 1 < min(r) and max(r) < 5375 + 5 and off < 100.0
PY
arc "$tmp/net/loop" 270
sed -e 's|  network: bend|  network: net/loop|' -e 's/edges: \[WB, BE\]/edges: [AB]/' \
    -e 's/speeds_kn: \[10, 12\]/speeds_kn: 10/' "$scn" > "$tmp/loop.yaml"
bad "$tmp/loop.yaml" "loop.yaml:9: own_ship.network_route: its starboard lanes' line needs 22 waypoints to stay within 40 m of it (a quarter of the narrowest one's width), a route has at most 9"
echo "ok: the own ship follows a network's edges; bad routes and networks refused"
