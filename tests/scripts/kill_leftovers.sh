# kill_leftovers.sh - after a SIGKILL nothing of fairway's goes on, and what
# it was writing is cleaned up by the next command (issue 28 item 7):
# a `fairway run` killed mid-run leaves no worker running (an orphan would
# finish the scenario and write it into --out seconds later) and its
# .NAME.tmp.PID directory is removed by the next run into the same output; a
# sweep killed mid-way leaves its fairway-sweep-* work directory in $TMPDIR,
# which the next sweep removes.  A marked directory of a live process, and
# anything unmarked, is left alone.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# a day of Dover: long enough to be killed in the middle
sed 's/^  duration_s: .*/  duration_s: 86400/' "$FAIRWAY_DATA/scenarios/traffic/dover-crossing.yaml" \
  > "$tmp/long.yaml"
grep -q "duration_s: 86400" "$tmp/long.yaml" || { echo "no duration to lengthen"; exit 1; }
"$FAIRWAY" run "$tmp/long.yaml" --out "$tmp/out" > /dev/null 2>&1 &
pid=$!
for _ in $(seq 1 100); do
  ls -d "$tmp"/out/.*.tmp.* > /dev/null 2>&1 && break
  sleep 0.05
done
sleep 0.5
kill -9 $pid
wait $pid 2>/dev/null || true
sleep 1
if pgrep -f "run $tmp/long.yaml" > /dev/null; then
  echo "a fairway run process outlived the SIGKILL:"; pgrep -af "run $tmp/long.yaml"; exit 1
fi
left=$(ls -d "$tmp"/out/.*.tmp.* 2>/dev/null | wc -l)
[ "$left" -eq 1 ] || { echo "expected one leftover temporary directory, found $left"; exit 1; }
[ ! -e "$tmp/out/dover-crossing" ] || { echo "the killed run was written out"; exit 1; }
mkdir "$tmp/out/.mine.tmp.1"   # not fairway's (no owner mark): left alone
sed 's/^  duration_s: .*/  duration_s: 60/' "$tmp/long.yaml" > "$tmp/short.yaml"
"$FAIRWAY" run "$tmp/short.yaml" --out "$tmp/out" > /dev/null 2> "$tmp/err"
grep -q "removed $tmp/out/.dover-crossing.tmp.[0-9]*, left by an interrupted fairway run" "$tmp/err" ||
  { echo "no removal said:"; cat "$tmp/err"; exit 1; }
[ "$(ls -d "$tmp"/out/.dover-crossing.tmp.* 2>/dev/null | wc -l)" -eq 0 ] || { echo "leftover kept"; exit 1; }
[ -d "$tmp/out/.mine.tmp.1" ] || { echo "an unmarked directory was removed"; exit 1; }
echo "run: no orphan, leftover removed"

# a sweep, killed, in a TMPDIR of its own
mkdir "$tmp/t"
study=$FAIRWAY_DATA/tests/data/study/small.yaml
TMPDIR=$tmp/t "$FAIRWAY" sweep "$study" --db "$tmp/s.db" --jobs 2 --progress none &
pid=$!
for _ in $(seq 1 100); do
  ls -d "$tmp"/t/fairway-sweep-* > /dev/null 2>&1 && break
  sleep 0.02
done
kill -9 $pid
wait $pid 2>/dev/null || true
sleep 0.5
[ "$(ls -d "$tmp"/t/fairway-sweep-* 2>/dev/null | wc -l)" -eq 1 ] ||
  { echo "expected the killed sweep's work directory"; ls -la "$tmp/t"; exit 1; }
TMPDIR=$tmp/t "$FAIRWAY" sweep "$study" --db "$tmp/s.db" --jobs 2 --progress none 2> "$tmp/err" ||
  { cat "$tmp/err"; exit 1; }
grep -q "removed $tmp/t/fairway-sweep-.*, left by an interrupted sweep" "$tmp/err" ||
  { echo "no removal said:"; cat "$tmp/err"; exit 1; }
[ "$(ls -d "$tmp"/t/fairway-sweep-* 2>/dev/null | wc -l)" -eq 0 ] ||
  { echo "work directories left:"; ls -la "$tmp/t"; exit 1; }

# a report, killed while its plotter runs (a stand-in that sleeps): the
# plotter dies with it (it went on, then drew into the leftover), and the
# next report into the same place removes the .NAME.tmp.PID directory
printf '#!/bin/sh\necho $$ > "$2.plotter"\nexec sleep 60\n' > "$tmp/slowplot"
chmod +x "$tmp/slowplot"
FAIRWAY_PYTHON=$tmp/slowplot "$FAIRWAY" report "$tmp/s.db" --out "$tmp/rep" > /dev/null 2>&1 &
pid=$!
for _ in $(seq 1 200); do
  [ -s "$(ls "$tmp"/.rep.tmp.*.plotter 2>/dev/null | head -1)" ] && break
  sleep 0.02
done
plotter=$(cat "$tmp"/.rep.tmp.*.plotter 2>/dev/null) || { echo "the plotter did not start"; exit 1; }
kill -9 $pid
wait $pid 2>/dev/null || true
sleep 0.3
# gone, or a zombie (killed, not yet reaped by whatever adopted it)
state=$(awk '{print $3}' "/proc/$plotter/stat" 2>/dev/null || true)
[ -z "$state" ] || [ "$state" = Z ] || { kill "$plotter"; echo "the plotter outlived the report"; exit 1; }
"$FAIRWAY" report "$tmp/s.db" --out "$tmp/rep" --no-plots > /dev/null 2> "$tmp/err" ||
  { cat "$tmp/err"; exit 1; }
grep -q "removed $tmp/.rep.tmp.[0-9]*, left by an interrupted fairway report" "$tmp/err" ||
  { echo "no removal said:"; cat "$tmp/err"; exit 1; }
[ -z "$(ls -d "$tmp"/.rep.tmp.*[0-9] 2>/dev/null)" ] || { echo "report leftover kept"; exit 1; }
[ ! -e "$tmp/rep/.fairway-owner" ] || { echo "the owner mark is in the report"; exit 1; }
echo "ok: nothing outlives a SIGKILL, leftovers removed"
