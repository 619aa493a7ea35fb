#!/usr/bin/env python3
"""Puts re-run psb-sweep rows in place of the committed ones whose outcome changed.

Usage: sweep-replace.py RESULTS.csv RERUN.csv [--dry-run]

RERUN.csv is what `psb-sweep --runs LIST --out RERUN.csv` wrote for some runs of the committed grid. Each of its
rows is matched to the row of RESULTS.csv with the same run index; the two must have the same settings (every
column but error, cpu_per_sim_s, stable, steps, sim_s and note), else nothing is written and the exit is 1. A
committed row is replaced by the re-run one (all columns, CPU included) when its error or stable column differs;
an unchanged row keeps its committed line, CPU column and all. RESULTS.csv is rewritten through a temporary file
beside it (whole or untouched). Prints the number of re-run and changed rows, by problem. Exit 2 on bad usage.
"""
import collections
import csv
import io
import os
import sys
import tempfile

OUTCOME = {"error", "cpu_per_sim_s", "stable", "steps", "sim_s", "note"}


def read(path):
    with open(path, newline="", encoding="utf-8") as f:
        text = f.read()
    lines = text.splitlines(keepends=True)
    header = next(csv.reader([lines[0]]))
    rows = [next(csv.reader([line])) for line in lines[1:]]
    return lines[0], lines[1:], header, rows


def main(argv):
    args = [a for a in argv[1:] if a != "--dry-run"]
    if len(args) != 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    results_path, rerun_path = args
    for p in args:
        if not os.path.isfile(p):
            print(f"sweep-replace: no file '{p}'", file=sys.stderr)
            return 2
    head, lines, header, rows = read(results_path)
    rhead, rlines, rheader, rrows = read(rerun_path)
    if header != rheader:
        print(f"sweep-replace: '{rerun_path}' has another header than '{results_path}'", file=sys.stderr)
        return 1
    col = {name: i for i, name in enumerate(header)}
    by_run = {row[col["run"]]: k for k, row in enumerate(rows)}
    settings = [i for i, name in enumerate(header) if name not in OUTCOME]
    rerun, changed = collections.Counter(), collections.Counter()
    for line, row in zip(rlines, rrows):
        run = row[col["run"]]
        if run not in by_run:
            print(f"sweep-replace: run {run} is not in '{results_path}'", file=sys.stderr)
            return 1
        k = by_run[run]
        old = rows[k]
        if [old[i] for i in settings] != [row[i] for i in settings]:
            print(f"sweep-replace: run {run} has other settings than the committed row", file=sys.stderr)
            return 1
        problem = row[col["problem"]]
        rerun[problem] += 1
        if old[col["error"]] != row[col["error"]] or old[col["stable"]] != row[col["stable"]]:
            changed[problem] += 1
            lines[k] = line if line.endswith("\n") else line + "\n"
    for problem in sorted(rerun):
        print(f"{problem}: {rerun[problem]} re-run, {changed[problem]} changed")
    print(f"total: {sum(rerun.values())} re-run, {sum(changed.values())} changed")
    if "--dry-run" in argv:
        return 0
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(os.path.abspath(results_path)), prefix=".sweep-replace.")
    with os.fdopen(fd, "w", encoding="utf-8", newline="") as f:
        f.write(head)
        f.writelines(lines)
    os.chmod(tmp, 0o644)
    os.replace(tmp, results_path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
