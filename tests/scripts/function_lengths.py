"""function_lengths.py SRC [LIMIT]: every C/C++ function in SRC no longer than LIMIT lines.

The project's style puts a function's opening and closing braces alone at
column 0, so a function is the lines from its signature to the closing `}`.
Prints each function over the limit (file:line name length) and exits 1 if any.
"""
import pathlib
import re
import sys

SIGNATURE = re.compile(r"^[A-Za-z_][\w \*]*?\b(\w+)\s*\(")


def functions(path):
    lines = path.read_text(errors="replace").splitlines()
    start = name = None
    for i, line in enumerate(lines):
        m = SIGNATURE.match(line)
        if start is None and m and not line.rstrip().endswith(";"):
            start, name = i, m.group(1)
        elif start is not None and line.startswith("{"):
            body = i
            for j in range(i + 1, len(lines)):
                if lines[j].startswith("}"):
                    yield name, start + 1, j - start + 1
                    break
            start = None
        elif start is not None and (line.strip() == "" or line.rstrip().endswith(";")):
            start = None


def main():
    root = pathlib.Path(sys.argv[1])
    limit = int(sys.argv[2]) if len(sys.argv) > 2 else 100
    over = []
    for path in sorted(root.rglob("*")):
        if path.suffix in (".c", ".cpp"):
            for name, line, n in functions(path):
                if n > limit:
                    over.append(f"{path.relative_to(root)}:{line} {name} {n} lines")
    for o in over:
        print(o)
    if over:
        sys.exit(1)
    print(f"no function over {limit} lines")


main()
