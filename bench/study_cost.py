#!/usr/bin/env python3
"""study_cost.py - a study's CPU per simulated own-ship hour against SUMO alone (issue 25 item 5).

A: `fairway sweep` of the default study cut to REPS replications of one domain (dover-domain.yaml:
the C-3 crossing the Dover scheme, one hour a run), --jobs 1, its runs kept; CPU = user + system of
the sweep and every process it forked (RUSAGE_CHILDREN), divided by the simulated own-ship hours the
database holds.  B: `sumo -c RUN/sumo/run.sumocfg` for each run the sweep kept (the same network,
routes and options fairway gave SUMO: the same traffic), CPU per simulated hour.  ROUNDS rounds, A and
B interleaved; the ratio is taken within each round (the host's load moves both), its median reported.

    bench/study_cost.py FAIRWAY [ROUNDS [REPS [DURATION_S]]]   (CSV rows, then a summary on stderr)

With DURATION_S 60 the runs are a minute long: what is left is each run's fixed cost (fairway: a
forked process, SUMO's simulation started, network and routes read, records opened, the database;
sumo: a process, its libraries loaded, network and routes read), the most that keeping SUMO loaded
across runs could save.
"""
import os
import re
import resource
import sqlite3
import statistics
import subprocess
import sys
import tempfile

fairway = os.path.abspath(sys.argv[1])
rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 5
reps = int(sys.argv[3]) if len(sys.argv) > 3 else 4
duration = int(sys.argv[4]) if len(sys.argv) > 4 else 3600  # s a run (60: the fixed cost of a run)
src = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
os.environ.setdefault("SUMO_HOME", "/usr/share/sumo")


def cpu(cmd, **kw):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, **kw)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


with tempfile.TemporaryDirectory() as tmp:
    study = open(os.path.join(src, "scenarios/studies/dover-domain.yaml")).read()
    study = re.sub(r"(?m)^replications: .*", "replications: %d" % reps, study)
    study = re.sub(r"(?m)^domains_m: .*", "domains_m: [300]", study)
    study = re.sub(r"(?m)^duration_s: .*", "duration_s: %d" % duration, study)
    study = re.sub(r"(?m)^scenario: \.\./", "scenario: %s/scenarios/" % src, study)
    path = os.path.join(tmp, "study.yaml")
    open(path, "w").write(study)
    print("round,fairway_cpu_s,fairway_sim_h,fairway_cpu_per_h,sumo_cpu_s,sumo_sim_h,sumo_cpu_per_h,ratio")
    ratios, fa, sb = [], [], []
    for k in range(rounds):
        db, keep = os.path.join(tmp, "s%d.db" % k), os.path.join(tmp, "keep%d" % k)
        a = cpu([fairway, "sweep", path, "--db", db, "--jobs", "1", "--keep", keep,
                 "--progress", "none"])
        sim_h = sqlite3.connect(db).execute(
            "select sum(sim_s) from runs where status = 'ok'").fetchone()[0] / 3600
        cfgs = sorted(os.path.join(r, d, "sumo", "run.sumocfg") for r, ds, _ in os.walk(keep)
                      for d in ds if os.path.exists(os.path.join(r, d, "sumo", "run.sumocfg")))
        b = 0.0
        for c in cfgs:
            b += cpu(["sumo", "-c", c, "--no-step-log", "true", "--duration-log.disable", "true"],
                     cwd=os.path.dirname(c))
        b_h = sum(float(re.search(r'<end value="([0-9.]+)"', open(c).read()).group(1))
                  for c in cfgs) / 3600
        ratio = (a / sim_h) / (b / b_h)
        ratios.append(ratio)
        fa.append(a / sim_h)
        sb.append(b / b_h)
        print("%d,%.3f,%.3f,%.4f,%.3f,%.3f,%.4f,%.3f" % (k, a, sim_h, a / sim_h, b, b_h, b / b_h,
                                                       ratio), flush=True)
    print("runs of %d s: study CPU per own-ship hour %.3f s (median of %d rounds), sumo alone %.3f s per hour, "
          "ratio %.2f (median; %.2f..%.2f)" % (duration, statistics.median(fa), rounds, statistics.median(sb),
                                               statistics.median(ratios), min(ratios), max(ratios)),
          file=sys.stderr)
