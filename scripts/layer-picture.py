#!/usr/bin/env python3
"""Draws the layer table of README.md ("Layout") as a text picture for docs/architecture.md.

Layers are drawn in levels: a layer sits one level above the highest layer it may include, so every arrow points
down. Each layer lists only the layers it includes directly that no other layer it includes already brings in
(the transitive reduction), which is what a picture of the table needs. GL/ImGui layers are marked [GL].
The picture sits in docs/architecture.md between the markers `<!-- layers:begin` and `<!-- layers:end -->`.

usage: scripts/layer-picture.py [--root REPO]           # rewrite the picture in docs/architecture.md
       scripts/layer-picture.py --check [--root REPO]   # exit 1 if the picture differs from the README's table
"""
import argparse
import importlib.util
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def read_table(root):
    spec = importlib.util.spec_from_file_location("check_layers", os.path.join(HERE, "check-layers.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.read_table(os.path.join(root, "README.md"))


def levels(layers):
    level = {}

    def of(name):
        if name not in level:
            below = [of(d) for d in layers[name][0] if d in layers and d != name]
            level[name] = 1 + max(below) if below else 0
        return level[name]

    for name in layers:
        of(name)
    return level


def reduced(layers):
    """Each layer's direct dependencies less those reachable through another of them."""
    def reach(name, seen):
        for d in layers[name][0]:
            if d in layers and d not in seen:
                seen.add(d)
                reach(d, seen)
        return seen

    out = {}
    for name, (allowed, _) in layers.items():
        deps = [d for d in allowed if d in layers]
        out[name] = sorted(d for d in deps if not any(d in reach(o, set()) for o in deps if o != d))
    return out


def picture(layers):
    level, deps = levels(layers), reduced(layers)
    order = list(layers)  # the table's order within a level
    width = max(len(n) for n in layers) + 7
    lines = ["```"]
    for lv in range(max(level.values()), -1, -1):
        names = [n for n in order if level[n] == lv]
        for i, name in enumerate(names):
            tag = ("[GL] " if layers[name][1] else "     ") + name + "/"
            head = ("level %d  " % lv) if i == 0 else "         "
            arrow = ("──▶ " + ", ".join(d + "/" for d in deps[name])) if deps[name] else "(includes no other layer)"
            lines.append(head + tag.ljust(width) + arrow)
        if lv > 0:
            lines.append("         │")
    lines.append("```")
    return lines


def replace_block(text, lines):
    begin = text.index("<!-- layers:begin")
    begin = text.index("\n", begin) + 1
    end = text.index("<!-- layers:end -->")
    return text[:begin] + "\n".join(lines) + "\n" + text[end:]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--root", default=os.path.dirname(HERE))
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    path = os.path.join(args.root, "docs", "architecture.md")
    text = open(path, encoding="utf-8").read()
    new = replace_block(text, picture(read_table(args.root)))
    if args.check:
        if new != text:
            sys.exit("layer-picture: docs/architecture.md's layer picture differs from README.md's table; run "
                     "scripts/layer-picture.py")
        return 0
    with open(path, "w", encoding="utf-8") as f:
        f.write(new)
    return 0


if __name__ == "__main__":
    sys.exit(main())
