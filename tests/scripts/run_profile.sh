# run_profile.sh - fairway run --profile: run.log and stderr get one line
# saying where the run's CPU time went, the parts add up to no more than the
# whole, the traffic's step is there for a SUMO run, and the results are the
# same bytes as without --profile (the timings touch nothing a run writes).
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
yaml=$FAIRWAY_DATA/scenarios/paper/1-head-on.yaml
"$FAIRWAY" run "$yaml" --out "$tmp/plain" > /dev/null
"$FAIRWAY" run "$yaml" --out "$tmp/prof" --profile > /dev/null 2> "$tmp/err"
line=$(grep '^profile: ' "$tmp/err") || { echo "no profile line on stderr:"; cat "$tmp/err"; exit 1; }
grep -qF "$line" "$tmp/prof/paper-1-head-on/run.log" || { echo "run.log lacks the profile line"; exit 1; }
for f in own.csv targets.csv encounters.csv summary.json; do
  cmp "$tmp/plain/paper-1-head-on/$f" "$tmp/prof/paper-1-head-on/$f" ||
    { echo "$f differs with --profile"; exit 1; }
done
# CPU C: set-up S; steps L: parts...; finish F  ->  S + L + F <= C, parts = L.
# Every figure is printed to the millisecond, so each is off by up to 0.5 ms:
# a sum of n printed figures against one more may miss by (n + 1) * 0.5 ms.
echo "$line" | "$PYTHON" -c '
import re, sys
line = sys.stdin.read()
num = lambda key: float(re.search(key + r" ([0-9.]+)", line).group(1))
cpu, setup, steps, fin = num("CPU"), num("set-up"), num("steps"), num("finish")
parts = [num(k) for k in ("traffic.s step", "own ship placed", "ships read", "decisions",
                          "traffic.s reactions", "own dynamics", "records and monitors", "the rest")]
assert re.search(r", (\d+) steps,", line).group(1) != "0", line
half = 0.0005 + 1e-9
assert setup + steps + fin <= cpu + 4 * half, line
assert cpu <= num("the process so far") + 2 * half, line
assert abs(sum(parts) - steps) <= (len(parts) + 1) * half, (parts, steps)
assert num("traffic.s step") > 0 and num("decisions") > 0, line
print("profile adds up: CPU %.3f s, steps %.3f s, SUMO %.3f s" % (cpu, steps, parts[0]))
'
echo "ok: --profile says where the time went, results unchanged"
