# fairway report on a synthetic study (make_study_db random): tables, the five
# PNGs, report.md embedding them, --json; then plotting that fails (exit 1,
# tables kept) and --no-plots.   Usage: report_plots.sh MAKE_STUDY_DB
set -u
make_db=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
"$make_db" random "$dir/study.db" 7 || fail "make_study_db"

out=$("$FAIRWAY" report "$dir/study.db" 2>&1) || fail "exit $?: $out"
rep="$dir/study-report"
for f in summary.csv traffic.csv paired.csv cpa.csv cpa_hist.csv runs.csv report.md \
         rates.png encounter_types.png cpa_hist.png traffic.png paired.png; do
  [ -s "$rep/$f" ] || fail "$f missing or empty"
done
for f in "$rep"/*.png; do
  [ "$(head -c 8 "$f" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || fail "$f is not a PNG"
done
[ ! -e "$rep/plot.log" ] || fail "plot.log left after plots that worked"
for f in rates encounter_types cpa_hist traffic paired; do
  grep -q "]($f.png)" "$rep/report.md" || fail "report.md does not embed $f.png"
done
grep -q "^density,behaviour,domain_m,fore_aft_ratio,measure,n,mean,sd,ci_low,ci_high,method$" "$rep/summary.csv" || fail "summary.csv header"
# 4 domain sizes x 2 densities, 23 own-ship measures each
[ "$(tail -n +2 "$rep/summary.csv" | wc -l)" -eq 184 ] || fail "summary.csv rows: $(wc -l < "$rep/summary.csv")"
grep -q "47 finished and counted, 2 failed, 49 in the database" "$rep/report.md" || fail "run counts"
ls -a "$dir" | grep -q '\.tmp\.' && fail "temporary directory left behind"

# --json is one JSON object with a group per setting
"$FAIRWAY" report "$dir/study.db" --out "$dir/j" --no-plots --json > "$dir/j.json" || fail "--json exit $?"
"$PYTHON" -c "
import json, sys
d = json.load(open(sys.argv[1]))
assert d['runs_ok'] == 47 and d['runs_failed'] == 2 and d['plots'] == 'skipped', d
assert len(d['groups']) == 8 and d['reference_m'] == 100
g = d['groups'][0]['encounters_per_h']
assert g['ci_low'] <= g['mean'] <= g['ci_high']
" "$dir/j.json" || fail "--json content"
ls "$dir/j"/*.png >/dev/null 2>&1 && fail "--no-plots drew PNGs"

# plotting that fails: exit 1, says so, keeps the tables and report.md
out=$(FAIRWAY_PYTHON=/bin/false "$FAIRWAY" report "$dir/study.db" --out "$dir/bad" 2>&1)
rc=$?
[ "$rc" -eq 1 ] || fail "failed plots: exit $rc, expected 1: $out"
grep -q "plotting failed" <<<"$out" || fail "no 'plotting failed' in: $out"
[ -s "$dir/bad/summary.csv" ] && grep -q "Plotting failed" "$dir/bad/report.md" || fail "tables not kept"

# --reference picks the comparison
"$FAIRWAY" report "$dir/study.db" --out "$dir/r" --no-plots --reference 600 >/dev/null || fail "--reference 600"
grep -q "^1,,100,,600,,manoeuvres_per_h," "$dir/r/paired.csv" || fail "paired.csv against 600 m"
echo "ok: report with plots, json, failed plots, reference"
