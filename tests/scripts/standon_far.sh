#!/usr/bin/env bash
# Rule 17(b) for the own ship is about the give-way ship alone (avoid/policy.c standon_last): in
# tests/data/own/standon-far.yaml (the Dover crossing in the spring tidal stream on AIS and radar,
# domain 150 m: run 6 of scenarios/studies/dover-imperfect.yaml) a ferry comes on from the port side
# as the give-way ship, 10.2 km off at 1038 s (DCPA 57 m, TCPA 619 s).  Judged against every target
# at once, the largest helm two minutes later failed for the crowd around and the own ship acted
# "alone" there, 20 deg to starboard; judged for the ferry alone it stands on.  The test: no rule
# 17(b) action farther off than 2 nm, and the run ends without a collision.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$FAIRWAY" run "$FAIRWAY_DATA/tests/data/own/standon-far.yaml" --out "$tmp/o" > "$tmp/out" 2>&1 ||
  { cat "$tmp/out"; exit 1; }
log="$tmp/o/standon-far/run.log"
grep 'own ship alone must act' "$log" | grep ' act ' || true
far=$( { grep 'own ship alone must act' "$log" || true; } | { grep ' act ' || true; } |
  sed -E 's/.*range ([0-9]+) m.*/\1/' | awk '$1 > 3704' | wc -l)
[ "$far" -eq 0 ] || { echo "rule 17(b) action farther off than 2 nm"; exit 1; }
grep -q '"collision": false' "$tmp/o/standon-far/summary.json" || { echo "collision"; exit 1; }
echo "no rule 17(b) action beyond 2 nm, no collision"
