# env_run.sh - a scenario's environment: section reaches the run.  The own
# ship alone for 30 minutes in calm water and in a uniform current of 2 kn
# towards 090 (tests/data/env): over ground the drifting track is the calm
# one shifted 1852 m east (2 kn x 1800 s), to 1 m, its heading the same, its
# speed over ground sqrt(12^2 + 2^2) = 12.166 kn.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for s in calm drift; do
  "$FAIRWAY" run "$FAIRWAY_DATA/tests/data/env/$s.yaml" --out "$tmp" > /dev/null
done
"$PYTHON" - "$tmp/calm/own.csv" "$tmp/drift/own.csv" <<'PY'
import csv, sys
calm = list(csv.DictReader(open(sys.argv[1])))
drift = list(csv.DictReader(open(sys.argv[2])))
assert len(calm) == len(drift) and len(calm) > 100
for a, b in zip(calm, drift):
    t = float(a["t_s"])
    de = float(b["east_m"]) - float(a["east_m"])
    dn = float(b["north_m"]) - float(a["north_m"])
    assert abs(de - 2 * 1852.0 / 3600.0 * t) < 1.0 and abs(dn) < 1.0, (t, de, dn)
    assert abs(float(b["heading_deg"]) - float(a["heading_deg"])) < 1e-6, t
last = drift[-1]
assert abs(float(last["speed_kn"]) - (12.0 ** 2 + 2.0 ** 2) ** 0.5) < 0.01, last["speed_kn"]
print("drift at %s s: %.2f m east" % (last["t_s"], float(last["east_m"]) - float(calm[-1]["east_m"])))
PY
# the gusty beam wind (windy.yaml): the own ship's track differs from the calm
# one (it keeps its line by line-of-sight guidance, crabbing, and the wind
# costs it speed); run twice, the same seed gives the same bytes
"$FAIRWAY" run "$FAIRWAY_DATA/tests/data/env/windy.yaml" --out "$tmp" > /dev/null
cp "$tmp/windy/own.csv" "$tmp/windy1.csv"
"$FAIRWAY" run "$FAIRWAY_DATA/tests/data/env/windy.yaml" --out "$tmp" > /dev/null
cmp "$tmp/windy1.csv" "$tmp/windy/own.csv"
"$PYTHON" - "$tmp/calm/own.csv" "$tmp/windy/own.csv" <<'PY'
import csv, sys
calm = list(csv.DictReader(open(sys.argv[1])))
windy = list(csv.DictReader(open(sys.argv[2])))
de = float(windy[-1]["east_m"]) - float(calm[-1]["east_m"])
dn = float(windy[-1]["north_m"]) - float(calm[-1]["north_m"])
assert abs(de) > 50.0, de
print("wind: %.1f m east, %.1f m north of the calm track after %s s, heading %s deg"
      % (de, dn, windy[-1]["t_s"], windy[-1]["heading_deg"]))
PY
echo "ok: the current carries the own ship"
