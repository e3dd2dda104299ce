#!/usr/bin/env python3
"""Plots a series CSV written by bench/run_series.py like the paper's
figures: wall time of the contact solve against d on log-log axes, one line
per solver, with O(d) and O(d^2) guides; and the ratio of the contact solve
time to one elastic solve on the same mesh.

usage: bench/plot_series.py [--csv doc/benchmarks/series.csv] [--out doc/benchmarks]
Writes <out>/example1-time.png, example1-ratio.png, example2-time.png,
example2-ratio.png and example2-mu.png (where there are data).
"""
import argparse
import csv
import os
import sys
from collections import defaultdict

# matplotlib is imported after the arguments are parsed (pyplot()), so
# that --help works where it is missing.
plt = None

LABELS = {"primal-dual": "Algorithm 2 (accelerated primal-dual)",
          "newton": "semismooth Newton"}


def series(rows, example, mu="0.5"):
    lines = defaultdict(list)
    for row in rows:
        if row["example"] == example and row["mu"] == mu and row["converged"] == "1":
            lines[row["solver"]].append((int(row["d"]), float(row["solve_s"]),
                                         float(row["ratio_to_elastic"] or "nan")))
    return {solver: sorted(points) for solver, points in lines.items()}


def guides(axis, ds, t0):
    """O(d) and O(d^2) through the first point of the slowest line."""
    d0, d1 = min(ds), max(ds)
    for power, style in ((1, ":"), (2, "--")):
        axis.loglog([d0, d1], [t0, t0 * (d1 / d0) ** power], "k" + style, lw=0.8,
                    label=f"O(d^{power})" if power > 1 else "O(d)")


def loglog_by_solver(lines, column):
    """A new figure with one line per solver: d against point[column]."""
    figure, axis = plt.subplots(figsize=(6, 4.5))
    for solver, points in lines.items():
        axis.loglog([p[0] for p in points], [p[column] for p in points], "o-",
                    label=LABELS.get(solver, solver))
    return axis


def finish(axis, ylabel, title, file_name,
           xlabel="d (free displacement dofs)"):
    axis.set_xlabel(xlabel)
    axis.set_ylabel(ylabel)
    axis.set_title(title)
    axis.grid(True, which="both", alpha=0.3)
    axis.legend(fontsize=8)
    axis.figure.tight_layout()
    axis.figure.savefig(file_name, dpi=110)


def pyplot():
    """matplotlib's pyplot with a file backend, as the module's plt."""
    global plt
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot
    plt = matplotlib.pyplot
    return plt


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--csv", default="doc/benchmarks/series.csv")
    parser.add_argument("--out", default="doc/benchmarks")
    args = parser.parse_args()
    pyplot()
    with open(args.csv) as f:
        rows = list(csv.DictReader(f))

    for example, title in (("1", "Example I (2D)"), ("2", "Example II (3D)")):
        lines = series(rows, example)
        if not lines:
            continue
        slowest = max(lines.values(), key=lambda p: p[0][1])
        axis = loglog_by_solver(lines, 1)
        guides(axis, [p[0] for pts in lines.values() for p in pts], slowest[0][1])
        finish(axis, "wall time of the contact solve (s)", f"{title}, mu = 0.5",
               os.path.join(args.out, f"example{example}-time.png"))
        axis = loglog_by_solver(lines, 2)
        finish(axis, "contact solve time / one elastic solve",
               f"{title}: cost in elastic solves",
               os.path.join(args.out, f"example{example}-ratio.png"))

    by_mu = defaultdict(dict)
    for row in rows:
        if row["example"] == "2" and row["N_Y"] == "20" and row["converged"] == "1":
            by_mu[row["solver"]][float(row["mu"])] = float(row["solve_s"])
    if any(len(v) > 1 for v in by_mu.values()):
        figure, axis = plt.subplots(figsize=(6, 4.5))
        for solver, values in by_mu.items():
            mus = sorted(values)
            axis.semilogy(mus, [values[m] for m in mus], "o-", label=LABELS.get(solver, solver))
        finish(axis, "wall time of the contact solve (s)", "Example II, N_Y = 20",
               os.path.join(args.out, "example2-mu.png"),
               xlabel="friction coefficient mu")
    print(f"plots in {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
