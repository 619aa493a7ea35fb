#!/usr/bin/env python3
"""Prints docs/soft-solver.md's table of the mass-ratio scenes ("Mass ratios") from what tests/physics/MassRatio_test.cpp
prints: for each scenes/mass-*.json, the deepest penetration and the largest sideways distance of any body over
10 s at 60 Hz and at 0.03 s, in mm; then the Coulomb slides (how far the top box slid against v^2 / (2 mu g)).

usage: scripts/mass-ratio-table.py BUILD_DIR   (runs BUILD_DIR/psb_core_tests --gtest_filter='MassRatio.*')"""
import re
import subprocess
import sys

NAMES = {
    "mass-heavy-on-light.json": "1000 kg on 1 kg",
    "mass-light-on-heavy.json": "1 kg on 1000 kg",
    "mass-heavy-between-light.json": "1, 1000, 1 kg",
    "mass-heavy-on-tower.json": "100 kg on ten 1 kg",
}
STAND = re.compile(r"^soft (\S+) dt ([\d.]+) s: deepest ([\d.]+) m, sideways ([\d.]+) m$")
SLIDE = re.compile(r"^soft (\S+) dt ([\d.]+) s: top slid ([\d.]+) m \(Coulomb ([\d.]+) m\), the one under it "
                   r"([-\d.]+) m$")


def mm(metres):
    return "%.2f" % (float(metres) * 1000.0)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    binary = sys.argv[1].rstrip("/") + "/psb_core_tests"
    out = subprocess.run([binary, "--gtest_filter=MassRatio.*"], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit("%s failed (exit %d):\n%s" % (binary, out.returncode, out.stdout[-2000:]))
    stands, slides = {}, {}
    for line in out.stdout.splitlines():
        m = STAND.match(line)
        if m:
            stands.setdefault(m.group(1), []).append((mm(m.group(3)), mm(m.group(4))))
        m = SLIDE.match(line)
        if m:
            slides.setdefault(m.group(1), []).append((m.group(3), m.group(4), mm(m.group(5))))
    if set(stands) != set(NAMES) or any(len(v) != 2 for v in stands.values()):
        sys.exit("unexpected test output: scenes %s" % sorted(stands))
    print("| scene | 60 Hz: deepest / sideways (mm) | 0.03 s: deepest / sideways (mm) |")
    print("|---|---|---|")
    for name, label in NAMES.items():
        (d60, s60), (d03, s03) = stands[name]
        print("| %s | %s / %s | %s / %s |" % (label, d60, s60, d03, s03))
    print()
    print("| top box launched at 2 m/s | 60 Hz: slid (m) | 0.03 s: slid (m) | Coulomb v²/(2μg) (m) |")
    print("|---|---|---|---|")
    for name, rows in slides.items():
        print("| %s | %s | %s | %s |" % (NAMES[name], rows[0][0], rows[1][0], rows[0][1]))


if __name__ == "__main__":
    main()
