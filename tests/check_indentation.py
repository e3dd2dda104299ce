#!/usr/bin/env python3
"""Checks a ball indentation of an elasto-plastic half space
(parameters/ball_indentation_axisymmetric.prm: a rigid ball of radius R
pressed to a depth d and lifted off again) against Tabor's hardness
relation: at the deepest point the mean pressure F / (pi a^2) is about
2.8 times the flow stress at Tabor's representative strain 0.2 a / R (a
fully plastic impression; a rule measured on metals, within about 10 %).
The flow stress comes from the run's own J2 entries (linear or Voce
hardening). Then: the ball leaves the block before the last increment
(no contact force), and the impression stays: the top surface's
displacement on the axis at the end is between --kept and 1 times d.

usage: check_indentation.py OUTPUT_DIR --radius 1 --depth 0.05 [--tolerance 0.1] [--kept 0.8]
"""
import argparse
import glob
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_analytic import read_parameters  # noqa: E402
import statistics_file  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("directory")
parser.add_argument("--radius", type=float, required=True)
parser.add_argument("--depth", type=float, required=True)
parser.add_argument("--tolerance", type=float, default=0.1)
parser.add_argument("--kept", type=float, default=0.8)
args = parser.parse_args()

p = read_parameters(os.path.join(args.directory, "parameters.prm"))
s0 = float(p["Material/J2 plasticity/Yield stress"])
H = float(p.get("Material/J2 plasticity/Isotropic hardening modulus", "0"))
voce = p.get("Material/J2 plasticity/Hardening", "linear") == "Voce"


def flow_stress(ep):
    sigma = s0 + H * ep
    if voce:
        s_inf = float(p["Material/J2 plasticity/Saturation yield stress"])
        delta = float(p["Material/J2 plasticity/Saturation rate"])
        sigma += (s_inf - s0) * (1 - math.exp(-delta * ep))
    return sigma


path = os.path.join(args.directory, "statistics")
column = statistics_file.names(path)
rows = statistics_file.table(path)
times = [r[column["Time"] - 1] for r in rows]
deepest = rows[min(range(len(rows)), key=lambda i: abs(times[i] - 1))]
force = deepest[column["Normal contact force"] - 1]
area = deepest[column["Contact area"] - 1]      # of the surface of revolution, pi a^2
a = math.sqrt(area / math.pi)
hardness = force / area
tabor = 2.8 * flow_stress(0.2 * a / args.radius)
failures = []
print(f"at t = 1: a = {a:.4g}, F / (pi a^2) = {hardness:.5g}, Tabor's 2.8 sigma_f(0.2 a / R) "
      f"= {tabor:.5g}: {hardness / tabor - 1:+.2%}")
if abs(hardness / tabor - 1) > args.tolerance:
    failures.append(f"the mean pressure is {hardness / tabor - 1:+.2%} from Tabor's, "
                    f"more than {args.tolerance:.0%}")
last = rows[-1]
if last[column["Normal contact force"] - 1] != 0:
    failures.append(f"the ball still presses at t = {times[-1]}")
kept = None
last_csv = sorted(glob.glob(os.path.join(args.directory, "displacement-*.csv")))[-1]
with open(last_csv) as f:
    header = f.readline().strip().split(",")
    for line in f:
        row = dict(zip(header, map(float, line.split(","))))
        if row["x"] == 0 and row["y"] == 0:
            kept = -row["uy"] / args.depth
if kept is None:
    sys.exit(f"FAILED: no vertex at the top surface on the axis (0, 0) in {last_csv}")
print(f"the impression on the axis at the end: {kept:.4f} of the depth")
if not args.kept <= kept <= 1:
    failures.append(f"the impression keeps {kept:.4f} of the depth, not within [{args.kept}, 1]")
for failure in failures:
    print("FAILED: " + failure)
sys.exit(1 if failures else 0)
