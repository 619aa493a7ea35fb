#!/usr/bin/env python3
"""scripts/check-structure.py on small made-up trees: a clean tree passes; an include circle between two units
(one through a .cpp, as Runner.cpp and AutoModelHost.cpp once were) fails and is named, and so does the Physics
circle the check once let through as known; a file over 600 lines
fails; a function over 80 lines outside tests/ and bench/ fails and is named with its line and length.
Usage: check_structure_test.py PATH/TO/check-structure.py"""
import os
import subprocess
import sys
import tempfile


def write(root, rel, text):
    path = os.path.join(root, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def run(script, root):
    r = subprocess.run([sys.executable, script, root, "--functions"], capture_output=True, text=True)
    return r.returncode, r.stdout


def clean_tree(root):
    write(root, "App/Low.h", "#pragma once\nint Low();\n")
    write(root, "App/Low.cpp", '#include "App/Low.h"\nint Low() { return 1; }\n')
    write(root, "App/High.h", '#pragma once\n#include "App/Low.h"\nint High();\n')
    write(root, "App/High.cpp", '#include "App/High.h"\nint High() { return Low() + 1; }\n')


def main():
    script = sys.argv[1]
    failures = []

    def expect(condition, what, out):
        if not condition:
            failures.append(what + "\n" + out)

    with tempfile.TemporaryDirectory() as root:
        clean_tree(root)
        code, out = run(script, root)
        expect(code == 0 and "0 problems" in out, "a clean tree passes", out)

        write(root, "App/Low.cpp", '#include "App/Low.h"\n#include "App/High.h"\nint Low() { return 1; }\n')
        code, out = run(script, root)
        expect(code == 1 and "include circle: App/High -> App/Low" in out, "a circle through a .cpp fails", out)

    with tempfile.TemporaryDirectory() as root:
        # The circle this check once let through as known (Physics/'s WorldSettings <-> Particle, a header-only unit
        # among them): no circle is allowed, whatever its files.
        write(root, "Physics/WorldSettings.h", '#pragma once\n#include "Physics/Particle.h"\nstruct WorldSettings {};\n')
        write(root, "Physics/Particle.h", '#pragma once\nstruct Particle {};\n')
        write(root, "Physics/Particle.cpp", '#include "Physics/Particle.h"\n#include "Physics/WorldSettings.h"\n')
        code, out = run(script, root)
        expect(code == 1 and "include circle: Physics/Particle -> Physics/WorldSettings" in out,
               "the once-known Physics circle fails like any other", out)
        expect("known" not in out, "no circle is reported as known", out)

    with tempfile.TemporaryDirectory() as root:
        clean_tree(root)
        write(root, "App/Long.cpp", "".join(f"int v{i} = {i};\n" for i in range(601)))
        write(root, "tests/LongTest.cpp", "".join(f"int t{i} = {i};\n" for i in range(700)))
        code, out = run(script, root)
        expect(code == 1 and "App/Long.cpp: 601 lines" in out, "a 601-line file fails", out)
        expect("tests/LongTest.cpp" not in out, "tests/ may hold long files", out)

    with tempfile.TemporaryDirectory() as root:
        clean_tree(root)
        body = "".join(f"    x += {i};  // a '{{' in a comment and \"}}\" in a string do not count\n" for i in range(85))
        write(root, "App/Fn.cpp", "namespace n {\nstruct S {\n    int Small() { return 0; }\n};\n"
              "int Big(int x) {\n" + body + "    return x;\n}\n}  // namespace n\n")
        write(root, "bench/Fn.cpp", "int Long(int x) {\n" + body + "    return x;\n}\n")
        code, out = run(script, root)
        expect(code == 1, "a long function fails", out)
        expect("App/Fn.cpp:5: Big is 88 lines" in out, "a long function is named with its line and length", out)
        expect("Small" not in out, "a short member function is not reported", out)
        expect("bench/Fn.cpp" not in out, "bench/ may hold long functions", out)
        write(root, "App/Fn.cpp", "int Short(int x) {\n" + body[: body.index("\n") + 1] * 70 + "    return x;\n}\n")
        code, out = run(script, root)
        expect(code == 0, "a 73-line function passes", out)

    for f in failures:
        print("FAILED: " + f)
    print(f"check_structure_test: {len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
