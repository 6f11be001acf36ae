#!/usr/bin/env bash
# quickstart.sh main|test - install what is missing, build, then run the main job or the tests.
#
#   main  runs the default Monte Carlo study (scenarios/studies/dover-domain.yaml:
#         the C-3 crossing the Dover Strait scheme, 4 domain sizes x 20
#         replications of one simulated hour) into out/dover-domain.db and writes its
#         report (CSV, PNG, Markdown) into out/dover-domain-report/; before that it
#         prints the C-3 manoeuvring report (out/manoeuvres/) and runs the paper's five
#         encounter cases and the 22 Imazu cases (out/runs/, out/imazu.png)
#   test  builds twice (plain, and with AddressSanitizer + UndefinedBehaviorSanitizer)
#         and runs the whole ctest suite on both builds
# clang and libclang-rt-14-dev (libFuzzer's runtime) are for fuzz/run.sh.
# xvfb, xauth and python3-pil are for the sumo-gui screenshot test (tests/gui_tests.cmake).
set -euo pipefail
cd "$(dirname "$0")/.."

mode=${1:-main}
packages=(build-essential cmake pkg-config libyaml-dev libsundials-dev libsqlite3-dev sqlite3
          sumo sumo-tools python3 python3-matplotlib python3-pandas python3-numpy python3-yaml
          libopenmpi-dev openmpi-bin clang libclang-rt-14-dev xvfb xauth python3-pil
          libproj-dev libjansson-dev python3-jsonschema)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -q
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
export SUMO_HOME=${SUMO_HOME:-/usr/share/sumo}
jobs=$(nproc)

build() { # build DIR [cmake options...]
  local dir=$1; shift
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@" >/dev/null
  cmake --build "$dir" -j "$jobs"
}

case "$mode" in
  main)
    build build
    mkdir -p out/manoeuvres
    ./build/fairway manoeuvre report --ship c3 --csv-dir out/manoeuvres
    /usr/bin/python3 analysis/plot_manoeuvre.py out/manoeuvres/*.csv --trial c3 --out out/manoeuvres
    # the paper's five encounters and the 22 Imazu cases, with SUMO moving the targets
    ./build/fairway run scenarios/paper/*.yaml scenarios/paper/fast-time/*.yaml scenarios/imazu/*.yaml --out out/runs
    for run in out/runs/paper-*; do /usr/bin/python3 analysis/plot_run.py "$run" > /dev/null; done
    /usr/bin/python3 analysis/plot_imazu.py out/runs --out out/imazu.png
    # the default study: resumes if out/dover-domain.db already holds some runs
    study=(./build/fairway sweep scenarios/studies/dover-domain.yaml --db out/dover-domain.db)
    rc=0; "${study[@]}" || rc=$?
    if [ $rc -eq 2 ] && [ -f out/dover-domain.db ]; then
      # a database of an older version of the study cannot be resumed: keep it aside, start anew
      mv -f out/dover-domain.db out/dover-domain.db.old
      rm -f out/dover-domain.db-wal out/dover-domain.db-shm
      rc=0; "${study[@]}" || rc=$?
    fi
    [ $rc -ne 2 ] || exit 2
    [ $rc -eq 0 ] || echo "some runs failed (reasons in out/dover-domain.db, table runs); the report covers the others"
    ./build/fairway report out/dover-domain.db --out out/dover-domain-report
    echo "plots: out/manoeuvres/*.png, out/runs/paper-*/*.png, out/imazu.png"
    echo "study: out/dover-domain.db, report out/dover-domain-report/report.md"
    ;;
  test)
    build build
    (cd build && ctest --output-on-failure -j "$jobs")
    build build-asan -DFAIRWAY_SANITIZE=ON
    (cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
       ctest --output-on-failure -j "$jobs" -LE no_sanitize)
    ;;
  *)
    echo "usage: $0 main|test" >&2
    exit 2
    ;;
esac
