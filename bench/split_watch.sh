#!/usr/bin/env bash
# split_watch.sh - splitting on a fairway case at p about 1e-5 (issue 25's floor), checked
# against the case's exact answer and, at p about 1e-2, against crude Monte Carlo.
#
# The case: scenarios/watch/headon-watch.yaml, the own ship's watch detecting a head-on
# ship after an exponential time (mean detect_s).  Step 1 finds, with fixed decision delays
# instead of drawn detections (detect_s 0, delay_s D: deterministic runs), the first whole
# second of lateness that collides (k_c) and that makes a near miss (k_nm, hull to hull
# under 185.2 m), checking every D on the way; then P(event) = exp(-(k - 1) / detect_s).
# Step 2 sweeps scenarios/studies/headon-watch.yaml with more replications and batches:
# detect_s 92 s (p about 1e-5) and 230 s (p about 1e-2), crude Monte Carlo in both cells,
# splitting (20 particles) in both.  Step 3 writes the figures.
#
#   bench/split_watch.sh FAIRWAY [OUT.txt] [BATCHES] [REPLICATIONS] [JOBS]
# (KEEP_DB=FILE keeps the study's database; results: bench/results/split_watch.txt, taken with
# 40 batches, 1000 replications, 2 jobs: 38 min on 2 shared cores)
set -euo pipefail
fairway=$(realpath "$1")
out=${2:-/dev/stdout}
batches=${3:-16}
reps=${4:-1000}
jobs=${5:-2}
src=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export SUMO_HOME=${SUMO_HOME:-/usr/share/sumo}
scn=$src/scenarios/watch/headon-watch.yaml

# 1. the thresholds: the least hull distance for a decision delay of D s, detection at once
hull() {
  sed "s/watch: {detect_s: 92, own_ship: human}/watch: {delay_s: $1, own_ship: human}/" "$scn" \
    > "$tmp/d.yaml"
  rm -rf "$tmp/d"
  "$fairway" run "$tmp/d.yaml" --out "$tmp/d" > /dev/null
  python3 -c "import json,glob; print(json.load(open(glob.glob('$tmp/d/*/summary.json')[0]))['min_hull_distance_m'])"
}
: > "$tmp/scan"
for D in $(seq 960 1 1070) 1100 1200 1300 1400; do
  echo "$D $(hull "$D")" >> "$tmp/scan"
done

# 2. the study, more of it
sed -e "s/^replications: .*/replications: $reps/" \
    -e "s/batches: [0-9]*/batches: $batches/" \
    -e "s#^scenario: .*#scenario: $scn#" \
    "$src/scenarios/studies/headon-watch.yaml" > "$tmp/study.yaml"
t0=$(date +%s)
"$fairway" sweep "$tmp/study.yaml" --db "$tmp/s.db" --jobs "$jobs" --progress none > "$tmp/sweep.log" 2>&1
t1=$(date +%s)

# 3. the figures
[ -z "${KEEP_DB:-}" ] || cp "$tmp/s.db" "$KEEP_DB"
python3 "$src/bench/split_watch.py" "$tmp/scan" "$tmp/s.db" "$((t1 - t0))" "$jobs" > "$out"
