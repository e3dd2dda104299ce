#!/usr/bin/env python3
"""Compares a run of Lame's problem past first yield (tests/lame_plastic_*.prm:
the shell geometry of elastic-perfectly plastic J2 material under an internal
pressure p that is loaded and then removed, Load table 0: 0; 1: 1; 2: 0) with
the closed-form solution (Hill, The Mathematical Theory of Plasticity, ch. V;
exact for von Mises by the symmetry). Radii a < c < b, c the elastic-plastic
radius, sigma_y the yield stress.

Sphere: yield where sigma_t - sigma_r = sigma_y;
  plastic (r < c): sigma_r = -p + 2 sigma_y ln(r/a), sigma_t = sigma_r + sigma_y
  elastic: sigma_r = -(2 sigma_y c^3 / (3 b^3)) (b^3 / r^3 - 1),
           sigma_t =  (2 sigma_y c^3 / (3 b^3)) (b^3 / (2 r^3) + 1)
  p = 2 sigma_y ln(c/a) + 2 sigma_y / 3 (1 - c^3 / b^3)
An axisymmetric run (Material/Two-dimensional model = axisymmetric) is the
section x = r >= 0 of the sphere.
Tube in plane strain, incompressible (nu -> 1/2, so sigma_z is the mean of
sigma_r and sigma_t): with k = sigma_y / sqrt(3),
  plastic: sigma_r = -p + 2 k ln(r/a), sigma_t = sigma_r + 2 k
  elastic: sigma_r = -k c^2 (1/r^2 - 1/b^2), sigma_t = k c^2 (1/r^2 + 1/b^2)
  p = 2 k ln(c/a) + k (1 - c^2 / b^2)
After unloading, the residual stresses are these less the elastic (Lame)
stresses of p, as long as nothing yields again (p below twice the first
yield pressure).

usage: check_lame_plastic.py OUTPUT_DIR [--tolerance 0.02]

Checks, at the peak (the last increment at t = 1) and after unloading (the
last increment): the radial and hoop stress of every cell within tolerance *
p of the closed form; at the peak the elastic-plastic radius (the largest
centre radius of a flowing cell, yield_state 2) within one cell of c, c
found from p by bisection; and at each loading increment past first yield
its elastic-plastic radius against that of its pressure (the pressure-radius
relation).
"""
import argparse
import csv
import glob
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_analytic import read_parameters  # noqa: E402
import check_statistics  # noqa: E402


def plastic_radius(p, a, b, sphere, sigma_y):
    def pressure(c):
        if sphere:
            return 2 * sigma_y * math.log(c / a) + 2 * sigma_y / 3 * (1 - c ** 3 / b ** 3)
        k = sigma_y / math.sqrt(3)
        return 2 * k * math.log(c / a) + k * (1 - c ** 2 / b ** 2)
    if p < pressure(a):
        return a
    low, high = a, b
    for _ in range(100):
        mid = (low + high) / 2
        low, high = (mid, high) if pressure(mid) < p else (low, mid)
    return (low + high) / 2


def loaded(r, p, a, b, c, sphere, sigma_y):
    if sphere:
        if r < c:
            radial = -p + 2 * sigma_y * math.log(r / a)
            return radial, radial + sigma_y
        s = 2 * sigma_y * c ** 3 / (3 * b ** 3)
        return -s * (b ** 3 / r ** 3 - 1), s * (b ** 3 / (2 * r ** 3) + 1)
    k = sigma_y / math.sqrt(3)
    if r < c:
        radial = -p + 2 * k * math.log(r / a)
        return radial, radial + 2 * k
    return -k * c ** 2 * (1 / r ** 2 - 1 / b ** 2), k * c ** 2 * (1 / r ** 2 + 1 / b ** 2)


def elastic(r, p, a, b, sphere):
    if sphere:
        s = p * a ** 3 / (b ** 3 - a ** 3)
        return s * (1 - b ** 3 / r ** 3), s * (1 + b ** 3 / (2 * r ** 3))
    s = p * a ** 2 / (b ** 2 - a ** 2)
    return s * (1 - b ** 2 / r ** 2), s * (1 + b ** 2 / r ** 2)


def stresses(row, dim, center, axisymmetric=False):
    """Radius, radial and hoop stress of a stress table's row (of an
    axisymmetric section of the sphere: the mean of the meridional and the
    circumferential hoop stress)."""
    axes = "xyz"[:dim]
    x = [float(row[c]) - center[i] for i, c in enumerate(axes)]
    r = math.sqrt(sum(v * v for v in x))
    n = [v / r for v in x]
    def component(i, j):
        return float(row["s" + "".join(sorted(axes[i] + axes[j], key="xyz".index))])
    s = [[component(i, j) for j in range(dim)] for i in range(dim)]
    radial = sum(n[i] * s[i][j] * n[j] for i in range(dim) for j in range(dim))
    trace = sum(s[i][i] for i in range(dim))
    hoop = (trace - radial) / 2 if dim == 3 else trace - radial
    if axisymmetric:
        hoop = (hoop + float(row["stt"])) / 2
    return r, radial, hoop


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("directory")
    parser.add_argument("--tolerance", type=float, default=0.02)
    args = parser.parse_args()
    prm = read_parameters(args.directory + "/parameters.prm")
    dim = int(prm["Dimension"])
    axisymmetric = prm.get("Material/Two-dimensional model") == "axisymmetric"
    sphere = dim == 3 or axisymmetric
    a = float(prm["Geometry/Shell/Inner radius"])
    b = float(prm["Geometry/Shell/Outer radius"])
    center = [float(v) for v in prm["Geometry/Shell/Center"].split(",")]
    sigma_y = float(prm["Material/J2 plasticity/Yield stress"])
    p = float(prm["Boundary conditions/Pressure"].split(":")[1])
    c = plastic_radius(p, a, b, sphere, sigma_y)

    columns, rows = check_statistics.read_statistics(args.directory + "/statistics")
    times = [float(row[columns["Time"]]) for row in rows]
    peak = times.index(1.0) + 1
    files = sorted(glob.glob(args.directory + "/stress-*.csv"))
    ok = True
    for label, number, residual in (("at the peak", peak, False),
                                    ("after unloading", len(times), True)):
        worst, largest_flowing, sizes = 0.0, a, []
        with open(files[number - 1]) as f:
            table = list(csv.DictReader(f))
        for row in table:
            r, radial, hoop = stresses(row, dim, center, axisymmetric)
            exact_r, exact_t = loaded(r, p, a, b, c, sphere, sigma_y)
            if residual:
                elastic_r, elastic_t = elastic(r, p, a, b, sphere)
                exact_r, exact_t = exact_r - elastic_r, exact_t - elastic_t
            worst = max(worst, abs(radial - exact_r) / p, abs(hoop - exact_t) / p)
            if row["yield_state"] == "2":
                largest_flowing = max(largest_flowing, r)
        passed = worst <= args.tolerance
        text = (f"Lame {'sphere' if sphere else 'tube'} past yield, {label}: stresses off "
                f"by {100 * worst:.2f} % of p (allowed {100 * args.tolerance:g} %)")
        if not residual:
            radial_cells = sorted({round(stresses(row, dim, center, axisymmetric)[0], 6) for row in table})
            spacing = max(y - x for x, y in zip(radial_cells, radial_cells[1:]))
            passed = passed and abs(largest_flowing - c) <= spacing
            text += (f"; elastic-plastic radius {largest_flowing:.4f} against {c:.4f} "
                     f"(allowed one cell, {spacing:.4f})")
        print(text)
        ok = ok and passed
    # The pressure-radius relation along the loading: each increment past
    # first yield flows out to the radius of its pressure.
    for number, t in enumerate(times, start=1):
        if t > 1 or plastic_radius(p * t, a, b, sphere, sigma_y) <= a:
            continue
        with open(files[number - 1]) as f:
            table = list(csv.DictReader(f))
        flowing = max([stresses(row, dim, center, axisymmetric)[0] for row in table
                       if row["yield_state"] == "2"] or [a])
        radii = sorted({round(stresses(row, dim, center, axisymmetric)[0], 6) for row in table})
        spacing = max(y - x for x, y in zip(radii, radii[1:]))
        c_t = plastic_radius(p * t, a, b, sphere, sigma_y)
        print(f"  t = {t:g}, p = {p * t:.6g}: elastic-plastic radius {flowing:.4f} "
              f"against {c_t:.4f}")
        ok = ok and abs(flowing - c_t) <= spacing
    print("PASSED" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
