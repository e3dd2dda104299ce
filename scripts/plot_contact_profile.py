#!/usr/bin/env python3
"""Plots the contact pressure and the tangential traction along the
contact boundary of a 2D run, against x, from its contact-NNNNN.csv
(Postprocess/Visualization/Write csv tables = true): the nodal pressure
(normal reaction over lumped length), |tangential reaction| over the same
length, and mu times the pressure, the bound the traction reaches where
the node slips; markers show each node's state. For a half disc on a rigid
or elastic base (parameters/hertz_2d.prm, cattaneo_2d.prm), Hertz's
pressure p0 sqrt(1 - x^2 / a^2) for the run's total normal force is drawn
beside it (for an axisymmetric section of a ball, hertz_axisymmetric.prm,
his point contact's).

usage: plot_contact_profile.py OUTPUT_DIR [--increment N] [--out FILE.png]
By default the increment with the most nodes in contact, written to
OUTPUT_DIR/figures/contact-profile.png.
"""
import argparse
import csv
import glob
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests"))


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def chosen_file(directory, increment):
    files = sorted(glob.glob(os.path.join(directory, "contact-*.csv")))
    if not files:
        sys.exit(f"no contact-*.csv in {directory}: run with "
                 "Postprocess/Visualization/Write csv tables = true")
    if increment is not None:
        path = os.path.join(directory, f"contact-{increment:05d}.csv")
        if not os.path.exists(path):
            sys.exit(f"{path} does not exist")
        return path
    # The increment with the most nodes in contact (the latest of equals).
    return max(files, key=lambda p: (sum(r["state"] != "free" for r in read_rows(p)), p))


def read_scene(directory):
    """The run's scene as tests/check_analytic.py reads it (materials,
    friction, half-disc geometry), or None if it cannot."""
    try:
        import check_analytic
        return check_analytic.Scene(directory)
    except Exception:
        return None


def hertz_curve(scene, rows):
    """(x, p) of Hertz's pressure for the run's normal force, or None where
    the scene is not a half disc or its contact is too wide for Hertz's
    theory (a half-width beyond a fifth of the radius, as in a squeezed
    O-ring)."""
    if scene is None or scene.dim != 2 or math.isnan(scene.radius) or math.isnan(scene.E_star):
        return None
    # The normal force of this increment: the sum of the nodal reactions,
    # doubled for the symmetry plane (an axisymmetric section's are
    # totals over the revolution: Hertz's point contact).
    P = scene.copies * sum(abs(float(r["rn"])) for r in rows)
    if scene.axisymmetric:
        a = (3 * P * scene.radius / (4 * scene.E_star)) ** (1 / 3)
        p0 = 3 * P / (2 * math.pi * a ** 2)
    else:
        a = math.sqrt(4 * P * scene.radius / (math.pi * scene.E_star))
        p0 = 2 * P / (math.pi * a)
    if a > 0.2 * scene.radius:
        return None
    centre = scene.center[0]
    # Only the side the mesh models where a symmetry plane cuts it.
    half = math.pi / 2 if scene.planes > 0 else math.pi
    xs = [centre + a * math.cos(half * k / 200) for k in range(201)]
    return xs, [p0 * math.sqrt(max(0.0, 1 - ((x - centre) / a) ** 2)) for x in xs]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog=__doc__)
    parser.add_argument("output_directory")
    parser.add_argument("--increment", type=int)
    parser.add_argument("--out")
    args = parser.parse_args()
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("matplotlib is missing: apt-get install python3-matplotlib")

    directory = os.path.abspath(args.output_directory)
    path = chosen_file(directory, args.increment)
    rows = read_rows(path)
    if "rt2" in rows[0]:
        sys.exit("a 3D run: this plot is for 2D contact boundaries "
                 "(render 3D runs with scripts/render_contact.py)")
    scene = read_scene(directory)
    mu = scene.mu if scene is not None else float("nan")
    # Along the coordinate in which the zone in contact (or, with none, the
    # contact boundary) extends most: x for a body on a floor, y for a fit
    # along a shaft.
    zone = [r for r in rows if r["state"] not in ("free", "not a candidate")] or rows
    spans = {c: max(float(r[c]) for r in zone) - min(float(r[c]) for r in zone)
             for c in ("x", "y")}
    along = max(spans, key=spans.get)
    rows.sort(key=lambda r: float(r[along]))
    x = [float(r[along]) for r in rows]
    pressure = [float(r["pressure"]) for r in rows]
    traction = [abs(float(r["rt1"])) / float(r["area"]) if float(r["area"]) > 0 else 0.0
                for r in rows]

    figure, axis = plt.subplots(figsize=(8, 4.5))
    axis.plot(x, pressure, "-", color="tab:red", label="contact pressure")
    axis.plot(x, traction, "-", color="tab:blue", label="|tangential traction|")
    if mu > 0:
        axis.plot(x, [mu * p for p in pressure], ":", color="tab:blue",
                  label=f"mu x pressure (mu = {mu:g})")
    curve = hertz_curve(scene, rows)
    if curve:
        axis.plot(*curve, "--", color="black", lw=1, label="Hertz")
    for state, marker, colour in (("stick", "o", "tab:blue"), ("slip", "s", "tab:orange")):
        points = [(xi, p) for xi, p, r in zip(x, pressure, rows) if r["state"] == state]
        if points:
            axis.plot(*zip(*points), marker, ms=3, color=colour, ls="none",
                      label=f"{state} nodes")
    # The zone in contact with a margin of half its width on each side.
    touching = [xi for xi, r in zip(x, rows) if r["state"] != "free"]
    if touching:
        low, high = min(touching), max(touching)
        margin = 0.5 * max(high - low, 1e-12)
        axis.set_xlim(max(min(x), low - margin), min(max(x), high + margin))
    axisymmetric = scene is not None and scene.axisymmetric
    names = {"x": "r (x of the axisymmetric section)", "y": "z (y of the axisymmetric section)"}
    axis.set_xlabel(names[along] if axisymmetric else along)
    axis.set_ylabel("traction (force per area)" if axisymmetric else
                    "traction (force per length)")
    axis.set_title(f"{os.path.basename(directory)}, {os.path.basename(path)}")
    axis.grid(True, lw=0.3)
    axis.legend(fontsize=8)
    figure.tight_layout()
    out = os.path.abspath(args.out or os.path.join(directory, "figures",
                                                   "contact-profile.png"))
    os.makedirs(os.path.dirname(out), exist_ok=True)
    figure.savefig(out, dpi=110)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
