# sensing_run.sh - the own ship deciding on AIS reports (sense/sensing.h):
# Imazu case 1 (head-on) with AIS sensing (10% of reports lost, 1 s late):
# the own ship still acts and passes clear; the records keep the truth (its
# least distance is the true one, from targets.csv's true positions); the
# same seed gives the same run to the byte, another seed another; the summary
# counts the reports.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
src=$FAIRWAY_DATA/scenarios/imazu/imazu-01.yaml
sed 's/^name: imazu-01/name: ais/; s/^run:/sensing: {mode: ais, dropout: 0.1, latency_s: 1}\nrun:/' "$src" > "$tmp/a.yaml"
sed 's/^  seed: 1/  seed: 2/' "$tmp/a.yaml" > "$tmp/b.yaml"
sed -i 's/^name: ais/name: ais2/' "$tmp/b.yaml"
"$FAIRWAY" run "$tmp/a.yaml" --out "$tmp/o1" > /dev/null
"$FAIRWAY" run "$tmp/a.yaml" --out "$tmp/o2" > /dev/null
"$FAIRWAY" run "$tmp/b.yaml" --out "$tmp/o3" > /dev/null
cmp "$tmp/o1/ais/own.csv" "$tmp/o2/ais/own.csv" || { echo "the same seed gave another run"; exit 1; }
if cmp -s "$tmp/o1/ais/own.csv" "$tmp/o3/ais2/own.csv"; then echo "another seed gave the same run"; exit 1; fi
"$PYTHON" - "$tmp/o1/ais" <<'PY'
import csv, json, math, sys
d = sys.argv[1]
s = json.load(open(d + "/summary.json"))
sen = s["sensing"]
assert sen["mode"] == "ais" and sen["reports_sent"] > 100, sen
assert 0.05 < sen["lost"] / sen["reports_sent"] < 0.15, sen
own = {r["t_s"]: r for r in csv.DictReader(open(d + "/own.csv"))}
least = min(math.hypot(float(r["east_m"]) - float(own[r["t_s"]]["east_m"]),
                       float(r["north_m"]) - float(own[r["t_s"]]["north_m"]))
            for r in csv.DictReader(open(d + "/targets.csv")) if r["t_s"] in own)
enc = s["encounters"][0]
assert enc["act_side"] == "starboard" and not enc["collision"], enc
assert abs(enc["min_distance_m"] - least) < 30.0, (enc["min_distance_m"], least)  # the truth (5 s rows)
print("AIS: %d reports, %d lost; acted, least distance %.0f m (true positions %.0f m)"
      % (sen["reports_sent"], sen["lost"], enc["min_distance_m"], least))
PY
echo "ok: the own ship decides on AIS reports"
