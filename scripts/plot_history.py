#!/usr/bin/env python3
"""Plots convergence histories (history-NNNNN.txt, written with
Postprocess/Convergence history/Write convergence history = true) as the paper's figures: each of
the three residuals and the step |du_k+1 - du_k| against wall time (or
iterations), on log axes, several runs overlaid.

usage: plot_history.py [-o residuals.png] [--x time|iteration]
                       [LABEL=]history-00001.txt [[LABEL=]other.txt ...]
"""
import argparse
import os
import sys

# matplotlib is imported after the arguments are parsed (pyplot()), so
# that --help works where it is missing.
plt = None

PANELS = [
    ("force_balance", "force balance |K du - p - T r|"),
    ("complementarity", "complementarity (eq. 25)"),
    ("penetration", "penetration |min(g - T_n^T du, 0)|"),
    ("step", "step |du_k+1 - du_k|"),
]


def read_history(path):
    columns, rows = None, []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                words = line[1:].split()
                if "iteration" in words:
                    columns = words
            elif line.strip():
                rows.append([float(x) for x in line.split()])
    if columns is None or not rows:
        raise SystemExit(f"{path}: not a convergence history (no header or no rows)")
    return {name: [row[i] for row in rows] for i, name in enumerate(columns)}


def label_and_path(item):
    """'LABEL=path' or 'path'; the label may hold '=', and so may the path."""
    if os.path.exists(item):
        return item, item
    for i, c in enumerate(item):
        if c == "=" and os.path.exists(item[i + 1:]):
            return item[:i], item[i + 1:]
    raise SystemExit(f"{item}: no such history file")


def pyplot():
    """matplotlib's pyplot with a file backend, as the module's plt."""
    global plt
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot
    plt = matplotlib.pyplot
    return plt


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("histories", nargs="+", help="[LABEL=]file")
    parser.add_argument("-o", "--output", default="residuals.png")
    parser.add_argument("--x", choices=["time", "iteration"], default="time")
    parser.add_argument("--title", default=None)
    args = parser.parse_args()
    pyplot()

    figure, axes = plt.subplots(2, 2, figsize=(10, 7.5))
    for item in args.histories:
        label, path = label_and_path(item)
        history = read_history(path)
        x = history["seconds"] if args.x == "time" else history["iteration"]
        for axis, (column, title) in zip(axes.flat, PANELS):
            # Zeros (no contact yet) cannot be drawn on a log axis.
            points = [(a, b) for a, b in zip(x, history[column]) if b > 0 and a > 0]
            if points:
                axis.loglog(*zip(*points), label=label)
            axis.set_title(title, fontsize=10)
            axis.set_xlabel("wall time (s)" if args.x == "time" else "iteration")
            axis.grid(True, which="major", alpha=0.3)
    axes.flat[0].legend(fontsize=8)
    if args.title:
        figure.suptitle(args.title)
    figure.tight_layout()
    figure.savefig(args.output, dpi=110)
    print(f"wrote {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
