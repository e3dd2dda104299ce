#!/usr/bin/env python3
"""Checks an axisymmetric press fit (tests/press_fit_axisymmetric.prm: a
ring of outer radius c on a solid shaft of radius b, the ring's inner
radius b - delta, both of one material and held axially at both ends,
which makes the fit plane strain along its whole length) against Lame's
interference-fit pressure

  p = E delta / (b (1 + nu) (((1 - 2 nu) b^2 + c^2) / (c^2 - b^2) + 1 - 2 nu)),

the radial displacements of the ring's bore under p and of the shaft under
-p adding up to delta. Reads the run's parameters.prm (E, nu) and its last
contact-NNNNN.csv: every node of the fit within --tolerance of p, and the
pressure uniform along the fit (max - min within --uniformity of p).

usage: check_press_fit.py OUTPUT_DIR --shaft-radius 1 --outer-radius 2
                          --interference 0.001 [--tolerance 0.01] [--uniformity 1e-6]
"""
import argparse
import csv
import glob
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_analytic import read_parameters  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("directory")
parser.add_argument("--shaft-radius", type=float, required=True)
parser.add_argument("--outer-radius", type=float, required=True)
parser.add_argument("--interference", type=float, required=True)
parser.add_argument("--tolerance", type=float, default=0.01)
parser.add_argument("--uniformity", type=float, default=1e-6)
args = parser.parse_args()
p = read_parameters(os.path.join(args.directory, "parameters.prm"))
E = float(p["Material/Young's modulus"])
nu = float(p["Material/Poisson's ratio"])
b, c, delta = args.shaft_radius, args.outer_radius, args.interference
exact = E * delta / (b * (1 + nu) * (((1 - 2 * nu) * b * b + c * c) / (c * c - b * b)
                                     + 1 - 2 * nu))
files = sorted(glob.glob(os.path.join(args.directory, "contact-*.csv")))
if not files:
    sys.exit("no contact-*.csv: set Postprocess/Visualization/Write csv tables = true")
with open(files[-1]) as f:
    pressures = [float(row["pressure"]) for row in csv.DictReader(f) if row["state"] != "free"]
if not pressures:
    sys.exit("FAILED: no node of the fit is in contact")
error = max(abs(q - exact) for q in pressures) / exact
spread = (max(pressures) - min(pressures)) / exact
ok = error <= args.tolerance and spread <= args.uniformity
print(f"press fit: {len(pressures)} nodes in contact, pressure {min(pressures):.6g} to "
      f"{max(pressures):.6g} against Lame's {exact:.6g} (error {100 * error:.3f} %, allowed "
      f"{100 * args.tolerance:g} %; spread {spread:.2e} of p, allowed {args.uniformity:g})")
print("PASSED" if ok else "FAILED")
sys.exit(0 if ok else 1)
