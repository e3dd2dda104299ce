#!/usr/bin/env python3
"""Checks the squeezed and pressed O-ring (parameters/o_ring_axisymmetric.prm)
at its last increment:
- it seals: the largest contact pressure against the bore and against the
  groove exceed the fluid's pressure (the run's <Boundary
  conditions/Pressure>), the rule an O-ring is designed by;
- the fluid pushed it onto the back wall: its nodes on the wall z =
  --back-wall carry contact pressure;
- no vertex of the ring, those in contact and the others (the wetted arc,
  the short arc in front of the extrusion gap) alike, is inside the bore
  (r > --bore) or inside the shaft around the groove (r < --shaft with z
  outside the groove's walls, or r < --bottom), by more than --tolerance
  times the cord.

usage: check_o_ring.py OUTPUT_DIR --bore 10.6 --bottom 9 --shaft 10.5
                       --walls -1.4,1.4 [--cord 2] [--tolerance 1e-3]
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
parser.add_argument("--bore", type=float, required=True)
parser.add_argument("--bottom", type=float, required=True)
parser.add_argument("--shaft", type=float, required=True)
parser.add_argument("--walls", required=True)
parser.add_argument("--cord", type=float, default=2)
parser.add_argument("--tolerance", type=float, default=1e-3)
args = parser.parse_args()
back_wall, front_wall = (float(v) for v in args.walls.split(","))
p = read_parameters(os.path.join(args.directory, "parameters.prm"))
fluid = float(p["Boundary conditions/Pressure"].split(":")[1])
slack = args.tolerance * args.cord


def last(pattern):
    return sorted(glob.glob(os.path.join(args.directory, pattern)))[-1]


failures = []
with open(last("contact-*.csv")) as f:
    nodes = [{k: (v if k == "state" else float(v)) for k, v in r.items()} for r in csv.DictReader(f)]
on_bore = [n["pressure"] for n in nodes if abs(n["x"] + n["ux"] - args.bore) < slack]
on_groove = [n["pressure"] for n in nodes if abs(n["x"] + n["ux"] - args.bore) >= slack]
on_back_wall = [n["pressure"] for n in nodes if abs(n["y"] + n["uy"] - back_wall) < slack]
print(f"fluid pressure {fluid:g}; the largest contact pressure on the bore "
      f"{max(on_bore, default=0):.4g}, on the groove {max(on_groove, default=0):.4g}, "
      f"on the back wall {max(on_back_wall, default=0):.4g}")
for name, pressures in (("bore", on_bore), ("groove", on_groove)):
    if max(pressures, default=0) <= fluid:
        failures.append(f"the contact pressure on the {name} does not exceed the fluid's: it leaks")
if max(on_back_wall, default=0) <= 0:
    failures.append("the ring does not press on the back wall")

deepest = 0
with open(last("displacement-*.csv")) as f:
    for r in csv.DictReader(f):
        x, y = float(r["x"]) + float(r["ux"]), float(r["y"]) + float(r["uy"])
        inside = max(x - args.bore, args.bottom - x)
        if x < args.shaft:
            inside = max(inside, min(args.shaft - x, max(back_wall - y, y - front_wall)))
        deepest = max(deepest, inside)
print(f"the deepest vertex inside the bore or the shaft: {deepest:.3g} "
      f"({deepest / args.cord:.2g} of the cord)")
if deepest > slack:
    failures.append(f"a vertex is {deepest:.3g} inside the bore or the shaft")
for failure in failures:
    print("FAILED: " + failure)
sys.exit(1 if failures else 0)
