#!/usr/bin/env bash
# identify and calibrate --write on ship files with CR or CRLF line breaks, or
# one bare CR: the output loads, every value not written is unchanged, the
# file keeps its line breaks, and no temporary file is left.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
ship=$FAIRWAY_DATA/scenarios/ships/c3.yaml
trial=$FAIRWAY_DATA/scenarios/ships/c3-trial.yaml
value() { # value FILE KEY: the number after "KEY:" (any line break)
  tr '\r' '\n' < "$1" | sed -n "s/^ *$2: *\([-0-9.e]*\).*/\1/p" | head -1
}
tr '\n' '\r' < "$ship" > "$dir/cr.yaml"
sed 's/$/\r/' "$ship" > "$dir/crlf.yaml"
for f in cr crlf; do
  out=$("$FAIRWAY" identify --ship "$dir/$f.yaml" --speeds 14.55,20.12,26.7 --rudders 10,20,35 \
        --sides starboard --duration 300 --out "$dir/$f-id.yaml" 2>&1)
  [ $? -eq 0 ] || { echo "identify $f: $out"; exit 1; }
  "$FAIRWAY" ship "$dir/$f-id.yaml" >/dev/null || { echo "identify $f: output does not load"; exit 1; }
  [ "$(value "$dir/$f-id.yaml" N_vvv)" = "$(value "$ship" N_vvv)" ] || { echo "identify $f: N_vvv changed"; exit 1; }
  grep -q "source: fairway identify" <(tr '\r' '\n' < "$dir/$f-id.yaml") || { echo "identify $f: no new block"; exit 1; }
done
[ "$(tr -cd '\n' < "$dir/cr-id.yaml" | wc -c)" -eq 0 ] || { echo "identify cr: LF added"; exit 1; }
# one bare CR ends the first line; the rest is LF
awk 'NR == 1 { printf "%s\r", $0; next } { print }' "$ship" > "$dir/one.yaml"
nvvv=$(value "$dir/one.yaml" N_vvv)
out=$("$FAIRWAY" calibrate --ship "$dir/one.yaml" --trial "$trial" --write 2>&1)
[ $? -eq 0 ] || { echo "calibrate: $out"; exit 1; }
"$FAIRWAY" ship "$dir/one.yaml" >/dev/null || { echo "calibrate: the ship file no longer loads"; exit 1; }
[ "$(value "$dir/one.yaml" N_vvv)" = "$nvvv" ] || { echo "calibrate: N_vvv overwritten"; exit 1; }
grep -q "N_r: .*\[CAL\]" "$dir/one.yaml" || { echo "calibrate: N_r not written"; exit 1; }
# a value on the line after its key cannot be rewritten line by line: refused
# before the fit, the file byte for byte as it was
sed 's/^\(  N_r:\) *\([-0-9.e]*\)\(.*\)$/\1\3\n    \2/' "$ship" > "$dir/split.yaml"
cp "$dir/split.yaml" "$dir/split.orig"
out=$("$FAIRWAY" calibrate --ship "$dir/split.yaml" --trial "$trial" --write 2>&1)
[ $? -eq 2 ] && grep -q "split.yaml:[0-9]*: hull.N_r: cannot edit in place" <<<"$out" || { echo "split: $out"; exit 1; }
grep -q "RMS relative error" <<<"$out" && { echo "split: refused only after the fit"; exit 1; }
cmp -s "$dir/split.yaml" "$dir/split.orig" || { echo "split: the file was changed"; exit 1; }
left=$(ls -A "$dir" | grep -v -x -e cr.yaml -e crlf.yaml -e cr-id.yaml -e crlf-id.yaml -e one.yaml \
       -e split.yaml -e split.orig)
[ -z "$left" ] || { echo "left behind: $left"; exit 1; }
echo "ok: line breaks kept, values intact"
