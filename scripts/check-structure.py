#!/usr/bin/env python3
"""Checks the source tree's shape beyond the layer table (scripts/check-layers.py checks that).

Fails (exit 1) on
  - an include circle: a file's unit (Foo.h and Foo.cpp are one unit, Foo) reaches itself through the project's
    quoted includes, as Runner -> AutoModelHost -> Runner once did;
  - a source file over 600 lines outside tests/ and bench/ (docs/STYLE.md, "Size");
  - a function over 80 lines outside tests/ and bench/ (its file, first line and length, longest first).

Usage: check-structure.py REPO_ROOT [--functions]. Prints one line per problem (a long function is one);
--functions is accepted for older callers and changes nothing. No circle is allowed: the last known one (Physics/'s core:
WorldSettings <-> Particle, the solvers <-> PhysicsSystem) was cut when the contact solvers went behind
IContactSolver.h.
"""
import os
import re
import sys

SOURCE_EXT = (".cpp", ".h", ".hpp", ".c", ".cc")
SKIP_TOPS = {"docs", "scripts", "third_party", ".git", ".ci"}
FREE = ("tests/", "bench/")
MAX_FILE_LINES = 600
MAX_FUNCTION_LINES = 80
INCLUDE = re.compile(r'\s*#\s*include\s*"([^"]+)"')


def source_files(root):
    for top in sorted(os.listdir(root)):
        if top in SKIP_TOPS or top.startswith(("build", ".")) or not os.path.isdir(os.path.join(root, top)):
            continue
        for dirpath, dirnames, filenames in os.walk(os.path.join(root, top)):
            dirnames.sort()
            for name in sorted(filenames):
                if name.endswith(SOURCE_EXT):
                    yield os.path.relpath(os.path.join(dirpath, name), root)


def unit(path):
    return os.path.splitext(path)[0]


def include_graph(root, files):
    """{unit: {unit it includes}} over the project's own quoted includes."""
    graph = {}
    for rel in files:
        edges = graph.setdefault(unit(rel), set())
        with open(os.path.join(root, rel), encoding="utf-8") as f:
            for line in f:
                m = INCLUDE.match(line)
                if m and os.path.isfile(os.path.join(root, m.group(1))) and unit(m.group(1)) != unit(rel):
                    edges.add(unit(m.group(1)))
    return graph


def circles(graph):
    """Strongly connected components of more than one unit (Tarjan, iterative), each as a sorted list."""
    index, low, on_stack, stack, found = {}, {}, set(), [], []
    counter = [0]
    for start in sorted(graph):
        if start in index:
            continue
        work = [(start, iter(sorted(graph.get(start, ()))))]
        index[start] = low[start] = counter[0]
        counter[0] += 1
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = counter[0]
                    counter[0] += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph.get(child, ())))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    top = stack.pop()
                    on_stack.discard(top)
                    component.append(top)
                    if top == node:
                        break
                if len(component) > 1:
                    found.append(sorted(component))
    return sorted(found)


def strip_code(text):
    """The text with comments, string and character literals blanked (newlines kept), so braces count."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            k = text.find("(", i)
            delim = ")" + text[i + 2:k] + '"'
            j = text.find(delim, k)
            j = n if j < 0 else j + len(delim)
            out.append('""' + "\n" * text.count("\n", i, j))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


SCOPE = re.compile(r"\b(namespace|class|struct|union|enum)\b[^;()]*$|extern\s*\"\"\s*$")
NOT_FUNCTION = re.compile(r"^(if|for|while|switch|do|else|try|catch|return)\b|=\s*$|=\s*[\w:<>]*\s*$")


def long_functions(root, rel):
    """[(first line, lines, name)] of the functions in rel longer than MAX_FUNCTION_LINES."""
    with open(os.path.join(root, rel), encoding="utf-8") as f:
        code = strip_code(f.read())
    found = []
    scopes = []  # for each open brace: "scope" (namespace/class) or "function" or "block"
    head_start = 0  # where the text before the next brace begins
    line = 1
    open_line = {}
    names = {}
    for pos, c in enumerate(code):
        if c == "\n":
            line += 1
        elif c in ";":
            if all(s == "scope" for s in scopes):
                head_start = pos + 1
        elif c == "{":
            head = " ".join(code[head_start:pos].split())
            outer_is_scope = all(s == "scope" for s in scopes)
            if outer_is_scope and SCOPE.search(head):
                kind = "scope"
            elif outer_is_scope and head.endswith((")", "const", "override", "noexcept", "final")) or (
                    outer_is_scope and re.search(r"\)\s*(const\s*)?(->[^{]*)?$|\)\s*:.*$", head)):
                kind = "function" if not NOT_FUNCTION.search(head.split("(")[0].strip()) else "block"
            else:
                kind = "block"
            scopes.append(kind)
            open_line[len(scopes)] = line
            names[len(scopes)] = head.split("(")[0].split()[-1] if "(" in head and head.split("(")[0].split() else ""
            head_start = pos + 1
        elif c == "}":
            if not scopes:
                continue
            depth = len(scopes)
            kind = scopes.pop()
            if kind == "function":
                length = line - open_line[depth] + 1
                if length > MAX_FUNCTION_LINES:
                    found.append((open_line[depth], length, names[depth]))
            if all(s == "scope" for s in scopes):
                head_start = pos + 1
    return found


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    root = args[0] if args else "."
    files = list(source_files(root))
    problems = []
    for component in circles(include_graph(root, files)):
        problems.append("include circle: " + " -> ".join(component) + " (each includes another of them)")
    long_ones = []
    for rel in files:
        if rel.startswith(FREE):
            continue
        with open(os.path.join(root, rel), encoding="utf-8") as f:
            lines = sum(1 for _ in f)
        if lines > MAX_FILE_LINES:
            problems.append(f"{rel}: {lines} lines, over the {MAX_FILE_LINES}-line limit")
        long_ones += [(length, rel, first, name) for first, length, name in long_functions(root, rel)]
    for p in problems:
        print(p)
    long_ones.sort(key=lambda x: (-x[0], x[1], x[2]))
    for length, rel, first, name in long_ones:
        print(f"{rel}:{first}: {name} is {length} lines, over the {MAX_FUNCTION_LINES}-line limit")
    problems += long_ones
    print(f"check-structure: {len(files)} files, {len(problems)} problems ({len(long_ones)} of them functions over "
          f"{MAX_FUNCTION_LINES} lines)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
