#!/usr/bin/env python3
"""Checks a run of a cube in uniaxial stress (tests/j2_uniaxial_*.prm,
tests/j2_finite_*.prm: rollers on three faces, the top face moved along z;
or a cylinder's axisymmetric section, its top moved along the axis y)
against the exact stress-strain curve of J2 plasticity with isotropic
hardening (linear, Voce or a flow curve) and linear kinematic hardening,
which in uniaxial stress is the 1D law sigma = E (eps - eps_p), yield where
|sigma - q| = sigma_y(alpha), q = H_kin eps_p (the Bauschinger effect),
integrated increment by increment with the 1D radial return (its step by
bisection).

At finite strain (<Material/Kinematics> = finite strain: the Hencky law with
the exponential map) the same 1D law holds between the logarithmic strain
eps = ln(1 + u_z / z) and the Kirchhoff stress tau; the lateral logarithmic
strain is then -nu tau / E - eps_p / 2 (elastic contraction and isochoric
flow), the lateral stretch lambda = exp of it (checked against 1 + u_x / x
of the vertices off the axis), and the Cauchy stress tau / J with
J = exp(eps + 2 eps_lateral).

usage: check_uniaxial.py OUTPUT_DIR --tolerance 1e-10

Reads the run's parameters.prm (E, the hardening, H_kin), and for every
increment displacement-NNNNN.csv (the strain eps = u_z / z of the top
vertices, all equal) and stress-NNNNN.csv: in every cell s_zz must equal the
exact sigma, the other stress components vanish, and the equivalent plastic
strain equal alpha, all within the tolerance relative to sigma_y (strain:
relative to sigma_y / E, at finite strain to the path's largest strain if
larger). A small-strain path must leave the elastic range
and come back in both directions, a finite-strain one yield and reach a
logarithmic strain of 0.5, or the check proves little.
"""
import argparse
import csv
import glob
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_analytic import read_parameters  # noqa: E402


def yield_curve(p):
    """sigma_y(alpha) of the run's <Material/J2 plasticity/Hardening>: linear,
    Voce or a flow curve (piecewise linear, constant past its last point)."""
    entry = "Material/J2 plasticity/"
    law = p.get(entry + "Hardening", "linear")
    s0 = float(p[entry + "Yield stress"])
    H = float(p[entry + "Isotropic hardening modulus"])
    if law == "linear":
        return lambda a: s0 + H * a
    if law == "Voce":
        s_inf = float(p[entry + "Saturation yield stress"])
        delta = float(p[entry + "Saturation rate"])
        return lambda a: s0 + (s_inf - s0) * (1 - math.exp(-delta * a)) + H * a
    points = [tuple(float(x) for x in item.split()) for item in p[entry + "Flow curve"].split(",")]

    def curve(a):
        for (a0, s_0), (a1, s_1) in zip(points, points[1:]):
            if a < a1:
                return s_0 + (s_1 - s_0) * (a - a0) / (a1 - a0)
        return points[-1][1]
    return curve


def exact_path(strains, E, sigma_y, H_kin):
    """(sigma, alpha, eps_p) after each strain of the path, by the 1D radial return:
    the plastic step s solves |sigma_trial - q| - (E + H_kin) s =
    sigma_y(alpha + s), by bisection (linear hardening: exactly)."""
    plastic, alpha, back = 0.0, 0.0, 0.0
    path = []
    for eps in strains:
        trial = E * (eps - plastic)
        relative = trial - back
        excess = abs(relative) - sigma_y(alpha)
        sigma = trial
        if excess > 0:
            low, high = 0.0, abs(relative) / (E + H_kin)
            for _ in range(200):
                step = 0.5 * (low + high)
                if abs(relative) - (E + H_kin) * step - sigma_y(alpha + step) > 0:
                    low = step
                else:
                    high = step
            step = 0.5 * (low + high)
            sign = 1.0 if relative > 0 else -1.0
            plastic += step * sign
            alpha += step
            back += H_kin * step * sign
            sigma = trial - E * step * sign
        path.append((sigma, alpha, plastic))
    return path


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("directory")
    parser.add_argument("--tolerance", type=float, default=1e-10)
    args = parser.parse_args()
    p = read_parameters(os.path.join(args.directory, "parameters.prm"))
    E = float(p["Material/Young's modulus"])
    sigma_y = yield_curve(p)
    yield_stress = sigma_y(0)
    law = p.get("Material/J2 plasticity/Hardening", "linear")
    H_kin = float(p["Material/J2 plasticity/Kinematic hardening modulus"])

    finite = p.get("Material/Kinematics", "small strain") == "finite strain"
    nu = float(p["Material/Poisson's ratio"])
    # The axis of the load: z, or y in an axisymmetric section (x = r, the
    # third direction the hoop one, t).
    axisymmetric = p.get("Material/Two-dimensional model") == "axisymmetric"
    axial = "y" if axisymmetric else "z"
    others = ("sxx", "stt", "sxy") if axisymmetric else ("sxx", "syy", "sxy", "sxz", "syz")
    strains, lateral_stretches = [], []
    for name in sorted(glob.glob(os.path.join(args.directory, "displacement-*.csv"))):
        with open(name) as f:
            rows = list(csv.DictReader(f))
        top = [r for r in rows if float(r[axial]) > 0]
        stretch = sum(1 + float(r["u" + axial]) / float(r[axial]) for r in top) / len(top)
        strains.append(math.log(stretch) if finite else stretch - 1)
        width = max(float(r["x"]) for r in rows)
        lateral_stretches.append([1 + float(r["ux"]) / float(r["x"])
                                  for r in rows if float(r["x"]) > 1e-6 * width])
    path = exact_path(strains, E, sigma_y, H_kin)

    worst = {"axial stress": 0.0, "other stress": 0.0, "plastic strain": 0.0}
    if finite:
        worst["lateral stretch"] = 0.0
    files = sorted(glob.glob(os.path.join(args.directory, "stress-*.csv")))
    if len(files) != len(strains) or not files:
        sys.exit(f"{len(files)} stress tables for {len(strains)} increments")
    # Strains relative to sigma_y / E, or at finite strain to the largest
    # strain of the path where it is larger (1e-10 of 1 is round-off).
    strain_scale = max([yield_stress / E] + ([abs(e) for e in strains] if finite else []))
    for name, (tau, alpha, plastic), eps, lateral in zip(files, path, strains,
                                                         lateral_stretches):
        sigma = tau
        if finite:
            eps_lateral = -nu * tau / E - plastic / 2
            sigma = tau / math.exp(eps + 2 * eps_lateral)
            worst["lateral stretch"] = max(
                [worst["lateral stretch"]]
                + [abs(s - math.exp(eps_lateral)) / strain_scale for s in lateral])
        with open(name) as f:
            for row in csv.DictReader(f):
                worst["axial stress"] = max(worst["axial stress"],
                                            abs(float(row["s" + 2 * axial]) - sigma) / yield_stress)
                for c in others:
                    worst["other stress"] = max(worst["other stress"],
                                                abs(float(row[c])) / yield_stress)
                worst["plastic strain"] = max(
                    worst["plastic strain"],
                    abs(float(row["equivalent_plastic_strain"]) - alpha) / strain_scale)
    yielded = [s for s, _, _ in path if abs(s) > yield_stress * (1 - 1e-12)]
    # A small-strain path must yield both ways (the reversal is the point);
    # a finite-strain one yield and reach a logarithmic strain of 0.5.
    if finite:
        covered = bool(yielded) and max(abs(e) for e in strains) >= 0.5
        shortfall = "; the path does not yield and reach |eps| = 0.5"
    else:
        covered = any(s > 0 for s in yielded) and any(s < 0 for s in yielded)
        shortfall = "; the path does not yield both ways"
    ok = covered and all(v <= args.tolerance for v in worst.values())
    kind = "finite-strain (logarithmic strain " + f"{strains[-1]:.4g})" if finite else "small-strain"
    print(f"uniaxial {kind} J2 ({law} hardening, H_kin = {H_kin:g}), {len(path)} increments, "
          f"peak stresses {max(s for s, _, _ in path):.6g} and "
          f"{min(s for s, _, _ in path):.6g}: "
          + ", ".join(f"{k} off by {v:.2e}" for k, v in worst.items())
          + f" (relative, allowed {args.tolerance:g})"
          + ("" if covered else shortfall))
    print("PASSED" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
