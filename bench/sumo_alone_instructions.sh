#!/usr/bin/env bash
# sumo_alone_instructions.sh - bench_sumo_alone's comparison in instructions, which
# do not move with the machine's load as CPU seconds do (the same binary's CPU
# swings by half on this shared host): valgrind's callgrind counts every
# instruction a process and its children execute.  Programs, as bench_sumo_alone
# has them: A `fairway run` of the default study's base scenario (one hour), A0 a
# baseline fairway if given, B the sumo binary stepping the route file A wrote
# with the options fairway gives SUMO, W the same with SUMO's collision check on,
# L SUMO through fairway's libsumo module alone.  Instructions are not time (a
# cache miss costs more than an add), so this is the second view, not the floor.
#
#   bench/sumo_alone_instructions.sh [CSV_FILE|- [FAIRWAY [BASELINE_FAIRWAY]]]
#   (run from the checkout; default FAIRWAY build/fairway; each program once,
#   about 20 s each under callgrind)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:--}
fw=${2:-build/fairway}
base=${3:-}
command -v valgrind > /dev/null || { echo "$0: needs valgrind (apt-get install valgrind)" >&2; exit 2; }
bench=$(dirname "$fw")/bench/bench_sumo_alone
[ -x "$bench" ] || bench=build/bench/bench_sumo_alone
[ -x "$fw" ] && [ -x "$bench" ] || { echo "$0: no $fw or $bench: build first" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
scn=scenarios/traffic/dover-crossing.yaml

# instructions of a command and every process it forks
count() {
  local tag=$1; shift
  valgrind --tool=callgrind --trace-children=yes --callgrind-out-file="$tmp/cg.$tag.%p" \
    "$@" > /dev/null 2> "$tmp/$tag.err" || { cat "$tmp/$tag.err" >&2; exit 1; }
  grep -h 'Collected :' "$tmp/$tag.err" | awk '{s += $NF} END {printf "%.0f", s}'
}

a=$(count fairway "$fw" run "$scn" --out "$tmp/a")
rou="$tmp/a/dover-crossing/sumo/demand.rou.xml"
net=$(sed -n 's/.*<net-file value="\([^"]*\)".*/\1/p' "$tmp/a/dover-crossing/sumo/run.sumocfg")
args=(--net-file "$net" --route-files "$rou" --additional-files networks/ships.add.xml
      --step-length 1 --seed 1 --time-to-teleport -1 --collision.action none
      --lanechange.duration 2800 --no-step-log true --duration-log.disable true --end 3600
      --log /dev/null)
b=$(count sumo sumo "${args[@]}")
warn=("${args[@]}")
for i in "${!warn[@]}"; do [ "${warn[$i]}" = none ] && warn[$i]=warn; done
w=$(count sumo_warn sumo "${warn[@]}")
l=$(count libsumo "$bench" --libsumo-only sumo "${args[@]}")
a0=
[ -z "$base" ] || a0=$(count baseline "$base" run "$scn" --out "$tmp/a0")

{
  echo "program,instructions"
  echo "fairway,$a"
  [ -z "$a0" ] || echo "baseline,$a0"
  echo "sumo,$b"
  echo "sumo_collision_check,$w"
  echo "libsumo,$l"
} > "$tmp/table.csv"
if [ "$out" = - ]; then cat "$tmp/table.csv"; else cp "$tmp/table.csv" "$out"; fi
awk -F, -v a="$a" -v b="$b" -v w="$w" -v l="$l" -v a0="$a0" 'END {
  printf "fairway/sumo %.2f  fairway/libsumo %.2f  fairway/sumo with its collision check %.2f  that/sumo %.2f\n",
         a / b, a / l, a / w, w / b
  if (a0 != "") printf "fairway/baseline %.2f  baseline/sumo %.2f\n", a / a0, a0 / b
}' /dev/null >&2
