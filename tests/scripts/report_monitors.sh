# The report's first lines say whether the traffic behaved like ships: a
# synthetic study with the monitors all zero, then with overlaps and a
# sideways jump in two runs (written into the database as a sweep would).
#   Usage: report_monitors.sh MAKE_STUDY_DB
set -u
make_db=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
"$make_db" random "$dir/study.db" 7 || fail "make_study_db"
sqlite3 "$dir/study.db" "UPDATE runs SET behaviour = 'colregs', give_way = 3, give_way_short = 0,
  mon_sideways = 0, mon_teleport = 0, mon_overlap = 0, mon_appear = 0, mon_vanish = 0,
  mon_start_close = 0, mon_stopped = 0, max_lateral_mps = 0.9 WHERE status = 'ok'" || fail "sqlite3"
"$FAIRWAY" report "$dir/study.db" --out "$dir/a" --no-plots >/dev/null 2>&1 || fail "report a"
sed -n 3p "$dir/a/report.md" | grep -q "^Traffic monitors: in none of the 47 runs" ||
  fail "clean traffic: $(sed -n 3p "$dir/a/report.md")"
grep -q "^Background ships: colregs (141 give-way speed orders in all)" "$dir/a/report.md" ||
  fail "behaviour line"
sqlite3 "$dir/study.db" "UPDATE runs SET mon_overlap = 2 WHERE run_id = (SELECT MIN(run_id) FROM runs WHERE status = 'ok');
  UPDATE runs SET mon_sideways = 1, max_lateral_mps = 900 WHERE run_id = (SELECT MAX(run_id) FROM runs WHERE status = 'ok')" || fail "sqlite3"
"$FAIRWAY" report "$dir/study.db" --out "$dir/b" --no-plots >/dev/null 2>&1 || fail "report b"
sed -n 3p "$dir/b/report.md" | grep -q "^\*\*Warning: the background traffic did what no ship can do\*\* in 2 of 47 runs: 1 sideways jumps, 2 overlaps of background hulls (largest sideways speed 900.00 m/s)" ||
  fail "warning: $(sed -n 3p "$dir/b/report.md")"
echo "ok: the report says whether the traffic behaved"
