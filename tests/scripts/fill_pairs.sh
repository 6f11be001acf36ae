# fill_pairs.sh - the start-up fill puts no two ships on a collision course
# with each other anywhere on the network (src/traffic/source_sumo.h), not
# only about the own ship: the Dover crossing at three times its density with
# blind traffic (no ship gives way, so a pair put on a collision course
# collides), surveyed over the whole network (25 nm), seeds 1 and 2.  No two
# fill ships on crossing courses may pass within 0.25 nm (clear_cpa) in the
# first 10 minutes (clear_tcpa).  Before the whole network was checked: 15
# such pairs in these two runs (5 and 10), one passing 129 m centre to centre
# at t = 30 s.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for seed in 1 2; do
  sed -e 's/^  density: 1$/  density: 3\n  behaviour: blind/' -e "s/^  seed: 1$/  seed: $seed/" \
      -e 's/^  duration_s: 3600$/  duration_s: 600/' -e 's/^survey: .*/survey: {radius_nm: 25}/' \
      "$FAIRWAY_DATA/scenarios/traffic/dover-crossing.yaml" > "$tmp/s$seed.yaml"
  grep -q "behaviour: blind" "$tmp/s$seed.yaml" && grep -q "radius_nm: 25" "$tmp/s$seed.yaml" ||
    { echo "the scenario was not made"; exit 1; }
  "$FAIRWAY" run "$tmp/s$seed.yaml" --out "$tmp/o$seed" > /dev/null 2>&1 ||
    { echo "run failed"; cat "$tmp/o$seed"/*/run.log; exit 1; }
  "$PYTHON" - "$tmp/o$seed/dover-crossing" "$seed" <<'PY'
import csv, re, sys
d, seed = sys.argv[1], sys.argv[2]
taken = int(re.search(r"traffic: (\d+) ships the fill put", open(d + "/run.log").read()).group(1))
bad = [r for r in csv.DictReader(open(d + "/traffic_encounters.csv"))
       if r["own"] == "0" and "_fill" in r["ship_a"] and "_fill" in r["ship_b"]
       and r["type"] == "crossing" and float(r["min_dist_m"]) < 463.0 and float(r["t_min_s"]) < 600.0]
print("seed", seed, "fill ships taken out", taken, "fill pairs crossing within 0.25 nm", len(bad))
assert taken > 0, "the fill was not checked"
assert not bad, [(r["ship_a"], r["ship_b"], r["min_dist_m"], r["t_min_s"]) for r in bad]
PY
done
echo "ok: no fill pair on a collision course"
