#!/usr/bin/env python3
"""Checks that every relative link and image in the repository's Markdown files points at a file that exists.

Links to web addresses are not followed. An anchor (#...) into a Markdown file must name one of its headings, as
GitHub spells them (lower case, punctuation dropped, spaces as hyphens). Reads the tracked .md files (git ls-files),
or every .md file below the root when git is not available.
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


def slug(heading):
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def anchors(path, cache={}):
    """The heading anchors of a Markdown file (GitHub's spelling), with -1, -2 ... for repeated headings."""
    if path not in cache:
        seen, out, in_code = {}, set(), False
        for line in open(path, encoding="utf-8"):
            if line.lstrip().startswith("```"):
                in_code = not in_code
            if in_code or not line.startswith("#"):
                continue
            base = slug(line.lstrip("#"))
            n = seen.get(base, 0)
            seen[base] = n + 1
            out.add(base if n == 0 else "%s-%d" % (base, n))
        cache[path] = out
    return cache[path]


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
                if re.match(r"[a-z]+:", target):
                    continue
                local, _, anchor = target.partition("#")
                resolved = os.path.normpath(os.path.join(os.path.dirname(path), local)) if local else path
                if not os.path.exists(resolved):
                    problems.append("%s:%d: link to %s: no such file" % (rel, number, target))
                elif anchor and resolved.endswith(".md") and anchor not in anchors(resolved):
                    problems.append("%s:%d: link to %s: no heading with that anchor" % (rel, number, target))
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
