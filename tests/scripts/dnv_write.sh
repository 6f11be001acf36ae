#!/usr/bin/env bash
# fairway situation writes the 22 Imazu and 5 paper cases as DNV traffic situations
# (src/run/dnv_situation.h): every file validates against DNV's traffic_situation.schema.json
# (Debian's python3-jsonschema, draft 2020-12), and a situation read back runs as its scenario:
# the own ship's positions within 1 m at every common instant (Imazu 5, 12 and 16 with fairway's
# default avoidance settings, which a situation cannot carry, and the paper's case 3 with c3-mmg,
# the reader's default model); the
# read-back runs' situation outputs validate too.  A scenario with a network is refused, exit 2,
# nothing written.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
D=$FAIRWAY_DATA/scenarios
"$FAIRWAY" situation "$D"/imazu/imazu-*.yaml "$D"/paper/*.yaml --out "$dir/all" > /dev/null || exit 1
mkdir "$dir/rt"
for c in imazu/imazu-05 imazu/imazu-12 imazu/imazu-16 paper/3-crossing; do
  n=$(basename $c)
  grep -v "return: heading\|domain_from: centre\|domain_reading: transverse" "$D/$c.yaml" |
    sed "s/ship: c3-paper-mmg/ship: c3-mmg/" > "$dir/rt/$n.yaml"
done
"$FAIRWAY" situation "$dir"/rt/*.yaml --out "$dir/rt" > /dev/null || exit 1
"$FAIRWAY" run "$dir"/rt/*.yaml --out "$dir/yaml" > "$dir/out.txt" 2>&1 &&
  "$FAIRWAY" run "$dir"/rt/*.json --out "$dir/json" >> "$dir/out.txt" 2>&1 || { cat "$dir/out.txt"; exit 1; }
out=$("$FAIRWAY" situation "$D/traffic/dover-crossing.yaml" --out "$dir/none" 2>&1)
rc=$?
[ "$rc" -eq 2 ] && [ ! -e "$dir/none" ] && grep -q "only scenarios with explicit targets" <<<"$out" ||
  { echo "network scenario: exit $rc: $out"; exit 1; }
"$PYTHON" - "$dir" "$D/dnv" <<'PY' || exit 1
import csv, glob, json, os, sys
import jsonschema
d, schemas = sys.argv[1], sys.argv[2]
sit = jsonschema.Draft202012Validator(json.load(open(schemas + "/traffic_situation.schema.json")))
out = jsonschema.Draft202012Validator(json.load(open(schemas + "/situation_output.schema.json")))
files = sorted(glob.glob(d + "/all/*.json"))
bad = [(f, [e.message for e in sit.iter_errors(json.load(open(f)))][:2]) for f in files]
bad = [b for b in bad if b[1]]
answers = sorted(glob.glob(d + "/json/*/situation_output.json"))
bad += [(f, e) for f in answers for e in [[x.message for x in out.iter_errors(json.load(open(f)))]] if e]
print(f"{len(files)} situations and {len(answers)} situation outputs validated, {len(bad)} invalid", bad[:3])
worst = 0.0
for y in sorted(glob.glob(d + "/yaml/*/own.csv")):
    n = y.split("/")[-2]
    a = list(csv.DictReader(open(y)))
    b = {r["t_s"]: r for r in csv.DictReader(open(f"{d}/json/{n}/own.csv"))}
    # the situation's plane is centred on the own ship's start: the same plane moved
    oe = float(a[0]["east_m"]) - float(b["0.0"]["east_m"])
    on = float(a[0]["north_m"]) - float(b["0.0"]["north_m"])
    dev = max(((float(r["east_m"]) - float(b[r["t_s"]]["east_m"]) - oe) ** 2 +
               (float(r["north_m"]) - float(b[r["t_s"]]["north_m"]) - on) ** 2) ** 0.5
              for r in a if r["t_s"] in b)
    print(f"{n}: own ship {dev:.2e} m from the scenario's run at most ({len(a)} instants)")
    worst = max(worst, dev)
sys.exit(0 if len(files) == 27 and len(answers) == 4 and not bad and worst < 1.0 else 1)
PY
echo "situations written, valid, and read back to the same run"
