"""study_db_compare.py A.db B.db: do two study databases hold the same results?

Compares every table row by row, keyed and sorted, leaving out the wall-clock
columns (wall_s, sumo_s), which differ from machine to machine by nature.  Also
checks that each run is present exactly once and that no run is half there
(encounter rows without their run).  Prints the first differences; exit 1 if any.
"""
import sqlite3
import sys

TIMING = {"wall_s", "sumo_s"}


def dump(path):
    db = sqlite3.connect(f"file:{path}?mode=ro", uri=True)
    out = {}
    for table in ("runs", "encounters", "traffic_encounters"):
        cols = [r[1] for r in db.execute(f"PRAGMA table_info({table})") if r[1] not in TIMING]
        rows = db.execute(f"SELECT {','.join(cols)} FROM {table}").fetchall()
        out[table] = (cols, sorted(rows, key=repr))
    ids = [r[0] for r in db.execute("SELECT run_id FROM runs")]
    if len(ids) != len(set(ids)):
        sys.exit(f"{path}: a run is recorded twice")
    orphans = db.execute("SELECT COUNT(*) FROM encounters WHERE run_id NOT IN "
                         "(SELECT run_id FROM runs)").fetchone()[0]
    if orphans:
        sys.exit(f"{path}: {orphans} encounter rows without their run")
    total = db.execute("SELECT value FROM meta WHERE key='runs'").fetchone()
    return out, len(ids), int(total[0]) if total else None


def main():
    a, na, ta = dump(sys.argv[1])
    b, nb, tb = dump(sys.argv[2])
    bad = 0
    if na != nb or na != ta:
        print(f"run counts: {na} and {nb}, the study has {ta}")
        bad += 1
    for table in a:
        ca, ra = a[table]
        cb, rb = b[table]
        if ca != cb or ra != rb:
            bad += 1
            print(f"{table}: {len(ra)} and {len(rb)} rows differ")
            for x, y in zip(ra, rb):
                if x != y:
                    print("  ", dict(zip(ca, x)))
                    print("  ", dict(zip(cb, y)))
                    break
    if bad:
        sys.exit(1)
    print(f"same results: {na} runs, {len(a['encounters'][1])} encounters, "
          f"{len(a['traffic_encounters'][1])} traffic encounters")


main()
