# sweep_axes.sh - a study with an axis over a scenario key (the own ship's
# speed, 10 and 16 kn) run end to end: each run's setting is in the database,
# the setting acts (the own ship's track is 1.6 times as long at 16 kn as at
# 10 kn in the same replication, within 5%: calm water, the same start), the
# replications are paired across settings (the same seed), and the report
# shows the settings and their paired differences.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
study=$FAIRWAY_DATA/tests/data/study/axes-sweep.yaml
"$FAIRWAY" sweep "$study" --db "$tmp/a.db" --jobs 2 > "$tmp/out" 2>&1 ||
  { echo "sweep failed:"; cat "$tmp/out"; exit 1; }
"$PYTHON" - "$tmp/a.db" <<'PY'
import sqlite3, sys
db = sqlite3.connect(sys.argv[1])
rows = db.execute("SELECT run_id, replication, seed, setting, path_length_m FROM runs "
                  "WHERE status = 'ok' ORDER BY run_id").fetchall()
assert len(rows) == 4, rows
assert [r[3] for r in rows] == ["own_ship.speed_kn=10"] * 2 + ["own_ship.speed_kn=16"] * 2, rows
for rep in (0, 1):
    slow, fast = [r for r in rows if r[1] == rep]
    assert slow[2] == fast[2], (slow, fast)                # paired: one seed per replication
    ratio = fast[4] / slow[4]
    assert abs(ratio - 1.6) < 0.08, (rep, ratio)
meta = dict(db.execute("SELECT key, value FROM meta"))
assert meta["axes"] == "own_ship.speed_kn: 10, 16", meta.get("axes")
print("settings recorded and acting: path ratios",
      [round(r[4] / s[4], 3) for s, r in zip(rows[:2], rows[2:])])
PY
"$FAIRWAY" report "$tmp/a.db" --out "$tmp/rep" --no-plots > "$tmp/rout" 2>&1 ||
  { echo "report failed:"; cat "$tmp/rout"; exit 1; }
grep -q "^## Axes: each setting - the first (own_ship.speed_kn=10)" "$tmp/rep/report.md" ||
  { echo "no axes section"; cat "$tmp/rep/report.md"; exit 1; }
grep -q "| 3 | colregs; own_ship.speed_kn=16 | 300 | 2 |" "$tmp/rep/report.md" ||
  { echo "no row for the second setting's pairs"; grep -n "speed_kn" "$tmp/rep/report.md"; exit 1; }
head -1 "$tmp/rep/settings.csv" | grep -q "^setting,density,behaviour,domain_m" ||
  { echo "settings.csv:"; head -3 "$tmp/rep/settings.csv"; exit 1; }
grep -q '^own_ship.speed_kn=16,3,colregs,300' "$tmp/rep/summary.csv" ||
  { echo "summary.csv has no row of the second setting"; head -3 "$tmp/rep/summary.csv"; exit 1; }
echo "ok: axes swept, recorded, reported"
