#!/usr/bin/env bash
# The remote SUMO's timeouts are a setting (issue 28 item 2): with
# FAIRWAY_SUMO_TIMEOUT=1 a peer that accepts and never answers is given up
# after about 1 s (the default: 60 s), exit 1 naming the reply timeout; a bad
# value is refused naming the variable, exit 2, before anything is written.
set -u
dir=$(mktemp -d)
peer=
trap '[ -n "$peer" ] && kill $peer 2>/dev/null; rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
# a silent peer: accepts every connection, reads, never answers
"$PYTHON" -c '
import socket, sys, time
s = socket.socket(); s.bind(("127.0.0.1", 0)); s.listen(8)
print(s.getsockname()[1], flush=True)
conns = []
while True:
    c, _ = s.accept(); conns.append(c)
' > "$dir/port" &
peer=$!
for _ in $(seq 1 100); do [ -s "$dir/port" ] && break; sleep 0.02; done
port=$(cat "$dir/port")
[ -n "$port" ] || fail "no peer"
cd "$dir"
t0=$(date +%s%N)
out=$(FAIRWAY_SUMO_TIMEOUT=1 "$FAIRWAY" traffic --network channel --duration 10 \
        --sumo "remote:127.0.0.1:$port" 2>&1)
rc=$?
ms=$((($(date +%s%N) - t0) / 1000000))
[ $rc -eq 1 ] || fail "silent peer: exit $rc: $out"
grep -q "no answer for 1 s (the reply timeout)" <<<"$out" || fail "message: $out"
[ $ms -ge 900 ] && [ $ms -lt 8000 ] || fail "gave up after $ms ms, not about 1 s"
rm -f "$dir"/fairway-traffic* "$dir/run.sumocfg" "$dir/remote-command.txt"
for bad in abc 0 -5 1e9 nan; do
  out=$(FAIRWAY_SUMO_TIMEOUT=$bad "$FAIRWAY" traffic --network channel --duration 10 \
          --sumo "remote:127.0.0.1:$port" 2>&1)
  rc=$?
  [ $rc -eq 2 ] && grep -qF "FAIRWAY_SUMO_TIMEOUT '$bad': expected seconds, 0.1 to 86400" <<<"$out" ||
    fail "FAIRWAY_SUMO_TIMEOUT=$bad: exit $rc: $out"
done
[ -z "$(ls "$dir" | grep -v '^port$')" ] || fail "written: $(ls "$dir")"
echo "ok: the SUMO timeout is a setting (silent peer given up after $ms ms)"
