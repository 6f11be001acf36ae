#!/usr/bin/env bash
# The same study with --jobs 1 and --jobs 2 gives the same per-run results,
# and a second sweep over a finished database runs nothing.
set -eu
study=$FAIRWAY_DATA/tests/data/study/small.yaml
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$FAIRWAY" sweep "$study" --db "$dir/j1.db" --jobs 1 --progress none
"$FAIRWAY" sweep "$study" --db "$dir/j2.db" --jobs 2 --progress none
"$PYTHON" "$FAIRWAY_DATA/tests/scripts/study_db_compare.py" "$dir/j1.db" "$dir/j2.db"
# every run finished: a digest of failed runs would keep a crash as the expected result
failed=$("$PYTHON" -c 'import sqlite3, sys
print(sqlite3.connect(sys.argv[1]).execute("SELECT COUNT(*) FROM runs WHERE status <> '"'ok'"'").fetchone()[0])' "$dir/j1.db")
[ "$failed" = 0 ] || { echo "$failed runs failed"; exit 1; }
again=$("$FAIRWAY" sweep "$study" --db "$dir/j2.db" --jobs 2 --progress lines 2>&1)
grep -q "10 already in the database, 0 to run" <<<"$again" || { echo "$again"; exit 1; }

# the results themselves, against the digest kept with the tests
# (FAIRWAY_WRITE_DIGESTS=FILE writes the one found instead)
got=$("$PYTHON" "$FAIRWAY_DATA/tests/scripts/study_db_digest.py" "$dir/j1.db")
if [ -n "${FAIRWAY_WRITE_DIGESTS:-}" ]; then
  echo "$got" > "$FAIRWAY_WRITE_DIGESTS"
else
  want=$(cat "$FAIRWAY_DATA/tests/data/digests/study-small.txt")
  [ "$got" = "$want" ] || { echo "study results digest $got, expected $want"; exit 1; }
  echo "study results digest as kept"
fi
echo "jobs 1 and 2 agree; resume of a finished sweep runs nothing"
