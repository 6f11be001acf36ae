#!/usr/bin/env bash
# fairway run stopped by SIGINT or SIGTERM: exit 1 with a message naming the
# finished runs it kept; the unfinished run's temporary directory is removed.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
src=$FAIRWAY_DATA/scenarios/traffic/strait-crossing.yaml
sed -e 's/^name: strait-crossing/name: long-crossing/' -e 's/duration_s: 3600/duration_s: 86400/' \
    -e 's/leg_nm: 12/leg_nm: 400/' "$src" > "$dir/long.yaml"
for sig in INT TERM; do
  out=$dir/out-$sig
  "$FAIRWAY" run "$FAIRWAY_DATA/scenarios/paper/1-head-on.yaml" "$dir/long.yaml" --out "$out" \
    > "$dir/log-$sig" 2>&1 &
  pid=$!
  for _ in $(seq 1 1000); do
    [ -d "$out/paper-1-head-on" ] && ls -a "$out" | grep -q '^\.long-crossing\.tmp\.' && break
    sleep 0.02
  done
  sleep 0.2
  kill -$sig $pid
  wait $pid
  rc=$?
  [ $rc -eq 1 ] || { echo "SIG$sig: exit $rc: $(cat "$dir/log-$sig")"; exit 1; }
  grep -q "kept 1 finished run in $out: paper-1-head-on; the unfinished run was removed" "$dir/log-$sig" ||
    { echo "SIG$sig: $(cat "$dir/log-$sig")"; exit 1; }
  left=$(ls -A "$out")
  [ "$left" = "paper-1-head-on" ] || { echo "SIG$sig: left in --out: $left"; exit 1; }
  [ -s "$out/paper-1-head-on/summary.json" ] || { echo "SIG$sig: the finished run is incomplete"; exit 1; }
done
echo "ok: interrupted runs cleaned up"
