#!/usr/bin/env python3
"""Writes the paper's five cases as the paper simulated them: fast time, with its own simplified model.

    python3 scenarios/paper/fast-time/generate.py      # rewrites the five YAML files here

Each file is its case in scenarios/paper/ (the same geometry, targets, domain reading and settings;
read each one's header there) with two differences, both from the paper's text:

  1. The own ship is the paper's Nomoto model, not an MMG ship: `ship: c3-paper` (its knowledge base is
     the paper's equations 10-13) with `dynamics: nomoto`, so each step moves it along equation 9's
     track, as the policy predicts it.  Section 4: "we examined simple and complex collision avoidance
     cases in fast-time simulations", the simulation model being "the simplified simulation model",
     whose step 4 obtains "the instantaneous trajectories of the own ship by substituting K, T1, T2, T3,
     U and delta into Equation (9)" (section 3, Figure 21).  The ship keeps its speed and has no drift
     angle, as equation 9's track has none.
  2. The give-way action is taken at the paper's point of action only: "the acting time of the rudder
     will be at least 1.0 nautical mile in advance of the own ship to the moving ships"
     (`act_range_nm: 1`), without fairway's own earlier trigger (`act_lookahead_s: 0`: act before the
     1 nm point only when waiting 10 s more would need more than the least helm; that rule is ours,
     rule 16's early action, not the paper's).

At 10 kn the paper's equations are extrapolated (fitted at 14.55-26.7 kn), as in the paper; the run says
so in run.log.  The MMG cases in scenarios/paper/ are the same encounters with a ship that drifts and
slows in the turn.
"""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.path.dirname(HERE)
CASES = ["1-head-on", "2-overtaking", "3-crossing", "4-head-on-complex", "5-crossing-complex"]

HEADER = """# Written by scenarios/paper/fast-time/generate.py from ../{case}.yaml (edit those, then run it).
# The paper's case as the paper simulated it: fast time with its own simplified model, the own
# ship stepped along equation 9's track (c3-paper, dynamics: nomoto) and acting at the paper's
# 1 nm point only (act_lookahead_s: 0).  Why each: generate.py.  The case itself:
#
"""


def convert(case):
    with open(os.path.join(SRC, case + ".yaml")) as f:
        text = f.read()
    # the MMG ship's paragraph of the header is not this file's
    text = re.sub(r"^# Own ship c3-paper-mmg:.*?(?=^[^#])", "", text, flags=re.M | re.S)
    out, n = re.subn(r"^name: (paper-\S+)$", r"name: \1-fast-time", text, flags=re.M)
    out, m = re.subn(r"^  ship: c3-paper-mmg$",
                     "  ship: c3-paper       # the paper's equations 10-13\n"
                     "  dynamics: nomoto     # stepped along equation 9's track", out, flags=re.M)
    out, k = re.subn(r"^(  act_range_nm: 1 .*)$",
                     r"\1\n  act_lookahead_s: 0   # no earlier action than the paper's 1 nm point",
                     out, flags=re.M)
    if (n, m, k) != (1, 1, 1):
        sys.exit(f"generate.py: {case}.yaml: name/ship/act_range_nm lines not as expected "
                 f"({n}, {m}, {k})")
    return HEADER.format(case=case) + out


def main():
    for case in CASES:
        path = os.path.join(HERE, case + ".yaml")
        tmp = path + ".tmp"
        with open(tmp, "w") as f:
            f.write(convert(case))
        os.replace(tmp, path)
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
