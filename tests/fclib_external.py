#!/usr/bin/env python3
"""Solves an FCLIB problem from outside the project and compares the result
with Siconos' solution of the same file (stored next to it): the error
measure must be below --limit and the velocities v within --difference of
Siconos' (relative, Euclidean norm).

usage: fclib_external.py <contact> <problem.hdf5> <siconos.hdf5>
                         [--limit 1e-8] [--difference 1e-6]
"""
import argparse
import re
import subprocess
import sys


def run(command):
    print("$", " ".join(command), flush=True)
    result = subprocess.run(command, capture_output=True, text=True)
    print(result.stdout + result.stderr, flush=True)
    if result.returncode != 0:
        sys.exit(f"*** exit code {result.returncode}")
    return result.stdout


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("contact")
    parser.add_argument("problem")
    parser.add_argument("siconos")
    parser.add_argument("--limit", type=float, default=1e-8)
    parser.add_argument("--difference", type=float, default=1e-6)
    arguments = parser.parse_args()

    run([arguments.contact, "--fclib", arguments.problem, "--solution", "ours.hdf5"])
    output = run([arguments.contact, "--fclib", arguments.problem,
                  "--evaluate", "ours.hdf5", "--reference", arguments.siconos])
    error = float(re.search(r"FCLIB error: (\S+)", output).group(1))
    v, r = (float(x) for x in re.search(
        r"Relative difference to the solution in \S+: v (\S+), r (\S+)",
        output).groups())
    checks = [("FCLIB error", error, arguments.limit),
              ("relative difference to Siconos in v", v, arguments.difference)]
    failed = False
    for name, value, limit in checks:
        failed |= not value <= limit
        print(f"{name}: {value:.3e} (limit {limit:g}) "
              f"{'ok' if value <= limit else 'FAILED'}")
    print(f"relative difference to Siconos in r: {r:.3e} (not checked: r is "
          "not unique where contacts share a body)")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
