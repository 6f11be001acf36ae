#!/usr/bin/python3
"""manpages.py FAIRWAY OUTDIR VERSION - manual pages from fairway's help texts.

Run at build time (CMakeLists.txt): fairway.1 from `fairway --help` and
fairway-COMMAND.1 from `fairway COMMAND --help` for every command the main help
lists, so the pages never disagree with the program.  The help texts follow
one layout, which is all this relies on:

    usage: fairway run SCENARIO... [options]     first line(s): the synopsis
           mpirun -np K fairway sweep ...        (continued, indented)

    A paragraph of text ...                      not indented: prose

      --opt ARG     what it does, continued      an entry (option or word): indented
                    on deeper-indented lines     two, two spaces or more between the
                                                 term and its text

    turning   helm to ...                        an entry at the margin: one word, two
              its text, continued                spaces or more, then its text

Other indented lines (lists, examples) are kept as they are (.nf).  Any help
that fails or does not begin with "usage:" stops the build: a command whose
--help is broken must not ship with a page that hides it.
"""
import os
import re
import subprocess
import sys

OPTION = re.compile(r"^  (\S.*?)(?:\s{2,}(\S.*))?$")
# a word at the margin and its text two or more spaces on (manoeuvre's kinds)
TERM = re.compile(r"^(\S+) {2,}(\S.*)$")


def help_text(fairway, *args):
    p = subprocess.run([fairway, *args, "--help"], capture_output=True, text=True)
    if p.returncode != 0 or not p.stdout.startswith("usage:"):
        sys.exit(f"manpages.py: '{' '.join(['fairway', *args, '--help'])}' gave exit code "
                 f"{p.returncode} and no usage line")
    return p.stdout.rstrip("\n").split("\n")


def esc(text):
    """roff-safe text: backslashes, and a leading dot or quote made literal."""
    text = text.replace("\\", "\\e")
    return "\\&" + text if text[:1] in (".", "'") else text


def opt(text):
    return esc(text).replace("-", "\\-")


def synopsis(lines):
    """The usage lines (the first, and indented ones right after it)."""
    out, i = [], 0
    while i < len(lines) and (i == 0 or lines[i].startswith(" ")) and lines[i].strip():
        out.append(lines[i].strip().removeprefix("usage:").strip())
        i += 1
    return out, lines[i:]


def body(lines):
    """Prose paragraphs, option entries (.TP) and verbatim indented blocks."""
    out, para, state = [], [], None  # state: None, "entry" (an option's text), "verbatim"

    def end_block():
        nonlocal para, state
        if para:
            out.extend([".PP", esc(" ".join(para))])
            para = []
        if state == "verbatim":
            out.append(".fi")
        state = None

    for line in lines:
        if not line.strip():
            end_block()
        elif TERM.match(line):
            end_block()
            m = TERM.match(line)
            out.extend([".TP", "\\fB" + opt(m.group(1)) + "\\fR", esc(m.group(2))])
            state = "entry"
        elif not line.startswith(" "):
            if state:
                end_block()
            para.append(line.strip())
        else:
            if para:
                end_block()
            m = OPTION.match(line)
            entry = m and (m.group(2) or m.group(1).startswith("-"))
            if entry and state != "verbatim":
                out.extend([".TP", "\\fB" + opt(m.group(1)) + "\\fR"])
                if m.group(2):
                    out.append(esc(m.group(2)))
                state = "entry"
            elif state == "entry" and line.startswith("    "):
                out.append(esc(line.strip()))  # the option's text, continued
            else:
                if state != "verbatim":
                    end_block()
                    out.append(".nf")
                    state = "verbatim"
                out.append(esc(line))
    end_block()
    return out


def page(name, summary, version, lines, see_also):
    syn, rest = synopsis(lines)
    out = [f'.TH {name.upper()} 1 "" "fairway {version}" "User Commands"',
           ".SH NAME", f"{opt(name)} \\- {esc(summary)}", ".SH SYNOPSIS"]
    for k, s in enumerate(syn):
        out.extend(([".br"] if k else []) + [esc(s)])
    out.append(".SH DESCRIPTION")
    out.extend(body(rest))
    out.extend([".SH SEE ALSO", ", ".join(f"\\fB{opt(s)}\\fR(1)" for s in see_also)])
    return "\n".join(out) + "\n"


def commands(main_help):
    """(name, summary) of each command the main help lists under 'commands:'."""
    out, inside = [], False
    for line in main_help:
        if line.strip() == "commands:":
            inside = True
        elif inside and not line.strip():
            break
        elif inside:
            name, summary = line.strip().split(None, 1)
            out.append((name, summary))
    if not out:
        sys.exit("manpages.py: 'fairway --help' lists no commands")
    return out


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: manpages.py FAIRWAY OUTDIR VERSION")
    fairway, outdir, version = sys.argv[1:]
    os.makedirs(outdir, exist_ok=True)
    main_help = help_text(fairway)
    cmds = commands(main_help)
    names = ["fairway-" + c for c, _ in cmds]
    pages = {"fairway": page("fairway", "maritime traffic safety studies", version, main_help,
                             names)}
    for c, summary in cmds:
        pages["fairway-" + c] = page("fairway-" + c, summary, version, help_text(fairway, c),
                                     ["fairway"])
    for name, text in pages.items():
        with open(os.path.join(outdir, name + ".1"), "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
