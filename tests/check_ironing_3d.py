#!/usr/bin/env python3
"""Compares the 3D ironing run (tests/ironing_3d.prm: the die a rigid tool
from a surface mesh, contact by mortar, a block of unit width in plane
strain) with the 2D ironing scene on the same cells (the die an analytic
cylinder, contact at the nodes), from their statistics files: at every
time both have, the drag (x force) agrees to DRAG and the press (the 2D y
force, the 3D z force) to PRESS, both relative to the largest 2D press. The two
discretisations differ (mortar against nodes, a faceted die against a
round one): they agree better on finer cells (doc/validation.md). With
--most-newton, the 3D run's Newton steps (its statistics' solver
iterations) are at most that many in all.

usage: check_ironing_3d.py <2D statistics> <3D statistics> --drag DRAG --press PRESS
                           [--most-newton N]
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_analytic import read_statistics, report  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("flat")
    parser.add_argument("solid")
    parser.add_argument("--drag", type=float, required=True)
    parser.add_argument("--press", type=float, required=True)
    parser.add_argument("--most-newton", type=int,
                        help="the most Newton steps the 3D run may take in all")
    args = parser.parse_args()
    flat = {round(row["Time"], 9): row for row in read_statistics(args.flat)}
    solid = {round(row["Time"], 9): row for row in read_statistics(args.solid)}
    times = sorted(set(flat) & set(solid))
    if len(times) < 10:
        sys.exit(f"*** only {len(times)} times in both runs")
    scale = max(abs(flat[t]["Contact force y"]) for t in times)
    if not scale > 0:
        sys.exit("*** the 2D die does not press")
    drag = press = 0.0
    for t in times:
        drag = max(drag, abs(solid[t]["Contact force x"] - flat[t]["Contact force x"]) / scale)
        press = max(press, abs(solid[t]["Contact force z"] - flat[t]["Contact force y"]) / scale)
    print(f"{len(times)} times: the 3D drag differs from the 2D one by at most "
          f"{drag:.3g}, the press by {press:.3g} (of the largest 2D press)")
    failures = []
    if not drag <= args.drag:
        failures.append(f"the drag differs by {drag:.3g}, more than {args.drag:g}")
    if not press <= args.press:
        failures.append(f"the press differs by {press:.3g}, more than {args.press:g}")
    if args.most_newton is not None:
        steps = sum(int(row["Contact solver iterations"]) for row in solid.values())
        print(f"the 3D run took {steps} Newton steps")
        if not steps <= args.most_newton:
            failures.append(f"the 3D run took {steps} Newton steps, more than "
                            f"{args.most_newton}")
    return report(failures)


if __name__ == "__main__":
    sys.exit(main())
