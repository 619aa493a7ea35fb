#!/usr/bin/env python3
"""Runs every command in README.md's ```sh blocks, so an example that stops working fails CI.

Each command runs as written, from a scratch folder that links the repository's files and `build/` to the build
tree, with one change: `--frames N` becomes `--frames min(N, FRAMES)` to keep the test short. A command must
exit 0 and leave what it promises: `--out DIR` a PNG per frame, `--state FILE` a CSV with a header and rows,
`--video FILE` a non-empty file, `--export-scene FILE` a JSON object. Two kinds are not run: `bash scripts/*.sh`
(installing packages, or the whole CI) is syntax-checked with `bash -n`, and `cmake` configure and build commands
are what made the build tree this test runs in. Any other command fails the test until it is taught here.

usage: readme_commands_test.py REPO BUILD_DIR WORK_DIR [README]
"""
import json
import os
import shlex
import shutil
import subprocess
import sys

FRAMES = 12


def commands(readme):
    """Every command line of the README's sh blocks, continuation lines joined, comments dropped."""
    out, in_sh, pending = [], False, ""
    for line in open(readme, encoding="utf-8"):
        stripped = line.strip()
        if stripped.startswith("```"):
            in_sh = (not in_sh) and stripped in ("```sh", "```bash")
            continue
        if not in_sh:
            continue
        if stripped.endswith("\\"):
            pending += stripped[:-1] + " "
            continue
        tokens = shlex.split(pending + stripped, comments=True)
        pending = ""
        if tokens:
            out.append(tokens)
    return out


def split_and(tokens):
    parts, part = [], []
    for t in tokens:
        if t == "&&":
            parts.append(part)
            part = []
        else:
            part.append(t)
    return parts + [part]


def scratch(repo, build, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    for name in os.listdir(repo):
        if name not in ("build", "out", ".git"):
            os.symlink(os.path.join(repo, name), os.path.join(work, name))
    os.symlink(os.path.abspath(build), os.path.join(work, "build"))


def value_of(args, flag):
    return args[args.index(flag) + 1] if flag in args and args.index(flag) + 1 < len(args) else None


def check_outputs(args, work):
    """Problems with what the command promised to write (empty list when all is there)."""
    problems = []
    frames = value_of(args, "--frames")
    out = value_of(args, "--out")
    if out and frames and "--only-frames" not in args:
        for i in range(int(frames)):
            if not os.path.isfile(os.path.join(work, out, "frame_%05d.png" % i)):
                problems.append("%s/frame_%05d.png missing" % (out, i))
                break
    state = value_of(args, "--state")
    if state:
        path = os.path.join(work, state)
        lines = open(path).read().splitlines() if os.path.isfile(path) else []
        if len(lines) < 2 or "," not in lines[0]:
            problems.append("--state %s: no CSV header and rows" % state)
    video = value_of(args, "--video")
    if video and not (os.path.isfile(os.path.join(work, video)) and os.path.getsize(os.path.join(work, video)) > 0):
        problems.append("--video %s: no file" % video)
    export = value_of(args, "--export-scene")
    if export:
        try:
            json.load(open(os.path.join(work, export)))
        except (OSError, ValueError) as e:
            problems.append("--export-scene %s: %s" % (export, e))
    return problems


def run_program(args, work):
    args = list(args)
    if "--frames" in args:
        i = args.index("--frames") + 1
        args[i] = str(min(int(args[i]), FRAMES))
    shown = " ".join(shlex.quote(a) for a in args)
    result = subprocess.run(args, cwd=work, capture_output=True, text=True, timeout=300)
    if result.returncode != 0:
        return ["`%s` exited %d: %s" % (shown, result.returncode, result.stderr.strip()[-400:])]
    return ["`%s`: %s" % (shown, p) for p in check_outputs(args, work)]


def run_part(part, repo, work):
    """Problems with one command of an `a && b` chain, and a line saying what was done."""
    if part[0] == "bash" and len(part) == 2 and part[1].startswith("scripts/"):
        script = os.path.join(repo, part[1])
        if not os.path.isfile(script):
            return ["%s: no such script" % part[1]], ""
        syntax = subprocess.run(["bash", "-n", script], capture_output=True, text=True)
        if syntax.returncode != 0:
            return ["%s: %s" % (part[1], syntax.stderr.strip())], ""
        ci = os.path.join(repo, ".ci", "run")
        if part[1] == "scripts/test.sh" and not (os.path.isfile(ci) and "scripts/test.sh" in open(ci).read()):
            return [".ci/run does not run scripts/test.sh, the README's test command"], ""
        return [], "syntax-checked %s" % part[1]
    if part[0] == "cmake":
        return [], "not run (this build tree was made by it): %s" % " ".join(part)
    if part[0].startswith("build/"):
        if not os.path.isfile(os.path.join(work, part[0])):
            return ["%s: not built" % part[0]], ""
        return run_program(part, work), "ran %s" % " ".join(part)
    return ["a README command this test cannot run: %s (teach tests/docs/readme_commands_test.py)" % " ".join(part)], ""


def main():
    repo, build, work = sys.argv[1:4]
    readme = sys.argv[4] if len(sys.argv) > 4 else os.path.join(repo, "README.md")
    scratch(repo, build, work)
    problems, ran = [], 0
    cmds = commands(readme)
    if not cmds:
        problems.append("%s: no commands found in its sh blocks" % readme)
    for tokens in cmds:
        for part in split_and(tokens):
            found, done = run_part(part, repo, work)
            problems += found
            ran += 1
            if done:
                print(done)
    for p in problems:
        print("FAIL " + p)
    print("readme_commands_test: %d commands, %d problems" % (ran, len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
