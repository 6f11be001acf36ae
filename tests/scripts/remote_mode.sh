# remote_mode.sh - `fairway run --sumo remote:HOST:PORT` end to end with a sumo
# started from the command fairway writes (sumo/remote-command.txt):
#   1. nothing listening: exit 1 naming remote-command.txt, no libtraci retry
#      noise on the terminal, the command file in the kept run directory;
#   2. a sumo started with that command: the run's results equal the embedded
#      run's byte for byte;
#   3. a sumo started with another scenario's command (another network): refused,
#      "runs another network", exit 1.
set -uo pipefail
tmp=$(mktemp -d)
pids=()
trap 'for p in "${pids[@]}"; do kill "$p" 2> /dev/null; done; rm -rf "$tmp"' EXIT
port() { "$PYTHON" -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }
scn=$FAIRWAY_DATA/scenarios/paper/3-crossing.yaml
other=$FAIRWAY_DATA/scenarios/paper/1-head-on.yaml

p1=$(port)
rc=0
"$FAIRWAY" run "$scn" --sumo "remote:127.0.0.1:$p1" --out "$tmp/none" > "$tmp/out1" 2>&1 || rc=$?
cmdfile=$tmp/none/paper-3-crossing/sumo/remote-command.txt
[ "$rc" -eq 1 ] || { echo "no sumo: exit $rc, expected 1"; cat "$tmp/out1"; exit 1; }
grep -q "remote-command.txt" "$tmp/out1" || { echo "the error does not name remote-command.txt:"; cat "$tmp/out1"; exit 1; }
grep -q "Retrying" "$tmp/out1" && { echo "libtraci's retry noise on the terminal"; exit 1; }
[ -f "$cmdfile" ] || { echo "no $cmdfile"; exit 1; }
grep -q -- "--remote-port' '$p1'" "$cmdfile" || { echo "$cmdfile lacks --remote-port $p1:"; cat "$cmdfile"; exit 1; }
echo "no sumo: $(grep -o 'no SUMO at [^(]*' "$tmp/out1")"

# 2. the sumo the command file starts (in the kept directory of the failed run)
sh "$cmdfile" > "$tmp/sumo1.out" 2>&1 &
pids+=($!)
"$FAIRWAY" run "$scn" --sumo "remote:127.0.0.1:$p1" --out "$tmp/remote" > "$tmp/out2" 2>&1 \
  || { echo "remote run failed:"; cat "$tmp/out2" "$tmp/sumo1.out"; exit 1; }
"$FAIRWAY" run "$scn" --out "$tmp/embedded" > /dev/null 2>&1 || { echo "embedded run failed"; exit 1; }
for f in own.csv targets.csv encounters.csv summary.json; do
  cmp -s "$tmp/remote/paper-3-crossing/$f" "$tmp/embedded/paper-3-crossing/$f" \
    || { echo "remote $f differs from the embedded run's"; exit 1; }
done
echo "remote run = embedded run"

# 3. another scenario's sumo: another network
p2=$(port)
"$FAIRWAY" run "$other" --sumo "remote:127.0.0.1:$p2" --out "$tmp/other" > /dev/null 2>&1
sh "$tmp/other/paper-1-head-on/sumo/remote-command.txt" > "$tmp/sumo2.out" 2>&1 &
pids+=($!)
rc=0
"$FAIRWAY" run "$scn" --sumo "remote:127.0.0.1:$p2" --out "$tmp/wrong" > "$tmp/out3" 2>&1 || rc=$?
[ "$rc" -eq 1 ] && grep -q "runs another network" "$tmp/out3" \
  || { echo "a sumo on another network: exit $rc"; cat "$tmp/out3"; exit 1; }
echo "wrong network: $(grep -o 'runs another network.*' "$tmp/out3" | head -1)"
echo "ok: remote mode"
