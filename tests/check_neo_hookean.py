#!/usr/bin/env python3
"""Checks a run of a neo-Hookean block compressed between rollers and a
frictionless rigid plane (tests/neo_hookean_compression_*.prm,
tests/nearly_incompressible_compression_*.prm) against the homogeneous
uniaxial solution of its law, which the Q1 element holds exactly at any
stretch: 'neo-Hookean', W = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2,
or 'nearly incompressible neo-Hookean', W = mu/2 (J^-2/3 tr C - 3) +
kappa/4 (J^2 - 1 - 2 ln J) (its cell's mean volume ratio is J itself).

With lambda_1 the axial stretch (the last axis: y in 2D, z in 3D) and
lambda_2 the lateral one (plane strain: the out-of-plane stretch is 1), the
lateral stress vanishes where
  mu (lambda_2^2 - 1) + lambda ln J = 0,  J = lambda_1 lambda_2^(dim - 1),
the axial second Piola-Kirchhoff stress is S = mu (1 - lambda_1^-2) +
lambda ln J lambda_1^-2, the Cauchy stress lambda_1^2 S / J, the nominal
contact pressure -lambda_1 S, and in plane strain sigma_zz = lambda ln J / J.
For the split law the principal Cauchy stresses are sigma_i = mu J^-5/3
(lambda_i^2 - I_1/3) + kappa/2 (J - 1/J) (I_1 over the three stretches, the
out-of-plane one 1 in plane strain), and lambda_2 makes sigma_2 vanish.

usage: check_neo_hookean.py OUTPUT_DIR --tolerance 1e-10

For every increment: the displacement of every vertex (lateral (lambda_2 -
1) X, axial (lambda_1 - 1) X) relative to the largest displacement, the
Cauchy stress of every cell and the contact pressure of every contact node
relative to the axial stress, and det F of every cell. lambda_1 is read
from the top vertices; the path must compress the block by more than 20 %,
or the check proves little of finite strain.
"""
import argparse
import csv
import glob
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_analytic import read_parameters  # noqa: E402


def rows(path):
    with open(path) as f:
        return [{k: float(v) if k != "state" else v for k, v in row.items()}
                for row in csv.DictReader(f)]


def lateral_stretch(axial, mu, lam, dim):
    """lambda_2 with mu (lambda_2^2 - 1) + lambda ln(lambda_1 lambda_2^(dim-1)) = 0."""
    stretch = 1.0
    for _ in range(100):
        f = mu * (stretch ** 2 - 1) + lam * math.log(axial * stretch ** (dim - 1))
        df = 2 * mu * stretch + lam * (dim - 1) / stretch
        step = f / df
        stretch -= step
        if abs(step) < 1e-16:
            break
    return stretch


def split_law_stresses(axial, lateral, mu, kappa, dim):
    """The principal Cauchy stresses (axial, lateral, out of plane) of the
    nearly incompressible law at the stretches (axial, lateral)."""
    stretches = [axial] + [lateral] * (dim - 1) + ([1.0] if dim == 2 else [])
    J = axial * lateral ** (dim - 1)
    first = sum(x * x for x in stretches)
    pressure = kappa / 2 * (J - 1 / J)
    return [mu * J ** (-5 / 3) * (x * x - first / 3) + pressure for x in stretches]


def split_law_lateral_stretch(axial, mu, kappa, dim):
    """lambda_2 where the lateral stress of the split law vanishes (secant)."""
    a, b = 1.0, 1.01
    fa = split_law_stresses(axial, a, mu, kappa, dim)[1]
    fb = split_law_stresses(axial, b, mu, kappa, dim)[1]
    for _ in range(200):
        if fb == fa:
            break
        a, fa, b = b, fb, b - fb * (b - a) / (fb - fa)
        fb = split_law_stresses(axial, b, mu, kappa, dim)[1]
        if abs(b - a) < 1e-15:
            break
    return b


def uniaxial(axial, law, mu, lam, kappa, dim):
    """(lateral stretch, J, axial Cauchy stress, sigma_zz in plane strain,
    axial second Piola-Kirchhoff stress) at the axial stretch."""
    if law == "nearly incompressible neo-Hookean":
        lateral = split_law_lateral_stretch(axial, mu, kappa, dim)
        J = axial * lateral ** (dim - 1)
        stresses = split_law_stresses(axial, lateral, mu, kappa, dim)
        return lateral, J, stresses[0], stresses[-1], J * stresses[0] / axial ** 2
    lateral = lateral_stretch(axial, mu, lam, dim)
    J = axial * lateral ** (dim - 1)
    S = mu * (1 - axial ** -2) + lam * math.log(J) * axial ** -2
    return lateral, J, axial ** 2 * S / J, lam * math.log(J) / J, S


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output")
    parser.add_argument("--tolerance", type=float, required=True)
    args = parser.parse_args()

    parameters = read_parameters(os.path.join(args.output, "parameters.prm"))
    dim = int(parameters["Dimension"])
    E = float(parameters["Material/Young's modulus"])
    nu = float(parameters["Material/Poisson's ratio"])
    mu = E / (2 * (1 + nu))
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    kappa = E / (3 * (1 - 2 * nu))
    law = parameters.get("Material/Model", "neo-Hookean")
    axes = "xyz"[:dim]
    axis = axes[-1]

    files = sorted(glob.glob(os.path.join(args.output, "displacement-*.csv")))
    if not files:
        print(f"no displacement-*.csv in {args.output}")
        return 1
    worst = {"displacement": 0.0, "stress": 0.0, "det F": 0.0, "pressure": 0.0}
    smallest_stretch = 1.0
    for path in files:
        number = path[-9:-4]
        vertices = rows(path)
        height = max(v[axis] for v in vertices)
        top = [v for v in vertices if abs(v[axis] - height) < 1e-12]
        axial = 1 + top[0]["u" + axis] / height
        smallest_stretch = min(smallest_stretch, axial)
        lateral, J, cauchy, out_of_plane, S = uniaxial(axial, law, mu, lam, kappa, dim)
        scale_u = max(abs(v["u" + a]) for v in vertices for a in axes)
        for v in vertices:
            for a in axes:
                stretch = axial if a == axis else lateral
                error = abs(v["u" + a] - (stretch - 1) * v[a]) / scale_u
                worst["displacement"] = max(worst["displacement"], error)
        for cell in rows(os.path.join(args.output, f"stress-{number}.csv")):
            exact = {"s" + a + b: 0.0 for a in axes for b in axes}
            exact["s" + axis + axis] = cauchy
            if dim == 2:
                exact["szz"] = out_of_plane
            for name, value in exact.items():
                if name in cell:
                    error = abs(cell[name] - value) / abs(cauchy)
                    worst["stress"] = max(worst["stress"], error)
            worst["det F"] = max(worst["det F"], abs(cell["det_F"] - J))
        nodes = [n for n in rows(os.path.join(args.output, f"contact-{number}.csv"))
                 if n["area"] > 0]
        if not nodes:
            print(f"increment {number}: no contact node")
            return 1
        for n in nodes:
            worst["pressure"] = max(worst["pressure"],
                                    abs(n["pressure"] + axial * S) / abs(axial * S))
        print(f"increment {number}: stretch {axial:.4f}, lateral {lateral:.10f}, "
              f"Cauchy stress {cauchy:.10g}, nominal pressure {-axial * S:.10g}")
    failed = False
    for name, error in worst.items():
        ok = error <= args.tolerance
        failed = failed or not ok
        print(f"{name}: largest relative error {error:.3g} "
              f"({'within' if ok else 'NOT within'} {args.tolerance:g})")
    if smallest_stretch > 0.8:
        print(f"the block was compressed to a stretch of {smallest_stretch:.3f} only: "
              "more than 20 % is needed to test finite strain")
        failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
