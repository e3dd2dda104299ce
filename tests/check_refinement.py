#!/usr/bin/env python3
"""Checks that a column of the statistics of runs of one scene on finer and
finer meshes converges: at every increment the runs share, the change from
each mesh to the next (relative to the finest run's value) must be smaller
than the change before it, the last change below --at-most.

usage: check_refinement.py COARSE_STATISTICS ... FINEST_STATISTICS
           --column "Contact force z" --at-most 0.05
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_analytic import read_statistics  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("statistics", nargs="+")
    parser.add_argument("--column", required=True)
    parser.add_argument("--at-most", type=float, required=True)
    args = parser.parse_args()
    if len(args.statistics) < 3:
        sys.exit("three runs or more are needed to see the changes fall")
    runs = [{row["Increment"]: row[args.column] for row in read_statistics(path)}
            for path in args.statistics]
    increments = sorted(set.intersection(*(set(run) for run in runs)))
    failures, largest_last = [], 0.0
    for k in increments:
        values = [run[k] for run in runs]
        scale = abs(values[-1])
        changes = [abs(b - a) / scale for a, b in zip(values, values[1:])]
        largest_last = max(largest_last, changes[-1])
        if any(later >= earlier for earlier, later in zip(changes, changes[1:])):
            failures.append(f"increment {k:g}: changes " + ", ".join(f"{c:.2e}" for c in changes))
    final = [run[increments[-1]] for run in runs]
    print(f"{args.column} on {len(runs)} meshes at {len(increments)} increments; at the last: "
          + ", ".join(f"{v:.6g}" for v in final)
          + f"; the last change at most {100 * largest_last:.2f} % (allowed "
          f"{100 * args.at_most:g} %)")
    for failure in failures:
        print("*** not falling at " + failure)
    ok = bool(increments) and not failures and largest_last <= args.at_most
    print("PASSED" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
