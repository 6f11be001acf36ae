#!/usr/bin/env bash
# A --db that is not a SQLite file, or holds another study, is refused (exit 2)
# and left as it was.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
echo "not a database" > "$dir/text.db"
out=$("$FAIRWAY" sweep "$FAIRWAY_DATA/tests/data/study/small.yaml" --db "$dir/text.db" 2>&1)
[ $? -eq 2 ] && grep -q "not a usable SQLite database" <<<"$out" || { echo "$out"; exit 1; }
[ "$(cat "$dir/text.db")" = "not a database" ] || { echo "the file was changed"; exit 1; }
"$FAIRWAY" sweep "$FAIRWAY_DATA/tests/data/study/small.yaml" --db "$dir/s.db" --limit 1 --progress none || exit 1
out=$("$FAIRWAY" sweep "$FAIRWAY_DATA/tests/data/study/bad-twice.yaml" --db "$dir/s.db" 2>&1)
[ $? -eq 2 ] || { echo "$out"; exit 1; }
sed 's/domains_m: \[200, 800\]/domains_m: [200, 900]/' "$FAIRWAY_DATA/tests/data/study/small.yaml" > "$dir/other.yaml"
sed -i "s|scenario: base.yaml|scenario: $FAIRWAY_DATA/tests/data/study/base.yaml|" "$dir/other.yaml"
out=$("$FAIRWAY" sweep "$dir/other.yaml" --db "$dir/s.db" 2>&1)
[ $? -eq 2 ] && grep -q "holds results of another study" <<<"$out" || { echo "$out"; exit 1; }
echo "ok: refused; $out"
