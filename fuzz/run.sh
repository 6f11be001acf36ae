#!/usr/bin/env bash
# fuzz/run.sh [SECONDS] [TARGET...] - build the libFuzzer targets and run each
# for SECONDS (default 60), one after the other, under ASan and UBSan.
#
#   targets: fuzz_yaml fuzz_ship fuzz_scenario fuzz_study fuzz_demand fuzz_ais fuzz_json (default all)
#   FUZZ_BUILD  build directory (default build/fuzz, configured with clang)
#   FUZZ_NICE   nice level of the fuzzers (default 19)
#
# Seeds are the shipped data files (ships, scenarios, studies, demands, AIS
# CSVs, DNV's situations: fuzz_ais uses fuzz/ais.dict, fuzz_json fuzz/json.dict, the others fuzz/yaml.dict)
# and the kept corpus fuzz/corpus/TARGET (the minimised inputs of the
# campaigns so far: fuzz/corpus/README.md); each target keeps what it finds in
# FUZZ_BUILD/corpus/TARGET, so a later run starts from there.  To keep a
# campaign's finds, merge them into the kept corpus (libFuzzer keeps the
# inputs that add coverage):
#   mkdir new && FUZZ_BUILD/fuzz/TARGET -merge=1 new fuzz/corpus/TARGET \
#     FUZZ_BUILD/corpus/TARGET && rm -r fuzz/corpus/TARGET && mv new fuzz/corpus/TARGET  Crashes, leaks and UB stop the target, leave the input
# in FUZZ_BUILD/artifacts/ and make this script exit 1.  Each target's
# figures (executions, coverage) are the last lines of FUZZ_BUILD/logs/TARGET.log.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_yaml fuzz_ship fuzz_scenario fuzz_study fuzz_demand fuzz_ais fuzz_json)
build=${FUZZ_BUILD:-build/fuzz}
nice_level=${FUZZ_NICE:-19}
export SUMO_HOME=${SUMO_HOME:-/usr/share/sumo}

CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFAIRWAY_FUZZ=ON >/dev/null
nice -n 10 cmake --build "$build" -j "$(nproc)" --target "${targets[@]}" >/dev/null

seed() { # seed TARGET DIR: the shipped files a target reads
  local t=$1 dir=$2 f
  rm -rf "$dir"; mkdir -p "$dir"
  case $t in
    fuzz_ship)     cp scenarios/ships/*.yaml "$dir"/; rm -f "$dir"/*-trial.yaml ;;
    fuzz_scenario) for f in scenarios/paper/*.yaml scenarios/imazu/*.yaml scenarios/traffic/*.yaml; do
                     cp "$f" "$dir/$(basename "$(dirname "$f")")-$(basename "$f")"; done ;;
    fuzz_study)    cp scenarios/studies/*.yaml "$dir"/ ;;
    fuzz_demand)   for f in networks/*/demand.yaml; do cp "$f" "$dir/$(basename "$(dirname "$f")").yaml"; done ;;
    fuzz_ais)      # first byte: the variant (fuzz_ais.c); the example cut to its first rows
                   for f in scenarios/ais/*.csv tests/data/ais/*.csv; do
                     for m in 0 2 6; do
                       { printf "\\$(printf %o $m)"; head -c 12000 "$f"; } > "$dir/$m-$(basename "$f")"; done; done ;;
    fuzz_json)     cp scenarios/dnv/*.json "$dir"/ ;;
    fuzz_yaml)     # first byte: which edits to try (all)
                   for f in scenarios/*/*.yaml networks/*/demand.yaml; do
                     { printf '\377'; cat "$f"; } > "$dir/$(basename "$(dirname "$f")")-$(basename "$f")"; done ;;
  esac
}

mkdir -p "$build/logs" "$build/artifacts"
status=0
for t in "${targets[@]}"; do
  seed "$t" "$build/seeds/$t"
  mkdir -p "$build/corpus/$t"
  echo "== $t: $seconds s"
  dict=fuzz/yaml.dict
  [ "$t" != fuzz_ais ] || dict=fuzz/ais.dict
  [ "$t" != fuzz_json ] || dict=fuzz/json.dict
  rc=0
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    nice -n "$nice_level" "$build/fuzz/$t" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 \
      -max_len=16384 -dict="$dict" -print_final_stats=1 \
      -artifact_prefix="$build/artifacts/$t-" "$build/corpus/$t" "$build/seeds/$t" \
      $( [ -d "fuzz/corpus/$t" ] && echo "fuzz/corpus/$t" ) \
      > "$build/logs/$t.log" 2>&1 || rc=$?
  grep -E "^#[0-9]+.*DONE|stat::number_of_executed_units|stat::peak_rss_mb" "$build/logs/$t.log" || true
  if [ $rc -ne 0 ]; then
    echo "$t: FAILED (exit $rc), see $build/logs/$t.log"
    grep -E "ERROR|SUMMARY|runtime error" "$build/logs/$t.log" | head -5 || true
    status=1
  fi
done
exit $status
