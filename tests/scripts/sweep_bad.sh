#!/usr/bin/env bash
# sweep_bad.sh STUDY PATTERN: a bad study is refused with exit 2 and a message
# matching PATTERN, before anything runs: no database is created.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
out=$("$FAIRWAY" sweep "$1" --db "$dir/s.db" 2>&1)
rc=$?
[ $rc -eq 2 ] || { echo "exit $rc, expected 2: $out"; exit 1; }
grep -Eq -- "$2" <<<"$out" || { echo "message does not match /$2/: $out"; exit 1; }
[ ! -e "$dir/s.db" ] || { echo "a database was created for a bad study"; exit 1; }
echo "ok: no database; $out"
