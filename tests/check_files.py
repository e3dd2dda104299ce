#!/usr/bin/env python3
"""Checks what a run wrote: each path after --exists must exist, each after
--absent must not (a run writes nothing it does not announce, not even an
empty folder), and the first file matching the --contains pattern must
contain each of the given texts.

usage: check_files.py [--exists PATH ...] [--absent PATH ...]
                      [--contains GLOB TEXT ...]
"""
import glob
import argparse
import os
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exists", nargs="*", default=[])
    parser.add_argument("--absent", nargs="*", default=[])
    parser.add_argument("--contains", nargs="+", default=[])
    arguments = parser.parse_args()
    failed = False
    for path in arguments.exists:
        ok = os.path.exists(path)
        failed |= not ok
        print(f"{path}: {'exists' if ok else 'MISSING'}")
    for path in arguments.absent:
        ok = not os.path.exists(path)
        failed |= not ok
        print(f"{path}: {'absent' if ok else 'PRESENT, but nothing asked for it'}")
    if arguments.contains:
        files = sorted(glob.glob(arguments.contains[0]))
        text = open(files[0], errors="replace").read() if files else ""
        print(f"{files[0] if files else arguments.contains[0] + ': no such file'}")
        failed |= not files
        for wanted in arguments.contains[1:]:
            ok = wanted in text
            failed |= not ok
            print(f"  {wanted!r}: {'found' if ok else 'MISSING'}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
