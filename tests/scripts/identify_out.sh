#!/usr/bin/env bash
# identify's --out is checked before the turning tests: a directory, a
# missing directory and an existing file (without --force) are refused at
# once, and nothing is written.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
echo "keep me" > "$dir/exists.yaml"
expect() { # expect PATTERN ARGS...
  local pattern=$1; shift
  local t0=$SECONDS
  out=$("$FAIRWAY" identify --ship c3 "$@" 2>&1)
  rc=$?
  [ $rc -eq 2 ] && grep -q -- "$pattern" <<<"$out" || { echo "exit $rc: $* -> $out"; exit 1; }
  grep -q "MMG turning tests" <<<"$out" && { echo "computed before refusing: $*"; exit 1; }
  [ $((SECONDS - t0)) -le 2 ] || { echo "slow refusal: $*"; exit 1; }
}
expect "--out $dir: is a directory" --out "$dir"
expect "--out $dir/no/x.yaml: no directory" --out "$dir/no/x.yaml"
expect "--out $dir/exists.yaml: file exists (give --force to replace it)" --out "$dir/exists.yaml"
[ "$(cat "$dir/exists.yaml")" = "keep me" ] || { echo "the existing file was changed"; exit 1; }
expect "--speeds: empty item in '10,,12'" --speeds 10,,12
expect "--speeds: 45 kn outside 1-40 kn" --speeds 10,45
[ "$(ls -A "$dir")" = "exists.yaml" ] || { echo "left: $(ls -A "$dir")"; exit 1; }
echo "ok: --out refused before computing"
