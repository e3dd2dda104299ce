#!/usr/bin/env python3
"""Checks that a finite-strain run agrees with the small-strain run of the
same scene and mesh where the strains are small (tests/step42_shallow_*):
the contact force (statistics, Contact force z, of the last increment), the
plastic zone (the cells whose equivalent plastic strain is > 0, in the last
stress-NNNNN.csv) and the integral of the equivalent plastic strain over
the cells (the mesh is uniform: their sum) within the relative --tolerance,
the same number of cells in both runs, and the zone not empty.

usage: check_small_strain_limit.py SMALL_DIR FINITE_DIR --tolerance 0.01
"""
import argparse
import csv
import glob
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_analytic import read_statistics  # noqa: E402


def measures(directory):
    force = read_statistics(os.path.join(directory, "statistics"))[-1]["Contact force z"]
    with open(sorted(glob.glob(os.path.join(directory, "stress-*.csv")))[-1]) as f:
        plastic = [float(r["equivalent_plastic_strain"]) for r in csv.DictReader(f)]
    return {"force": abs(force), "plastic cells": sum(e > 0 for e in plastic),
            "plastic strain integral": sum(plastic), "cells": len(plastic),
            "largest plastic strain": max(plastic)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("small")
    parser.add_argument("finite")
    parser.add_argument("--tolerance", type=float, default=0.01)
    args = parser.parse_args()
    small, finite = measures(args.small), measures(args.finite)
    deviations = {k: abs(finite[k] / small[k] - 1)
                  for k in ("force", "plastic cells", "plastic strain integral")}
    ok = (small["cells"] == finite["cells"] and small["plastic cells"] > 0
          and all(v <= args.tolerance for v in deviations.values()))
    print(f"finite against small strain, {small['cells']} cells, plastic strains up to "
          f"{small['largest plastic strain']:.3g}: "
          + ", ".join(f"{k} {small[k]:.6g} and {finite[k]:.6g} ({100 * v:.2f} %)"
                      for k, v in deviations.items())
          + f" (allowed {100 * args.tolerance:g} %)"
          + ("" if small["cells"] == finite["cells"] else "; the meshes differ"))
    print("PASSED" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
