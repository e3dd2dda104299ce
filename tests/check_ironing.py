#!/usr/bin/env python3
"""Checks two runs of the ironing scene (parameters/ironing_2d.prm: the die,
a cylinder of radius 3 about (2.5, 6), pressed 1.4 in over t in [0, 1] and
slid 4 to the right over [1, 2]; the block 9 long), one frictionless and one
with friction coefficient MU, from their output folders (statistics and the
contact-NNNNN.csv tables):
- every node that presses on the die lies on its surface (its deformed
  position at distance 3 from the die's axis, to 1e-8) and no vertex of the
  block's surface is inside the die by more than 1e-8 of the indentation, in
  either run: the gaps are those of the deformed surface, not linearised at
  the reference one;
- frictionless, the die at mirrored positions x and 9 - x (times t and
  3 - t) feels mirrored forces (a hyperelastic body and no friction: the
  force depends on the die's position only), to 1e-6 of the largest force;
- with friction, once the die slides (t >= 1.5) no node sticks, the
  tangential force is at most MU times the normal one, and the drag
  exceeds the frictionless run's at every sliding increment.

usage: check_ironing.py <frictionless output> <frictional output> --mu MU
"""
import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_analytic import read_statistics, report  # noqa: E402

INDENTATION = 1.4
RADIUS = 3.0


def die_axis(t):
    """The die's axis at time t (the scene's Rigid displacement)."""
    return (2.5 + 4 * max(t - 1, 0), 6 - INDENTATION * min(t, 1))


def off_the_die(output, rows):
    """The largest | |x + u - axis| - R | of a node with pressure, over all
    increments of the run in @p output."""
    worst = 0.0
    for row in rows:
        path = os.path.join(output, f"contact-{int(row['Increment']):05d}.csv")
        cx, cy = die_axis(row["Time"])
        with open(path) as f:
            for node in csv.DictReader(f):
                if float(node["pressure"]) > 0:
                    x = float(node["x"]) + float(node["ux"])
                    y = float(node["y"]) + float(node["uy"])
                    worst = max(worst, abs(math.hypot(x - cx, y - cy) - RADIUS))
    return worst


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("frictionless")
    parser.add_argument("frictional")
    parser.add_argument("--mu", type=float, required=True)
    args = parser.parse_args()
    smooth = read_statistics(os.path.join(args.frictionless, "statistics"))
    rough = read_statistics(os.path.join(args.frictional, "statistics"))
    failures = []

    for name, output, rows in (("frictionless", args.frictionless, smooth),
                               ("frictional", args.frictional, rough)):
        deepest = max(row["Max boundary penetration"] for row in rows)
        off = off_the_die(output, rows)
        print(f"{name}: deepest vertex inside the die {deepest:.3g}, pressing "
              f"nodes off its surface by {off:.3g}")
        if deepest > 1e-8 * INDENTATION:
            failures.append(f"{name}: a vertex is {deepest:.3g} inside the die")
        if off > 1e-8 * RADIUS:
            failures.append(f"{name}: a pressing node is {off:.3g} off the die's surface")

    by_time = {round(row["Time"], 9): row for row in smooth}
    largest = max(abs(row["Contact force y"]) for row in smooth)
    worst, pairs = 0.0, 0
    for t, row in by_time.items():
        mirror = by_time.get(round(3 - t, 9))
        if t < 1 or mirror is None:
            continue
        pairs += 1
        worst = max(worst,
                    abs(row["Contact force x"] + mirror["Contact force x"]),
                    abs(row["Contact force y"] - mirror["Contact force y"]))
    print(f"frictionless: {pairs} mirrored positions, forces differ by "
          f"{worst / largest:.3g} of the largest")
    if pairs < 4 or worst > 1e-6 * largest:
        failures.append("frictionless: the forces at mirrored positions differ")

    smooth_drag = {round(row["Time"], 9): row["Contact force x"] for row in smooth}
    for row in rough:
        t = row["Time"]
        if t < 1.5 - 1e-9:
            continue
        ratio = row["Tangential contact force"] / row["Normal contact force"]
        if row["Stick nodes"] != 0:
            failures.append(f"frictional, t = {t:g}: {row['Stick nodes']:g} nodes stick")
        if ratio > args.mu * (1 + 1e-8):
            failures.append(f"frictional, t = {t:g}: tangential/normal force {ratio:.6g}")
        drag = smooth_drag.get(round(t, 9))
        if drag is not None and not row["Contact force x"] > drag:
            failures.append(f"frictional, t = {t:g}: drag {row['Contact force x']:.6g} "
                            f"not above the frictionless {drag:.6g}")
    last = rough[-1]
    print(f"frictional: at t = {last['Time']:g} drag {last['Contact force x']:.6g}, "
          f"press {-last['Contact force y']:.6g}")
    return report(failures)


if __name__ == "__main__":
    sys.exit(main())
