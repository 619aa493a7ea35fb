#!/usr/bin/env python3
"""CTest model_choice.auto_validate: the machinery of bench/model_choice/auto_validate.py (docs/model-choice-
validation.md, "Problems nobody tuned") on a small seeded slice. Not auto's figures (those are the bench's report):

1. the exact answers are right, checked against independent integrations of the same equations;
2. instances run with a very fine fixed model through the program match their exact answers closely;
3. the bench writes its CSVs with their columns, and a refused instance gets its whole grid of fixed models.

Usage: auto_validate_test.py PATH/TO/physics-sandbox SCRATCH_DIR"""
import csv
import math
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bench", "model_choice"))
import auto_families as af  # noqa: E402
import auto_validate as av  # noqa: E402

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print(f"FAIL: {what}", file=sys.stderr)


def rk4(f, y, h, n):
    for _ in range(n):
        k1 = f(y)
        k2 = f([a + h / 2 * b for a, b in zip(y, k1)])
        k3 = f([a + h / 2 * b for a, b in zip(y, k2)])
        k4 = f([a + h * b for a, b in zip(y, k3)])
        y = [a + h / 6 * (b + 2 * c + 2 * d + e) for a, b, c, d, e in zip(y, k1, k2, k3, k4)]
    return y


def check_exact_answers():
    # The pendulum through Jacobi's sn against RK4 on theta'' = -(g / L) sin(theta), up to 150 degrees.
    for deg in (20.0, 120.0, 150.0):
        theta0, omega0 = math.radians(deg), math.sqrt(af.G / 0.8)
        y = rk4(lambda s: [s[1], -omega0 * omega0 * math.sin(s[0])], [theta0, 0.0], 1e-3, 3000)
        exact = af.pendulum_angle(theta0, omega0, 3.0)
        check(abs(exact - y[0]) < 1e-8, f"pendulum at {deg} deg after 3 s: sn gives {exact}, RK4 {y[0]}")
    # One damped spring: the matrix exponential against the closed form x = A e^(-gamma t) (cos wd t + ...).
    k, m, b, rest, amp = 40.0, 0.5, 0.6, 1.0, 0.2
    system = af.chain_matrix([m], [k], [b], [rest], 0.0)
    gamma = b / (2 * m)
    wd = math.sqrt(k / m - gamma * gamma)
    for t in (0.3, 2.0, 5.5):
        closed = rest + amp * math.exp(-gamma * t) * (math.cos(wd * t) + gamma / wd * math.sin(wd * t))
        got = af.chain_state(system, [rest + amp, 0.0, 1.0], t)[0]
        check(abs(got - closed) < 1e-10, f"spring at {t} s: exp(A t) gives {got}, the closed form {closed}")
    # A chain of three under gravity against RK4 on the forces written out bob by bob.
    ms, ks, bs, ls = [0.5, 1.2, 0.8], [120.0, 60.0, 200.0], [0.3, 0.0, 1.1], [0.6, 0.9, 0.5]

    def forces(s):
        u, v = s[:3], s[3:]
        tension = [ks[i] * (u[i] - (u[i - 1] if i else 0.0) - ls[i]) + bs[i] * (v[i] - (v[i - 1] if i else 0.0))
                   for i in range(3)]
        acc = [af.G - tension[i] / ms[i] + (tension[i + 1] / ms[i] if i < 2 else 0.0) for i in range(3)]
        return v + acc

    start = [0.7, 1.7, 2.3, 0.0, 0.4, -0.2]
    y = rk4(forces, start, 1e-4, 20000)
    z = af.chain_state(af.chain_matrix(ms, ks, bs, ls, af.G), start + [1.0], 2.0)
    check(max(abs(a - b) for a, b in zip(z[:6], y)) < 1e-8, f"chain after 2 s: exp(A t) gives {z[:6]}, RK4 {y}")
    # The bounce: continuous at its impacts, each apex e^2 of the one before.
    h, e = 2.0, 0.6
    t1 = math.sqrt(2 * h / af.G)
    t2 = t1 + 2 * e * af.G * t1 / af.G
    for t in (t1, t2):
        before, after = af.bounce_position(h, 0.0, e, t - 1e-9)[1], af.bounce_position(h, 0.0, e, t + 1e-9)[1]
        check(abs(before) < 1e-7 and abs(after) < 1e-7, f"bounce at its impact {t}: y {before}, {after}")
    apex = af.bounce_position(h, 0.0, e, t1 + e * t1)[1]
    check(abs(apex - e * e * h) < 1e-12, f"bounce: first apex {apex}, not e^2 h = {e * e * h}")


# A very fine fixed model per family (the slice: instance 0 of each family at the bench's seed, and bounce-001), with
# the error allowed. Particles run RK4 at 1 ms: finer, float rounding of the positions adds up (the projectile ends
# 1.3 mm off at 0.1 ms over 15,833 steps).
FINE = {
    False: ({"integrator": "rk4", "step": 1e-3}, 2e-4),
    True: ({"contactSolver": "book", "iterations": 20, "step": 1e-4}, 1e-3),
}
# Where the fine model itself stays off the rigid answer: a particle's impact is resolved at the end of its step
# (an error of up to its speed times the step) and the particle is put Particle::kContactOffset (3 mm) off the surface
# (3 mm, and 3 mm times e more at the next impact), so bounce-001 (two impacts; instance 0 ends before its first)
# runs at 0.1 ms and is allowed 3.5 mm per impact more. The pendulum runs its joint as tension (world.jointModel,
# docs/ch16.md), where RK4 keeps its order; the book's joint is first order (0.22, 0.11, 0.065 mm at 1, 0.5, 0.25 ms
# on pendulum-000, 29 degrees).
OVERRIDE = {"bounce-001": ({"integrator": "rk4", "step": 1e-4}, 2e-4 + 2 * 3.5e-3),
            "pendulum-000": ({"integrator": "rk4", "step": 1e-3, "jointModel": "tension"}, 2e-4)}


def check_grid_models():
    """A world with joints has both joint models in its grid, tension only where it pulls (velocity Verlet, RK4)."""
    labels = [m["label"] for m in av.Instance(av.SEED, "pendulum", 0).grid()]
    tension = [label for label in labels if "tension joints" in label]
    check(len(tension) == 2 * len(av.PARTICLE_STEPS) and all(("rk4" in t) != ("velocity-verlet" in t) for t in tension),
          f"the pendulum's grid has {len(tension)} tension-joint models: {tension}")
    check(not any("joints" in m["label"] for m in av.Instance(av.SEED, "projectile", 0).grid()),
          "a world without joints has joint models in its grid")


def check_fine_runs(binary, scratch):
    for inst in [av.Instance(av.SEED, family, 0) for family in af.FAMILIES] + [av.Instance(av.SEED, "bounce", 1)]:
        world, tolerance = OVERRIDE.get(inst.id, FINE[inst.volumes])
        run = av.run_scene(binary, inst.fixed_scene({"world": world}), os.path.join(scratch, inst.id), 60)
        if run["time"] is None:
            check(False, f"{inst.id}: the fine run exited {run['exit']}: {run['stderr'].strip()}")
            continue
        # The last row holds the physics at its own time (docs/app.md "Time"): the error is read there, as a user does.
        error = inst.error(run)
        check(error <= tolerance,
              f"{inst.id} {inst.parameters}: the fine run ends {error:.3g} m from the exact answer at t = {run['time']} "
              f"(allowed {tolerance})")


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.reader(f))


def check_bench(binary, scratch):
    out = os.path.join(scratch, "bench")
    common = ["--binary", binary, "--per-family", "1", "--work-dir", os.path.join(out, "work")]
    # projectile-000 at 0.1 m (its grid then stops early), and spring-000 at 1e-9 m, which nothing meets: refused.
    args = common + ["--families", "projectile", "--budget", "0.1", "--csv", os.path.join(out, "a.csv"), "--grid-csv",
                     os.path.join(out, "a-grid.csv"), "--md", os.path.join(out, "a.md")]
    os.makedirs(out)
    check(av.main(args) == 0, "the bench on projectile-000 did not exit 0")
    args = common + ["--families", "spring", "--budget", "1e-9", "--csv", os.path.join(out, "b.csv"), "--grid-csv",
                     os.path.join(out, "b-grid.csv")]
    check(av.main(args) == 0, "the bench on spring-000 at 1e-9 did not exit 0")
    a, b = read_csv(os.path.join(out, "a.csv")), read_csv(os.path.join(out, "b.csv"))
    for name, rows in (("a.csv", a), ("b.csv", b)):
        check(rows[0] == av.CSV_COLUMNS, f"{name}: columns {rows[0]}, not {av.CSV_COLUMNS}")
        check(len(rows) == 2 and len(rows[1]) == len(av.CSV_COLUMNS), f"{name}: not one full row: {rows}")
    row = dict(zip(a[0], a[1]))
    check(row["refused"] == "0" and row["error"] != "-" and float(row["last_time"]) > 0,
          f"projectile-000 did not run and get an error: {row}")
    if row["error"] != "-":
        ratio = float(row["error"]) / float(row["budget"])
        check(abs(ratio - float(row["error_over_budget"])) < 1e-4 * ratio, f"error / budget is not: {row}")
        check(row["within"] == str(int(float(row["error"]) <= float(row["budget"]))), f"within is not: {row}")
    grid = read_csv(os.path.join(out, "a-grid.csv"))
    check(grid[0] == av.GRID_COLUMNS, f"a-grid.csv: columns {grid[0]}")
    meets = [r for r in grid[1:] if r[6] == "1"]
    check(row["grid_meets"] == str(int(bool(meets))), f"grid_meets {row['grid_meets']} against the grid's rows")
    row = dict(zip(b[0], b[1]))
    grid = read_csv(os.path.join(out, "b-grid.csv"))
    whole = len(av.Instance(av.SEED, "spring", 0).grid())
    check(row["refused"] == "1" and row["error"] == "-", f"spring-000 at 1e-9 was not refused: {row}")
    check(row["grid_runs"] == str(whole) and len(grid) == whole + 1 and row["grid_meets"] == "0",
          f"the refusal did not get its whole grid of {whole} models ({row['grid_runs']} runs, {len(grid) - 1} rows)")
    check(all(r[0] == "spring-000" and r[5] != "nan" and r[6] == "0" for r in grid[1:]),
          "a grid row of the refusal has no error, or meets 1e-9 m")
    check("within budget:" in open(os.path.join(out, "a.md")).read(), "the report has no figures")


def main(argv):
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    binary, scratch = argv
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    check_exact_answers()
    check_grid_models()
    check_fine_runs(binary, scratch)
    check_bench(binary, scratch)
    print(f"auto_validate: {len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
