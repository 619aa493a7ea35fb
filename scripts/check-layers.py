#!/usr/bin/env python3
"""Checks the layering of the source tree against the table in README.md, section "Layout".

Each row of that table names a folder, its CMake target, the folders its files may include besides their own,
and whether it may include GL or ImGui headers. This check fails when
  - a quoted include does not name its file from the repository root ("Physics/PhysicsSystem.h"),
  - a file includes a header of a folder its row does not allow (a higher layer, or a sibling it must not see),
  - a file in a layer without GL includes a GL, OSMesa, GLAD or ImGui header,
  - a source file lies in a folder that has no row (every code folder is one layer),
  - a GL-free test folder (tests/math, geometry, physics, scenes, view) includes a GL, OSMesa, GLAD or ImGui
    header.
An angle-bracket include that names a file of the repository (<Physics/PhysicsSystem.h>) is checked like a
quoted one.
Usage: check-layers.py REPO_ROOT. Prints one line per problem; exit 1 if any, else 0.
"""
import os
import re
import sys

SOURCE_EXT = (".cpp", ".h", ".hpp", ".c", ".cc")
GL_HEADER = re.compile(r"^(GL/|glad/|KHR/|EGL/|GLFW/|imgui|backends/imgui)")
ROW = re.compile(r"^\|\s*`([^`]+)/`\s*\|\s*`([^`]+)`\s*\|([^|]*)\|([^|]*)\|")


def read_table(readme):
    """Returns {folder: (allowed folders, gl allowed)} from the README's layer table."""
    layers = {}
    in_layout = False
    with open(readme, encoding="utf-8") as f:
        for line in f:
            if line.startswith("## "):
                in_layout = line.strip() == "## Layout"
                continue
            m = ROW.match(line) if in_layout else None
            if m:
                folder = m.group(1)
                allowed = set(re.findall(r"`([^`]+)/`", m.group(3)))
                gl = m.group(4).strip().lower().startswith("yes")
                layers[folder] = (allowed, gl)
    return layers


def layer_of(path, layers):
    folder = os.path.dirname(path)
    return folder if folder in layers else None


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "."
    layers = read_table(os.path.join(root, "README.md"))
    if len(layers) < 5:
        print("check-layers: README.md has no layer table under '## Layout'")
        return 1
    free = ("tests/", "bench/")  # tests and benchmarks may include any layer; their includes still name folders
    gl_free_tests = ("tests/math/", "tests/geometry/", "tests/physics/", "tests/scenes/", "tests/view/")
    skip_tops = {"docs", "scripts", "third_party", ".git", ".ci"}
    problems = []
    checked = 0
    tops = set(p.split("/")[0] for p in layers) | {"tests", "bench"}
    tops |= {d for d in os.listdir(root) if os.path.isdir(os.path.join(root, d)) and not d.startswith(("build", "."))}
    for top in sorted(tops - skip_tops):
        for dirpath, dirnames, filenames in os.walk(os.path.join(root, top)):
            dirnames.sort()
            for name in sorted(filenames):
                if not name.endswith(SOURCE_EXT):
                    continue
                rel = os.path.relpath(os.path.join(dirpath, name), root)
                is_free = rel.startswith(free)
                layer = layer_of(rel, layers)
                if layer is None and not is_free:
                    problems.append(f"{rel}: folder {os.path.dirname(rel)}/ has no row in README.md's layer table")
                    continue
                checked += 1
                allowed, gl = layers.get(layer, (set(), True)) if not is_free else (None, True)
                if rel.startswith(gl_free_tests):
                    gl = False
                with open(os.path.join(root, rel), encoding="utf-8") as f:
                    for lineno, line in enumerate(f, 1):
                        m = re.match(r'\s*#\s*include\s*([<"])([^>"]+)[>"]', line)
                        if not m:
                            continue
                        kind, inc = m.groups()
                        where = f"{rel}:{lineno}"
                        if kind == "<":
                            if GL_HEADER.match(inc) and not gl:
                                problems.append(f"{where}: {layer or os.path.dirname(rel)}/ has no GL, but includes <{inc}>")
                            if not os.path.isfile(os.path.join(root, inc)) or "/" not in inc:
                                continue  # a system or generated header
                        if not os.path.isfile(os.path.join(root, inc)):
                            problems.append(f'{where}: "{inc}" does not name a file from the repository root')
                            continue
                        target = os.path.dirname(inc)
                        if allowed is not None and target != layer and target not in allowed:
                            problems.append(f'{where}: {layer}/ may not include "{inc}" ({target}/ is not in its row)')
    for p in problems:
        print(p)
    print(f"check-layers: {checked} files, {len(layers)} layers, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
