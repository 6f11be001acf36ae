#!/usr/bin/env bash
# Runs that fail (here: no SUMO listening) are recorded with their reason, the
# sweep goes on and exits 1; a plain rerun skips them, --retry-failed runs them.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
study=$FAIRWAY_DATA/tests/data/study/small.yaml
q() { "$PYTHON" -c "import sqlite3,sys; print(sqlite3.connect(sys.argv[1]).execute(sys.argv[2]).fetchone()[0])" "$dir/s.db" "$1"; }
"$FAIRWAY" sweep "$study" --db "$dir/s.db" --limit 2 --sumo remote:127.0.0.1:9 --progress none
rc=$?
[ $rc -eq 1 ] || { echo "exit $rc, expected 1 for failed runs"; exit 1; }
[ "$(q "select count(*) from runs where status='failed' and reason like '%no SUMO at 127.0.0.1:9%'")" = 2 ] || { echo "failures not recorded with their reason"; exit 1; }
"$FAIRWAY" sweep "$study" --db "$dir/s.db" --limit 1 --progress none
[ "$(q "select count(*) from runs where status='ok'")" = 1 ] || { echo "plain rerun did not skip the failed runs"; exit 1; }
"$FAIRWAY" sweep "$study" --db "$dir/s.db" --retry-failed --limit 2 --progress none || { echo "retry failed"; exit 1; }
[ "$(q "select count(*) from runs where status='failed'")" = 0 ] && [ "$(q "select count(*) from runs where run_id < 2 and status='ok'")" = 2 ] || { echo "--retry-failed did not rerun them"; exit 1; }
echo "failed runs recorded, skipped, then retried"
