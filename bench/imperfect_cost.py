#!/usr/bin/env python3
"""imperfect_cost.py - the imperfect sea's cost (issue 24, "Cost": at most 1.25x), whole process.

A ("on"): scenarios/traffic/dover-crossing-imperfect.yaml in 1 nm fog (visibility_nm 1): the spring
tidal stream, AIS and radar sensing for the own ship and the reacting background ships, rule 19 and
19(e), the watch's crossing lapse.  B ("off"): the same file with no environment: section, sensing
perfect and no watch.  Each `fairway run` is one process; its CPU (user + system, RUSAGE_CHILDREN) is
taken for PAIRS pairs run A B A B ..., and the ratio A/B within each pair; the median of the pairs is
reported (the host's load moves both members of a pair alike), for the CPU and for each process's
wall time (which the load distorts more).  With --study the same for the study:
dover-imperfect cut to REPS replications a cell (4 cells) against the same study over the "off"
scenario with no axis and 2 REPS replications, `fairway sweep --jobs 2` into a fresh database each time.

    bench/imperfect_cost.py FAIRWAY [PAIRS [--study [REPS]]]     (one line a pair, then the medians)
"""
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time

fairway = os.path.abspath(sys.argv[1])
pairs = int(sys.argv[2]) if len(sys.argv) > 2 else 5
study = "--study" in sys.argv
reps = int(sys.argv[sys.argv.index("--study") + 1]) if study and len(sys.argv) > sys.argv.index("--study") + 1 else 5
src = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
os.environ.setdefault("SUMO_HOME", "/usr/share/sumo")


walls = []


def cpu(cmd):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    walls.append(time.perf_counter() - t0)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def scenarios(tmp):
    base = open(os.path.join(src, "scenarios/traffic/dover-crossing-imperfect.yaml")).read()
    on = re.sub(r"(?m)^  visibility_nm: 10", "  visibility_nm: 1", base)
    off = re.sub(r"(?ms)^environment:.*?(?=^# what)", "", base)
    off = re.sub(r"(?m)^sensing: .*$", "", off)
    off = re.sub(r"(?m)^  watch: .*$", "", off)
    paths = []
    for name, text in (("on", on), ("off", off)):
        text = text.replace("name: dover-crossing-imperfect", "name: imperfect-" + name)
        # the scenario's relative paths (none but the network's name) stay valid in tmp
        path = os.path.join(tmp, name + ".yaml")
        open(path, "w").write(text)
        paths.append(path)
    return paths


def studies(tmp, on_scn, off_scn):
    base = open(os.path.join(src, "scenarios/studies/dover-imperfect.yaml")).read()
    base = re.sub(r"(?m)^replications: .*", "replications: %d" % reps, base)
    on = re.sub(r"(?m)^scenario: .*", "scenario: " + os.path.join(src, "scenarios/traffic/dover-crossing-imperfect.yaml"), base)
    off = re.sub(r"(?m)^scenario: .*", "scenario: " + off_scn, base)
    off = re.sub(r"(?ms)^axes:.*", "", off)
    off = re.sub(r"(?m)^replications: .*", "replications: %d" % (2 * reps), off)
    paths = []
    for name, text in (("on", on), ("off", off)):
        path = os.path.join(tmp, "study-" + name + ".yaml")
        open(path, "w").write(text)
        paths.append(path)
    return paths


with tempfile.TemporaryDirectory() as tmp:
    on_scn, off_scn = scenarios(tmp)
    if study:
        on_st, off_st = studies(tmp, on_scn, off_scn)
    rows = []
    for i in range(pairs):
        if study:
            for p in ("a.db", "b.db"):
                if os.path.exists(os.path.join(tmp, p)):
                    os.remove(os.path.join(tmp, p))
            a = cpu([fairway, "sweep", on_st, "--db", os.path.join(tmp, "a.db"), "--jobs", "2"])
            b = cpu([fairway, "sweep", off_st, "--db", os.path.join(tmp, "b.db"), "--jobs", "2"])
        else:
            a = cpu([fairway, "run", on_scn, "--out", os.path.join(tmp, "runs")])
            b = cpu([fairway, "run", off_scn, "--out", os.path.join(tmp, "runs")])
        wa, wb = walls[-2], walls[-1]
        rows.append((a, b, a / b, wa, wb, wa / wb))
        print("pair %d: on %.3f s  off %.3f s  on/off %.3f   wall %.3f s  %.3f s  %.3f"
              % (i + 1, a, b, a / b, wa, wb, wa / wb), flush=True)
    med = lambda k: statistics.median(r[k] for r in rows)
    print("%s, median of %d pairs: on %.3f s CPU, off %.3f s, on/off %.3f (%.3f-%.3f)"
          % ("study" if study else "one run", pairs, med(0), med(1), med(2),
             min(r[2] for r in rows), max(r[2] for r in rows)))
    print("%s, median of %d pairs: wall on %.3f s, off %.3f s, on/off %.3f (%.3f-%.3f)"
          % ("study" if study else "one run", pairs, med(3), med(4), med(5),
             min(r[5] for r in rows), max(r[5] for r in rows)))
