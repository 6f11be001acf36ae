"""layers.py SRC: every #include in SRC keeps the modules' layers.

A module is a directory of SRC.  LAYERS lists them from the bottom up; the
modules on one line are peers.  A file may include its own module and any
module on a lower line, never a peer or a module above: a peer or upward
include is printed as file:line with both modules and the script exits 1.
Every quoted include must name its module ("dynamics/mmg.h"), so none can
slip past the check; a directory of SRC missing from the table also fails,
so a new module has to be given its place.  The module graph is then searched
for cycles on its own (a cycle would need an upward include, but the check
does not rest on the table being right).

Prints "layers kept: N includes across M modules" when all is well.
"""
import pathlib
import re
import sys

# Bottom up.  Peers (one line) may not include each other: the order within a
# line means nothing.  Derived from the includes of issue 23's tree:
#   geom, yaml       plane geometry / YAML tree: each needs only core
#   ship             ship files (yaml)
#   env, sense       wind and current fields of the world (geom, ship); what a
#                    ship knows of the others (targets, core's streams)
#   dynamics, nomoto, traffic
#                    the two ship models never see each other (the cycle
#                    calibrate/identify made is why fit exists); traffic
#                    needs only ships and geometry
#   fit, avoid, ais  fit uses both models; avoid predicts with Nomoto; ais
#                    feeds the track source (traffic)
#   audit, survey, world
#                    audit and survey judge encounters (avoid); the world
#                    steps dynamics, avoid and traffic
#   scenario         loads a world's set-up (world, audit, survey, ais)
#   run, study, cli  each on the one below
LAYERS = [
    ["core"],
    ["geom", "yaml"],
    ["ship"],
    ["env", "sense"],
    ["dynamics", "nomoto", "traffic"],
    ["fit", "avoid", "ais"],
    ["audit", "survey", "world"],
    ["scenario"],
    ["run"],
    ["study"],
    ["cli"],
]

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]*)"')
SOURCES = (".c", ".h", ".cpp", ".hpp")


def level_of():
    level = {}
    for i, line in enumerate(LAYERS):
        for m in line:
            level[m] = i
    return level


def find_cycle(graph):
    """One cycle of the module graph as a list of modules, or None."""
    state = {}
    stack = []

    def visit(m):
        state[m] = 1
        stack.append(m)
        for n in sorted(graph.get(m, ())):
            if state.get(n) == 1:
                return stack[stack.index(n):] + [n]
            if n not in state:
                c = visit(n)
                if c:
                    return c
        stack.pop()
        state[m] = 2
        return None

    for m in sorted(graph):
        if m not in state:
            c = visit(m)
            if c:
                return c
    return None


def main():
    root = pathlib.Path(sys.argv[1])
    level = level_of()
    errors = []
    graph = {}
    count = 0
    modules = sorted(p.name for p in root.iterdir() if p.is_dir())
    for m in modules:
        if m not in level:
            errors.append(f"{m}/: a module missing from the table of layers (tests/scripts/layers.py)")
    for path in sorted(root.rglob("*")):
        if path.suffix not in SOURCES or not path.is_file():
            continue
        rel = path.relative_to(root)
        if len(rel.parts) < 2:
            continue
        mod = rel.parts[0]
        for n, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            count += 1
            target = m.group(1)
            parts = target.split("/")
            if len(parts) != 2 or parts[0] not in modules:
                errors.append(f'{rel}:{n}: "{target}" does not name a module of src ("module/file.h")')
                continue
            dep = parts[0]
            if dep == mod:
                continue
            graph.setdefault(mod, set()).add(dep)
            if mod not in level or dep not in level:
                continue
            if level[dep] == level[mod]:
                errors.append(f"{rel}:{n}: {mod} includes its peer {dep} ({target})")
            elif level[dep] > level[mod]:
                errors.append(f"{rel}:{n}: {mod} includes {dep}, a layer above it ({target})")
    cycle = find_cycle(graph)
    if cycle:
        errors.append("module cycle: " + " -> ".join(cycle))
    for e in errors:
        print(e)
    if errors:
        print(f"{len(errors)} broken")
        return 1
    print(f"layers kept: {count} includes across {len(modules)} modules")
    return 0


if __name__ == "__main__":
    sys.exit(main())
