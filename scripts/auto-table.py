#!/usr/bin/env python3
"""Prints the README's table of `model: auto` against the sweep from docs/sweep/auto.csv (psb-model-choice-bench
--csv; docs/model-choice-validation.md). Each cell is auto's error over the budget / its CPU over the cheapest sweep
setting meeting the budget, both to three significant digits; a ratio above 3 is bold; a refused budget reads
"refused", or "refused (none meets)" when no sweep setting meets it either.

usage: scripts/auto-table.py [docs/sweep/auto.csv]"""
import csv
import sys


def g3(value):
    """Three significant digits, as the bench prints them (1e-05 as 1e-5)."""
    text = "%.3g" % value
    return text.replace("e-0", "e-").replace("e+0", "e+")


def cell(row):
    if row["refused"] == "1":
        return "refused" if row["cheapest"] not in ("", "-") else "refused (none meets)"
    ratio = float(row["error"]) / float(row["budget"])
    text = g3(ratio)
    if ratio > 3:
        text = "**" + text + "**"
    cost = row["cost_ratio"]
    return text + " / " + (g3(float(cost)) if cost not in ("", "-", "nan") else "-")


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "docs/sweep/auto.csv"
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    budgets = list(dict.fromkeys(r["budget"] for r in rows))  # in the CSV's order, each once
    problems = list(dict.fromkeys(r["problem"] for r in rows))
    labels = ["budget 1e-1", "1e-2", "1e-3"] if budgets == ["0.1", "0.01", "0.001"] else budgets
    print("| problem | " + " | ".join(labels) + " |")
    print("|---" * (len(budgets) + 1) + "|")
    for p in problems:
        cells = {r["budget"]: cell(r) for r in rows if r["problem"] == p}
        print("| " + p + " | " + " | ".join(cells.get(b, "-") for b in budgets) + " |")


if __name__ == "__main__":
    main()
