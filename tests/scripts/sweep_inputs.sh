#!/usr/bin/env bash
# A resumed sweep whose network demand (or any other input a run reads)
# changed is refused with exit 2, naming the file; the database keeps only
# the runs of the first inputs.  Runs on a copy of the data tree.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
mkdir -p "$dir/data/tests/data"
cp -r "$FAIRWAY_DATA/scenarios" "$FAIRWAY_DATA/networks" "$dir/data/"
cp -r "$FAIRWAY_DATA/tests/data/study" "$dir/data/tests/data/"
export FAIRWAY_DATA=$dir/data
study=$dir/data/tests/data/study/small.yaml
"$FAIRWAY" sweep "$study" --db "$dir/s.db" --limit 1 --progress none || { echo "first sweep failed"; exit 1; }
check() { # check FILE ROLE: after FILE changed, the resume is refused naming it
  cp "$1" "$dir/saved"
  case "$1" in *.xml) echo "<!-- changed -->" >> "$1";; *) echo "# changed" >> "$1";; esac
  out=$("$FAIRWAY" sweep "$study" --db "$dir/s.db" --limit 1 --progress none 2>&1)
  rc=$?
  cp "$dir/saved" "$1"
  [ $rc -eq 2 ] || { echo "exit $rc after $1 changed: $out"; exit 1; }
  grep -q "$1 (the $2) changed since" <<<"$out" || { echo "$2 not named: $out"; exit 1; }
}
check "$dir/data/networks/strait/demand.yaml" demand
check "$dir/data/networks/strait/strait.edg.xml" network_edges
check "$dir/data/networks/ships.add.xml" ship_types
check "$dir/data/scenarios/ships/c3-mmg.yaml" ship
check "$study" study
n=$("$PYTHON" -c "import sqlite3,sys; print(sqlite3.connect(sys.argv[1]).execute('select count(*) from runs').fetchone()[0])" "$dir/s.db")
[ "$n" = 1 ] || { echo "$n runs in the database, expected 1"; exit 1; }
# the same files again: resumes
"$FAIRWAY" sweep "$study" --db "$dir/s.db" --limit 1 --progress none || { echo "resume refused"; exit 1; }
echo "ok: every changed input refused by name"
