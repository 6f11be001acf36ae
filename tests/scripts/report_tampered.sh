# fairway report and fairway worst refuse a tampered study database (db_check.h):
# exit 2, one line naming the table, the row, the run and the column, nothing
# written; the untampered database reports exactly as a copy of it that was
# tampered with and put back.   Usage: report_tampered.sh MAKE_STUDY_DB
set -u
make_db=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
"$make_db" hand "$dir/hand.db" || fail "make_study_db hand"
(cd "$dir" && "$FAIRWAY" report hand.db --out clean --no-plots >/dev/null 2>&1) || fail "clean report"

# tampered SQL PATTERN [CMD]: a fresh copy of hand.db with SQL run on it is refused by
# fairway CMD (report, or worst) with exit 2 and one line matching PATTERN
n=0
tampered() {
  local sql=$1 pattern=$2 cmd=${3:-report}
  n=$((n + 1))
  local db="$dir/t$n.db"
  cp "$dir/hand.db" "$db"
  "$make_db" exec "$db" "$sql" || fail "tampering: $sql"
  out=$("$FAIRWAY" "$cmd" "$db" --out "$dir/out" 2>&1)
  rc=$?
  [ "$rc" -eq 2 ] || fail "$cmd exit $rc, expected 2 after '$sql': $out"
  [ "$(wc -l <<<"$out")" -eq 1 ] || fail "more than one line after '$sql': $out"
  grep -Fq -- "t$n.db: $pattern" <<<"$out" || fail "after '$sql': '$out' does not say '$pattern'"
  [ ! -e "$dir/out" ] || fail "$cmd wrote its output after '$sql'"
  return 0
}
enc="table encounters, row"
runs="table runs, row"
# negative rates: a count of manoeuvres, a count of helm orders below 0
tampered "UPDATE runs SET n_actions = -3 WHERE run_id = 2" \
  "$runs 2 (run synthetic-000002), column n_actions: -3 is not a count (must be >= 0)"
tampered "UPDATE runs SET helm_orders = -1 WHERE run_id = 4" \
  "$runs 4 (run synthetic-000004), column helm_orders: -1 is not a count (must be >= 0)"
# -inf and inf (9e999 is how SQL writes them); -inf or 1e30 in a count of two runs
# of a group was UBSan's signed overflow summing their events (report_stats.c)
tampered "UPDATE runs SET n_actions = -9e999 WHERE run_id IN (1, 2)" \
  "$runs 1 (run synthetic-000001), column n_actions: -inf is not a count"
tampered "UPDATE runs SET helm_orders = 1e30 WHERE run_id IN (1, 2)" \
  "$runs 1 (run synthetic-000001), column helm_orders: 1e+30 is not a count (at most 1000000000)"
tampered "UPDATE encounters SET min_dist_m = -9e999 WHERE rowid = 5" \
  "$enc 5 (run synthetic-000001), column min_dist_m: -inf is not a distance"
tampered "UPDATE runs SET path_lengthening_m = 9e999 WHERE run_id = 0" \
  "$runs 0 (run synthetic-000000), column path_lengthening_m: inf is not a distance"
tampered "UPDATE traffic_encounters SET min_dist_m = -1 WHERE rowid = 3" \
  "table traffic_encounters, row 3 (run synthetic-000000), column min_dist_m: -1 is not a distance (must be >= 0)"
# NaN: SQLite stores no NaN as a number, so it arrives as text
tampered "UPDATE runs SET time_lost_s = 'NaN' WHERE run_id = 3" \
  "$runs 3 (run synthetic-000003), column time_lost_s: 'NaN' is text, not a time"
# text in a number column is refused, not read as 0
tampered "UPDATE encounters SET min_dist_m = 'far' WHERE rowid = 2" \
  "$enc 2 (run synthetic-000000), column min_dist_m: 'far' is text, not a distance"
tampered "UPDATE runs SET sim_s = 'half an hour' WHERE run_id = 5" \
  "$runs 5 (run synthetic-000005), column sim_s: 'half an hour' is text, not a simulated time"
# a finished run without its exposure, or with one so short its rates overflow
tampered "UPDATE runs SET sim_s = 0 WHERE run_id = 5" \
  "$runs 5 (run synthetic-000005), column sim_s: 0 s in a finished run (status ok; at least 0.001 s)"
tampered "UPDATE runs SET sim_s = NULL WHERE run_id = 5" \
  "$runs 5 (run synthetic-000005), column sim_s: missing in a finished run"
tampered "UPDATE runs SET sim_s = 1e-300 WHERE run_id = 5" \
  "$runs 5 (run synthetic-000005), column sim_s: 1e-300 s in a finished run"
# a distance no encounter can have
tampered "UPDATE encounters SET min_dist_m = 1e300 WHERE rowid = 3" \
  "$enc 3 (run synthetic-000000), column min_dist_m: 1e+300 is not a distance (at most 100000000)"
# the reference domain: 0 and -300 m
tampered "UPDATE runs SET domain_m = 0 WHERE domain_m = 100" \
  "$runs 0 (run synthetic-000000), column domain_m: 0 is not a domain size (must be > 0)"
tampered "UPDATE runs SET domain_m = -300 WHERE domain_m = 100" \
  "$runs 0 (run synthetic-000000), column domain_m: -300 is not a domain size (must be > 0)"
# replications beyond what the study says, or any study could
tampered "UPDATE runs SET replication = 1000000 WHERE run_id = 1" \
  "$runs 1 (run synthetic-000001), column replication: 1000000 is not a replication (at most 999999)"
tampered "INSERT INTO meta VALUES('replications', '3'); UPDATE runs SET replication = 3 WHERE run_id = 4" \
  "$runs 4 (run synthetic-000004), column replication: 3 is not a replication of this study (meta says 3 replications)"
tampered "INSERT INTO meta VALUES('replications', 'many')" \
  "table meta, row 4 (key replications), column value: 'many' is not a number of replications"
# a run the study does not have
tampered "INSERT INTO meta VALUES('runs', '7'); UPDATE encounters SET run_id = 9 WHERE rowid = 6" \
  "$enc 6 (run synthetic-000009), column run_id: 9 is not a run id of this study (meta says 7 runs)"
tampered "UPDATE encounters SET run_id = -4 WHERE rowid = 6" \
  "$enc 6, column run_id: -4 is not a run id (must be >= 0)"
# a boolean of 2, a count that is not whole, a count too large to sum exactly
tampered "UPDATE encounters SET collision = 2 WHERE rowid = 6" \
  "$enc 6 (run synthetic-000001), column collision: 2 is not a flag (0 or 1)"
tampered "UPDATE runs SET near_miss = 2 WHERE run_id = 3" \
  "$runs 3 (run synthetic-000003), column near_miss: 2 is not a flag (0 or 1)"
tampered "UPDATE runs SET n_encounters = 2.5 WHERE run_id = 3" \
  "$runs 3 (run synthetic-000003), column n_encounters: 2.5 is not a count (not an integer)"
tampered "UPDATE runs SET helm_orders = 1e18 WHERE run_id = 3" \
  "$runs 3 (run synthetic-000003), column helm_orders: 1e+18 is not a count (at most 1000000000)"
# a blob where text is meant, a control character shown as ?
tampered "UPDATE encounters SET situation = x'00ff' WHERE rowid = 1" \
  "$enc 1 (run synthetic-000000), column situation: a blob is not text"
tampered "UPDATE encounters SET min_hull_m = 'a' || char(10) || 'b' WHERE rowid = 1" \
  "$enc 1 (run synthetic-000000), column min_hull_m: 'a?b' is text, not a distance"
# names the report counts by
tampered "UPDATE encounters SET situation = 'sideways' WHERE rowid = 4" \
  "$enc 4 (run synthetic-000000), column situation: 'sideways' is not one of head-on, overtaking, being overtaken, crossing give-way, crossing stand-on"
tampered "UPDATE traffic_encounters SET type = 'zigzag' WHERE rowid = 1" \
  "table traffic_encounters, row 1 (run synthetic-000000), column type: 'zigzag' is not one of head-on, overtaking, crossing"
tampered "UPDATE encounters SET candidate = 1, outcome = 'sunk' WHERE rowid = 2" \
  "$enc 2 (run synthetic-000000), column outcome: 'sunk' is not one of collision, near miss, domain, passed"
# meta: its numbers as the sweep writes them, its texts one printable line
# (each was printed into report.md, or named the runs, with exit 0)
meta="table meta, row"
tampered "INSERT INTO meta VALUES('duration_s', '-5')" \
  "$meta 4 (key duration_s), column value: '-5' is not a duration (above 0, at most 1000000000)"
tampered "UPDATE meta SET value = 'abc' WHERE key = 'near_miss_m'" \
  "$meta 3 (key near_miss_m), column value: 'abc' is not a distance (above 0"
tampered "INSERT INTO meta VALUES('domains_m', '-200,800')" \
  "$meta 4 (key domains_m), column value: '-200,800' is not a list of domain sizes"
tampered "UPDATE meta SET value = '' WHERE key = 'study_name'" \
  "$meta 2 (key study_name), column value: an empty study name (it names the runs)"
tampered "UPDATE meta SET value = 'a' || char(10) || 'b' WHERE key = 'study_name'" \
  "$meta 2 (key study_name), column value: 'a?b' holds a control character (byte 0x0a at 2)"
# texts of runs: an escape sequence reached the terminal, a line break split the warning
tampered "UPDATE runs SET setting = 'x' || char(27) || '[2J' WHERE run_id = 1" \
  "$runs 1 (run synthetic-000001), column setting: 'x?[2J' holds a control character (byte 0x1b at 2)"
tampered "UPDATE runs SET behaviour = 'a' || char(10) || 'b' WHERE run_id = 1" \
  "$runs 1 (run synthetic-000001), column behaviour: 'a?b' holds a control character"
# a seed no study draws, a helm beyond any rudder, a run longer than the study's
tampered "UPDATE runs SET seed = -1 WHERE run_id = 2" \
  "$runs 2 (run synthetic-000002), column seed: -1 is not a run's seed (must be >= 1)"
tampered "UPDATE runs SET max_helm_deg = 1e9 WHERE run_id = 2" \
  "$runs 2 (run synthetic-000002), column max_helm_deg: 1000000000 is not a helm angle (at most 90)"
tampered "INSERT INTO meta VALUES('duration_s', '900.000')" \
  "$runs 0 (run synthetic-000000), column sim_s: 1800 s is longer than the study's runs (meta says duration_s 900)"
# fairway worst reads the same database: refused before any run is sailed
tampered "UPDATE encounters SET min_hull_m = -9e999 WHERE rowid = 3" \
  "$enc 3 (run synthetic-000000), column min_hull_m: -inf is not a distance" worst
tampered "UPDATE encounters SET target = x'01' WHERE rowid = 2" \
  "$enc 2 (run synthetic-000000), column target: a blob is not text" worst

# tampered and put back: the same report to the byte as the clean database
# (the same name, from its directory: report.md names the database as given)
mkdir "$dir/back" && cp "$dir/hand.db" "$dir/back/hand.db"
"$make_db" exec "$dir/back/hand.db" "UPDATE runs SET n_actions = -9e999 WHERE run_id = 1" || fail "tamper"
"$make_db" exec "$dir/back/hand.db" "UPDATE runs SET n_actions = 4 WHERE run_id = 1" || fail "restore"
(cd "$dir/back" && "$FAIRWAY" report hand.db --out out --no-plots >/dev/null 2>&1) || fail "restored report"
diff -r "$dir/clean" "$dir/back/out" >/dev/null || fail "the restored database reports differently"
echo "ok: $n tampered databases refused"
