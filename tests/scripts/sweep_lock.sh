#!/usr/bin/env bash
# Two sweeps on one database: the second is refused at once (exit 2, a clear
# message, well before the first ends), the first finishes every run.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
# The shipped small study runs its three first runs in about 0.4 s on a fast
# machine, less than the wait below: the first sweep would be over before the
# second starts.  A copy with 40 replications keeps it busy for seconds.
study=$dir/small.yaml
sed -e "s|^scenario: base.yaml|scenario: $FAIRWAY_DATA/tests/data/study/base.yaml|" \
    -e 's|^replications: 5|replications: 40|' "$FAIRWAY_DATA/tests/data/study/small.yaml" > "$study"
grep -q "^replications: 40" "$study" || { echo "could not make the study copy"; exit 1; }
"$FAIRWAY" sweep "$study" --db "$dir/s.db" --jobs 1 --limit 30 --progress none > "$dir/first.log" 2>&1 &
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
[ "$n" = "(30, 30)" ] || { echo "runs: $n, expected (30, 30)"; exit 1; }
echo "ok: second sweep refused at once; $out"
