#!/usr/bin/env python3
"""Writes the tables of doc/ that quote the bench CSVs, from the CSVs.

A table in a doc page sits between two markers,

    <!-- table: two-bodies -->
    | ... |
    <!-- end table -->

and TABLES below says how each one is made from its CSV in
doc/benchmarks/. The bench scripts call write_tables() after they write
their CSV; `--check` (the test docs/tables_from_csv) fails with the
name of every table whose text in doc/ differs from what its CSV makes,
so that a number in those tables cannot drift from the measurement.

usage: bench/doc_tables.py [--check] [--root .]
"""
import argparse
import csv
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def rows(root, name):
    with open(os.path.join(root, "doc", "benchmarks", name), newline="") as f:
        return list(csv.DictReader(f))


def markdown(header, body):
    lines = ["| " + " | ".join(header) + " |",
             "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(cell) for cell in row) + " |" for row in body]
    return "\n".join(lines)


def thousands(value):
    return f"{int(float(value)):,}"


def seconds(value):
    """Two significant digits (whole seconds from 10 s on)."""
    value = float(value)
    return f"{value:.0f} s" if value >= 10 else f"{value:#.2g} s"


def two_bodies(root):
    body = []
    for r in rows(root, "two-bodies.csv"):
        if r["converged"] != "1":
            body.append([r["size"], r["ranks"], thousands(r["d"]), r["c"],
                         "failed"] + [""] * 7)
            continue
        increments = int(r["increments"])
        kb_per_unknown = float(r["peak_memory_mb"]) * int(r["ranks"]) * 1024 / float(r["d"])
        body.append([r["size"], r["ranks"], thousands(r["d"]), thousands(r["c"]),
                     f"{int(r['newton_iterations']) / increments:.1f}",
                     f"{int(r['krylov_iterations']) / int(r['newton_iterations']):.1f}",
                     seconds(float(r["contact_solve_s"]) / increments),
                     seconds(r["elastic_solve_s"]),
                     r["elastic_solves_per_increment"],
                     seconds(r["elastic_solve_reused_amg_s"]),
                     r["elastic_solves_reused_amg_per_increment"],
                     f"{kb_per_unknown:.1f}"])
    return markdown(["size", "ranks", "d", "c", "Newton steps per increment",
                     "Krylov per Newton step", "contact solve per increment",
                     "elastic solve (unit)", "in units", "elastic solve, AMG reused",
                     "in those", "peak kB per unknown (largest rank x ranks)"], body)


NU = ["0.3", "0.49", "0.499", "0.4999"]
VARIANTS = ["standard", "B-bar mixed", "B-bar condensed"]


def by_key(table):
    return {(r["case"], r["size"], r["nu"], r["variant"]): r for r in table}


def lame_elastic(root):
    table = by_key(rows(root, "nearly-incompressible.csv"))
    sizes = [("3", "5,400 dofs"), ("4", "39,984 dofs")]
    header = ["nu"] + [f"{v}, {label}" if v == "standard" else v
                       for _, label in sizes for v in VARIANTS]
    body = []
    for nu in NU:
        line = [nu]
        for size, _ in sizes:
            for variant in VARIANTS:
                r = table.get(("lame", size, nu, variant))
                line.append(f"{r['elastic_krylov_iterations']} ({seconds(r['elastic_s'])})"
                            if r and r["converged"] == "1" else "failed")
        body.append(line)
    return markdown(header, body)


def example2_newton(root):
    table = by_key(rows(root, "nearly-incompressible.csv"))
    sizes = ["8", "12"]
    header = ["nu"] + [f"N_Y = {s} {v}" if v == "standard" else v
                       for s in sizes for v in VARIANTS]
    body = []
    for nu in NU:
        line = [nu]
        for size in sizes:
            for variant in VARIANTS:
                r = table.get(("example2", size, nu, variant))
                line.append(f"{r['iterations']} / {r['krylov_iterations']}, "
                            f"{r['ratio_to_elastic']} ({r['elastic_krylov_iterations']})"
                            if r and r["converged"] == "1" else "failed")
        body.append(line)
    return markdown(header, body)


def kanno_series(root):
    """One line per size: the default and (where measured) the previous
    inner solves side by side, with the paper's time where it has one."""
    table = rows(root, "kanno-series.csv")
    by_size = {}
    for r in table:
        by_size.setdefault((int(r["example"]), int(r["N_Y"])), {})[r["path"]] = r
    body = []
    for (example, n_y), paths in sorted(by_size.items()):
        new = paths.get("default")
        old = paths.get("previous")
        line = ["I" if example == 1 else "II", n_y]
        if new is None or new["converged"] != "1":
            body.append(line + [""] * 9)
            continue
        line += [thousands(new["d"]), thousands(new["iterations"]),
                 f"{int(new['krylov_iterations']) / int(new['iterations']):.2f}",
                 seconds(new["solve_s"]), f"{float(new['ms_per_iteration']):.3g}",
                 new["ratio_to_elastic"]]
        if old is not None and old["converged"] == "1":
            line += [f"{thousands(old['iterations'])}, {seconds(old['solve_s'])}",
                     f"{float(old['solve_s']) / float(new['solve_s']):.1f}"]
        else:
            line += ["", ""]
        line.append(f"{float(new['paper_s']):.1f} s" if new["paper_s"] else "")
        body.append(line)
    return markdown(["example", "N_Y", "d", "iterations", "Krylov per iteration",
                     "solve", "ms per iteration", "in elastic solves",
                     "previous inner solves: iterations, solve", "speed-up",
                     "paper (Matlab)"], body)


def kanno_variants(root):
    table = rows(root, "kanno-variants.csv")
    body = []
    for r in table:
        if r["converged"] != "1":
            body.append([r["example"], r["initial_alpha"], r["preconditioner"],
                         r["start"], r["tolerance"], "failed", "", ""])
            continue
        body.append(["I, N_Y = 40" if r["example"] == "1" else "II, N_Y = 10",
                     r["initial_alpha"], r["preconditioner"], r["start"],
                     r["tolerance"], thousands(r["iterations"]),
                     r["krylov_per_iteration"], seconds(r["solve_s"])])
    return markdown(["example", "Initial alpha", "preconditioner", "CG start",
                     "primal step tolerance", "iterations", "Krylov per iteration",
                     "solve"], body)


def multigrid(root):
    body = []
    for r in rows(root, "multigrid.csv"):
        if r["converged"] != "1":
            body.append([r["n_y"], r["ranks"], r["path"], thousands(r["d"]) if r["d"] else "", "failed"]
                        + [""] * 6)
            continue
        levels = f"{r['levels']} ({thousands(r['coarse_unknowns'])})" if r["levels"] else ""
        setup = seconds(r["multigrid_setup_s"]) if r["multigrid_setup_s"] else ""
        body.append([r["n_y"], r["ranks"], r["path"], thousands(r["d"]), levels,
                     r["elastic_cg_iterations"], seconds(r["elastic_solve_s"]), setup,
                     f"{r['newton_iterations']} / {r['contact_krylov_iterations']}",
                     r["elastic_solves_per_contact_solve"], r["kb_per_unknown"]])
    return markdown(["N_Y", "ranks", "preconditioner", "d", "levels (coarsest unknowns)",
                     "elastic CG iterations", "elastic solve", "multigrid set-up",
                     "Newton / Krylov iterations", "contact solve in elastic solves",
                     "peak kB per unknown"], body)


def fclib_scenes(root):
    """Per exported file: our Newton method on the path auto chooses and on
    the sparse LU, and the fastest Siconos solver that reached the
    tolerance by the common measure."""
    by_file = {}
    for r in rows(root, "fclib-scenes.csv"):
        by_file.setdefault(r["file"], []).append(r)
    body = []

    def cell(r):
        if r is None:
            return "-"
        if r["success"] != "1":
            return f"- ({r['note'] or 'error ' + r['common_error']})"
        return f"{seconds(r['seconds'])}, {r['iterations']} it."

    for name, runs in by_file.items():
        solvers = {r["solver"]: r for r in runs}
        ours = solvers.get("ours: semismooth Newton")
        lu = solvers.get("ours: semismooth Newton; jacobi")
        siconos = [r for r in runs
                   if r["solver"].startswith("siconos") and r["success"] == "1"]
        best = min(siconos, key=lambda r: float(r["seconds"]), default=None)
        ratio = (f"{float(best['seconds']) / float(ours['seconds']):.1f}"
                 if best and ours and ours["success"] == "1" else "")
        body.append([f"{name.removesuffix('.hdf5')} ({thousands(runs[0]['n'])}, "
                     f"{runs[0]['contacts']})", cell(ours), cell(lu),
                     f"{best['solver'].removeprefix('siconos ')}: {cell(best)}"
                     if best else "none", ratio])
    return markdown(["file (n, contacts)", "ours: Newton (auto)",
                     "ours: Newton, sparse LU", "fastest Siconos solver",
                     "its time / ours"], body)


def preconditioners(root):
    body = []
    for r in rows(root, "preconditioners.csv"):
        if r["converged"] != "1":
            body.append([r["scene"], r["global_refinements"], r["ranks"], r["path"],
                         "failed", "", "", ""])
            continue
        body.append([r["scene"], r["global_refinements"], r["ranks"], r["path"],
                     thousands(r["d"]),
                     f"{r['newton_iterations']} / {r['krylov_iterations']}",
                     seconds(r["contact_solve_s"]), r["time_to_first_path"]])
    return markdown(["scene", "global refinements", "ranks", "preconditioner",
                     "d (last mesh)", "Newton / Krylov iterations", "contact solve",
                     "time / first row's"], body)


def same_solutions(root):
    """One row per scene; per path and rank count the larger of the force
    and displacement differences from ML's run on one rank."""
    table = rows(root, "same-solutions.csv")
    runs = []
    for r in table:
        run = (r["path"], r["ranks"])
        if r["force_difference"] or r["refused"]:
            if run not in runs:
                runs.append(run)
    body = {}
    for r in table:
        row = body.setdefault(r["scene"], {"d": r["d"], "increments": r["increments"]})
        if r["refused"]:
            row[(r["path"], r["ranks"])] = "refused"
        elif r["force_difference"]:
            larger = max(float(r["force_difference"]), float(r["displacement_difference"]))
            tight = (max(float(r["tight_force_difference"]),
                         float(r["tight_displacement_difference"]))
                     if r["tight_force_difference"] else None)
            row[(r["path"], r["ranks"])] = (
                f"{larger:.0e}" + (" (initial mesh)" if r["mesh"] == "initial" else "")
                + (f"; {tight:.0e} at Tolerance 1e-12" if tight is not None else ""))
    return markdown(["scene", "d", "increments"] +
                    [f"{path}, {ranks} rank{'s' if ranks != '1' else ''}"
                     for path, ranks in runs],
                    [[scene, thousands(row["d"]) if row["d"] else "", row["increments"]] +
                     [row.get(run, "") for run in runs]
                     for scene, row in body.items()])


TABLES = {
    "same-solutions": same_solutions,
    "fclib-scenes": fclib_scenes,
    "preconditioners": preconditioners,
    "multigrid": multigrid,
    "kanno-series": kanno_series,
    "kanno-variants": kanno_variants,
    "two-bodies": two_bodies,
    "nearly-incompressible-lame": lame_elastic,
    "nearly-incompressible-example2": example2_newton,
}

MARKED = re.compile(r"(<!-- table: ([a-z0-9-]+) -->\n)(.*?)\n?(<!-- end table -->)", re.S)


def pages(root):
    folder = os.path.join(root, "doc")
    return [os.path.join(folder, name) for name in sorted(os.listdir(folder))
            if name.endswith(".md")]


def write_tables(root=ROOT, check=False):
    """Rewrites (or with check, compares) every marked table; returns the
    names of the tables that differ, and of markers with no known table."""
    differing = []
    for page in pages(root):
        with open(page) as f:
            text = f.read()

        def replace(match):
            name = match.group(2)
            if name not in TABLES:
                differing.append(f"{os.path.relpath(page, root)}: unknown table '{name}'")
                return match.group(0)
            made = TABLES[name](root)
            if made != match.group(3):
                differing.append(f"{os.path.relpath(page, root)}: table '{name}'")
            return match.group(1) + made + "\n" + match.group(4)

        new_text = MARKED.sub(replace, text)
        if not check and new_text != text:
            with open(page, "w") as f:
                f.write(new_text)
    return differing


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true",
                        help="only compare; exit 1 if a table differs from its CSV")
    parser.add_argument("--root", default=ROOT, help="the top of the repository")
    args = parser.parse_args()
    differing = write_tables(args.root, args.check)
    for line in differing:
        print(("differs from its CSV: " if args.check else "rewritten: ") + line)
    if args.check and differing:
        print("run python3 bench/doc_tables.py to rewrite them from the CSVs")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
