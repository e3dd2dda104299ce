#!/usr/bin/env python3
"""Checks an objectivity run (tests/pair_rotation.prm, pair_rotation_3d.prm:
a pressed pair at finite strain turned by 90 degrees between t = 1 and
t = 2, in 2D about (1, 0.5), in 3D about the line x = 1, z = 0.5) from its
contact tables: at t = 2 every slave node stands where the rotation takes
it from t = 1 (its deformed position, to TOLERANCE times the block's
height of 0.5), and its contact pressure and tangential traction are
those of t = 1 to TOLERANCE of the largest pressure (in 3D the traction's
magnitude: the tangents of a frame are not unique).

usage: check_pair_rotation.py <output folder> --tolerance TOLERANCE
"""
import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_analytic import report  # noqa: E402

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
    # The plane of the rotation: (x, y) in 2D, (x, z) in 3D.
    axes = ("x", "z") if "z" in before[0] else ("x", "y")
    moved = pressure = traction = 0.0
    for a, b in zip(before, after):
        position = [float(a[c]) + float(a["u" + c]) for c in axes]
        turned = (CENTRE[0] - (position[1] - CENTRE[1]),
                  CENTRE[1] + (position[0] - CENTRE[0]))
        reached = [float(b[c]) + float(b["u" + c]) for c in axes]
        off = math.hypot(reached[0] - turned[0], reached[1] - turned[1])
        if "y" not in axes:
            off = math.hypot(off, float(b["y"]) + float(b["uy"])
                             - float(a["y"]) - float(a["uy"]))
        moved = max(moved, off)
        pressure = max(pressure, abs(float(b["pressure"]) - float(a["pressure"])))
        rt = [key for key in a if key.startswith("rt")]
        if len(rt) == 1:
            change = float(b[rt[0]]) / float(b["area"]) - float(a[rt[0]]) / float(a["area"])
        else:
            change = (math.hypot(*(float(b[key]) for key in rt)) / float(b["area"])
                      - math.hypot(*(float(a[key]) for key in rt)) / float(a["area"]))
        traction = max(traction, abs(change))
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
    return report(failures)


if __name__ == "__main__":
    sys.exit(main())
