#!/usr/bin/env python3
"""Checks what a run wrote: each path after --exists must exist, each after
--absent must not (a run writes nothing it does not announce, not even an
empty folder).

usage: check_files.py [--exists PATH ...] [--absent PATH ...]
"""
import argparse
import os
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exists", nargs="*", default=[])
    parser.add_argument("--absent", nargs="*", default=[])
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
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
