#!/usr/bin/env python3
"""Writes the tables of doc/ that quote the bench CSVs, from the CSVs.

A table in a doc page sits between two markers,

    <!-- table: two-bodies -->
    | ... |
    <!-- end table -->

and TABLES in bench/doc_table_builders.py says how each one is made from
its CSV in doc/benchmarks/. Numbers quoted in prose sit between inline
markers,

    ... went to <!-- quote: multigrid-1.6m -->19 and 189<!-- end quote --> ...

and QUOTES below says how each text is made (the page may wrap it over
lines: the check compares the words). The pages are README.md,
bench/README.md and every .md under doc/. The bench scripts call
write_tables() after they write their CSV; `--check` (the test
docs/tables_from_csv) fails with the name of every table or quote whose
text differs from what its CSV makes, so that a number in them cannot
drift from the measurement. This module also has the bench scripts'
writers of their CSVs (append_rows, replace_rows, replace_runs).

usage: bench/doc_tables.py [--check] [--root .]
"""
import argparse
import csv
import math
import os
import re
import sys

from doc_table_builders import TABLES, latest_by_scene, rows, thousands
import doc_table_scenes

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


# -- quotes: numbers of the CSVs in a sentence ------------------------------

ERROR_COLUMNS = ["radial_displacement_error", "radial_stress_error",
                 "hoop_stress_error", "radius_error", "peak_pressure_error",
                 "profile_error"]


def nearly_incompressible_errors(root):
    """The standard element's and the B-bar element's errors (in %) at
    nu = 0.4999 over Lame's sphere and the Hertz scenes
    (doc/robustness.md)."""
    table = [r for r in rows(root, "nearly-incompressible.csv")
             if r["nu"] == "0.4999" and r["converged"] == "1"]

    def errors(variant, columns, cases=None):
        return [float(r[c]) for r in table for c in columns
                if r["variant"] == variant and r[c]
                and (cases is None or r["case"] in cases)]

    radius = [float(r["radius_error"]) for case in ("hertz_2d", "hertz_3d")
              for r in table if r["case"] == case and r["variant"] == "standard"
              and r["radius_error"]]
    others = errors("standard", [c for c in ERROR_COLUMNS if c != "radius_error"])
    profile_3d = errors("B-bar mixed", ["profile_error"], ("hertz_3d",))
    b_bar = [float(r[c]) for r in table for c in ERROR_COLUMNS
             if r["variant"] == "B-bar mixed" and r[c]
             and not (r["case"] == "hertz_3d" and c == "profile_error")]
    return (f"{' and '.join(f'{e:.0f}' for e in radius)} % in the contact radius "
            f"of the Hertz scenes (2D, 3D) and {min(others):.0f} to "
            f"{max(others):.0f} % in Lame's displacements and stresses and in "
            f"Hertz's pressures, and the B-bar element's below "
            f"{math.ceil(max(b_bar)):.0f} % ({max(profile_3d):.0f} % of p0 in the "
            f"nodal pressure profile of the 3D ball)")


def multigrid_row(root, n_y, ranks, path):
    for r in rows(root, "multigrid.csv"):
        if r["n_y"] == n_y and r["ranks"] == ranks and r["path"] == path \
                and r["converged"] == "1":
            return r
    raise KeyError(f"multigrid.csv has no converged row N_Y = {n_y}, "
                   f"{ranks} ranks, '{path}'")


def multigrid_largest_ml(root):
    """The multigrid with K matrix-free at d = 1.6M on 2 ranks: Newton
    steps and Krylov iterations (doc/algorithm.md)."""
    r = multigrid_row(root, "64", "2", "geometric multigrid, K matrix-free")
    return f"{r['newton_iterations']} and {r['contact_krylov_iterations']}"


def multigrid_against_ml(root):
    """The same run against ML's (doc/performance.md)."""
    mg = multigrid_row(root, "64", "2", "geometric multigrid, K matrix-free")
    ml = multigrid_row(root, "64", "2", "amg")
    mg_s, ml_s = float(mg["contact_solve_s"]), float(ml["contact_solve_s"])
    return (f"{mg_s / ml_s:.2f} times at d = 1.6M ({mg_s:.0f} s against "
            f"{ml_s:.0f} s, {mg['newton_iterations']} Newton steps and "
            f"{mg['contact_krylov_iterations']} Krylov iterations against "
            f"{ml['newton_iterations']} and {ml['contact_krylov_iterations']})")


def step42_goals(root):
    """The goals of elasto-plastic bodies from bench/step42.py's CSV: times
    faster than step-42 at d >= 100k per element and rank count, Newton
    steps against step-42's, the Newton step in elastic solves, and the
    memory per rank of the plastic scene at d >= 1M against the elastic."""
    latest = {}
    for r in rows(root, "step42.csv"):
        latest[(r["mesh"], int(r["cells_per_edge"]), int(r["ranks"]), r["program"],
                r["element"])] = r
    parts = []
    for element in ("standard", "B-bar"):
        ratios = []
        for (mesh, edge, ranks, program, el), r in sorted(latest.items()):
            ref = latest.get((mesh, edge, ranks, "step-42", "standard"))
            if mesh == "global" and program == "contact" and el == element and ref \
                    and int(ref["d"]) >= 100000:
                ratios.append((edge, ranks, float(ref["compute_s"]) / float(r["compute_s"]),
                               int(r["newton_steps"]), int(ref["newton_steps"])))
        parts.append(f"{element} element " + ", ".join(
            f"{t:.1f} ({e}^3, {k} rank{'s' if k > 1 else ''}, {n} Newton steps against {m})"
            for e, k, t, n, m in ratios))
    steps = [float(r["newton_step_in_elastic_solves"]) for r in latest.values()
             if r["program"] == "contact" and r["newton_step_in_elastic_solves"]]
    large = {r["program"]: r for k, r in latest.items() if k[0] == "global" and int(r["d"]) >= 1000000}
    memory = ""
    if "contact" in large and "contact, elastic" in large:
        a, b = large["contact"], large["contact, elastic"]
        memory = (f"; at d = {thousands(a['d'])} on {a['ranks']} ranks the plastic scene "
                  f"took {float(a['peak_mb']):.0f} MB per rank, the elastic one "
                  f"{float(b['peak_mb']):.0f} MB ({float(a['peak_mb']) / float(b['peak_mb']):.2f} times)")
    return ("times faster than step-42: " + "; ".join(parts) +
            f"; a Newton step costs {min(steps):.2f} to {max(steps):.2f} elastic solves" + memory)


def ironing_fold(root):
    """The smallest det F of the 2D ironing's converged states on two
    meshes with the law at the Gauss points, where the fine one stops, and
    how far the Gauss-Lobatto points take the fine meshes
    (doc/performance.md)."""
    table = rows(root, "ironing-fold.csv")

    def run(size, quadrature):
        return [r for r in table if r["cell_size"] == size and r["quadrature"] == quadrature]

    coarse, fine = run("0.125", "Gauss"), run("0.0625", "Gauss")
    at_1_7 = next((r for r in fine if float(r["time"]) == 1.7), None)
    if not coarse or at_1_7 is None:
        return "(bench/ironing_fold.py has not run on both meshes with the Gauss points)"
    last = fine[-1]
    text = (f"on the shipped cells of 0.125 it is "
            f"{float(coarse[-1]['smallest_det_F']):.2f} at t = {float(coarse[-1]['time']):g}; "
            f"on cells of 0.0625 it falls from {float(at_1_7['smallest_det_F']):.2f} at "
            f"t = 1.7 to {float(last['smallest_det_F']):.0e} at "
            f"t = {float(last['time']):.6g}, where the run stops with the cell at "
            f"{last['failed_cell']} inverted")
    corners = []
    for size in ("0.0625", "0.03125"):
        mine = run(size, "Gauss-Lobatto")
        if mine:
            end = mine[-1]
            reached = (f"reach t = {float(end['time']):g}" if not end["stopped_at"] else
                       f"stop at t = {float(end['time']):.6g} (the cell at {end['failed_cell']})")
            corners.append(f"cells of {size} {reached}, the smallest det F of any "
                           f"converged state {min(float(r['smallest_det_F']) for r in mine):.2f}, "
                           f"in {end['wall_s']} s")
    if corners:
        text += ". With the law at the Gauss-Lobatto points, " + "; ".join(corners)
    return text


def process_start(root):
    """The start of a process with the libraries in the linker's order and
    in the order cmake/loader_order.cmake gives (doc/performance.md): the
    last run of bench/process_start.py that timed both."""
    table = rows(root, "process-start.csv")
    for mine in reversed(table):
        linker = [r for r in table if r["commit"] == mine["commit"]
                  and int(r["needed_libraries"]) < int(mine["needed_libraries"])]
        if linker:
            old = linker[-1]
            return (f"{float(old['cpu_s']):.2f} s of CPU to {float(mine['cpu_s']):.2f} s "
                    f"(the median of {mine['repeat']} starts each, alternately)")
    return "(bench/process_start.py has not timed both orders)"


def finite_strain_block(root):
    """The block on block's ratios of finite to small strain, with the
    pair's geometry at every Newton iterate, from the last run of
    bench/finite_strain.py (doc/performance.md)."""
    latest = latest_by_scene(root, "finite-strain.csv", "kinematics")
    within = "finite strain, pair geometry at every Newton iterate"
    refined = latest.get("block_on_block_2d refined 3 times", {}).get(within)
    own = latest.get("block_on_block_2d", {}).get(within)
    if not refined or not own:
        return "(bench/finite_strain.py has not run the block on block)"
    return (f"the block on block's refined mesh at {refined['finite_over_small']} times "
            f"small strain, its own mesh at {own['finite_over_small']}")


def finite_strain_goal(root):
    """Every scene's ratio of finite to small strain in the last run of
    bench/finite_strain.py (a pair's with its geometry at every Newton
    iterate), for the goals' table of doc/performance.md."""
    latest = latest_by_scene(root, "finite-strain.csv", "kinematics")
    within = "finite strain, pair geometry at every Newton iterate"
    ratios = []
    for scene, variants in latest.items():
        row = variants.get(within) or variants.get("finite strain")
        if row:
            ratios.append(f"{scene} {row['finite_over_small']}")
    if not ratios:
        return "(bench/finite_strain.py has not run)"
    return ", ".join(ratios)


def forming_goal(root):
    """step-42's finite over small strain per increment in bench/forming.py's
    rows (as shipped and a fifth as deep), for the goals' table."""
    per_part = {}
    for r in rows(root, "forming.csv"):
        if r["part"].startswith("step42"):
            per_part.setdefault(r["part"], {})[r["variant"]] = \
                float(r["increment_in_elastic_solves"])
    ratios = [f"{part} {v['finite strain'] / v['small strain']:.2f}"
              for part, v in per_part.items() if len(v) == 2]
    return ", ".join(ratios) if ratios else "(bench/forming.py has not run)"


def axisymmetric_goal(root):
    """bench/axisymmetric.py: the set-up and solve time of the 3D run from
    which every finer one is within 1 % of Hertz's contact radius (fitted
    to the nodal pressures) over that of the axisymmetric one."""
    ladders = {}
    for r in rows(root, "axisymmetric.csv"):
        ladders.setdefault(r["kind"], []).append(
            (int(r["level"]), float(r["fitted_radius_error_percent"]),
             float(r["setup_and_solve_s"])))
    reached = {}
    for kind, ladder in ladders.items():
        ladder.sort()
        for i, (_, _, seconds) in enumerate(ladder):
            if all(error <= 1 for _, error, _ in ladder[i:]):
                reached[kind] = seconds
                break
    if len(reached) != 2:
        return "(bench/axisymmetric.py has not run)"
    return f"{reached['3D'] / reached['axisymmetric']:.0f}"


QUOTES = {
    "axisymmetric-goal": axisymmetric_goal,
    "process-start": process_start,
    "forming-goal": forming_goal,
    "finite-strain-block": finite_strain_block,
    "finite-strain-goal": finite_strain_goal,
    "ironing-fold": ironing_fold,
    "step42-goals": step42_goals,
    "nearly-incompressible-errors": nearly_incompressible_errors,
    "multigrid-1.6m": multigrid_largest_ml,
    "multigrid-1.6m-against-ml": multigrid_against_ml,
    **doc_table_scenes.QUOTES,
}
TABLES = {**TABLES, **doc_table_scenes.TABLES}

MARKED = re.compile(r"(<!-- table: ([a-z0-9.-]+) -->\n)(.*?)\n?(<!-- end table -->)", re.S)
QUOTED = re.compile(r"(<!-- quote: ([a-z0-9.-]+) -->)(.*?)(<!-- end quote -->)", re.S)


def pages(root):
    """README.md, bench/README.md and every Markdown page under doc/."""
    found = [os.path.join(root, p) for p in ("README.md", os.path.join("bench", "README.md"))
             if os.path.isfile(os.path.join(root, p))]
    for folder, subfolders, names in os.walk(os.path.join(root, "doc")):
        subfolders.sort()
        found += [os.path.join(folder, name) for name in sorted(names)
                  if name.endswith(".md")]
    return found


def words(text):
    return " ".join(text.split())


def differences(root=ROOT, check=True):
    """Rewrites (or with check, compares) every marked table and quote;
    returns (page, line, what) for each one that differs, each marker with
    no known table or quote, and each quote marker left open."""
    found = []
    for page in pages(root):
        with open(page) as f:
            text = f.read()
        relative = os.path.relpath(page, root)

        def line_of(match):
            return text.count("\n", 0, match.start()) + 1

        def made(kind, known, match):
            name = match.group(2)
            if name not in known:
                found.append((relative, line_of(match), f"unknown {kind} '{name}'"))
                return None
            try:
                return known[name](root)
            except (OSError, KeyError, ValueError) as error:
                found.append((relative, line_of(match),
                              f"{kind} '{name}' cannot be made from its CSV: {error}"))
                return None

        def replace_table(match):
            table = made("table", TABLES, match)
            if table is None:
                return match.group(0)
            if table != match.group(3):
                found.append((relative, line_of(match), f"table '{match.group(2)}'"))
            return match.group(1) + table + "\n" + match.group(4)

        def replace_quote(match):
            quote = made("quote", QUOTES, match)
            if quote is None:
                return match.group(0)
            if words(quote) != words(match.group(3)):
                found.append((relative, line_of(match),
                              f"quote '{match.group(2)}' says '{words(match.group(3))}', "
                              f"its CSV makes '{quote}'"))
                return match.group(1) + quote + match.group(4)
            return match.group(0)

        new_text = QUOTED.sub(replace_quote, MARKED.sub(replace_table, text))
        for match in re.finditer(r"<!-- quote: [^>]*-->", text):
            if not QUOTED.match(text, match.start()) or \
                    "<!-- quote:" in QUOTED.match(text, match.start()).group(3):
                found.append((relative, line_of(match),
                              "a quote marker without its <!-- end quote -->"))
        if not check and new_text != text:
            with open(page, "w") as f:
                f.write(new_text)
    return found


def append_rows(path, columns, rows):
    """Appends @p rows (dicts; floats to 6 digits) to the CSV @p path, with
    its header @p columns if the file is new."""
    new_file = not os.path.exists(path)
    with open(path, "a", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        if new_file:
            writer.writeheader()
        for row in rows:
            writer.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v)
                             for k, v in row.items()})


def replace_rows(path, columns, rows):
    """Writes the CSV @p path anew with @p rows (see append_rows()): for
    the benches whose file holds their last run only."""
    if os.path.exists(path):
        os.remove(path)
    append_rows(path, columns, rows)


def replace_runs(path, columns, rows, key):
    """Writes the CSV @p path with @p rows in place of the rows of the same
    runs (@p key of a row: the run it belongs to); the rows of other runs
    stay, for the benches whose file holds the last run of each."""
    made = {key(row) for row in rows}
    kept = []
    if os.path.exists(path):
        with open(path, newline="") as f:
            kept = [row for row in csv.DictReader(f) if key(row) not in made]
    replace_rows(path, columns, kept + rows)


def write_tables(root=ROOT, check=False):
    """Rewrites (or with check, compares) every marked table and quote;
    returns 'page: what' for each that differs (see differences())."""
    return [f"{page}: {what}" for page, _, what in differences(root, check)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true",
                        help="only compare; exit 1 if a table or quote differs from its CSV")
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
