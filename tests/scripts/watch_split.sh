#!/usr/bin/env bash
# watch_split.sh - a watch that draws is randomness after t = 0: splitting accepts a
# study whose only randomness is the own ship's watch (tests/data/study/split-watch.yaml:
# perfect sensing, traffic.watch.own_ship human and detect_s swept in) and estimates
# its cell; summary.json of a run of the swept scenario counts the ships the watch met.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
study=$FAIRWAY_DATA/tests/data/study/split-watch.yaml
"$FAIRWAY" sweep "$study" --db "$tmp/s.db" --jobs 1 --progress none > "$tmp/out" 2>&1 ||
  { cat "$tmp/out"; exit 1; }
[ "$(sqlite3 "$tmp/s.db" "select count(*) from splits where status = 'ok'")" -eq 2 ] ||
  { echo "splits:"; sqlite3 "$tmp/s.db" "select * from splits"; exit 1; }
sed 's/^traffic:/traffic:\n  watch: {detect_s: 120, own_ship: human}/' \
  "$FAIRWAY_DATA/scenarios/imazu/imazu-01.yaml" > "$tmp/watch.yaml"
"$FAIRWAY" run "$tmp/watch.yaml" --out "$tmp/runs" > /dev/null
grep -Eq '"own_watch": \{"ships": 1, "lapsed": 0\}' "$tmp"/runs/*/summary.json ||
  { echo "summary.json:"; cat "$tmp"/runs/*/summary.json; exit 1; }
echo "ok: splitting over the own ship's watch"
