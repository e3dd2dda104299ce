#!/usr/bin/env python3
"""Compares a run of Lame's problem (a thick-walled tube in plane strain or
a thick-walled sphere, tests/lame_*.prm: the shell geometry under an
internal pressure, outer surface free) with the exact solution. Reads the
run's parameters.prm and its last displacement-NNNNN.csv and
stress-NNNNN.csv (Postprocess/Visualization/Write csv tables = true).

usage: check_lame.py OUTPUT_DIR [--tolerance 0.01]

Radial displacement at every vertex: |u_r - u_r,exact| <= tolerance *
max |u_r,exact|. Radial and hoop stress at every cell centre:
|sigma - sigma_exact| <= tolerance * p, with p the internal pressure.
Tube (plane strain), radii a < b:
  u_r = p a^2 (1 + nu) / (E (b^2 - a^2)) ((1 - 2 nu) r + b^2 / r)
  sigma_r = p a^2 / (b^2 - a^2) (1 - b^2 / r^2), sigma_t with 1 + b^2 / r^2
An axisymmetric run (Material/Two-dimensional model = axisymmetric: the
section x = r >= 0 of the sphere) is held to the sphere's solution, and
its circumferential stress (the stt column) to the hoop stress as well.
Sphere:
  u_r = p a^3 / (E (b^3 - a^3)) ((1 - 2 nu) r + (1 + nu) b^3 / (2 r^2))
  sigma_r = p a^3 / (b^3 - a^3) (1 - b^3 / r^3),
  sigma_t = p a^3 / (b^3 - a^3) (1 + b^3 / (2 r^3))
"""
import argparse
import csv
import glob
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_analytic import read_parameters  # noqa: E402


def last(directory, prefix):
    files = sorted(glob.glob(f"{directory}/{prefix}-*.csv"))
    if not files:
        sys.exit(f"no {prefix}-*.csv in {directory}: set Postprocess/Visualization/Write csv tables = true")
    with open(files[-1]) as f:
        return list(csv.DictReader(f))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("directory")
    parser.add_argument("--tolerance", type=float, default=0.01)
    args = parser.parse_args()
    prm = read_parameters(args.directory + "/parameters.prm")
    dim = int(prm["Dimension"])
    axisymmetric = prm.get("Material/Two-dimensional model") == "axisymmetric"
    E = float(prm["Material/Young's modulus"])
    nu = float(prm["Material/Poisson's ratio"])
    a = float(prm["Geometry/Shell/Inner radius"])
    b = float(prm["Geometry/Shell/Outer radius"])
    center = [float(c) for c in prm["Geometry/Shell/Center"].split(",")]
    pressure = prm["Boundary conditions/Pressure"]
    p = float(pressure.split(":")[1])
    axes = "xyz"[:dim]

    def radius(row):
        x = [float(row[c]) - center[i] for i, c in enumerate(axes)]
        return x, math.sqrt(sum(c * c for c in x))

    if dim == 2 and not axisymmetric:
        k = p * a * a / (b * b - a * a)
        u_exact = lambda r: k * (1 + nu) / E * ((1 - 2 * nu) * r + b * b / r)
        s_r = lambda r: k * (1 - b * b / r ** 2)
        s_t = lambda r: k * (1 + b * b / r ** 2)
    else:
        k = p * a ** 3 / (b ** 3 - a ** 3)
        u_exact = lambda r: k / E * ((1 - 2 * nu) * r + (1 + nu) * b ** 3 / (2 * r * r))
        s_r = lambda r: k * (1 - b ** 3 / r ** 3)
        s_t = lambda r: k * (1 + b ** 3 / (2 * r ** 3))

    worst_u = scale_u = 0
    for row in last(args.directory, "displacement"):
        x, r = radius(row)
        u_r = sum(float(row["u" + c]) * x[i] for i, c in enumerate(axes)) / r
        worst_u = max(worst_u, abs(u_r - u_exact(r)))
        scale_u = max(scale_u, abs(u_exact(r)))

    worst_r = worst_t = 0
    for row in last(args.directory, "stress"):
        x, r = radius(row)
        n = [c / r for c in x]
        sigma = [[0.0] * dim for _ in range(dim)]
        for i in range(dim):
            for j in range(dim):
                key = "s" + axes[min(i, j)] + axes[max(i, j)]
                sigma[i][j] = float(row[key])
        radial = sum(n[i] * sigma[i][j] * n[j] for i in range(dim) for j in range(dim))
        # The hoop stress: the trace of the in-plane stress less the radial
        # part, per remaining direction.
        hoop = (sum(sigma[i][i] for i in range(dim)) - radial) / (dim - 1)
        worst_r = max(worst_r, abs(radial - s_r(r)))
        worst_t = max(worst_t, abs(hoop - s_t(r)))
        if axisymmetric:
            worst_t = max(worst_t, abs(float(row["stt"]) - s_t(r)))

    errors = {"radial displacement": worst_u / scale_u,
              "radial stress": worst_r / p, "hoop stress": worst_t / p}
    ok = True
    for name, error in errors.items():
        passed = error <= args.tolerance
        ok = ok and passed
        print(f"Lame {'axisymmetric' if axisymmetric else f'{dim}D'}, nu = {nu:g}: {name} error {100 * error:.3f} % "
              f"(allowed {100 * args.tolerance:g} %): {'ok' if passed else 'TOO LARGE'}")
    print("PASSED" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
