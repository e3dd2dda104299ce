#!/usr/bin/env python3
"""Checks a tensile test of a round bar with a neck imperfection
(tests/j2_finite_necking.prm: the quarter of the upper half of a bar,
<Geometry/Billet/Neck imperfection> > 0, its top face pulled along z, the
bottom face its mid-plane) against Considere's condition: the largest
load of the homogeneous bar, max over the logarithmic strain eps of
sigma(eps) A(eps), with the Cauchy stress sigma = tau / J and the current
section A = A0 lambda^2 of the 1D law that check_uniaxial.py integrates
(Hencky, isochoric flow: the lateral logarithmic strain -nu tau / E -
eps_p / 2). A0 is the reference section of the mesh's top face (the
polygon of its side vertices: a Q1 mesh of a circle is a polygon).

The run passes when
- its peak force (column 'Prescribed boundary force z' of statistics) is
  below the homogeneous maximum and within --tolerance of it (the
  imperfection lowers it a little);
- the force falls after its peak by more than --tolerance, and
- the neck forms at the imperfection: at the end, the radial stretch of
  the bottom face's rim is smaller than the top face's by at least
  --neck (relative), where the imperfection alone makes them differ by
  the imperfection.

usage: check_necking.py OUTPUT_DIR --tolerance 0.01 --neck 0.1
"""
import argparse
import csv
import glob
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_analytic import read_parameters, read_statistics  # noqa: E402
from check_uniaxial import exact_path, yield_curve  # noqa: E402


def rim(rows, z):
    """The vertices of the side at height z: (reference x, y, current x, y),
    by angle."""
    at = [r for r in rows if abs(float(r["z"]) - z) < 1e-9 * max(1.0, abs(z))]
    radius = max(math.hypot(float(r["x"]), float(r["y"])) for r in at)
    side = [r for r in at if math.hypot(float(r["x"]), float(r["y"])) > (1 - 1e-9) * radius]
    side.sort(key=lambda r: math.atan2(float(r["y"]), float(r["x"])))
    return [(float(r["x"]), float(r["y"]), float(r["x"]) + float(r["ux"]),
             float(r["y"]) + float(r["uy"])) for r in side]


def quarter_area(points):
    """The area of the polygon of the origin and @p points (by angle)."""
    polygon = [(0.0, 0.0)] + points
    return 0.5 * abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1)
                         in zip(polygon, polygon[1:] + polygon[:1])))


def mean_stretch(points):
    return sum(math.hypot(X, Y) for _, _, X, Y in points) / \
        sum(math.hypot(x, y) for x, y, _, _ in points)


def homogeneous_maximum(p, section):
    """max over eps of sigma(eps) A0 lambda(eps)^2 and its strain."""
    E = float(p["Material/Young's modulus"])
    nu = float(p["Material/Poisson's ratio"])
    strains = [i * 1e-4 for i in range(1, 10001)]
    best = (0.0, 0.0)
    for eps, (tau, _, plastic) in zip(strains, exact_path(strains, E, yield_curve(p), 0.0)):
        lateral = -nu * tau / E - plastic / 2
        force = tau / math.exp(eps + 2 * lateral) * section * math.exp(2 * lateral)
        best = max(best, (force, eps))
    return best


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("directory")
    parser.add_argument("--tolerance", type=float, required=True)
    parser.add_argument("--neck", type=float, required=True)
    args = parser.parse_args()
    p = read_parameters(os.path.join(args.directory, "parameters.prm"))
    height = float(p["Geometry/Billet/Height"])
    imperfection = float(p["Geometry/Billet/Neck imperfection"])
    if imperfection <= 0 or p.get("Geometry/Billet/Symmetry planes", "2") != "2":
        sys.exit("FAILED: the check is for the quarter bar with a neck imperfection")
    files = sorted(glob.glob(os.path.join(args.directory, "displacement-*.csv")))
    with open(files[-1], newline="") as f:
        last = list(csv.DictReader(f))
    top, bottom = rim(last, height), rim(last, 0.0)
    maximum, strain = homogeneous_maximum(p, quarter_area([(x, y) for x, y, _, _ in top]))
    forces = [r["Prescribed boundary force z"] for r in
              read_statistics(os.path.join(args.directory, "statistics"))]
    peak = max(forces)
    below = (maximum - peak) / maximum
    fall = (peak - forces[-1]) / peak
    neck = 1 - mean_stretch(bottom) / mean_stretch(top)
    print(f"homogeneous maximum {maximum:.6g} at eps = {strain:.4f}; peak {peak:.6g} "
          f"({100 * below:.3f} % below), then down by {100 * fall:.1f} %; radial "
          f"stretch at the neck {100 * neck:.1f} % below the top's (imperfection "
          f"{100 * imperfection:.2f} %)")
    failures = []
    if not 0 <= below <= args.tolerance:
        failures.append(f"the peak is not within {args.tolerance} below the maximum")
    if fall <= args.tolerance:
        failures.append("the force does not fall after its peak")
    if neck < args.neck:
        failures.append(f"no neck: the stretches differ by less than {args.neck}")
    if failures:
        sys.exit("FAILED: " + "; ".join(failures))
    print("PASSED")


if __name__ == "__main__":
    main()
