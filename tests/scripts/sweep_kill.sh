#!/usr/bin/env bash
# SIGKILL a sweep mid-way, resume it: every run ends in the database exactly
# once, with the results of an uninterrupted sweep, and no worker outlives it.
set -eu
study=$FAIRWAY_DATA/tests/data/study/small.yaml
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$FAIRWAY" sweep "$study" --db "$dir/ref.db" --jobs 2 --progress none
"$FAIRWAY" sweep "$study" --db "$dir/cut.db" --jobs 2 --progress none &
pid=$!
count() { "$PYTHON" -c "import sqlite3,sys
try: print(sqlite3.connect(sys.argv[1]).execute('select count(*) from runs').fetchone()[0])
except Exception: print(0)" "$dir/cut.db"; }
for _ in $(seq 1 600); do
  n=$(count)
  [ "$n" -ge 3 ] && break
  sleep 0.02
done
kill -9 $pid
wait $pid 2>/dev/null || true
n=$(count)
echo "killed with $n of 10 runs committed"
[ "$n" -lt 10 ] || { echo "the sweep finished before the kill: the test proves nothing"; exit 1; }
sleep 0.5
if pgrep -P $pid >/dev/null; then echo "workers outlived the killed sweep"; exit 1; fi
out=$("$FAIRWAY" sweep "$study" --db "$dir/cut.db" --jobs 2 --progress lines 2>&1)
grep -q "$n already in the database, $((10 - n)) to run" <<<"$out" || { echo "$out"; exit 1; }
"$PYTHON" "$FAIRWAY_DATA/tests/scripts/study_db_compare.py" "$dir/ref.db" "$dir/cut.db"
