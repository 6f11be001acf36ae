# range_read.sh - the libsumo back end's range query (src/traffic/range_read.h)
# spares the position reads of ships that cannot be in range, and finds
# exactly the ships SUMO's own range test finds: both traffic scenarios run
# with FAIRWAY_RANGE_CHECK=1, which also reads every ship every step and fails
# the run on any difference, and give the results of a run without the check
# byte for byte.  With the bound a hundred times too small (=understate) the
# check must catch a ship the read missed.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for s in dover-crossing strait-crossing; do
  yaml=$FAIRWAY_DATA/scenarios/traffic/$s.yaml
  FAIRWAY_RANGE_CHECK=1 "$FAIRWAY" run "$yaml" --out "$tmp/check" > "$tmp/out" 2> "$tmp/err" ||
    { echo "$s with the check failed:"; cat "$tmp/err"; exit 1; }
  line=$(grep 'range read:' "$tmp/err") || { echo "$s: no range read summary"; cat "$tmp/err"; exit 1; }
  made=$(echo "$line" | sed -E 's/.*: ([0-9]+) position reads, ([0-9]+) spared.*/\1/')
  spared=$(echo "$line" | sed -E 's/.*: ([0-9]+) position reads, ([0-9]+) spared.*/\2/')
  [ "$spared" -gt 0 ] || { echo "$s: no read spared ($line)"; exit 1; }
  "$FAIRWAY" run "$yaml" --out "$tmp/plain" > /dev/null
  for f in own.csv encounters.csv traffic_encounters.csv summary.json; do
    cmp "$tmp/check/$s/$f" "$tmp/plain/$s/$f" || { echo "$s: $f differs with the check"; exit 1; }
  done
  echo "$s: $made position reads, $spared spared, every step as SUMO's range test"
done
rc=0
FAIRWAY_RANGE_CHECK=understate "$FAIRWAY" run "$FAIRWAY_DATA/scenarios/traffic/dover-crossing.yaml" \
  --out "$tmp/under" > "$tmp/out" 2> "$tmp/err" || rc=$?
[ "$rc" -ne 0 ] && grep -q 'range query failed: range read (FAIRWAY_RANGE_CHECK): at step' "$tmp/err" ||
  { echo "an understated bound was not caught (exit $rc):"; tail -3 "$tmp/out" "$tmp/err"; exit 1; }
echo "ok: range read exact, an understated bound caught"
