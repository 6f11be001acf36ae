"""study_db_digest.py DB: one SHA-256 over a study database's results.

The result tables' rows (runs, encounters, traffic_encounters; not meta,
which holds the input files' digest), in a fixed order, without the wall-clock columns (wall_s,
sumo_s), which differ from machine to machine by nature.  The sweep tests
compare it with tests/data/digests/study-small.txt (empty tables and unused optional
columns left out), so a redesign that should
not change results is checked to the byte.
"""
import hashlib
import sqlite3
import sys

TIMING = {"wall_s", "sumo_s"}
OPTIONAL = {"setting"}


def main():
    db = sqlite3.connect(f"file:{sys.argv[1]}?mode=ro", uri=True)
    h = hashlib.sha256()
    tables = [r[0] for r in db.execute(
        "SELECT name FROM sqlite_master WHERE type='table' AND name != 'meta' ORDER BY name")]
    for table in tables:
        cols = [r[1] for r in db.execute(f"PRAGMA table_info({table})") if r[1] not in TIMING]
        # a column a study did not use (runs.setting without axes: NULL in
        # every row) changes no result either
        cols = [c for c in cols if c not in OPTIONAL or db.execute(
            f"SELECT COUNT(*) FROM {table} WHERE {c} IS NOT NULL").fetchone()[0]]
        rows = db.execute(f"SELECT {','.join(cols)} FROM {table}").fetchall()
        if not rows:
            continue  # a table a study did not use (splits without estimate:) changes no result
        h.update(f"{table}:{','.join(cols)}\n".encode())
        for row in sorted(rows, key=repr):
            h.update((repr(row) + "\n").encode())
    print(h.hexdigest())


main()
