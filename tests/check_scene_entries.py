#!/usr/bin/env python3
"""Checks that a scene file sets only entries that differ from their
documented defaults, each with a comment saying why (on the same line, or
on the line just above).

usage: check_scene_entries.py <contact executable> <scene.prm>
"""
import json
import re
import subprocess
import sys


def numbers(text):
    """The numbers of a value, or None if it is not a list of numbers."""
    pieces = [p for p in re.split(r"[,;:\s]+", text.strip()) if p]
    try:
        return [float(p) for p in pieces]
    except ValueError:
        return None


def same(value, default):
    if value.strip() == default.strip():
        return True
    a, b = numbers(value), numbers(default)
    return a is not None and b is not None and len(a) == len(b) and \
        all(abs(x - y) <= 1e-14 * max(1.0, abs(y)) for x, y in zip(a, b))


def main():
    if len(sys.argv) != 3 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(sys.argv) == 2 else 2
    contact, scene = sys.argv[1], sys.argv[2]
    listing = subprocess.run([contact, "--print-parameters", "--json", scene],
                             capture_output=True, text=True, check=True).stdout
    tree = json.loads(listing)

    problems, path, previous = [], [], ""
    for number, line in enumerate(open(scene), start=1):
        code, _, comment = line.partition("#")
        words = code.split()
        if words[:1] == ["subsection"]:
            path.append(code.strip()[len("subsection"):].strip())
        elif words[:1] == ["end"]:
            path.pop()
        elif words[:1] == ["set"]:
            name, _, value = code.strip()[len("set"):].partition("=")
            node = tree
            for section in path + [name.strip()]:
                node = node[section]
            where = f"line {number}: {'/'.join(path + [name.strip()])}"
            if same(value, node["default_value"]):
                problems.append(f"{where} = '{value.strip()}' is the default")
            if not comment.strip() and not previous.lstrip().startswith("#"):
                problems.append(f"{where} has no comment saying why")
        previous = line

    for problem in problems:
        print(f"{scene}: {problem}")
    print(f"{scene}: {'PASSED' if not problems else 'FAILED'}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
