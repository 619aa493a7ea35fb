#!/usr/bin/env python3
"""Checks that the repository explains itself: comments and docs cite only documents inside it.

For every tracked source, CMake, script and Markdown file this check fails when
  - it cites the fact sheet that lived outside the repository (by its old file name) or any path under the
    shared folder beside the repository, instead of docs/book-reference.md;
  - it cites a tracker issue number (the word issue or issues followed by a number);
  - it cites a section "docs/book-reference.md §N.M" that docs/book-reference.md has no heading for;
  - it cites an erratum id (erratum 5.x-N in a comment, Erratum5_x_N in a test name) that docs/ERRATA.md does
    not list.
In C/C++ files only comments are read, except for test names (a path in a string literal is behaviour, not a
citation); CMake, shell, Python and Markdown files are read whole. This file is not scanned: it has to spell
the patterns out.
Usage: check-citations.py REPO_ROOT. Prints one line per problem; exit 1 if any, else 0.
"""
import os
import re
import subprocess
import sys

CPP_EXT = (".cpp", ".h", ".hpp", ".c", ".cc")
TEXT_EXT = (".md", ".cmake", ".sh", ".py")
SELF = "scripts/check-citations.py"

FORBIDDEN = [
    (re.compile(r"(?<![\w-])book\.md\b", re.I), "cites the out-of-repo fact sheet; cite docs/book-reference.md §N.M"),
    (re.compile(r"\.\./shared\b|/work/shared\b"), "points outside the repository"),
    (re.compile(r"\bissues?\s+#?\d+", re.I), "cites a tracker issue number"),
]
SECTION_CITE = re.compile(r"book-reference\.md(?:\s|/)*((?:§\d+(?:\.\d+)?(?:-\d+\.\d+)?(?:,\s*|\s+and\s+)?)+)")
SECTION_NUM = re.compile(r"§(\d+(?:\.\d+)?)(?:-(\d+\.\d+))?")
SECTION_HEADING = re.compile(r"^#{2,4}\s+(\d+(?:\.\d+)?)[.\s]", re.M)
ERRATUM_CITE = re.compile(r"\berrat(?:um|a)\s+(5\.[12]-\d+)", re.I)
ERRATUM_TEST = re.compile(r"\bErratum(5)_([12])_(\d+)")
ERRATUM_LISTED = re.compile(r"^(?:\|\s*|#+\s+)(5\.[12]-\d+)\b", re.M)


def cpp_comments(text):
    """The text with everything but // and /* */ comments blanked (newlines kept, so line numbers hold).
    String, character and raw string literals are skipped."""
    keep = [ch if ch == "\n" else " " for ch in text]
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i) or text.startswith("/*", i):
            j = text.find("\n", i) if text[i + 1] == "/" else text.find("*/", i + 2)
            j = n if j < 0 else (j if text[i + 1] == "/" else j + 2)
            keep[i:j] = text[i:j]
            i = j
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            k = text.find("(", i + 2)
            delim = text[i + 2:k]
            j = text.find(")" + delim + '"', k)
            i = n if j < 0 else j + len(delim) + 2
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            i = j + 1
        else:
            i += 1
    return "".join(keep)


def tracked_files(root):
    try:
        out = subprocess.run(["git", "-C", root, "ls-files"], check=True, capture_output=True, text=True).stdout
        names = [n for n in out.split("\n") if n]
        if names:
            return sorted(names)
    except (OSError, subprocess.CalledProcessError):
        pass
    names = []
    for d, dirs, files in os.walk(root):
        dirs[:] = sorted(x for x in dirs if not x.startswith((".", "build")))
        names += [os.path.relpath(os.path.join(d, f), root) for f in files]
    return sorted(names)


def scanned(rel):
    base = os.path.basename(rel)
    return rel != SELF and (rel.endswith(CPP_EXT + TEXT_EXT) or base == "CMakeLists.txt" or rel == ".ci/run")


def line_of(text, pos):
    return text.count("\n", 0, pos) + 1


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "."
    try:
        with open(os.path.join(root, "docs", "book-reference.md"), encoding="utf-8") as f:
            sections = set(SECTION_HEADING.findall(f.read()))
        with open(os.path.join(root, "docs", "ERRATA.md"), encoding="utf-8") as f:
            errata = set(ERRATUM_LISTED.findall(f.read()))
    except OSError as e:
        print(f"check-citations: {e}")
        return 1
    if len(sections) < 30 or len(errata) < 40:
        print(f"check-citations: found only {len(sections)} sections in docs/book-reference.md and "
              f"{len(errata)} errata in docs/ERRATA.md")
        return 1

    problems, checked = [], 0
    for rel in tracked_files(root):
        path = os.path.join(root, rel)
        if not scanned(rel) or not os.path.isfile(path):
            continue
        with open(path, encoding="utf-8") as f:
            text = f.read()
        checked += 1
        prose = cpp_comments(text) if rel.endswith(CPP_EXT) else text
        for pattern, why in FORBIDDEN:
            for m in pattern.finditer(prose):
                problems.append(f"{rel}:{line_of(prose, m.start())}: '{m.group(0)}' {why}")
        for m in SECTION_CITE.finditer(prose):
            for first, last in SECTION_NUM.findall(m.group(1)):
                for number in filter(None, (first, last)):
                    if number not in sections:
                        problems.append(f"{rel}:{line_of(prose, m.start())}: cites §{number}, which "
                                        "docs/book-reference.md does not have")
        for m in ERRATUM_CITE.finditer(prose):
            if m.group(1) not in errata:
                problems.append(f"{rel}:{line_of(prose, m.start())}: erratum {m.group(1)} is not in docs/ERRATA.md")
        if rel.endswith(CPP_EXT):
            for m in ERRATUM_TEST.finditer(text):
                erratum = f"{m.group(1)}.{m.group(2)}-{m.group(3)}"
                if erratum not in errata:
                    problems.append(f"{rel}:{line_of(text, m.start())}: test names erratum {erratum}, "
                                    "which is not in docs/ERRATA.md")

    for p in problems:
        print(p)
    print(f"check-citations: {checked} files, {len(sections)} reference sections, {len(errata)} errata, "
          f"{len(problems)} problems")
    return 1 if problems or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
