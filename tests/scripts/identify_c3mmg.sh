#!/usr/bin/env bash
# scenarios/ships/c3-mmg.yaml's knowledge base is what the command in its
# header writes: fairway identify over 4-20 kn, both sides, 900 s tests, the
# drift and speed-loss terms kept from the file itself (--slip-from).  The
# nomoto: and nomoto_port: blocks must come out byte for byte.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
ship=$FAIRWAY_DATA/scenarios/ships/c3-mmg.yaml
"$FAIRWAY" identify --ship c3 --speeds 4,6,8,10,12,14,16,18,20 --rudders 5,10,15,20,25,30,35 \
  --sides both --duration 900 --slip-from c3-mmg --out "$tmp/c3-mmg.yaml" > "$tmp/out.txt"
grep -q "worst RMS error: 2.56% of the final rate" "$tmp/out.txt" ||
  { echo "fit error changed:"; grep worst "$tmp/out.txt"; exit 1; }
diff <(sed -n '/^nomoto:/,$p' "$tmp/c3-mmg.yaml") <(sed -n '/^nomoto:/,$p' "$ship") ||
  { echo "c3-mmg.yaml's knowledge base is not what its command writes"; exit 1; }
echo "ok: c3-mmg's knowledge base is its command's"
