#!/usr/bin/env bash
# A finished sweep's database is reported from a read-only file in a
# directory the reader cannot write, and the report leaves no -wal or -shm.
# As root (who may write anywhere) the report runs as user nobody.
set -u
study=$FAIRWAY_DATA/tests/data/study/small.yaml
dir=$(mktemp -d)
trap 'chmod -R u+w "$dir"; rm -rf "$dir"' EXIT
mkdir "$dir/ro" "$dir/out"
"$FAIRWAY" sweep "$study" --db "$dir/ro/s.db" --limit 2 --progress none >/dev/null 2>&1 || { echo "sweep failed"; exit 1; }
ls "$dir/ro" | grep -q -- '-wal\|-shm' && { echo "the sweep left $(ls "$dir/ro")"; exit 1; }
# a database still in WAL mode (as a killed sweep leaves it, once checkpointed)
cp "$dir/ro/s.db" "$dir/ro/w.db"
"$PYTHON" -c "import sqlite3,sys; c=sqlite3.connect(sys.argv[1]); c.execute('pragma journal_mode=wal'); c.close()" "$dir/ro/w.db"
chmod 0444 "$dir/ro/s.db" "$dir/ro/w.db"
chmod 0555 "$dir/ro"
chmod 0777 "$dir/out"
as=()
if [ "$(id -u)" -eq 0 ]; then
  chmod 0755 "$dir"
  as=(setpriv --reuid=65534 --regid=65534 --clear-groups)
fi
out=$("${as[@]}" "$FAIRWAY" report "$dir/ro/s.db" --out "$dir/out/rep" --no-plots 2>&1)
rc=$?
[ $rc -eq 0 ] || { echo "report: exit $rc: $out"; exit 1; }
[ -s "$dir/out/rep/report.md" ] || { echo "no report.md: $out"; exit 1; }
out=$("${as[@]}" "$FAIRWAY" report "$dir/ro/w.db" --out "$dir/out/rep2" --no-plots 2>&1)
[ $? -eq 0 ] && [ -s "$dir/out/rep2/report.md" ] || { echo "WAL database: $out"; exit 1; }
[ "$(ls "$dir/ro" | tr '\n' ' ')" = "s.db w.db " ] || { echo "left beside the database: $(ls "$dir/ro")"; exit 1; }
# a report into a directory the reader cannot write: refused before anything
# is computed, naming --out, the directory and the reason (was "cannot create
# DIR/.rep.tmp.PID", a path that is never made, and no reason)
out=$("${as[@]}" "$FAIRWAY" report "$dir/ro/s.db" --out "$dir/ro/rep" --no-plots 2>&1)
rc=$?
[ $rc -eq 2 ] && grep -qxF "fairway: --out $dir/ro/rep: cannot write in $dir/ro: Permission denied" \
  <<<"$out" || { echo "report into a read-only directory: exit $rc: $out"; exit 1; }
[ "$(ls "$dir/ro" | tr '\n' ' ')" = "s.db w.db " ] || { echo "left: $(ls "$dir/ro")"; exit 1; }
echo "ok: read-only database reported"
