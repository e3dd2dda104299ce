#!/usr/bin/env python3
"""Refinement study of the Hertz scenes: parameters/hertz_2d.prm and
hertz_3d.prm run at increasing levels of local refinement around the
contact; for each level a CSV row with the mesh, the element size at the
contact, the contact radius (half-width in 2D) and peak pressure, their
errors against Hertz's formulas, and the wall time. Plots the errors
against the element size and against the run time, and prints the
observed orders (least-squares slopes of log error against log h).

usage: bench/hertz_study.py [--levels-2d 2-7] [--levels-3d 1-6]
                            [--csv doc/benchmarks/hertz-refinement.csv]
                            [--plot doc/benchmarks/hertz-refinement.png]
                            [--contact build/contact]
Run from the top of the repository after scripts/setup.sh.
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests"))
import check_analytic  # noqa: E402

COLUMNS = ["dim", "local_refinements", "cells", "d", "h", "a", "a_hertz",
           "error_a", "p0", "p0_hertz", "error_p0", "newton_iterations",
           "solve_s", "total_s"]


def run(contact, dim, level, folder):
    scene = os.path.abspath(f"parameters/hertz_{dim}d.prm")
    prm = os.path.join(folder, "scene.prm")
    with open(prm, "w") as f:
        f.write(f"include {scene}\nset Output directory = {folder}/output\n"
                f"subsection Mesh refinement\n  set Local refinements = {level}\nend\n"
                "subsection Postprocess\n subsection Visualization\n"
                "  set Write vtu = false\n  set Write csv tables = true\n end\nend\n")
    env = dict(os.environ, OMP_NUM_THREADS="1")
    start = time.time()
    done = subprocess.run([contact, prm], capture_output=True, text=True, env=env)
    total = time.time() - start
    if done.returncode != 0:
        sys.exit(f"level {level} ({dim}D) failed:\n{done.stdout}{done.stderr}")
    cells = int(re.search(r"Mesh: (\d+) cells; d = (\d+)", done.stdout).group(1))
    dofs = int(re.search(r"Mesh: (\d+) cells; d = (\d+)", done.stdout).group(2))
    s = check_analytic.Scene(folder + "/output")
    row = s.rows[-1]
    _, a, a_h, p0, p_h = check_analytic.hertz(s)
    return {"dim": dim, "local_refinements": level, "cells": cells, "d": dofs,
            "h": s.element_size(), "a": a, "a_hertz": a_h,
            "error_a": abs(a - a_h) / a_h, "p0": p0, "p0_hertz": p_h,
            "error_p0": abs(p0 - p_h) / p_h,
            "newton_iterations": int(row["Contact solver iterations"]),
            "solve_s": row["Solve wall time (s)"], "total_s": total}


def slope(xs, ys):
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return sum((x - mx) * (y - my) for x, y in zip(lx, ly)) / \
        sum((x - mx) ** 2 for x in lx)


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for dim, colour in ((2, "tab:blue"), (3, "tab:red")):
        rs = [r for r in rows if r["dim"] == dim]
        if not rs:
            continue
        for key, marker, label in (("error_a", "o-", "contact radius"),
                                   ("error_p0", "s--", "peak pressure")):
            axes[0].loglog([r["h"] for r in rs], [max(r[key], 1e-6) for r in rs],
                           marker, color=colour, label=f"{dim}D {label}")
            axes[1].loglog([r["total_s"] for r in rs],
                           [max(r[key], 1e-6) for r in rs],
                           marker, color=colour, label=f"{dim}D {label}")
    h = sorted(r["h"] for r in rows)
    axes[0].loglog(h, [0.3 * x / h[-1] * 0.5 for x in h], "k:", label="O(h)")
    axes[0].set_xlabel("element size at the contact h")
    axes[1].set_xlabel("wall time of the run (s), one MPI rank")
    for ax in axes:
        ax.set_ylabel("relative error against Hertz")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    axes[0].invert_xaxis()
    figure.suptitle("Hertz contact, semismooth Newton: error against mesh "
                    "size and run time")
    figure.tight_layout()
    figure.savefig(path, dpi=120)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--levels-2d", default="2-7")
    parser.add_argument("--levels-3d", default="1-6")
    parser.add_argument("--csv", default="doc/benchmarks/hertz-refinement.csv")
    parser.add_argument("--plot", default="doc/benchmarks/hertz-refinement.png")
    parser.add_argument("--contact", default="build/contact")
    args = parser.parse_args()

    rows = []
    for dim, levels in ((2, args.levels_2d), (3, args.levels_3d)):
        first, last = (int(x) for x in levels.split("-"))
        for level in range(first, last + 1):
            with tempfile.TemporaryDirectory() as folder:
                row = run(args.contact, dim, level, folder)
            rows.append(row)
            print(f"{dim}D level {level}: {row['cells']} cells, d = {row['d']}, "
                  f"h = {row['h']:.3g}: a error {100 * row['error_a']:.2f} %, "
                  f"p0 error {100 * row['error_p0']:.2f} %, "
                  f"{row['total_s']:.1f} s", flush=True)
    with open(args.csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    for dim in (2, 3):
        rs = [r for r in rows if r["dim"] == dim]
        if len(rs) > 1:
            print(f"{dim}D observed order (slope of log error against log h): "
                  f"contact radius {slope([r['h'] for r in rs], [r['error_a'] for r in rs]):.2f}, "
                  f"peak pressure {slope([r['h'] for r in rs], [r['error_p0'] for r in rs]):.2f}")
    plot(rows, args.plot)
    print(f"wrote {args.csv} and {args.plot}")


if __name__ == "__main__":
    main()
