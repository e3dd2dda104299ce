#!/usr/bin/env python3
"""Checks the push-out of a shrink fit (parameters/shrink_fit_axisymmetric.prm:
a hub on a shaft with an interference, then the shaft pushed through the
hub, which rests on a support). At the last increment the fit slides as a
whole: every node of the fit slips with |r_t| = mu |r_n| (Coulomb, the
friction coefficient from the run's parameters), except those whose
sliding a support holds (r_t = 0); and the force that pushes the shaft
(the reaction on its prescribed face, the master side's total) is the
fit's friction, mu times the normal force of the slipping nodes (the slave
side's), within --push-tolerance: the totals over the surface of
revolution of the support, the contact rows and the statistics agree. And the fit's pressure is highest at the hub's ends
(the stress concentration of a hub shorter than its shaft).

usage: check_shrink_fit.py OUTPUT_DIR [--tolerance 1e-6] [--push-tolerance 1e-3]
"""
import argparse
import csv
import glob
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_analytic import read_parameters  # noqa: E402
import statistics_file  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("directory")
parser.add_argument("--tolerance", type=float, default=1e-6)
parser.add_argument("--push-tolerance", type=float, default=1e-3)
args = parser.parse_args()
p = read_parameters(os.path.join(args.directory, "parameters.prm"))
mu = float(p["Contact/Friction coefficient"])
tables = sorted(glob.glob(os.path.join(args.directory, "contact-*.csv")))
failures = []


def nodes(path):
    with open(path) as f:
        return sorted({(float(r["y"]), float(r["rn"]), float(r["rt1"]), r["state"], float(r["pressure"]))
                       for r in csv.DictReader(f)})


fitted = nodes(tables[0])
ends = max(fitted[0][4], fitted[-1][4])
middle = fitted[len(fitted) // 2][4]
print(f"after the fit: pressure {middle:.5g} in the middle of the fit, {ends:.5g} at its ends")
if not ends > middle:
    failures.append("the fit's pressure is not highest at the hub's ends")
slipping_normal = 0
for y, rn, rt, state, _ in nodes(tables[-1]):
    if rt == 0:
        continue
    slipping_normal += abs(rn)
    if state != "slip" or abs(abs(rt) - mu * abs(rn)) > args.tolerance * abs(rn):
        failures.append(f"the node at y = {y} does not slip with |r_t| = mu |r_n| "
                        f"({state}, r_t = {rt}, r_n = {rn})")
path = os.path.join(args.directory, "statistics")
column = statistics_file.names(path)
last = statistics_file.table(path)[-1]
push = abs(last[column["Prescribed boundary force y"] - 1])
friction = last[column["Tangential contact force"] - 1]
print(f"pushed out: the push {push:.6g}, the fit's friction {friction:.6g}, "
      f"mu times the slipping nodes' normal force {mu * slipping_normal:.6g}")
for name, value, tolerance in (("the fit's friction", friction, args.tolerance),
                               ("the push", push, args.push_tolerance)):
    if abs(value - mu * slipping_normal) > tolerance * push:
        failures.append(f"{name} {value} is not mu times the slipping nodes' normal force "
                        f"{mu * slipping_normal}")
for failure in failures:
    print("FAILED: " + failure)
sys.exit(1 if failures else 0)
