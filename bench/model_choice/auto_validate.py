#!/usr/bin/env python3
"""Validates `model: auto` on seeded random problems nobody tuned it to (docs/model-choice-validation.md, "Problems
nobody tuned").

Draws instances from the families of auto_families.py, each with a position budget log-uniform over 1e-4 .. 1e-1 m,
writes each as a scene file with "model": "auto", and runs the release program as a user would:
`physics-sandbox --scene F --state S.csv --no-ui` (plus `--size 16x16`, which only shrinks the frames it renders and
throws away). The error is read from the last --state row, against the exact answer at that row's `time`. Every
instance also runs a grid of fixed models (world.step, integrator and, where particles can hit a constraint, particle
contact; or contact solver, iterations or soft substeps) in
order of predicted work until one meets the budget, and on up to 4x that work for the cheapest; on a refusal it
shows whether any model of the grid meets the budget. CPU is the child process's (user + system, wait4).

Exit 0 unless something could not run; the targets are reported, not asserted (timings are benchmarks)."""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import random
import resource
import signal
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import auto_families  # noqa: E402

SEED = 2028  # the validation's seed and set: SEED, PER_FAMILY instances of every family
PER_FAMILY = 20
BUDGET_RANGE = (1e-4, 1e-1)  # m
PARTICLE_STEPS = [0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001, 5e-4, 2e-4, 1e-4]
# Volume position updates (world.volumePositions, docs/ch15.md "A position update exact for constant acceleration"):
# the book's (None: the default, euler) and the mean velocity's, which model=auto uses.
VOLUME_POSITIONS = [None, "average"]
VOLUME_STEPS = [0.05, 0.02, 0.01, 0.005, 0.002, 0.001, 5e-4, 2e-4, 1e-4]
INTEGRATORS = {"explicit-euler": 1, "euler": 1, "velocity-verlet": 2, "verlet": 1, "rk4": 4}  # force evaluations
PARTICLE_CONTACTS = ["book", "skin", "reflect"]  # world.particleContact, for particles that can hit a constraint
# Distance joint models (world.jointModel, docs/ch16.md): "tension" pulls only under these integrators (elsewhere it is
# the book's joint bit for bit, so the grid does not run it twice).
JOINT_MODELS = ["book", "tension"]
TENSION_INTEGRATORS = ("velocity-verlet", "rk4")
SOLVERS = [("book", 5), ("book", 20), ("accumulated", 5), ("accumulated", 20), ("soft", 4), ("soft", 16)]
CHEAPEST_WINDOW = 4.0  # after the first grid model meeting the budget, models up to this times its work also run
CSV_COLUMNS = ["id", "family", "index", "budget", "duration", "parameters", "auto_exit", "refused", "auto_model",
               "last_time", "error", "error_over_budget", "within", "auto_cpu_s", "grid_runs", "grid_meets",
               "cheapest_model", "cheapest_error", "cheapest_cpu_s", "auto_over_cheapest", "auto_overhead_s",
               "best_grid_model", "best_grid_error"]
GRID_COLUMNS = ["id", "model", "work", "exit", "last_time", "error", "meets", "cpu_s"]


class Instance:
    def __init__(self, seed, family, index):
        self.id = f"{family}-{index:03d}"
        self.family, self.index = family, index
        rng = random.Random(f"{seed}:{family}:{index}")
        self.budget = float(f"{auto_families.log_uniform(rng, *BUDGET_RANGE):.3g}")
        self.scene, self.exact, self.parameters = auto_families.FAMILIES[family](rng)
        self.duration = self.scene["duration"]
        bodies = self.scene["bodies"]
        self.volumes = any(b["type"] != "particle" and b["mass"] > 0 for b in bodies)
        self.contacts = bool(self.scene.get("constraints")) and any(b["type"] == "particle" for b in bodies)

    def auto_scene(self):
        s = dict(self.scene)
        s["model"], s["budget"] = "auto", {"quantity": "position", "bound": self.budget}
        return s

    def fixed_scene(self, model):
        s = json.loads(json.dumps(self.scene))
        s["world"].update(model["world"])
        return s

    def grid(self):
        """The fixed models of this instance's grid, cheapest predicted work first."""
        bodies = sum(1 for b in self.scene["bodies"] if b["mass"] > 0)
        models = []
        if self.volumes:
            for solver, passes in SOLVERS:
                for step in VOLUME_STEPS:
                    for positions in VOLUME_POSITIONS:
                        world = {"contactSolver": solver, "step": step}
                        world.update({"soft": {"substeps": passes}} if solver == "soft" else {"iterations": passes})
                        work = self.duration / step * bodies * (2 * passes if solver == "soft" else passes + 1)
                        label = f"{solver} {'substeps' if solver == 'soft' else 'iterations'} {passes}, dt {step:g}"
                        if positions is not None:
                            world["volumePositions"] = positions
                            label += f", {positions} positions"
                        models.append({"label": label, "world": world, "work": work})
        else:
            # Particles that can hit a constraint: every particle contact too (the engine's model space).
            contacts = PARTICLE_CONTACTS if self.contacts else [None]
            for integrator, evals in INTEGRATORS.items():
                for joints in JOINT_MODELS if self.scene.get("joints") and integrator in TENSION_INTEGRATORS else [None]:
                    for step in PARTICLE_STEPS:
                        for contact in contacts:
                            world = {"integrator": integrator, "step": step}
                            label = f"{integrator}, dt {step:g}"
                            if joints is not None:
                                world["jointModel"] = joints
                                label += f", {joints} joints"
                            if contact:
                                world["particleContact"] = contact
                                label += f", {contact} contact"
                            models.append({"label": label, "world": world, "work": self.duration / step * bodies * evals})
        return sorted(models, key=lambda m: m["work"])

    def error(self, run):
        """Largest distance of a moving body from the exact answer at the last row's time (m)."""
        exact = self.exact(run["time"])
        return max(math.dist(run["positions"][i], p) for i, p in exact.items())


def last_rows(path):
    """(time, {body: (x, y, z)}) of the last frame of a --state CSV."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    last = [r for r in rows if r["frame"] == rows[-1]["frame"]]
    return float(last[0]["time"]), {int(r["body"]): (float(r["x"]), float(r["y"]), float(r["z"])) for r in last}


def run_scene(binary, scene, path, cpu_limit):
    """Runs the scene file as a user would; returns exit code, CPU (s), the last row and stderr."""
    with open(path + ".json", "w") as f:
        json.dump(scene, f)
    state = path + ".csv"
    if os.path.exists(state):
        os.remove(state)

    def limit():
        resource.setrlimit(resource.RLIMIT_CPU, (cpu_limit, cpu_limit + 1))

    with open(path + ".err", "w") as err:
        p = subprocess.Popen([binary, "--scene", path + ".json", "--state", state, "--no-ui", "--size", "16x16"],
                             stdout=subprocess.DEVNULL, stderr=err, preexec_fn=limit)
        _, status, usage = os.wait4(p.pid, 0)
        p.returncode = os.waitstatus_to_exitcode(status)
    with open(path + ".err") as f:
        stderr = f.read()
    run = {"exit": p.returncode, "cpu": usage.ru_utime + usage.ru_stime, "stderr": stderr, "time": None}
    if p.returncode in (0, 4) and os.path.exists(state):
        run["time"], run["positions"] = last_rows(state)
    if os.path.exists(state):
        os.remove(state)
    return run


def auto_model(stderr):
    for line in stderr.splitlines():
        if "Model: auto, " in line:
            return line.split("Model: auto, ", 1)[1].split(";")[0]
    return "-"


def run_instance(inst, binary, work_dir, cpu_limit):
    folder = os.path.join(work_dir, inst.id)
    os.makedirs(folder, exist_ok=True)
    auto = run_scene(binary, inst.auto_scene(), os.path.join(folder, "auto"), cpu_limit)
    refused = auto["exit"] == 2 and "no model meets" in auto["stderr"]
    if auto["exit"] not in (0, 2, 3, 4, -signal.SIGXCPU, -signal.SIGKILL) or (auto["exit"] == 2 and not refused):
        raise RuntimeError(f"{inst.id}: auto exited {auto['exit']}: {auto['stderr'].strip()}")
    row = {"id": inst.id, "family": inst.family, "index": inst.index, "budget": inst.budget,
           "duration": inst.duration, "parameters": json.dumps(inst.parameters, sort_keys=True),
           "auto_exit": auto["exit"], "refused": int(refused), "auto_model": auto_model(auto["stderr"]),
           "last_time": auto["time"], "auto_cpu_s": auto["cpu"]}
    if auto["time"] is not None:
        row["error"] = inst.error(auto)
        row["error_over_budget"] = row["error"] / inst.budget
        row["within"] = int(row["error"] <= inst.budget)
    grid_rows, meeting, best, limit_work = [], [], None, math.inf
    for n, model in enumerate(inst.grid()):
        if model["work"] > limit_work:
            break
        r = run_scene(binary, inst.fixed_scene(model), os.path.join(folder, f"grid{n:02d}"), cpu_limit)
        error = inst.error(r) if r["time"] is not None else math.nan
        meets = error <= inst.budget
        grid_rows.append({"id": inst.id, "model": model["label"], "work": f"{model['work']:.4g}", "exit": r["exit"],
                          "last_time": r["time"], "error": error, "meets": int(meets), "cpu_s": r["cpu"]})
        if not math.isnan(error) and (best is None or error < best[1]):
            best = (model["label"], error)
        if meets:
            meeting.append((r["cpu"], model["label"], error))
            limit_work = min(limit_work, CHEAPEST_WINDOW * model["work"])
    row["grid_runs"], row["grid_meets"] = len(grid_rows), int(bool(meeting))
    if best:
        row["best_grid_model"], row["best_grid_error"] = best
    if meeting:
        cpu, label, error = min(meeting)
        row.update({"cheapest_model": label, "cheapest_error": error, "cheapest_cpu_s": cpu})
        if not refused and auto["time"] is not None:
            row["auto_over_cheapest"] = auto["cpu"] / cpu
            row["auto_overhead_s"] = auto["cpu"] - cpu
    return row, grid_rows


def instances(seed, per_family, families):
    return [Instance(seed, family, i) for family in families for i in range(per_family)]


def fmt(x, digits=3):
    if x is None or x == "":
        return "-"
    if isinstance(x, float):
        return "nan" if math.isnan(x) else f"{x:.{digits}g}"
    return str(x)


def percent(part, whole):
    return f"{100.0 * part / whole:.1f} %" if whole else "-"


def figures(rows):
    """The targets of docs/model-choice-validation.md, "Problems nobody tuned", as (text lines, table lines)."""
    n = len(rows)
    refused = [r for r in rows if r["refused"]]
    ran = [r for r in rows if "error" in r]
    failed = [r for r in rows if not r["refused"] and "error" not in r]
    within = [r for r in ran if r["within"]]
    ratios = [r["error_over_budget"] for r in ran]
    costly = [r for r in ran if r.get("cheapest_cpu_s", 0) >= 1.0 and "auto_over_cheapest" in r]
    cheap = [r for r in ran if r.get("cheapest_cpu_s", 1.0) < 1.0 and "auto_overhead_s" in r]
    overheads = sorted(r["auto_overhead_s"] for r in cheap)
    text = [
        f"instances: {n} ({len(set(r['family'] for r in rows))} families); ran {len(ran)}, refused {len(refused)}, "
        f"failed to run or stopped at the CPU limit {len(failed)}",
        f"within budget: {len(within)} / {len(ran)} not refused = {percent(len(within), len(ran))} (target >= 95 %)",
        f"largest error / budget: {fmt(max(ratios) if ratios else None)}; above 2x: {sum(x > 2 for x in ratios)} "
        f"(target 0); median error / budget {fmt(statistics.median(ratios) if ratios else None)}",
        f"refused: {len(refused)} / {n} = {percent(len(refused), n)} (target <= 10 %); the fixed grid meets the budget "
        f"in {sum(r['grid_meets'] for r in refused)} of them",
        f"cheapest meeting model >= 1 s CPU: {len(costly)} instances; auto's CPU over it at most 1.5x in "
        f"{sum(r['auto_over_cheapest'] <= 1.5 for r in costly)}"
        + (f" (from {fmt(min(r['auto_over_cheapest'] for r in costly))} to "
           f"{fmt(max(r['auto_over_cheapest'] for r in costly))})" if costly else ""),
        f"elsewhere ({len(cheap)} instances): auto's overhead over the cheapest meeting model, CPU s: median "
        f"{fmt(statistics.median(overheads) if overheads else None)}, 90th percentile "
        f"{fmt(overheads[int(0.9 * (len(overheads) - 1))] if overheads else None)}, largest "
        f"{fmt(overheads[-1] if overheads else None)}",
        f"no model of the grid meets the budget: {sum(1 for r in rows if not r['grid_meets'])} / {n}",
    ]
    return text


def family_table(rows):
    lines = ["| family | instances | refused | ran | within budget | above 2x | largest error / budget | "
             "grid meets none | median overhead, CPU s |", "|---|---|---|---|---|---|---|---|---|"]
    for family in dict.fromkeys(r["family"] for r in rows):
        fr = [r for r in rows if r["family"] == family]
        ran = [r for r in fr if "error" in r]
        over = [r.get("auto_overhead_s") for r in ran if r.get("auto_overhead_s") is not None]
        lines.append(f"| {family} | {len(fr)} | {sum(r['refused'] for r in fr)} | {len(ran)} | "
                     f"{sum(r['within'] for r in ran)} | {sum(r['error_over_budget'] > 2 for r in ran)} | "
                     f"{fmt(max((r['error_over_budget'] for r in ran), default=None))} | "
                     f"{sum(1 for r in fr if not r['grid_meets'])} | "
                     f"{fmt(statistics.median(over) if over else None)} |")
    return lines


def refusal_table(rows, grid_rows):
    lines = ["| instance | budget, m | grid models run | any meets | best of the grid | its error, m |",
             "|---|---|---|---|---|---|"]
    for r in rows:
        if r["refused"]:
            lines.append(f"| {r['id']} | {fmt(r['budget'])} | {r['grid_runs']} | "
                         f"{'yes: ' + r['cheapest_model'] if r['grid_meets'] else 'no'} | "
                         f"{r.get('best_grid_model', '-')} | {fmt(r.get('best_grid_error'))} |")
    return lines


def costly_table(rows):
    lines = ["| instance | budget, m | auto's model | error / budget | auto CPU s | cheapest meeting | its CPU s | "
             "auto over it |", "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if "auto_over_cheapest" in r and r["cheapest_cpu_s"] >= 1.0:
            lines.append(f"| {r['id']} | {fmt(r['budget'])} | {r['auto_model']} | {fmt(r['error_over_budget'])} | "
                         f"{fmt(r['auto_cpu_s'])} | {r['cheapest_model']} | {fmt(r['cheapest_cpu_s'])} | "
                         f"{fmt(r['auto_over_cheapest'])} |")
    return lines


def worst_table(rows, count):
    ran = sorted((r for r in rows if "error" in r), key=lambda r: -r["error_over_budget"])[:count]
    lines = ["| instance | budget, m | auto's model | last row's time, s | error, m | error / budget | "
             "cheapest meeting in the grid |", "|---|---|---|---|---|---|---|"]
    for r in ran:
        lines.append(f"| {r['id']} | {fmt(r['budget'])} | {r['auto_model']} | {fmt(r['last_time'], 6)} | "
                     f"{fmt(r['error'])} | {fmt(r['error_over_budget'])} | {r.get('cheapest_model', 'none')} |")
    return lines


def seeds_table(specs):
    """The summary of earlier runs' --csv files, one line each: `LABEL=PATH`, LABEL as "seed, run"."""
    lines = ["| seed | run | within budget | largest error / budget | above 2x | refused | grid meets in refusals |",
             "|---|---|---|---|---|---|---|"]
    for spec in specs:
        label, path = spec.split("=", 1)
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
        ran = [r for r in rows if r["error"] not in ("-", "")]
        ratios = [float(r["error_over_budget"]) for r in ran]
        refused = [r for r in rows if r["refused"] == "1"]
        seed, _, run = label.partition(",")
        lines.append(f"| {seed.strip()} | {run.strip()} | {percent(sum(r['within'] == '1' for r in ran), len(ran))} | "
                     f"{fmt(max(ratios) if ratios else None)} | {sum(x > 2 for x in ratios)} | "
                     f"{percent(len(refused), len(rows))} ({len(refused)}) | "
                     f"{sum(r['grid_meets'] == '1' for r in refused)} |")
    return lines


def write_csv(path, columns, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, restval="-")
        w.writeheader()
        for r in rows:
            w.writerow({k: fmt(v, 6) if isinstance(v, float) else v for k, v in r.items()})


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", default=os.path.join(here, "..", "..", "build", "physics-sandbox"))
    ap.add_argument("--seed", type=int, default=SEED)
    ap.add_argument("--per-family", type=int, default=PER_FAMILY)
    ap.add_argument("--families", default=",".join(auto_families.DEFAULT_FAMILIES),
                    help="comma-separated (default: all but slide-grid, the cost set)")
    ap.add_argument("--only", default="", help="comma-separated instance ids (e.g. pendulum-003)")
    ap.add_argument("--budget", type=float, help="every instance at this budget (m) instead of its drawn one")
    ap.add_argument("--work-dir", default="auto-validate", help="scene files and stderr of every run")
    ap.add_argument("--csv", default="", help="one row per instance")
    ap.add_argument("--grid-csv", default="", help="one row per fixed-model run")
    ap.add_argument("--md", default="", help="the generated tables (docs/model-choice-validation.md)")
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--cpu-limit", type=int, default=120, help="CPU s a run may take before it is stopped")
    ap.add_argument("--table", default="", help="print the summary of earlier --csv files as a table and exit: "
                    "'SEED, RUN=PATH;SEED, RUN=PATH...'")
    args = ap.parse_args(argv)
    if args.table:
        print("\n".join(seeds_table([s for s in args.table.split(";") if s])))
        return 0
    families = [f for f in args.families.split(",") if f]
    for f in families:
        if f not in auto_families.FAMILIES:
            ap.error(f"--families: unknown family {f!r} (known: {', '.join(auto_families.FAMILIES)})")
    todo = instances(args.seed, args.per_family, families)
    if args.only:
        wanted = args.only.split(",")
        todo = [i for i in todo if i.id in wanted]
        if len(todo) != len(wanted):
            ap.error(f"--only: no such instance among {', '.join(wanted)} at --per-family {args.per_family}")
    if args.budget is not None:
        for inst in todo:
            inst.budget = args.budget
    if not os.access(args.binary, os.X_OK):
        ap.error(f"--binary: {args.binary} is not an executable")
    start = time.time()
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        results = list(pool.map(lambda i: run_instance(i, args.binary, args.work_dir, args.cpu_limit), todo))
    rows = [r for r, _ in results]
    grid_rows = [g for _, gs in results for g in gs]
    text = figures(rows)
    print("\n".join(text))
    print(f"({len(grid_rows)} fixed-model runs; {time.time() - start:.0f} s wall)")
    if args.csv:
        write_csv(args.csv, CSV_COLUMNS, rows)
    if args.grid_csv:
        write_csv(args.grid_csv, GRID_COLUMNS, grid_rows)
    if args.md:
        stamp = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
        chosen = "" if families == auto_families.DEFAULT_FAMILIES else f" --families {args.families}"
        command = f"auto_validate.py --seed {args.seed} --per-family {args.per_family}{chosen}"
        parts = [f"Made by `{command}` on {stamp}.", "",
                 *[f"- {t}" for t in text], "", *family_table(rows), "", "Refusals and their grids:", "",
                 *refusal_table(rows, grid_rows), "", "Instances whose cheapest meeting model costs at least 1 s of "
                 "CPU:", "", *costly_table(rows), "", "The largest errors over the budget:", "",
                 *worst_table(rows, 15)]
        with open(args.md, "w") as f:
            f.write("\n".join(parts) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
