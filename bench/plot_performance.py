#!/usr/bin/env python3
"""Plots and tables of doc/performance.md from the CSVs bench/performance.sh
writes: scale.csv (example II at every size), solver-settings.csv (the
settings at N_Y = 20) and parallel.csv (1 against 2 ranks).

usage: bench/plot_performance.py [folder]   (default doc/benchmarks)
Writes <folder>/performance.png: the contact solve in elastic solves
against d, split into AMG set-ups, Krylov solves and contact operations;
the peak memory per unknown; 1 against 2 ranks. Prints the tables of
doc/performance.md in Markdown.
"""
import argparse
import csv
import os
import sys


def rows_of(folder, name):
    path = os.path.join(folder, name)
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(f))


def number(row, key):
    try:
        return float(row[key])
    except (KeyError, TypeError, ValueError):
        return float("nan")


def kb_per_unknown(row):
    """Peak resident memory of the largest rank times the ranks, per unknown."""
    return number(row, "peak_memory_mb") * number(row, "ranks") * 1e3 / number(row, "d")


def in_units(row, key):
    return number(row, key) / number(row, "elastic_solve_s")


def text(key):
    return lambda r: r[key]


def seconds(key, digits=3):
    return lambda r: f"{number(r, key):.{digits}g} s"


def fixed(key, digits=2, bold=False):
    mark = "**" if bold else ""
    return lambda r: f"{mark}{number(r, key):.{digits}f}{mark}"


def table(rows, columns):
    """A Markdown table: one row per CSV row, columns as (header, format)."""
    lines = ["| " + " | ".join(header for header, _ in columns) + " |",
             "|" + "---|" * len(columns)]
    lines += ["| " + " | ".join(form(r) for _, form in columns) + " |" for r in rows]
    return "\n".join(lines)


SCALE_COLUMNS = [
    ("N_Y", text("N_Y")), ("d", lambda r: f"{int(r['d']):,}"), ("ranks", text("ranks")),
    ("Newton steps", text("iterations")), ("Krylov iterations", text("cg_iterations")),
    ("AMG set-ups and updates", seconds("amg_setup_s")), ("Krylov solves", seconds("krylov_s")),
    ("contact operations", seconds("contact_operations_s", 2)), ("solve", seconds("solve_s")),
    ("elastic solve", seconds("elastic_solve_s")),
    ("ratio", fixed("ratio_to_elastic", bold=True)),
    ("peak memory per unknown", lambda r: f"{kb_per_unknown(r):.1f} kB")]

SETTINGS_COLUMNS = [
    ("variant", text("variant")), ("Newton steps", text("iterations")),
    ("Krylov iterations", text("krylov_iterations")), ("solve", seconds("solve_s")),
    ("elastic solve", seconds("elastic_solve_s")), ("ratio", fixed("ratio_to_elastic")),
    ("peak memory", lambda r: f"{number(r, 'peak_memory_mb'):.0f} MB")]

PARALLEL_COLUMNS = [
    ("ranks", text("ranks")), ("Newton steps", text("iterations")),
    ("Krylov iterations", text("krylov_iterations")), ("set-up", seconds("setup_s")),
    ("AMG set-ups and updates", seconds("amg_setup_s")), ("Krylov solves", seconds("krylov_s")),
    ("contact operations", seconds("contact_operations_s", 2)), ("solve", seconds("solve_s")),
    ("output", seconds("output_s", 2)), ("elastic solve", seconds("elastic_solve_s")),
    ("ratio", fixed("ratio_to_elastic")), ("speed-up", fixed("speed_up", bold=True))]


def stacked_bars(axis, positions, rows, parts, scale=lambda r, key: number(r, key)):
    """One bar per row at @p positions, stacked from @p parts (key, label)."""
    bottom = [0.] * len(rows)
    for key, label in parts:
        heights = [scale(r, key) for r in rows]
        axis.bar(positions, heights, bottom=bottom, label=label)
        bottom = [b + h for b, h in zip(bottom, heights)]


def plot(folder, scale, parallel):
    try:
        import matplotlib
    except ImportError:
        sys.exit("plot_performance: performance.png not written: this python3 lacks "
                 "matplotlib (apt-get install python3-matplotlib)")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, (cost, memory, ranks) = plt.subplots(1, 3, figsize=(15, 4.5))
    labels = [f"{int(r['N_Y'])}\n{int(r['d']) / 1e3:.0f}k" for r in scale]
    positions = range(len(scale))
    stacked_bars(cost, positions, scale, (("amg_setup_s", "AMG set-up and updates"),
                                          ("krylov_s", "Krylov solves"),
                                          ("contact_operations_s", "contact operations")),
                 in_units)
    cost.plot(positions, [number(r, "ratio_to_elastic") for r in scale], "k.",
              label="whole solve")
    cost.axhline(3, color="k", ls=":", lw=0.8)
    cost.axhline(4, color="k", ls="--", lw=0.8)
    cost.set_xticks(list(positions), labels, fontsize=7)
    cost.set_xlabel("N_Y, d (example II; the last two on 2 ranks)")
    cost.set_ylabel("contact solve / one elastic AMG-CG solve")
    cost.set_title("cost in elastic solves (goals 3 and 4)")
    cost.legend(fontsize=8)

    memory.semilogx([number(r, "d") for r in scale], [kb_per_unknown(r) for r in scale],
                    "o-")
    memory.axhline(2, color="k", ls=":", lw=0.8)
    memory.set_xlabel("d")
    memory.set_ylabel("peak resident memory per unknown (kB)")
    memory.set_title("memory (goal 2 kB at d >= 1M)")

    stacked_bars(ranks, [r["ranks"] for r in parallel], parallel,
                 (("setup_s", "mesh and dofs (before the solve)"),
                  ("amg_setup_s", "AMG set-up and updates"),
                  ("krylov_s", "Krylov solves"),
                  ("contact_operations_s", "contact operations")))
    ranks.set_xlabel("MPI ranks (N_Y = 28, d = 141,288)")
    ranks.set_ylabel("wall time (s)")
    ranks.set_title("1 against 2 ranks (goal: solve 1.85x faster)")
    ranks.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(os.path.join(folder, "performance.png"), dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folder", nargs="?", default="doc/benchmarks",
                        help="where scale.csv, solver-settings.csv and parallel.csv are")
    folder = parser.parse_args().folder
    scale = rows_of(folder, "scale.csv")
    settings = rows_of(folder, "solver-settings.csv")
    parallel = rows_of(folder, "parallel.csv")
    if not scale or not parallel:
        sys.exit(f"plot_performance: {folder} lacks scale.csv or parallel.csv; "
                 "run bench/performance.sh first")
    print(table(scale, SCALE_COLUMNS), end="\n\n")
    if settings:
        print(table(settings, SETTINGS_COLUMNS), end="\n\n")
    print(table(parallel, PARALLEL_COLUMNS))
    plot(folder, scale, parallel)


if __name__ == "__main__":
    main()
