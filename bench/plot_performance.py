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


def scale_table(rows):
    lines = ["| N_Y | d | ranks | Newton steps | Krylov iterations | AMG set-ups and updates | Krylov solves | contact operations | solve | elastic solve | ratio | peak memory per unknown |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(
            f"| {r['N_Y']} | {int(r['d']):,} | {r['ranks']} | {r['iterations']} "
            f"| {r['cg_iterations']} | {number(r, 'amg_setup_s'):.3g} s "
            f"| {number(r, 'krylov_s'):.3g} s | {number(r, 'contact_operations_s'):.2g} s "
            f"| {number(r, 'solve_s'):.3g} s | {number(r, 'elastic_solve_s'):.3g} s "
            f"| **{number(r, 'ratio_to_elastic'):.2f}** | {kb_per_unknown(r):.1f} kB |")
    return "\n".join(lines)


def settings_table(rows):
    lines = ["| variant | Newton steps | Krylov iterations | solve | elastic solve | ratio | peak memory |",
             "|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(
            f"| {r['variant']} | {r['iterations']} | {r['krylov_iterations']} "
            f"| {number(r, 'solve_s'):.3g} s | {number(r, 'elastic_solve_s'):.3g} s "
            f"| {number(r, 'ratio_to_elastic'):.2f} | {number(r, 'peak_memory_mb'):.0f} MB |")
    return "\n".join(lines)


def parallel_table(rows):
    lines = ["| ranks | Newton steps | Krylov iterations | set-up | AMG set-ups and updates | Krylov solves | contact operations | solve | output | elastic solve | ratio | speed-up |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(
            f"| {r['ranks']} | {r['iterations']} | {r['krylov_iterations']} "
            f"| {number(r, 'setup_s'):.3g} s | {number(r, 'amg_setup_s'):.3g} s "
            f"| {number(r, 'krylov_s'):.3g} s | {number(r, 'contact_operations_s'):.2g} s "
            f"| {number(r, 'solve_s'):.3g} s | {number(r, 'output_s'):.2g} s "
            f"| {number(r, 'elastic_solve_s'):.3g} s | {number(r, 'ratio_to_elastic'):.2f} "
            f"| **{number(r, 'speed_up'):.2f}** |")
    return "\n".join(lines)


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
    bottom = [0.] * len(scale)
    for key, name in (("amg_setup_s", "AMG set-up and updates"),
                      ("krylov_s", "Krylov solves"),
                      ("contact_operations_s", "contact operations")):
        heights = [in_units(r, key) for r in scale]
        cost.bar(positions, heights, bottom=bottom, label=name)
        bottom = [b + h for b, h in zip(bottom, heights)]
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

    bottom = [0.] * len(parallel)
    for key, name in (("setup_s", "mesh and dofs (before the solve)"), ("amg_setup_s", "AMG set-up and updates"),
                      ("krylov_s", "Krylov solves"),
                      ("contact_operations_s", "contact operations")):
        heights = [number(r, key) for r in parallel]
        ranks.bar([r["ranks"] for r in parallel], heights, bottom=bottom, label=name)
        bottom = [b + h for b, h in zip(bottom, heights)]
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
    print(scale_table(scale), end="\n\n")
    if settings:
        print(settings_table(settings), end="\n\n")
    print(parallel_table(parallel))
    plot(folder, scale, parallel)


if __name__ == "__main__":
    main()
