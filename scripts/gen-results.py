#!/usr/bin/env python3
"""Writes docs/results.md: every measured table of the project, generated from the benches' CSVs. Never edit
docs/results.md by hand; change a CSV (by re-running its bench) and run this script. CTest `results.up-to-date`
regenerates it into a temporary file and fails when the committed page differs.

Each CSV may have a sidecar FILE.csv.meta of `key: value` lines (date, machine, commit, command, note) saying when,
where and how it was measured; `--stamp FILE.csv --command "..."` writes one for a CSV just measured on this
machine (date now, this machine's CPU and core count, the checkout's commit). A table whose CSV is missing says
"not measured yet".

usage: scripts/gen-results.py [--root REPO] [--out FILE] [--peers CSV]
       scripts/gen-results.py --check [--root REPO]          # exit 1 if docs/results.md is not what this writes
       scripts/gen-results.py --stamp FILE.csv --command CMD [--date D] [--machine M] [--note N]
"""
import argparse
import csv
import datetime
import importlib.util
import os
import platform
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SWEEP_MAPS = ("spring-stiffness", "cloth-stiffness", "stack-mass-ratio")  # stability maps, not error targets
TARGETS = (0.1, 0.01, 0.001)
PEERS_HEADER = ["scene", "bodies", "sleep", "threads", "engine", "cpu_ms_per_step", "ratio_to_bullet",
                "max_displacement_m", "stands"]


def g3(value):
    """Three significant digits, exponents without a leading zero (1e-05 as 1e-5)."""
    return ("%.3g" % value).replace("e-0", "e-").replace("e+0", "e+")


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def read_meta(path):
    meta = {}
    if os.path.exists(path + ".meta"):
        with open(path + ".meta") as f:
            for line in f:
                key, sep, value = line.partition(":")
                if sep:
                    meta[key.strip()] = value.strip()
    return meta


def provenance(path, rel):
    """One line: which CSV, when, where and how it was measured (from the sidecar of the CSV at path)."""
    meta = read_meta(path)
    parts = ["Source: `%s`" % rel]
    parts.append("measured %s" % meta.get("date", "(date not recorded)"))
    parts.append("on %s" % meta.get("machine", "(machine not recorded)"))
    if "commit" in meta:
        parts.append("at commit %s" % meta["commit"])
    text = ", ".join(parts) + "."
    if "command" in meta:
        text += " Command: `%s`." % meta["command"]
    if "note" in meta:
        text += " " + meta["note"]
    return text


def setting_of(row):
    """The sweep row's model in words, as scripts/plot-sweep.sh writes it in cheapest.md."""
    if row["integrator"] != "-":
        s = row["integrator"]
    else:
        s = row["solver"] + " solver" if row["solver"] != "-" else "volumes"
    s += " dt=" + row["dt"]
    if row["substeps"] != "1":
        s += " substeps=" + row["substeps"]
    if row["iterations"] != "-":
        s += " iterations=" + row["iterations"]
    if row["projection"] != "-":
        s += " projection=" + ("on" if row["projection"] == "1" else "off")
    if row.get("soft_substeps", "-") not in ("-", None):
        s += " soft-substeps=" + row["soft_substeps"]
    return s


def label_of(row):
    return row["problem"] + (" (param %s)" % row["param"] if row["param"] != "-" else "")


def usable(row):
    return row["stable"] == "1" and row["error"] not in ("inf", "nan") and row["problem"] not in SWEEP_MAPS


def cheapest_table(rows):
    """Per problem and target error, the cheapest stable sweep run whose error is at or below the target."""
    best, order = {}, []
    for row in filter(usable, rows):
        label = label_of(row)
        if label not in order:
            order.append(label)
        error, cost = float(row["error"]), float(row["cpu_per_sim_s"])
        for target in TARGETS:
            key = (label, target)
            if error <= target and (key not in best or cost < best[key][0]):
                best[key] = (cost, setting_of(row), row["error"])
    out = ["| problem | target error | cheapest setting that meets it | error | CPU s per simulated s |",
           "|---|---|---|---|---|"]
    for label in order:
        for target in TARGETS:
            if (label, target) in best:
                cost, setting, error = best[(label, target)]
                out.append("| %s | %g | %s | %s | %s |" % (label, target, setting, error, g3(cost)))
            else:
                out.append("| %s | %g | none in the sweep | | |" % (label, target))
    return out


def is_book_model(row):
    """The demos' own model at their step: semi-implicit Euler, or the book's solver at 5 passes with projection."""
    if row["integrator"] != "-":
        return row["integrator"] == "euler"
    if row["solver"] == "-":
        return True
    return row["solver"] == "book" and row["iterations"] == "5" and row["projection"] == "1"


def solver_setting(row):
    """A contact-solver run's column: the solver with its passes, or the soft solver with its substeps."""
    if row["solver"] == "soft":
        return "soft, %s substeps" % row["soft_substeps"]
    return "%s, %s passes" % (row["solver"], row["iterations"])


def stack_map_table(rows):
    """stack-mass-ratio: per top-box mass ratio and solver setting, the largest step keeping the tower within 1 cm."""
    rows = [r for r in rows if r["problem"] == "stack-mass-ratio" and r["projection"] in ("1", "-")]
    columns = sorted(set(solver_setting(r) for r in rows))
    ratios = sorted(set(r["param"] for r in rows), key=float)
    best = {}
    for r in rows:
        if r["stable"] == "1" and r["error"] not in ("inf", "nan") and float(r["error"]) <= 0.01:
            key = (r["param"], solver_setting(r))
            best[key] = max(best.get(key, 0.0), float(r["dt"]))
    out = ["| top mass ratio | " + " | ".join(columns) + " |", "|---" * (len(columns) + 1) + "|"]
    for ratio in ratios:
        cells = [("%g s" % best[(ratio, c)]) if (ratio, c) in best else "none" for c in columns]
        out.append("| %s | %s |" % (ratio, " | ".join(cells)))
    return out


def demo_step_table(rows):
    """Per problem at the demos' 0.03 s: the book's model's error and the best model at that step."""
    groups = {}
    for row in rows:
        if row["problem"] not in SWEEP_MAPS:
            groups.setdefault(label_of(row), []).append(row)
    out = ["| problem | the book's model: error | best model at 0.03 s | its error | its cost / the book's |",
           "|---|---|---|---|---|"]
    for label, group in groups.items():
        book = next((r for r in group if is_book_model(r)), None)
        stable = [r for r in group if usable(r)]
        if book is None or not stable:
            continue
        best = min(stable, key=lambda r: float(r["error"]))
        book_cost = float(book["cpu_per_sim_s"])
        ratio = g3(float(best["cpu_per_sim_s"]) / book_cost) if book_cost > 0 else "-"
        book_error = g3(float(book["error"])) + ("" if book["stable"] == "1" else " (unstable)")
        out.append("| %s | %s | %s | %s | %s |" % (label, book_error, setting_of(best), g3(float(best["error"])),
                                                     ratio))
    return out


def auto_table(rows):
    """model=auto against the sweep, one cell per budget (scripts/auto-table.py's cells)."""
    spec = importlib.util.spec_from_file_location("auto_table", os.path.join(HERE, "auto-table.py"))
    auto = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(auto)
    budgets = list(dict.fromkeys(r["budget"] for r in rows))
    problems = list(dict.fromkeys(r["problem"] for r in rows))
    out = ["| problem | " + " | ".join("budget " + b for b in budgets) + " |", "|---" * (len(budgets) + 1) + "|"]
    for p in problems:
        cells = {r["budget"]: auto.cell(r) for r in rows if r["problem"] == p}
        out.append("| " + p + " | " + " | ".join(cells.get(b, "-") for b in budgets) + " |")
    answered = [r for r in rows if r["refused"] != "1"]
    within = sum(1 for r in answered if float(r["error"]) <= float(r["budget"]))
    ratios = [float(r["cost_ratio"]) for r in answered if r["cost_ratio"] not in ("", "-", "nan")]
    out.append("")
    out.append("%d of %d budgets answered (%d refused); %d of the answered runs end within their budget; auto's CPU "
               "over the cheapest sweep setting that meets the budget: median %s, within 2x in %d of %d." %
               (len(answered), len(rows), len(rows) - len(answered), within,
                g3(statistics.median(ratios)) if ratios else "-", sum(1 for x in ratios if x <= 2), len(ratios)))
    return out


def auto_families_table(rows):
    """Seeded problems nobody tuned: per family, within budget and auto's CPU over the cheapest grid setting."""
    families = list(dict.fromkeys(r["family"] for r in rows))
    out = ["| family | cases | refused | within budget | auto CPU / cheapest grid setting, median |",
           "|---|---|---|---|---|"]
    for fam in families:
        group = [r for r in rows if r["family"] == fam]
        refused = sum(1 for r in group if r["refused"] == "1")
        within = sum(1 for r in group if r["within"] == "1")
        ratios = [float(r["auto_over_cheapest"]) for r in group if r["auto_over_cheapest"] not in ("", "-", "nan")]
        median = g3(statistics.median(ratios)) if ratios else "-"
        out.append("| %s | %d | %d | %d | %s |" % (fam, len(group), refused, within, median))
    return out


def convergence_table(rows):
    """Contact problems with exact answers: each solver's smallest error over the grid, and its substep h."""
    problems = list(dict.fromkeys(r["problem"] for r in rows))
    solvers = list(dict.fromkeys(r["solver"] for r in rows))
    out = ["| problem | " + " | ".join("%s: smallest error (m) at h (s)" % s for s in solvers) + " |",
           "|---" * (len(solvers) + 1) + "|"]
    for p in problems:
        cells = []
        for s in solvers:
            group = [r for r in rows if r["problem"] == p and r["solver"] == s and r["error_m"] not in ("inf", "nan")]
            if not group:
                cells.append("-")
                continue
            best = min(group, key=lambda r: float(r["error_m"]))
            cells.append("%s at %s" % (g3(float(best["error_m"])), best["h"]))
        out.append("| " + p + " | " + " | ".join(cells) + " |")
    return out


def stands(row):
    return row["stands"].strip().lower() in ("1", "yes", "true")


def peers_table(rows):
    out = ["| scene | bodies | sleep | threads | engine | CPU ms per step | over Bullet | largest displacement (m) | "
           "stands |", "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        cells = [r[k] for k in PEERS_HEADER[:5]]
        for k in ("cpu_ms_per_step", "ratio_to_bullet", "max_displacement_m"):
            try:
                cells.append(g3(float(r[k])))
            except ValueError:
                cells.append(r[k])
        cells.append("yes" if stands(r) else "no" if r["stands"].strip().lower() in ("0", "no", "false") else r["stands"])
        out.append("| " + " | ".join(cells) + " |")
    return out


# (heading, CSV under the root, what the table is and where it is discussed, table function)
SECTIONS = [
    ("Speed against Bullet", "docs/data/peers.csv",
     "`psb-peer-bench --csv` ([peers.md](peers.md)): each scene built in Bullet and in this engine from one "
     "definition, run alternately in one process; CPU ms per step, this engine's time over Bullet's, the largest "
     "distance any body moved, and whether the scene stands.", peers_table),
    ("For this error, use this setting", "docs/sweep/results.csv",
     "`psb-sweep` ([sweep.md](sweep.md)): per reference problem and target error, the cheapest stable run of the "
     "sweep whose error is at or below the target. Cost is CPU seconds per simulated second.", cheapest_table),
    ("Stacks with a heavy or light top", "docs/sweep/results.csv",
     "`psb-sweep`, problem `stack-mass-ratio` ([sweep.md](sweep.md), \"Stack stability map\"): five cubes, the top one "
     "r times the others' mass, 5 s; the largest step at which the tower stays within 1 cm (book and accumulated "
     "solvers with linear projection), \"none\" when no step of the sweep does.", stack_map_table),
    ("What the demos' step costs in accuracy", "docs/sweep/demo-dt0.03.csv",
     "`psb-sweep --dt 0.03` ([sweep.md](sweep.md), \"What each demo chose\"): every problem at the demos' 0.03 s "
     "step, with the book's model (semi-implicit Euler; the book's solver at 5 passes with projection) and the most "
     "accurate stable model at the same step.", demo_step_table),
    ("An error budget instead of a step: `model=auto`", "docs/sweep/auto.csv",
     "`psb-model-choice-bench --csv` ([model-choice-validation.md](model-choice-validation.md)): each reference "
     "problem as a scene file; each cell is auto's error over the budget / its CPU (choice included) over the "
     "cheapest sweep setting that meets the budget; **bold** is above 3x.", auto_table),
    ("`model=auto` on problems nobody tuned", "docs/sweep/auto-validate.csv",
     "`bench/model_choice/auto_validate.py` ([model-choice-validation.md](model-choice-validation.md), \"Problems "
     "nobody tuned\"): seeded cases per family, each against a grid of fixed settings.", auto_families_table),
    ("Convergence of the contact solvers", "docs/sweep/contact-convergence.csv",
     "`psb-contact-convergence` ([soft-solver.md](soft-solver.md), \"Convergence of the contact solvers\"): "
     "problems with exact answers, every solver over a grid of steps and substeps.", convergence_table),
]

HEADER = """# Measured results

Generated by `scripts/gen-results.py` from the benches' CSVs; do not edit by hand (CTest `results.up-to-date`
fails when this page and the CSVs disagree). Each table names its CSV, when and where it was measured, and the doc
that explains it. Errors are deterministic; CPU times move with the machine's load (about 20 % on a shared
machine), so read ratios measured side by side rather than absolute times.

Figures still measured by hand, with their method beside them: the rigid benchmark and bounce tables
([ch15.md](ch15.md), "Benchmarks"), the soft solver against the accumulated one
([soft-solver.md](soft-solver.md), "What is measured"), frame rates and PNG encoding ([app.md](app.md), "Speed"),
particles, cloth and model cost ([ch14.md](ch14.md), [ch16.md](ch16.md), [sweep.md](sweep.md)), islands and sleep
([sleep.md](sleep.md)).
"""


def render(root, peers=None):
    lines = HEADER.rstrip("\n").split("\n")
    for heading, rel, intro, table in SECTIONS:
        path = peers if (peers and rel == "docs/data/peers.csv") else os.path.join(root, rel)
        lines += ["", "## " + heading, "", intro, ""]
        if not os.path.exists(path):
            lines.append("Not measured yet: `%s` does not exist." % rel)
            continue
        rows = read_rows(path)
        lines += table(rows) if rows else ["Not measured yet: `%s` has no rows." % rel]
        lines += ["", provenance(path, rel)]
    return "\n".join(lines) + "\n"


def optional_rows(root, rel, peers=None):
    path = peers if (peers and rel.endswith("peers.csv")) else os.path.join(root, rel)
    return read_rows(path) if os.path.exists(path) else []


def headline_peers(rows):
    ours = [r for r in rows if not r["engine"].lower().startswith("bullet")]
    if not ours:
        return "not measured yet ([hand-measured figures](docs/peers.md))"
    ratios = [float(r["ratio_to_bullet"]) for r in ours]
    standing = sum(1 for r in ours if stands(r))
    return "%s–%s× Bullet's CPU per step; %d of %d runs stand" % (g3(min(ratios)), g3(max(ratios)), standing, len(ours))


def headline(root, peers=None):
    """The README's short results table: one figure per measured area, each linking to its table."""
    rows = ["| what | figure | table |", "|---|---|---|"]
    peer_rows = optional_rows(root, "docs/data/peers.csv", peers)
    rows.append("| contacts against Bullet 3.24, same scenes, one process | %s | [results](docs/results.md#speed-against-"
                "bullet), [method](docs/peers.md) |" % headline_peers(peer_rows))
    sweep = optional_rows(root, "docs/sweep/results.csv")
    stack = [r for r in sweep if r["problem"] == "stack-10" and usable(r) and float(r["error"]) <= 0.01]
    if stack:
        best = min(stack, key=lambda r: float(r["cpu_per_sim_s"]))
        rows.append("| a tower of 10 cubes within 1 cm, cheapest setting | %s, %s CPU s per simulated s | [results](docs/"
                    "results.md#for-this-error-use-this-setting), [sweep](docs/sweep.md) |" %
                    (setting_of(best), g3(float(best["cpu_per_sim_s"]))))
    demo = optional_rows(root, "docs/sweep/demo-dt0.03.csv")
    proj = [r for r in demo if r["problem"] == "projectile"]
    book = next((r for r in proj if is_book_model(r)), None)
    if book:
        best = min((r for r in proj if usable(r)), key=lambda r: float(r["error"]))
        rows.append("| the book's 0.03 s step: projectile error after 2 s | %s m (semi-implicit Euler); %s m (%s) at %s× "
                    "the cost | [results](docs/results.md#what-the-demos-step-costs-in-accuracy) |" %
                    (g3(float(book["error"])), g3(float(best["error"])), best["integrator"],
                     g3(float(best["cpu_per_sim_s"]) / float(book["cpu_per_sim_s"]))))
    auto = optional_rows(root, "docs/sweep/auto.csv")
    answered = [r for r in auto if r["refused"] != "1"]
    if answered:
        within = sum(1 for r in answered if float(r["error"]) <= float(r["budget"]))
        rows.append("| `model=auto` on the %d reference problems | %d of %d answered budgets met, %d refused up front | "
                    "[results](docs/results.md#an-error-budget-instead-of-a-step-modelauto), [method](docs/model-"
                    "choice-validation.md) |" % (len(set(r["problem"] for r in auto)), within, len(answered),
                                              len(auto) - len(answered)))
    seeded = headline_seeds(root)
    if seeded:
        rows.append("| `model=auto` on seeded problems nobody tuned | %s | [method and per-seed table](docs/model-choice-"
                    "validation.md#problems-nobody-tuned) |" % seeded)
    return rows


def headline_seeds(root):
    """One line over every seed's CSV in docs/sweep/auto-validate-seeds/ (bench/model_choice/auto_validate.py)."""
    folder = os.path.join(root, "docs", "sweep", "auto-validate-seeds")
    runs = [read_rows(os.path.join(folder, f)) for f in sorted(os.listdir(folder)) if f.endswith(".csv")] \
        if os.path.isdir(folder) else []
    runs = [r for r in runs if r]
    if not runs:
        return ""
    refused, within, over = [], [], 0
    for rows in runs:
        ran = [r for r in rows if r["refused"] != "1" and r["error"] not in ("", "-")]
        refused.append(100.0 * (len(rows) - len(ran)) / len(rows))
        within.append(100.0 * sum(1 for r in ran if r["within"] == "1") / max(len(ran), 1))
        over += sum(1 for r in ran if float(r["error_over_budget"]) > 2.0)
    return ("%d seeds of %d instances: %.1f–%.1f %% refused; %.1f–%.1f %% of the rest within budget; %d above 2× the "
            "budget" % (len(runs), len(runs[0]), min(refused), max(refused), min(within), max(within), over))


def replace_block(readme, rows):
    begin = readme.index("<!-- results:begin")
    begin = readme.index("\n", begin) + 1
    end = readme.index("<!-- results:end -->")
    return readme[:begin] + "\n".join(rows) + "\n" + readme[end:]


def machine_name():
    model = platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return "%s, %d cores, %s" % (model, os.cpu_count() or 0, platform.system())


def stamp(args):
    """Writes FILE.csv.meta for a CSV just measured."""
    if not os.path.exists(args.stamp):
        sys.exit("gen-results: --stamp %s: no such file" % args.stamp)
    commit = subprocess.run(["git", "-C", os.path.dirname(os.path.abspath(args.stamp)), "rev-parse", "--short",
                             "HEAD"], capture_output=True, text=True).stdout.strip()
    meta = [("date", args.date or datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")),
            ("machine", args.machine or machine_name()), ("commit", commit or "unknown"), ("command", args.command)]
    if args.note:
        meta.append(("note", args.note))
    with open(args.stamp + ".meta", "w") as f:
        f.writelines("%s: %s\n" % kv for kv in meta if kv[1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--root", default=os.path.dirname(HERE))
    parser.add_argument("--out", help="write here instead of ROOT/docs/results.md")
    parser.add_argument("--peers", help="read the peer bench's CSV from here (a test's file)")
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--stamp")
    parser.add_argument("--command", default="")
    parser.add_argument("--date")
    parser.add_argument("--machine")
    parser.add_argument("--note")
    args = parser.parse_args()
    if args.stamp:
        return stamp(args)
    text = render(args.root, args.peers)
    target = os.path.join(args.root, "docs", "results.md")
    readme_path = os.path.join(args.root, "README.md")
    readme = open(readme_path).read()
    new_readme = replace_block(readme, headline(args.root, args.peers))
    if args.check:
        with tempfile.NamedTemporaryFile("w", suffix=".md", delete=False) as tmp:
            tmp.write(text)
        committed = open(target).read() if os.path.exists(target) else ""
        os.unlink(tmp.name)
        if committed != text or new_readme != readme:
            sys.exit("gen-results: docs/results.md or README.md's results table differs from what "
                     "scripts/gen-results.py writes from the CSVs; run scripts/gen-results.py and commit them")
        return 0
    with open(args.out or target, "w") as f:
        f.write(text)
    if not args.out:
        with open(readme_path, "w") as f:
            f.write(new_readme)
    return 0


if __name__ == "__main__":
    sys.exit(main())
