#!/usr/bin/env python3
"""Checks that the Newton steps of a run converge superlinearly at the end of
each increment, from its convergence histories (history-NNNNN.txt): in
every increment of at least 4 Newton steps, the last step is at most RATIO
times the step two before it. Steps that shrink linearly by a tenth give
1e-2 over two steps; quadratic convergence gives far less (the last step
is limited only by the forcing term's floor and round-off).

usage: check_superlinear.py <output folder> --ratio RATIO
"""
import argparse
import glob
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_analytic import report  # noqa: E402

STEP_COLUMN = 5  # iteration seconds force_balance complementarity penetration step ...


def steps(path):
    with open(path) as f:
        return [float(line.split()[STEP_COLUMN]) for line in f
                if line.strip() and not line.startswith("#")]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("output")
    parser.add_argument("--ratio", type=float, required=True)
    args = parser.parse_args()
    files = sorted(glob.glob(os.path.join(args.output, "history-*.txt")))
    if not files:
        sys.exit(f"*** no history-*.txt in {args.output}")
    failures, checked = [], 0
    for path in files:
        s = steps(path)
        if len(s) < 4:
            continue
        checked += 1
        ratio = s[-1] / s[-3] if s[-3] > 0 else float("inf")
        print(f"{os.path.basename(path)}: {len(s)} Newton steps, the last "
              f"{s[-1]:.3g}, {ratio:.2g} of the one two before")
        if not ratio <= args.ratio:
            failures.append(f"{os.path.basename(path)}: the last step is {ratio:.3g} "
                            f"of the step two before it, above {args.ratio:g}")
    if checked == 0:
        failures.append("no increment took 4 Newton steps or more")
    sys.exit(report(failures))


if __name__ == "__main__":
    main()
