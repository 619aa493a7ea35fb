#!/usr/bin/env python3
"""Checks that every relative link and image in the repository's Markdown files points at a file that exists.

Links to web addresses and to anchors alone (#...) are not followed; an anchor after a path is dropped. Reads the
tracked .md files (git ls-files), or every .md file below the root when git is not available.
usage: check-doc-links.py REPO_ROOT. Prints one line per broken link; exit 1 if any, else 0.
"""
import os
import re
import subprocess
import sys

LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")


def markdown_files(root):
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "*.md"], capture_output=True, text=True, check=True)
        return [f for f in out.stdout.split("\n") if f]
    except (OSError, subprocess.CalledProcessError):
        return [os.path.relpath(os.path.join(d, f), root) for d, _, fs in os.walk(root) for f in fs if f.endswith(".md")]


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "."
    problems = []
    for rel in markdown_files(root):
        path = os.path.join(root, rel)
        if not os.path.exists(path):
            continue
        in_code = False
        for number, line in enumerate(open(path, encoding="utf-8"), 1):
            if line.lstrip().startswith("```"):
                in_code = not in_code
            if in_code:
                continue
            for target in LINK.findall(line):
                if re.match(r"[a-z]+:", target) or target.startswith("#"):
                    continue
                local = target.split("#", 1)[0]
                if not os.path.exists(os.path.normpath(os.path.join(os.path.dirname(path), local))):
                    problems.append("%s:%d: link to %s: no such file" % (rel, number, target))
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
