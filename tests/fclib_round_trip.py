#!/usr/bin/env python3
"""The FCLIB round trip: a scene exports an increment as an FCLIB global
problem with its solution; the stored solution must pass FCLIB's error
measure, and the program, solving the file again from scratch with the
accelerated primal-dual method, must find the same solution.

usage: fclib_round_trip.py <contact> <scene.prm> [--ranks N] [--limit 1e-8]
Runs in the current folder; the scene writes output-fclib/fclib-00001.hdf5.
"""
import argparse
import re
import subprocess
import sys


def run(command, ranks):
    if ranks > 0:
        command = ["mpirun", "-np", str(ranks)] + command
    print("$", " ".join(command), flush=True)
    result = subprocess.run(command, capture_output=True, text=True)
    print(result.stdout + result.stderr, flush=True)
    if result.returncode != 0:
        sys.exit(f"*** exit code {result.returncode}")
    return result.stdout


def number(pattern, text):
    match = re.search(pattern, text)
    if not match:
        sys.exit(f"*** no line matching {pattern!r}")
    return [float(group) for group in match.groups()]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("contact")
    parser.add_argument("scene")
    parser.add_argument("--ranks", type=int, default=0)
    parser.add_argument("--limit", type=float, default=1e-8)
    arguments = parser.parse_args()
    contact, ranks, limit = arguments.contact, arguments.ranks, arguments.limit
    exported = "output-fclib/fclib-00001.hdf5"

    run([contact, arguments.scene], ranks)
    stored = run([contact, "--fclib", exported, "--evaluate", exported], 0)
    imported = run([contact, "--fclib", exported, "--solution", "imported.hdf5"],
                   ranks)
    compared = run([contact, "--fclib", exported, "--evaluate", "imported.hdf5",
                    "--reference", exported], 0)

    checks = [
        ("FCLIB error of the exported solution",
         number(r"FCLIB error: (\S+)", stored)[0]),
        ("FCLIB error of the imported problem's solution",
         number(r"FCLIB error: (\S+)", imported)[0]),
    ]
    v, r = number(r"Relative difference to the solution in \S+: v (\S+), r (\S+)",
                  compared)
    checks += [("relative difference in v", v), ("relative difference in r", r)]
    failed = False
    for name, value in checks:
        verdict = "ok" if value <= limit else "FAILED"
        failed |= value > limit
        print(f"{name}: {value:.3e} (limit {limit:g}) {verdict}")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
