#!/usr/bin/env python3
"""Kanno's method (accelerated primal-dual, Algorithm 2 with the paper's
settings) over the paper's sizes, with its inner solves as they are now
and as they were, in the same run; and, at one size per example, each
candidate for the inner solves on its own.

Series (doc/benchmarks/kanno-series.csv): example I at N_Y = 26 ... 144
and example II at N_Y = 10 ... 20 with the defaults ("default"), and at
the sizes of --previous-sizes with the inner solves of the previous
release ("previous": CG from du_k to 1e-6, ML's AMG in 2D and Jacobi in
3D, as its auto chose), each beside the wall time of one elastic solve
on the same mesh (the unit) and the paper's reported time where it gives
one (example I, d = 54,600: 382.6 s).

Variants (doc/benchmarks/kanno-variants.csv): at example I N_Y = 40 and
example II N_Y = 10, every combination of the preconditioner (Jacobi,
Cholesky, AMG), the start of CG (the previous iterate, as the paper, or
the extrapolation of the last two steps) and the primal step tolerance
(1e-6, 1e-4, 1e-3), and Initial alpha = 0.01 (a shift ten times
smaller, where Jacobi needs more iterations).

usage: bench/kanno_series.py [--part series,variants,plot]
                             [--sizes-ex1 26,40,...] [--sizes-ex2 10,...]
                             [--previous-sizes ex1:26,ex1:104,...]
Run from the top of the repository after scripts/setup.sh; the whole
run takes about 40 minutes. Rows already in a CSV are skipped.
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_series import best_run, scene  # noqa: E402

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
CONTACT = os.path.join(ROOT, "build", "contact")
PAPER_SECONDS = {(1, 104): 382.6}  # the only time the paper's text gives

SERIES_COLUMNS = ["example", "N_Y", "path", "d", "c", "iterations",
                  "krylov_iterations", "solve_s", "ms_per_iteration",
                  "elastic_solve_s", "ratio_to_elastic", "paper_s",
                  "converged"]
VARIANT_COLUMNS = ["example", "N_Y", "initial_alpha", "preconditioner",
                   "start", "tolerance", "d", "iterations",
                   "krylov_iterations", "krylov_per_iteration", "solve_s",
                   "converged"]


def settings(preconditioner=None, start=None, tolerance=None, alpha=None):
    """Overrides appended to a scene (a later entry wins)."""
    text = ""
    if preconditioner == "jacobi":
        # Jacobi for the steps only: the elastic solve and the eigenvalue
        # keep their AMG, as with auto.
        text += ("subsection Linear solver\n set Preconditioner = auto\n"
                 " set Jacobi threshold = 1e12\nend\n")
    elif preconditioner:
        text += f"subsection Linear solver\n set Preconditioner = {preconditioner}\nend\n"
    lines = []
    if start:
        lines.append(f"  set Primal step start = {start}")
    if tolerance:
        lines.append(f"  set Primal step tolerance = {tolerance}")
    if alpha:
        lines.append(f"  set Initial alpha = {alpha}")
    if lines:
        text += ("subsection Contact solver\n subsection Accelerated primal-dual\n"
                 + "\n".join(lines) + "\n end\nend\n")
    return text


def previous_settings(example):
    """The inner solves of the previous release: CG from du_k to 1e-6 with
    what its auto chose for the steps, AMG for example I (max diag(K) /
    sigma = 20) and Jacobi for example II (1.9)."""
    return settings("amg" if example == 1 else "jacobi", "previous iterate", "1e-6")


def done_keys(path, columns, key_columns):
    if not os.path.exists(path):
        with open(path, "w", newline="") as f:
            csv.writer(f).writerow(columns)
        return set()
    with open(path) as f:
        return {tuple(r[c] for c in key_columns) for r in csv.DictReader(f)}


def append(path, columns, row):
    with open(path, "a", newline="") as f:
        csv.DictWriter(f, columns, extrasaction="ignore").writerow(row)


def kanno(example, n_y, overrides=""):
    return scene(example, n_y, 0.5, "accelerated primal-dual") + overrides


def run_series(args):
    path = os.path.join(ROOT, "doc", "benchmarks", "kanno-series.csv")
    done = done_keys(path, SERIES_COLUMNS, ["example", "N_Y", "path"])
    previous = {tuple(s.split(":")) for s in args.previous_sizes.split(",") if s}
    instances = [(1, int(n)) for n in args.sizes_ex1.split(",") if n] + \
                [(2, int(n)) for n in args.sizes_ex2.split(",") if n]
    for example, n_y in instances:
        paths = ["default"]
        if (f"ex{example}", str(n_y)) in previous:
            paths.append("previous")
        paths = [p for p in paths if (str(example), str(n_y), p) not in done]
        if not paths:
            continue
        _, unit, _ = best_run(scene(example, n_y, 0.5, None, False), 1, 1, CONTACT)
        for name in paths:
            overrides = previous_settings(example) if name == "previous" else ""
            code, values, output = best_run(kanno(example, n_y, overrides), 1, 1,
                                            CONTACT)
            row = dict(example=example, N_Y=n_y, path=name, converged=int(code == 0),
                       d=values.get("d"), c=values.get("c"),
                       iterations=values.get("iterations"),
                       krylov_iterations=values.get("cg_iterations"),
                       solve_s=values["solve_s"], elastic_solve_s=unit["elastic_s"],
                       paper_s=PAPER_SECONDS.get((example, n_y), ""))
            if code == 0:
                row["ms_per_iteration"] = round(1e3 * values["solve_s"]
                                                / int(values["iterations"]), 4)
                row["ratio_to_elastic"] = round(values["solve_s"] / unit["elastic_s"], 1)
            else:
                print(output[-2000:], file=sys.stderr)
            append(path, SERIES_COLUMNS, row)
            print(f"example {example}, N_Y = {n_y}, {name}: d = {row['d']}, "
                  f"{row['iterations']} iterations, {row['krylov_iterations']} "
                  f"Krylov, {row['solve_s']:.3g} s"
                  f"{'' if code == 0 else ', FAILED (exit code %d)' % code}", flush=True)


def run_variants(args):
    path = os.path.join(ROOT, "doc", "benchmarks", "kanno-variants.csv")
    key = ["example", "N_Y", "initial_alpha", "preconditioner", "start", "tolerance"]
    done = done_keys(path, VARIANT_COLUMNS, key)
    for example, n_y in ((1, 40), (2, 10)):
        for alpha in ("0.1", "0.01"):
            for preconditioner in ("jacobi", "cholesky", "amg"):
                for start in ("previous iterate", "extrapolated"):
                    for tolerance in ("1e-6", "1e-4", "1e-3"):
                        values = dict(example=example, N_Y=n_y, initial_alpha=alpha,
                                      preconditioner=preconditioner, start=start,
                                      tolerance=tolerance)
                        if tuple(str(values[k]) for k in key) in done:
                            continue
                        code, result, _ = best_run(
                            kanno(example, n_y, settings(preconditioner, start,
                                                         tolerance, alpha)),
                            1, 1, CONTACT)
                        values.update(d=result.get("d"), converged=int(code == 0),
                                      iterations=result.get("iterations"),
                                      krylov_iterations=result.get("cg_iterations"),
                                      solve_s=result["solve_s"])
                        if code == 0:
                            values["krylov_per_iteration"] = round(
                                int(values["krylov_iterations"])
                                / int(values["iterations"]), 2)
                        append(path, VARIANT_COLUMNS, values)
                        print(" ".join(f"{k}={values[k]}" for k in VARIANT_COLUMNS),
                              flush=True)


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    path = os.path.join(ROOT, "doc", "benchmarks", "kanno-series.csv")
    with open(path) as f:
        rows = [r for r in csv.DictReader(f) if r["converged"] == "1"]
    figure, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for example, marker in (("1", "o"), ("2", "s")):
        for name, style in (("default", "-"), ("previous", "--")):
            points = sorted((int(r["d"]), float(r["solve_s"]), float(r["ms_per_iteration"]))
                            for r in rows if r["example"] == example and r["path"] == name)
            if not points:
                continue
            label = f"example {'I' if example == '1' else 'II'}, {name}"
            axes[0].loglog([p[0] for p in points], [p[1] for p in points],
                           marker + style, label=label)
            axes[1].loglog([p[0] for p in points], [p[2] for p in points],
                           marker + style, label=label)
    paper = [(int(r["d"]), float(r["paper_s"])) for r in rows if r["paper_s"]]
    if paper:
        axes[0].loglog(*zip(*paper), "k*", markersize=12, label="paper (Matlab)")
    for axis, ylabel in ((axes[0], "wall time of the solve (s)"),
                         (axes[1], "ms per outer iteration")):
        ds = [int(r["d"]) for r in rows]
        d0, d1 = min(ds), max(ds)
        lines = axis.get_lines()
        if lines:
            y0 = min(min(line.get_ydata()) for line in lines)
            axis.loglog([d0, d1], [y0, y0 * d1 / d0], "k:", lw=0.8, label="O(d)")
        axis.set_xlabel("d (free displacement unknowns)")
        axis.set_ylabel(ylabel)
        axis.grid(True, which="both", lw=0.3)
        axis.legend(fontsize=8)
    figure.suptitle("Kanno's Algorithm 2 with the paper's settings, one rank")
    figure.tight_layout()
    out = os.path.join(ROOT, "doc", "benchmarks", "kanno-series.png")
    figure.savefig(out, dpi=110)
    print(f"plot in {out}")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--part", default="series,variants,plot")
    parser.add_argument("--sizes-ex1", default="26,40,54,68,80,92,104,114,124,134,144")
    parser.add_argument("--sizes-ex2", default="10,12,14,16,18,20")
    parser.add_argument("--previous-sizes",
                        default="ex1:26,ex1:40,ex1:54,ex1:68,ex1:104,ex2:10,ex2:12,ex2:14")
    args = parser.parse_args()
    parts = args.part.split(",")
    if "variants" in parts:
        run_variants(args)
    if "series" in parts:
        run_series(args)
    if "plot" in parts:
        plot()
    from doc_tables import write_tables
    write_tables()
    return 0


if __name__ == "__main__":
    sys.exit(main())
