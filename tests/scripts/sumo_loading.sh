# sumo_loading.sh - which commands load SUMO (issue 15): the commands that do
# not simulate never open its modules (the dynamic loader's own record,
# LD_DEBUG=files, names every library a process maps: libsumocpp must not be
# among them), and a run that simulates maps libsumocpp exactly once.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
# how many times the process (and its children) mapped libsumocpp
loads() {
  local rc=0
  LD_DEBUG=files LD_DEBUG_OUTPUT="$tmp/ld" "$FAIRWAY" "$@" > out 2>&1 || rc=$?
  [ "$rc" -le 2 ] || { echo "fairway $* died (exit $rc):"; head -5 out; exit 1; }
  cat "$tmp"/ld.* | grep -c 'file=libsumocpp\.so .*needed by' || true
  rm -f "$tmp"/ld.*
}
while IFS= read -r cmd; do
  # shellcheck disable=SC2086 # the command's words
  n=$(loads $cmd)
  [ "$n" -eq 0 ] || { echo "fairway $cmd loaded libsumocpp $n times"; exit 1; }
done <<LIST
--help
ship c3
manoeuvre report --ship c3
helm --ship c3 --own 0,0,0,10 --target 0,1800,180,10
identify --ship c3 --speeds 10 --rudders 10
calibrate --ship c3-paper --check
report nosuch.db
run --help
LIST
echo "non-simulating commands: no libsumocpp"
n=$(loads run "$FAIRWAY_DATA/scenarios/paper/1-head-on.yaml" --out runs)
grep -q "ok$" out || { echo "the run failed:"; cat out; exit 1; }
[ "$n" -eq 1 ] || { echo "a simulating run loaded libsumocpp $n times, not once"; exit 1; }
echo "ok: SUMO loaded only to simulate, once"
