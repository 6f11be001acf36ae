#!/usr/bin/env bash
# A bad scenario among good ones: exit 2, FILE:LINE: FIELD, and no output
# directory at all (every file is checked before anything is created).
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
sed 's/speed_kn: 10$/speed_kn: .nan/' "$FAIRWAY_DATA/scenarios/paper/1-head-on.yaml" > "$dir/bad.yaml"
out=$("$FAIRWAY" run "$FAIRWAY_DATA/scenarios/paper/3-crossing.yaml" "$dir/bad.yaml" --out "$dir/out" 2>&1)
rc=$?
[ "$rc" -eq 2 ] || { echo "exit $rc, expected 2: $out"; exit 1; }
grep -Eq "bad.yaml:[0-9]+: own_ship.speed_kn" <<<"$out" || { echo "no FILE:LINE: FIELD in: $out"; exit 1; }
[ ! -e "$dir/out" ] || { echo "output directory left behind"; ls -R "$dir/out"; exit 1; }
echo "ok: no output, $out"
