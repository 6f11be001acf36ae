# split_worst.sh - a study's splitting estimates end to end, and the closest
# trajectory they found run again: `fairway sweep` on a study with estimate:
# (tests/data/study/split-tiny.yaml: AIS sensing gives the randomness after
# t = 0) writes table splits; `fairway report` shows the section;
# `fairway worst --splits` replays each cell's best path into its own run
# directory with the closeness the database has, to the last digit printed.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
study=$FAIRWAY_DATA/tests/data/study/split-tiny.yaml
"$FAIRWAY" sweep "$study" --db "$tmp/s.db" --jobs 2 --progress none > /dev/null 2>&1 ||
  { "$FAIRWAY" sweep "$study" --db "$tmp/s.db" --jobs 2; exit 1; }
[ "$(sqlite3 "$tmp/s.db" "select count(*) from splits where status = 'ok'")" -eq 2 ] ||
  { echo "splits:"; sqlite3 "$tmp/s.db" "select * from splits"; exit 1; }
"$FAIRWAY" report "$tmp/s.db" --out "$tmp/rep" --no-plots > /dev/null
grep -q "^## Rare events by splitting" "$tmp/rep/report.md" || { echo "no splitting section"; exit 1; }
"$FAIRWAY" worst "$tmp/s.db" --splits --out "$tmp/w" > "$tmp/w.csv"
"$PYTHON" - "$tmp/w.csv" "$tmp/w" <<'PY'
import csv, json, os, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 1, rows
r = rows[0]
assert r["db_closeness"] == r["replay_closeness"], r
s = json.load(open(os.path.join(r["dir"], "summary.json")))
assert s["sensing"]["mode"] == "ais", s["sensing"]
print("cell", r["cell"], "best closeness", r["db_closeness"], "replayed",
      r["replay_closeness"], "(%s m hull to hull)" % r["replay_min_hull_m"])
PY
echo "ok: splitting's closest path replayed"
