#!/usr/bin/env python3
"""Checks the objectivity run tests/j2_finite_rotation.prm: a body deformed
to the time 1 and then turned rigidly about z by phi = pi/2 (t - 1) with its
stretch held. In every cell and at every increment after t = 1 the Cauchy
stress must be R(phi) sigma(1) R(phi)^T, and the equivalent plastic strain
and the plastic strain components (on the reference configuration) those of
t = 1, within the tolerance relative to the largest stress component
(strains: to the largest plastic strain). The body must have flowed by
t = 1 and turned by 90 degrees at the end, or the check proves little.

usage: check_rotation.py OUTPUT_DIR --tolerance 1e-10
"""
import argparse
import csv
import glob
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_analytic import read_parameters  # noqa: E402

STRESS = ("sxx", "syy", "szz", "sxy", "sxz", "syz")
PLASTIC = ("equivalent_plastic_strain", "epxx", "epyy", "epzz", "epxy", "epxz", "epyz")


def matrix(row):
    s = {k: float(row[k]) for k in STRESS}
    return [[s["sxx"], s["sxy"], s["sxz"]],
            [s["sxy"], s["syy"], s["syz"]],
            [s["sxz"], s["syz"], s["szz"]]]


def turned(sigma, phi):
    c, s = math.cos(phi), math.sin(phi)
    R = [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]
    return [[sum(R[i][k] * sigma[k][l] * R[j][l] for k in range(3) for l in range(3))
             for j in range(3)] for i in range(3)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("directory")
    parser.add_argument("--tolerance", type=float, default=1e-10)
    args = parser.parse_args()
    p = read_parameters(os.path.join(args.directory, "parameters.prm"))
    end_time = float(p["Loading/End time"])
    n = int(p["Loading/Number of increments"])
    tables = []
    for name in sorted(glob.glob(os.path.join(args.directory, "stress-*.csv"))):
        with open(name) as f:
            tables.append(list(csv.DictReader(f)))
    times = [end_time * (k + 1) / n for k in range(n)]
    if len(tables) != n:
        sys.exit(f"{len(tables)} stress tables for {n} increments")
    first = min(range(n), key=lambda k: abs(times[k] - 1))
    if abs(times[first] - 1) > 1e-12:
        sys.exit("no increment ends at t = 1")
    reference = tables[first]
    stress_scale = max(abs(float(r[k])) for r in reference for k in STRESS)
    strain_scale = max(abs(float(r[k])) for r in reference for k in PLASTIC)
    worst_stress = worst_strain = 0.0
    for k in range(first + 1, n):
        phi = math.pi / 2 * (times[k] - 1)
        for row, before in zip(tables[k], reference):
            expected = turned(matrix(before), phi)
            actual = matrix(row)
            worst_stress = max(worst_stress, max(abs(actual[i][j] - expected[i][j])
                                                 for i in range(3) for j in range(3)))
            worst_strain = max(worst_strain, max(abs(float(row[c]) - float(before[c]))
                                                 for c in PLASTIC))
    flowed = min(float(r["equivalent_plastic_strain"]) for r in reference) > 0
    turned_fully = abs(math.pi / 2 * (times[-1] - 1) - math.pi / 2) < 1e-12
    ok = (flowed and turned_fully and worst_stress <= args.tolerance * stress_scale
          and worst_strain <= args.tolerance * strain_scale)
    print(f"turned by {math.degrees(math.pi / 2 * (times[-1] - 1)):.6g} degrees after "
          f"t = 1 (equivalent plastic strain {float(reference[0]['equivalent_plastic_strain']):.6g}): "
          f"Cauchy stress off R sigma R^T by {worst_stress / stress_scale:.2e}, plastic "
          f"strains changed by {worst_strain / strain_scale:.2e} (relative, allowed "
          f"{args.tolerance:g})" + ("" if flowed else "; the body did not flow"))
    print("PASSED" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
