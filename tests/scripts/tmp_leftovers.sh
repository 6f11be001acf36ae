# tmp_leftovers.sh - a file's temporary that a SIGKILLed fairway left beside
# its output (issue 28 item 7) is removed by the next fairway writing into the
# same directory, and nothing else is.  Outputs are begun as
# DIR/.NAME.fairway-tmp.PID.XXXXXX (core/files.h); the leftovers here are made
# by that naming, their writers real processes: one that has ended (removed),
# this shell (alive: kept), one started after its file was last written (the
# id reused: removed), an ended one whose file a live process holds open
# (kept).  Names of any other form, a symlink and a directory of the form, and
# the file a symlink points to are left alone.
set -euo pipefail
tmp=$(mktemp -d)
trap 'exec 3<&- 2>/dev/null || true; kill "$sleeper" 2>/dev/null || true; rm -rf "$tmp"' EXIT
sleeper=
fail() { echo "FAIL: $*"; exit 1; }
dead_pid() { sh -c 'exit 0' & local p=$!; wait "$p"; echo "$p"; }
out=$tmp/out
mkdir "$out"
d1=$(dead_pid)
d2=$(dead_pid)
d3=$(dead_pid)
touch "$out/.t.csv.fairway-tmp.$d1.Ab3xYz"          # a killed writer's: removed
touch "$out/.other.csv.fairway-tmp.$d2.q1W2e3"      # another output's, same directory: removed
touch "$out/.t.csv.fairway-tmp.$$.Zz9Zz9"           # a live writer's: kept
touch -d '1 hour ago' "$out/.t.csv.fairway-tmp.PID.r3used"
sleep 30 & sleeper=$!                                 # started after the file was written
mv "$out/.t.csv.fairway-tmp.PID.r3used" "$out/.t.csv.fairway-tmp.$sleeper.r3used"
touch "$out/.t.csv.fairway-tmp.$d3.h3ld00"          # held open by this shell: kept
exec 3< "$out/.t.csv.fairway-tmp.$d3.h3ld00"
# not of the form, or not a file of this user's: kept
echo victim > "$tmp/victim"
keep=(t.csv.tmp.Ab3xYz ".t.csv.fairway-tmp.$d1.short" ".t.csv.fairway-tmp.x$d1.Ab3xYz"
      "t.csv.fairway-tmp.$d1.Ab3xYz" ".t.csv.fairway-tmp.$d1.Ab3xYz.bak" ".t.csv.tmp.$d1")
for k in "${keep[@]}"; do touch "$out/$k"; done
ln -s "$tmp/victim" "$out/.t.csv.fairway-tmp.$d1.l1nk00"
mkdir "$out/.t.csv.fairway-tmp.$d1.d1r000"
"$FAIRWAY" manoeuvre turning --ship c3 --speed 20 --rudder 35 --csv "$out/t.csv" > /dev/null 2> "$tmp/err" ||
  { cat "$tmp/err"; fail "manoeuvre --csv"; }
for f in ".t.csv.fairway-tmp.$d1.Ab3xYz" ".other.csv.fairway-tmp.$d2.q1W2e3" ".t.csv.fairway-tmp.$sleeper.r3used"; do
  [ ! -e "$out/$f" ] || fail "leftover $f kept"
  grep -qF "fairway: removed $out/$f, left by an interrupted fairway (process " "$tmp/err" ||
    fail "removal of $f not said: $(cat "$tmp/err")"
done
[ "$(grep -c removed "$tmp/err")" -eq 3 ] || fail "removals: $(cat "$tmp/err")"
for k in "${keep[@]}" ".t.csv.fairway-tmp.$$.Zz9Zz9" ".t.csv.fairway-tmp.$d3.h3ld00"; do
  [ -f "$out/$k" ] || fail "$k removed"
done
[ -L "$out/.t.csv.fairway-tmp.$d1.l1nk00" ] && [ "$(cat "$tmp/victim")" = victim ] || fail "the link or its target touched"
[ -d "$out/.t.csv.fairway-tmp.$d1.d1r000" ] || fail "a directory removed"
head -1 "$out/t.csv" | grep -q '^t_s,east_m' || fail "no csv written"
# the run's own temporary is of the form, and gone
[ -z "$(find "$out" -type f -printf '%f\n' | grep -E "^\.t\.csv\.fairway-tmp\.[0-9]+\.[A-Za-z0-9]{6}$" |
        grep -vE "\.($$|$d3)\.")" ] || fail "left: $(ls -a "$out")"
echo "file: leftovers removed, the rest kept"

# a stream's temporary is in TMPDIR (--csv -), its leftovers removed there
mkdir "$tmp/t"
touch "$tmp/t/.fairway-out.fairway-tmp.$d1.Ab3xYz" "$tmp/t/fairway-out.Ab3xYz"
TMPDIR=$tmp/t "$FAIRWAY" manoeuvre turning --ship c3 --speed 20 --rudder 35 --csv - > "$tmp/csv" 2> "$tmp/err" ||
  { cat "$tmp/err"; fail "manoeuvre --csv -"; }
grep -q '^t_s,east_m' "$tmp/csv" || fail "nothing printed"
[ "$(ls -A "$tmp/t")" = fairway-out.Ab3xYz ] || fail "TMPDIR holds: $(ls -A "$tmp/t")"
grep -qF "removed $tmp/t/.fairway-out.fairway-tmp.$d1.Ab3xYz" "$tmp/err" || fail "not said: $(cat "$tmp/err")"
echo "ok: leftover temporaries removed, nothing else touched"
