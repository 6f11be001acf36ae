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
again=$("$FAIRWAY" sweep "$study" --db "$dir/j2.db" --jobs 2 --progress lines 2>&1)
grep -q "10 already in the database, 0 to run" <<<"$again" || { echo "$again"; exit 1; }
echo "jobs 1 and 2 agree; resume of a finished sweep runs nothing"
