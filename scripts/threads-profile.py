#!/usr/bin/env python3
"""Where a soft-solver step of the peer box pile spends its instructions, and how much of it runs in the job pool's
chunks (docs/threads.md, "Which passes scale"). Runs psb-peer-bench under callgrind (instruction counts: the figures
do not depend on what else the machine is doing), collecting only inside PhysicsSystem::Update, whose worlds run on
one thread there: every chunked pass then runs inside JobPool::Run, inline. Writes the table and the Amdahl bounds
between the markers in docs/threads.md.

Usage: threads-profile.py BUILD_DIR [N] [STEPS] [--reuse]   (defaults: boxpile 4000, 120 steps; --reuse: read
BUILD_DIR/threads-profile.callgrind from the last run instead of running again)
"""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BEGIN, END = "<!-- threads-profile:begin -->", "<!-- threads-profile:end -->"

# Passes of the soft step, by the function that runs each (the block solve is the rest of SoftContactSolver::Step,
# the batches' impulses back to the contacts included: each block stores its own at the end of its job).
PASSES = [
    ("pair search (Broadphase::FindPairs)", "Broadphase::FindPairs("),
    ("body load (LoadBodies)", "SoftContactSolver::LoadBodies("),
    ("manifolds and warm-start match (Collide)", "SoftContactSolver::Collide("),
    ("islands, blocks and colours (SoftContactGraph::Build)", "SoftContactGraph::Build("),
    ("batch fill (BuildBatches)", "SoftContactSolver::BuildBatches("),
    ("restitution (ApplyRestitution)", "SoftContactSolver::ApplyRestitution("),
    ("body store (StoreBodies)", "SoftContactSolver::StoreBodies("),
]


def run_callgrind(build, n, steps, out):
    exe = os.path.join(build, "psb-peer-bench")
    cmd = ["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out, "--toggle-collect=PhysicsSystem::Update*",
           exe, "boxpile", str(n), "--solver", "soft", "--steps", str(steps), "--warmup", "1", "--repeat", "1"]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def number(text):
    return int(text.replace(",", ""))


def inclusive_and_callers(out):
    """{function: inclusive Ir} and {(caller, callee): Ir} from callgrind_annotate's caller tree."""
    text = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--tree=caller", "--threshold=100", out],
                          check=True, capture_output=True, text=True).stdout
    inclusive, edges, callers = {}, {}, []
    for line in text.splitlines():
        m = re.match(r"\s*([\d,]+) \([^)]*\)\s+(<|\*)\s+\S*?:(.*?) (?:\(\d+x\) )?\[", line)
        if not m:
            if not line.strip():
                callers = []
            continue
        cost, kind, name = number(m.group(1)), m.group(2), m.group(3)
        if kind == "<":
            callers.append((name, cost))
        else:
            inclusive[name] = cost
            for caller, c in callers:
                edges[(caller, name)] = edges.get((caller, name), 0) + c
            callers = []
    return inclusive, edges


def find(table, prefix):
    """Inclusive Ir of the functions named `prefix...`, not of the lambdas defined inside them."""
    return sum(v for k, v in table.items() if k.startswith(prefix) and "{lambda" not in k)


def run_inside(edges, prefix):
    """Ir of JobPool::Run called directly from the functions named `prefix...`."""
    return sum(c for (caller, callee), c in edges.items() if callee.startswith("JobPool::Run(") and
               caller.startswith(prefix))


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 4000
    steps = int(sys.argv[3]) if len(sys.argv) > 3 else 120
    out = os.path.join(build, "threads-profile.callgrind")
    if "--reuse" not in sys.argv:
        run_callgrind(build, n, steps, out)
    inclusive, edges = inclusive_and_callers(out)
    total = find(inclusive, "PhysicsSystem::Update(")
    step = find(inclusive, "SoftContactSolver::Step(")
    rows, named = [], 0
    for label, prefix in PASSES:
        ir = find(inclusive, prefix)
        # Chunks run from the function itself or from the helpers it calls (the grid, its entries, the cell scan).
        # The cell scan runs its buckets directly on one thread and in chunks on more (PairsInCells).
        par = run_inside(edges, prefix) + (run_inside(edges, "Broadphase::BuildGrid(") +
                                           run_inside(edges, "Broadphase::SortEntries(") +
                                           find(inclusive, "Broadphase::PairsInBuckets(")
                                           if prefix.startswith("Broadphase") else 0)
        named += ir if not prefix.startswith("Broadphase") else 0
        rows.append((label, ir, par))
    pair_search = rows[0][1]
    solve_in_step = run_inside(edges, "SoftContactSolver::Step(")
    other_step = step - named
    rows.insert(5, ("block solve: substeps, warm start, solve, relax, integrate (per block)", other_step,
                    min(solve_in_step, other_step)))
    rest = total - step - pair_search
    rows.append(("rest of the step (islands off, contexts, pair list)", rest, 0))
    parallel = sum(r[2] for r in rows)
    p = parallel / total
    lines = [f"Measured by `scripts/threads-profile.py build {n} {steps}`: callgrind instruction counts of "
             f"`psb-peer-bench boxpile {n} --solver soft --steps {steps}` inside `PhysicsSystem::Update` (one thread), "
             f"{total / steps / 1e6:.1f} M instructions per step.", "",
             "| pass | share of the step | of it in chunks |", "|---|---:|---:|"]
    for label, ir, par in rows:
        lines.append(f"| {label} | {100 * ir / total:.1f} % | {100 * par / ir if ir else 0:.0f} % |")
    lines += ["", f"Parallel part p = {100 * p:.1f} %, serial part {100 * (1 - p):.1f} %. Amdahl, 1 / ((1 - p) + p / N), "
              "with no cost for synchronisation or memory bandwidth:", "",
              "| threads | 2 | 4 | 16 | 64 | unbounded |", "|---|---:|---:|---:|---:|---:|",
              "| speed-up on paper | " + " | ".join(f"{1 / ((1 - p) + p / t):.2f}" for t in (2, 4, 16, 64)) +
              f" | {1 / (1 - p):.2f} |"]
    path = os.path.join(ROOT, "docs", "threads.md")
    doc = open(path).read()
    a, b = doc.index(BEGIN) + len(BEGIN), doc.index(END)
    open(path, "w").write(doc[:a] + "\n" + "\n".join(lines) + "\n" + doc[b:])
    print("\n".join(lines))


if __name__ == "__main__":
    main()
