#!/usr/bin/env bash
# Explicit targets on a geo-referenced network (networks/geo-channel, drawn in
# degrees): the run writes their tracks' nodes in degrees and netconvert
# projects them with the network's PROJ string, so a target given in the plane
# sails its straight track at its speed (every recorded second within 0.05 m)
# and one given by latitude and longitude starts where they put it (0.05 m).
set -eu
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cat > "$dir/geo-targets.yaml" <<'YAML'
name: geo-targets
own_ship: {ship: c3-mmg, lat_deg: 57.0, lon_deg: 11.335065, course_deg: 90, speed_kn: 12, leg_nm: 5}
traffic:
  network: geo-channel
  targets:
    - {id: T1, east_m: 0, north_m: 3000, course_deg: 180, speed_kn: 10,
       length_m: 150, breadth_m: 25}
    - {id: T2, lat_deg: 56.98, lon_deg: 11.45, course_deg: 0, speed_kn: 8,
       length_m: 100, breadth_m: 18}
run: {duration_s: 300}
outputs: {targets_csv: true, record_every_s: 1}
YAML
"$FAIRWAY" run "$dir/geo-targets.yaml" --out "$dir/runs" > "$dir/out" ||
  { cat "$dir/out" "$dir"/runs/*/run.log; exit 1; }
grep -q 'x longitude, y latitude' "$dir/runs/geo-targets/sumo/tracks.nod.xml" ||
  { echo "the track nodes are not in degrees"; exit 1; }
"$PYTHON" - "$dir/runs/geo-targets/targets.csv" <<'PY'
import csv, math, sys
rows = [r for r in csv.DictReader(open(sys.argv[1]))]
t1 = [r for r in rows if r["id"] == "T1"]
assert len(t1) > 250, len(t1)
v = 10 * 1852 / 3600
worst = max(max(abs(float(r["east_m"]) - 0.0),
                abs(float(r["north_m"]) - (3000.0 - v * float(r["t_s"])))) for r in t1)
assert worst <= 0.05, worst
t2 = [r for r in rows if r["id"] == "T2" and float(r["t_s"]) == 0.0]
assert t2, "T2 not seen at t = 0"
# 56.98 N, 11.45 E in the network's plane (geo-channel.proj) by the ellipsoid's series
lat0, lon0 = 57.0, 11.5
a, f = 6378137.0, 1 / 298.257223563
e2 = f * (2 - f)
phi, lam = math.radians(56.98), math.radians(11.45 - lon0)
nu = a / math.sqrt(1 - e2 * math.sin(phi) ** 2)
dlat = float(t2[0]["lat_deg"]) - 56.98
dlon = float(t2[0]["lon_deg"]) - 11.45
err = math.hypot(dlat * math.pi / 180 * a, dlon * math.pi / 180 * nu * math.cos(phi))
assert err <= 0.05, (err, t2[0]["lat_deg"], t2[0]["lon_deg"])
print("T1 on its track within %.4f m over %d s; T2 starts %.4f m from its lat/lon" % (worst, len(t1), err))
PY
echo "geo targets ok"
