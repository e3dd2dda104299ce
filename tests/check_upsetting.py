#!/usr/bin/env python3
"""Checks the die force of a billet upset between flat dies
(parameters/billet_upsetting.prm and its variants in tests/) against the
slab method's mean die pressure

    p = sigma_y(eps) (1 + 2 mu R / (3 h)),

with h the billet's current height (twice the meshed half's), R its mean
current radius (the volume kept: R0 sqrt(h0 / h)), eps = ln(h0 / h) the
homogeneous logarithmic strain and sigma_y the run's hardening law
(check_uniaxial.yield_curve). The slab estimate holds where the friction
term is small, 2 mu R / h < 0.5 (asked by --slab-limit), and once the
billet is fully plastic (eps >= --from-strain): the mean pressure of each
such increment, die force over pi R^2 (a quarter of it for the quarter
billet), must lie within --tolerance of it. Reads parameters.prm and
statistics (Time, Contact force z).

usage: check_upsetting.py OUTPUT_DIR --tolerance 0.05
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_analytic import read_parameters, read_statistics  # noqa: E402
from check_uniaxial import yield_curve  # noqa: E402


def die_travel(expression, t):
    """The die's downward travel at t from the z component of <Contact/
    Obstacle/Rigid displacement> (a muParser expression of t)."""
    z = expression.split(";")[-1].strip()
    allowed = {"t": t, "min": min, "max": max, "abs": abs, "sin": math.sin,
               "cos": math.cos, "exp": math.exp, "pi": math.pi}
    return -eval(z.replace("^", "**"), {"__builtins__": {}}, allowed)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("directory")
    parser.add_argument("--tolerance", type=float, default=0.05)
    parser.add_argument("--slab-limit", type=float, default=0.5)
    parser.add_argument("--from-strain", type=float, default=0.05)
    args = parser.parse_args()
    p = read_parameters(os.path.join(args.directory, "parameters.prm"))
    R0 = float(p["Geometry/Billet/Radius"])
    H = float(p["Geometry/Billet/Height"])
    quarter = p.get("Geometry/Billet/Symmetry planes", "2") == "2"
    mu = float(p["Contact/Friction coefficient"])
    sigma_y = yield_curve(p)
    rows = read_statistics(os.path.join(args.directory, "statistics"))
    worst, checked, last_ratio = 0.0, 0, 0.0
    for t, force in ((r["Time"], r["Contact force z"]) for r in rows):
        h = H - die_travel(p["Contact/Obstacle/Rigid displacement"], t)
        eps = math.log(H / h)
        R = R0 * math.sqrt(H / h)
        ratio = 2 * mu * R / (2 * h)
        if eps < args.from_strain or ratio >= args.slab_limit:
            continue
        slab = sigma_y(eps) * (1 + 2 * mu * R / (3 * 2 * h))
        area = math.pi * R * R / (4 if quarter else 1)
        deviation = abs(abs(force) / area / slab - 1)
        worst = max(worst, deviation)
        checked += 1
        last_ratio = ratio
    ok = checked >= 3 and worst <= args.tolerance
    print(f"billet upsetting, mu = {mu:g}: mean die pressure against the slab estimate "
          f"in {checked} increments (2 mu R / h up to {last_ratio:.3g}): off by at most "
          f"{100 * worst:.2f} % (allowed {100 * args.tolerance:g} %)"
          + ("" if checked >= 3 else "; fewer than 3 increments in the slab range"))
    print("PASSED" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
