#!/usr/bin/env python3
"""Observed order of the rigid volumes' position update (world.volumePositions, docs/ch15.md "A position update exact
for constant acceleration"): error against the exact answer at the last --state row, per contact solver, per step, for
`euler` and `average`, on exact problems of bench/model_choice/auto_families.py (fixed instances, not tuned).

    python3 bench/model_choice/volume_positions_order.py --binary build/physics-sandbox --work-dir /tmp/vp"""
import argparse
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import auto_families as fam  # noqa: E402
from auto_validate import run_scene  # noqa: E402

STEPS = [1e-2, 3e-3, 1e-3, 3e-4, 1e-4]
SOLVERS = [("book", {"iterations": 5}), ("accumulated", {"iterations": 5}), ("soft", {"soft": {"substeps": 4}})]


def free_fall():
    p0 = (0.0, 10.0, 0.0)
    s = fam.scene("free fall", 2.6, [fam.volume("sphere", p0, radius=0.5)])
    return s, lambda t: {0: fam.ballistic(p0, (0, 0, 0), t)}


def drawn(draw, want=None, seed=1):
    """The first instance of `draw` from random.Random(seed, seed + 1, ...) whose parameters match `want`."""
    while True:
        s, exact, params = draw(random.Random(seed))
        if want is None or all(params.get(k) == v for k, v in want.items()):
            return s, exact
        seed += 1


PROBLEMS = {
    "free-fall sphere 2.6 s": free_fall,
    "box slide": lambda: drawn(fam.draw_box_slide),
    "incline box slides": lambda: drawn(lambda r: fam.draw_incline(r, "box"), {"regime": "slides"}),
    "incline box sticks": lambda: drawn(lambda r: fam.draw_incline(r, "box"), {"regime": "sticks"}),
    "incline sphere slides": lambda: drawn(lambda r: fam.draw_incline(r, "sphere"), {"regime": "slides"}),
    "incline sphere rolls": lambda: drawn(lambda r: fam.draw_incline(r, "sphere"), {"regime": "rolls"}),
    "rolling sphere": lambda: drawn(fam.draw_rolling),
}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--binary", required=True)
    ap.add_argument("--work-dir", required=True)
    ap.add_argument("--problems", default=",".join(PROBLEMS))
    ap.add_argument("--solvers", default="book,accumulated,soft")
    a = ap.parse_args()
    os.makedirs(a.work_dir, exist_ok=True)
    print("problem | solver | positions | " + " | ".join(f"dt {h:g}" for h in STEPS) + " | observed orders")
    for name in a.problems.split(","):
        for solver, extra in SOLVERS:
            if solver not in a.solvers.split(","):
                continue
            for mode in ("euler", "average"):
                errors = []
                for h in STEPS:
                    s, exact = PROBLEMS[name]()
                    s["world"].update({"contactSolver": solver, "step": h, "volumePositions": mode}, **extra)
                    run = run_scene(a.binary, s, os.path.join(a.work_dir, "run"), 600)
                    if run["time"] is None:
                        errors.append(float("nan"))
                        continue
                    e = exact(run["time"])
                    errors.append(max(math.dist(run["positions"][i], p) for i, p in e.items()))
                orders = [math.log(errors[k] / errors[k + 1]) / math.log(STEPS[k] / STEPS[k + 1])
                          if errors[k] > 0 and errors[k + 1] > 0 else float("nan") for k in range(len(STEPS) - 1)]
                print(f"{name} | {solver} | {mode} | " + " | ".join(f"{x:.2e}" for x in errors) + " | " +
                      " ".join(f"{p:.2f}" for p in orders), flush=True)


if __name__ == "__main__":
    main()
