# sweep_ais.sh - a study over recorded traffic (tests/data/study/ais.yaml: the
# replay of scenarios/ais/ais-crossing.yaml, 2 domains x 3 replications, the
# AIS window up to 600 s later and the start up to 500 m along the course):
# the runs of a replication share its window and start (paired domains), the
# replications differ; a replayed ship is where the later window puts it (its
# reported speed times the difference in start, within 1 m); the sweep runs
# every run; a changed AIS file stops a resume, naming it.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
study=$FAIRWAY_DATA/tests/data/study/ais.yaml
"$FAIRWAY" sweep "$study" --dry-run > "$tmp/plan.csv"
"$FAIRWAY" sweep "$study" --db "$tmp/ais.db" --jobs 2 --keep "$tmp/runs" > "$tmp/out" 2>&1 ||
  { echo "sweep failed:"; cat "$tmp/out"; exit 1; }
ok=$(sqlite3 "$tmp/ais.db" "select count(*) from runs where status = 'ok'")
[ "$ok" -eq 6 ] || { echo "$ok of 6 runs ok"; exit 1; }
"$PYTHON" - "$tmp/plan.csv" "$tmp/runs" <<'PY'
import csv, sys
lines = open(sys.argv[1]).read().splitlines()[1:]
plan = list(csv.DictReader(lines))
later = {}
for r in plan:
    t = float(r["ais_later_s"])
    assert 0.0 <= t < 600.0, r
    later.setdefault(r["replication"], set()).add(t)
assert all(len(v) == 1 for v in later.values()), later          # paired within a replication
assert len({v.pop() for v in later.values()}) == 3, later        # replications differ
# ship 219000101 sails east at 12 kn: at t = 0 it is speed x (later_a - later_b) apart
def first_east(run_id):
    for row in csv.DictReader(open("%s/ais-%06d/targets.csv" % (sys.argv[2], run_id))):
        if row["id"] == "219000101" and float(row["t_s"]) == 0.0:
            return float(row["east_m"]), float(row["speed_kn"])
    raise SystemExit("run %d: ship 219000101 not seen at t = 0" % run_id)
t = {int(r["run_id"]): float(r["ais_later_s"]) for r in plan}
e0, v = first_east(0)
for k in (2, 4):
    e, _ = first_east(k)
    want = v * 1852.0 / 3600.0 * (t[k] - t[0])
    assert abs((e - e0) - want) < 1.0, (k, e - e0, want)
print("windows: later by", sorted(set(t.values())), "s; the replayed ship where they put it")
PY
# a resume after the AIS file changed is refused, naming the file
mkdir "$tmp/own"
cp "$FAIRWAY_DATA/scenarios/ais/ais-crossing.yaml" "$FAIRWAY_DATA/scenarios/ais/aisdk-2026-03-01.csv" "$tmp/own/"
sed "s|scenario: .*|scenario: $tmp/own/ais-crossing.yaml|" "$study" > "$tmp/own/study.yaml"
"$FAIRWAY" sweep "$tmp/own/study.yaml" --db "$tmp/own.db" --limit 2 > /dev/null 2>&1 || true
echo "219000101,oops" >> "$tmp/own/aisdk-2026-03-01.csv"
rc=0
"$FAIRWAY" sweep "$tmp/own/study.yaml" --db "$tmp/own.db" > "$tmp/out" 2>&1 || rc=$?
[ "$rc" -eq 2 ] && grep -q "aisdk-2026-03-01.csv (the ais) changed" "$tmp/out" ||
  { echo "a changed AIS file was not refused (exit $rc):"; cat "$tmp/out"; exit 1; }
echo "ok: AIS study swept, paired, guarded"
