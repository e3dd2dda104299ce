#!/usr/bin/env python3
"""Checks the objectivity run (tests/pair_rotation.prm: a pressed pair at
finite strain turned by 90 degrees about (1, 0.5) between t = 1 and t = 2)
from its contact tables: at t = 2 every slave node stands where the
rotation takes it from t = 1 (its deformed position, to TOLERANCE times
the block's height of 0.5), and its contact pressure and tangential
traction are those of t = 1 to TOLERANCE of the largest pressure.

usage: check_pair_rotation.py <output folder> --tolerance TOLERANCE
"""
import argparse
import csv
import math
import os
import sys

CENTRE = (1.0, 0.5)


def read(output, increment):
    with open(os.path.join(output, f"contact-{increment:05d}.csv")) as f:
        return list(csv.DictReader(f))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("output")
    parser.add_argument("--tolerance", type=float, required=True)
    args = parser.parse_args()
    before, after = read(args.output, 2), read(args.output, 8)
    if len(before) != len(after) or not before:
        sys.exit(f"*** {len(before)} slave nodes at t = 1, {len(after)} at t = 2")
    largest = max(float(node["pressure"]) for node in before)
    if not largest > 0:
        sys.exit("*** no pressure at t = 1: the block does not press on the base")
    moved = pressure = traction = 0.0
    for a, b in zip(before, after):
        x, y = float(a["x"]) + float(a["ux"]), float(a["y"]) + float(a["uy"])
        turned = (CENTRE[0] - (y - CENTRE[1]), CENTRE[1] + (x - CENTRE[0]))
        moved = max(moved, math.hypot(float(b["x"]) + float(b["ux"]) - turned[0],
                                      float(b["y"]) + float(b["uy"]) - turned[1]))
        pressure = max(pressure, abs(float(b["pressure"]) - float(a["pressure"])))
        rt = [key for key in a if key.startswith("rt")]
        for key in rt:
            per_area_a = float(a[key]) / float(a["area"])
            per_area_b = float(b[key]) / float(b["area"])
            traction = max(traction, abs(per_area_b - per_area_a))
    print(f"largest pressure {largest:.6g}; after the rotation: nodes off the "
          f"rotated positions by {moved:.3g}, pressures changed by "
          f"{pressure / largest:.3g}, tangential tractions by "
          f"{traction / largest:.3g} (of the largest pressure)")
    failures = []
    if not moved <= args.tolerance * 0.5:
        failures.append(f"a slave node is {moved:.3g} off its rotated position")
    if not pressure <= args.tolerance * largest:
        failures.append(f"a pressure changed by {pressure / largest:.3g} of the "
                        f"largest, more than {args.tolerance:g}")
    if not traction <= args.tolerance * largest:
        failures.append(f"a tangential traction changed by {traction / largest:.3g} "
                        f"of the largest pressure, more than {args.tolerance:g}")
    for failure in failures:
        print("*** " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
