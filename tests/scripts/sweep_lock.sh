#!/usr/bin/env bash
# Two sweeps on one database: the second is refused at once (exit 2, a clear
# message, well before the first ends), the first finishes every run.
set -u
study=$FAIRWAY_DATA/tests/data/study/small.yaml
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$FAIRWAY" sweep "$study" --db "$dir/s.db" --jobs 1 --limit 3 --progress none > "$dir/first.log" 2>&1 &
pid=$!
for _ in $(seq 1 500); do [ -s "$dir/s.db" ] && break; sleep 0.01; done
sleep 0.3
start=$(date +%s)
out=$("$FAIRWAY" sweep "$study" --db "$dir/s.db" --jobs 1 --progress none 2>&1)
rc=$?
took=$(( $(date +%s) - start ))
wait $pid || { echo "the first sweep failed: $(cat "$dir/first.log")"; exit 1; }
[ $rc -eq 2 ] || { echo "second sweep: exit $rc: $out"; exit 1; }
grep -q "another fairway sweep is writing this database" <<<"$out" || { echo "$out"; exit 1; }
[ "$took" -le 2 ] || { echo "refused only after $took s"; exit 1; }
n=$("$PYTHON" -c "import sqlite3,sys; print(sqlite3.connect(sys.argv[1]).execute('select count(distinct run_id), count(*) from runs').fetchone())" "$dir/s.db")
[ "$n" = "(3, 3)" ] || { echo "runs: $n, expected (3, 3)"; exit 1; }
echo "ok: second sweep refused at once; $out"
