#!/usr/bin/env bash
# Bad --db and --keep paths are refused before anything runs, with a plain
# message, and no database file is left behind.
set -u
study=$FAIRWAY_DATA/tests/data/study/small.yaml
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
expect() { # expect PATTERN ARGS...: exit 2 with PATTERN
  local pattern=$1; shift
  out=$("$FAIRWAY" sweep "$study" --progress none "$@" 2>&1)
  rc=$?
  [ $rc -eq 2 ] && grep -q -- "$pattern" <<<"$out" || { echo "exit $rc: $* -> $out"; exit 1; }
}
mkdir "$dir/adir"
expect "--db $dir/adir: is a directory" --db "$dir/adir"
expect "--db $dir/nowhere/s.db: no directory" --db "$dir/nowhere/s.db"
touch "$dir/afile"
expect "--keep $dir/afile: not a directory" --db "$dir/k.db" --keep "$dir/afile"
[ ! -e "$dir/k.db" ] || { echo "a refused sweep created the database"; exit 1; }
# refused by the study check on a database it would have created
sed 's/domains_m: \[200, 800\]/domains_m: [200, 900]/' "$study" > "$dir/other.yaml"
sed -i "s|scenario: base.yaml|scenario: $FAIRWAY_DATA/tests/data/study/base.yaml|" "$dir/other.yaml"
"$FAIRWAY" sweep "$study" --db "$dir/s.db" --limit 1 --progress none >/dev/null 2>&1 || { echo "sweep failed"; exit 1; }
out=$("$FAIRWAY" sweep "$dir/other.yaml" --db "$dir/s.db" 2>&1)
[ $? -eq 2 ] || { echo "$out"; exit 1; }
[ -e "$dir/s.db" ] || { echo "an existing database was removed"; exit 1; }
ls "$dir" | grep -q -- '-wal\|-shm\|-journal' && { echo "journal files left: $(ls "$dir")"; exit 1; }
echo "ok: bad paths refused, nothing created"
