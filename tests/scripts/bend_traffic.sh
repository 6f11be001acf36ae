# bend_traffic.sh - ships on a bent channel turn as ships do: an hour of
# networks/bend at density 3 (tests/data/bend_traffic.yaml) and three more
# seeds; the traffic monitors see no ship move sideways faster than 2 m/s and
# none jump (on main before the hull track: 17 sideways flags, 32.7 m/s).
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for seed in 1 2 3; do
  sed "s/^  seed: 1/  seed: $seed/" "$FAIRWAY_DATA/tests/data/bend_traffic.yaml" > "$tmp/b$seed.yaml"
  "$FAIRWAY" run "$tmp/b$seed.yaml" --out "$tmp/o$seed" > /dev/null 2>&1 ||
    { echo "run failed"; cat "$tmp/o$seed"/*/run.log; exit 1; }
  "$PYTHON" - "$tmp/o$seed/bend-watch/summary.json" "$seed" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))["monitors"]
print("seed", sys.argv[2], "sideways", m["sideways"], "teleports", m["teleport"],
      "largest sideways speed %.2f m/s" % m["max_lateral_mps"])
assert m["sideways"] == 0 and m["teleport"] == 0 and m["max_lateral_mps"] < 2.0, m
PY
done
echo "ok: no ship jumps on the bend"
