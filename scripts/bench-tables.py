#!/usr/bin/env python3
"""Copies the tables the benchmark scripts wrote into docs/benchmarks.md, so the doc shows exactly
what the last run printed. A table in the doc sits between two markers naming its source and which
of its tables it is (counted from 1):

  <!-- table bench/results/all-meshes.md 1 -->
  | ... |
  <!-- end table -->

  scripts/bench-tables.py [ROOT]           # rewrites the tables after a benchmark run
  scripts/bench-tables.py --check [ROOT]   # exits 1, naming them, if any differ (ctest label `sources`)
"""
import os
import re
import sys

DOC = os.path.join("docs", "benchmarks.md")
BLOCK = re.compile(r"(<!-- table (\S+) (\d+) -->\n)(.*?)(<!-- end table -->)", re.S)


def tables(text):
    """Each run of lines starting with '|' in a file, in order."""
    found, current = [], []
    for line in text.split("\n") + [""]:
        if line.startswith("|"):
            current.append(line)
        elif current:
            found.append("\n".join(current) + "\n")
            current = []
    return found


def refreshed(root, doc):
    problems = []

    def replace(match):
        source, number = match.group(2), int(match.group(3))
        path = os.path.join(root, source)
        if not os.path.isfile(path):
            problems.append(f"{DOC}: {source}: no such file")
            return match.group(0)
        found = tables(open(path, encoding="utf-8").read())
        if not 1 <= number <= len(found):
            problems.append(f"{DOC}: {source} has {len(found)} tables, not a table {number}")
            return match.group(0)
        return match.group(1) + found[number - 1] + match.group(5)

    return BLOCK.sub(replace, doc), problems


def main():
    arguments = [a for a in sys.argv[1:] if a != "--check"]
    root = os.path.abspath(arguments[0] if arguments else os.path.join(os.path.dirname(__file__), ".."))
    path = os.path.join(root, DOC)
    doc = open(path, encoding="utf-8").read()
    new, problems = refreshed(root, doc)
    if "--check" in sys.argv:
        stale = [f"{DOC}: the table from {m.group(2)} ({m.group(3)}) is not what that file holds now"
                 for m, n in zip(BLOCK.finditer(doc), BLOCK.finditer(new)) if m.group(0) != n.group(0)]
        for problem in problems + stale:
            print(problem)
        print(f"bench-tables: {len(list(BLOCK.finditer(doc)))} tables, {len(problems + stale)} problems "
              "(scripts/bench-tables.py rewrites them)", file=sys.stderr)
        return 1 if problems or stale else 0
    for problem in problems:
        print(problem)
    if new != doc:
        open(path, "w", encoding="utf-8").write(new)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
