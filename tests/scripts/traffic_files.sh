#!/usr/bin/env bash
# fairway traffic writes, outside any output of its own, only the files its
# help names (issue 28, Files: "files fairway writes outside its outputs are
# named in the help"): run in an empty directory it leaves its route file,
# SUMO's log and run.sumocfg beside the log, each named in --help, and
# nothing else; with --log elsewhere run.sumocfg goes beside that log.
set -euo pipefail
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
help=$("$FAIRWAY" traffic --help)
mkdir "$dir/w"
(cd "$dir/w" && "$FAIRWAY" traffic --ships 5 --duration 20 --every 20 > /dev/null) || fail "traffic"
left=$(cd "$dir/w" && ls -A | sort | tr '\n' ' ')
[ "$left" = "fairway-traffic.log fairway-traffic.rou.xml run.sumocfg " ] || fail "written: $left"
for f in fairway-traffic.log fairway-traffic.rou.xml run.sumocfg; do
  grep -q "$f" <<<"$help" || fail "$f is not named in traffic --help"
done
mkdir "$dir/v" "$dir/v/logs"
(cd "$dir/v" && "$FAIRWAY" traffic --ships 5 --duration 20 --every 20 --log logs/t.log \
   --routes logs/t.rou.xml > /dev/null) || fail "traffic --log"
[ -z "$(ls -A "$dir/v" | grep -v '^logs$')" ] || fail "written in the working directory: $(ls -A "$dir/v")"
[ "$(ls -A "$dir/v/logs" | sort | tr '\n' ' ')" = "run.sumocfg t.log t.rou.xml " ] ||
  fail "beside the log: $(ls -A "$dir/v/logs")"
echo "ok: traffic writes only what its help names"
