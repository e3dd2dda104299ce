#!/usr/bin/env python3
"""The ironing scene (parameters/ironing_2d.prm) on 0 and 1 global
refinements with its friction (mu = 0.3), and frictionless on the shipped
mesh: the force on the die along its path, mesh convergence of the drag and
the press with the die in the middle of its slide (t = 1.5), and the Newton
steps. Rewrites doc/benchmarks/ironing.csv (one row per increment of each
run), the table of doc/validation.md ("Ironing") and the plot
doc/figures/ironing_2d-forces.png.

usage: bench/ironing.py [--program build/contact] [--levels 0,1]
"""
import argparse
import csv
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "tests"))
from check_analytic import read_statistics  # noqa: E402
from doc_tables import replace_rows, write_tables  # noqa: E402
from runs import run as run_program  # noqa: E402

COLUMNS = ["level", "mu", "d", "time", "die_x", "drag", "press", "newton_iterations",
           "wall_s"]


def run(program, level, mu, folder):
    with open(os.path.join(folder, "scene.prm"), "w") as f:
        f.write(f"include {ROOT}/parameters/ironing_2d.prm\n"
                "set Output directory = output\n"
                f"subsection Mesh refinement\n  set Global refinements = {level}\nend\n"
                f"subsection Contact\n  set Friction coefficient = {mu}\nend\n"
                "subsection Postprocess\n  subsection Visualization\n"
                "    set Write vtu = false\n  end\nend\n")
    _, wall = run_program([program, "scene.prm"], 1, folder)
    rows = []
    for r in read_statistics(os.path.join(folder, "output", "statistics")):
        rows.append(dict(level=level, mu=mu, d=int(r["Free dofs d"]), time=r["Time"],
                         die_x=2.5 + 4 * max(r["Time"] - 1, 0),
                         drag=r["Contact force x"], press=-r["Contact force y"],
                         newton_iterations=int(r["Contact solver iterations"]),
                         wall_s=wall))
    return rows


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(1, 2, figsize=(10, 3.8))
    runs = sorted({(r["level"], r["mu"]) for r in rows})
    for level, mu in runs:
        mine = [r for r in rows if r["level"] == level and r["mu"] == mu]
        label = f"{level} refinements, " + ("frictionless" if float(mu) == 0 else f"mu = {mu}")
        style = "--" if float(mu) == 0 else "-"
        time = [float(r["time"]) for r in mine]
        axes[0].plot(time, [float(r["press"]) for r in mine], style, label=label)
        axes[1].plot(time, [float(r["drag"]) for r in mine], style, label=label)
    for ax, what in zip(axes, ("press (vertical force on the block)",
                               "drag (horizontal force on the block)")):
        ax.set_xlabel("t (pressed 1.4 over [0, 1], slid 4 over [1, 2])")
        ax.set_title(what)
        ax.grid(alpha=0.3)
    axes[1].legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    print(f"wrote {path}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--program", default=os.path.join(ROOT, "build", "contact"))
    parser.add_argument("--levels", default="0,1")
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks", "ironing.csv"))
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        for level in [int(x) for x in args.levels.split(",")]:
            for mu in ("0.3", "0") if level == 1 else ("0.3",):
                folder = os.path.join(scratch, f"{level}-{mu}")
                os.makedirs(folder)
                mine = run(args.program, level, mu, folder)
                print(f"level {level}, mu = {mu}: d = {mine[0]['d']}, "
                      f"{sum(r['newton_iterations'] for r in mine)} Newton steps, "
                      f"{mine[0]['wall_s']:.1f} s")
                rows += mine
    replace_rows(args.csv, COLUMNS, rows)
    with open(args.csv) as f:
        plot(list(csv.DictReader(f)), os.path.join(ROOT, "doc", "figures", "ironing_2d-forces.png"))
    for line in write_tables():
        print(line)


if __name__ == "__main__":
    main()
