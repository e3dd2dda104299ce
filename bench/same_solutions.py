#!/usr/bin/env python3
"""Every shipped scene under each preconditioner path and rank count,
against ML's run on one rank: for each scene file of parameters/ (or
--scenes), each path of --paths and each rank count of --ranks, the
whole run with the scene's own settings, and the largest difference of
its contact forces (the statistics file: every increment's total forces,
relative to the largest of each column or a hundredth of the largest
force, as tests/compare_statistics.py) and of its vertex displacements
(every increment's displacement-NNNNN.csv, relative to the largest
displacement of the reference) from the reference run. Where a run ends
on other adapted meshes than the reference (the parallel Kelly marking,
the multigrid's rule of one level between neighbours at a vertex), both
are run again on the scene's initial mesh and compared there. A
difference above --tolerance is measured again with the Newton method's
Tolerance a hundred times smaller (1e-12): the solver tolerance times the
conditioning falls with it, a difference of the paths would not. A path the
program refuses for the scene (its one line) is listed as such. Rewrites
doc/benchmarks/same-solutions.csv (or --csv) and the tables of doc/.

usage: bench/same_solutions.py [--scenes parameters/a.prm,...]
                               [--paths "geometric multigrid;..."]
                               [--ranks 1,2] [--tolerance 1e-8]
                               [--csv doc/benchmarks/same-solutions.csv]
                               [--replace-rows]
Run from the top of the repository after scripts/setup.sh.
"""
import argparse
import csv
import glob
import os
import re
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "tests"))
from doc_tables import write_tables  # noqa: E402
from run_series import run  # noqa: E402
from statistics_file import names, table  # noqa: E402

REFERENCE = "amg"
# The Newton tolerance of the second comparison, for differences above
# --tolerance: a hundredth of the default.
TIGHT_TOLERANCE = 1e-12
MATRIX_FREE = "geometric multigrid, K matrix-free"
FORCES = ["Contact force x", "Contact force y", "Contact force z",
          "Normal contact force", "Tangential contact force"]
COLUMNS = ["scene", "ranks", "path", "increments", "d", "force_difference",
           "displacement_difference", "mesh", "tight_force_difference",
           "tight_displacement_difference", "same_to_tolerance", "refused"]


def text(scene, path, fixed_mesh, tight):
    linear = (" set Preconditioner = geometric multigrid\n"
              " set Matrix-free stiffness = true\n" if path == MATRIX_FREE else
              f" set Preconditioner = {path}\n")
    return (f"include {os.path.abspath(scene)}\n"
            "set Output directory = output\n"
            + ("subsection Mesh refinement\n set Strategy = none\nend\n" if fixed_mesh else "")
            + ("subsection Contact solver\n subsection Semismooth Newton\n"
               f"  set Tolerance = {TIGHT_TOLERANCE}\n end\nend\n" if tight else "") +
            f"subsection Linear solver\n{linear}end\n"
            "subsection Postprocess\n subsection Visualization\n"
            "  set Write vtu = false\n  set Write csv tables = true\n end\nend\n")


def read_run(folder):
    """The statistics table with its column numbers, and the vertex
    displacements of each increment keyed by position."""
    statistics = os.path.join(folder, "output", "statistics")
    forces = (table(statistics), names(statistics)) if os.path.exists(statistics) else None
    displacements = []
    for path in sorted(glob.glob(os.path.join(folder, "output", "displacement-*.csv"))):
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
        axes = [c for c in "xyz" if rows and c in rows[0]]
        # Two bodies have a vertex each where they touch: a position keeps
        # the displacements of all its vertices.
        at = {}
        for row in rows:
            at.setdefault(tuple(round(float(row[c]), 9) for c in axes), []).append(
                tuple(float(row["u" + c]) for c in axes))
        displacements.append(at)
    return forces, displacements


def force_difference(a, b):
    (rows_a, columns_a), (rows_b, columns_b) = a, b
    if len(rows_a) != len(rows_b):
        return float("inf")
    named = [n for n in FORCES if n in columns_a and n in columns_b]
    largest = max((abs(row[columns_a[n] - 1]) for n in named for row in rows_a), default=0)
    worst = 0.
    for n in named:
        x = [row[columns_a[n] - 1] for row in rows_a]
        y = [row[columns_b[n] - 1] for row in rows_b]
        scale = max(max(map(abs, x)), 1e-2 * largest, 1e-300)
        worst = max(worst, max(abs(p - q) for p, q in zip(x, y)) / scale)
    return worst


def vertex_difference(a, b):
    """The displacements of the vertices at one position, each paired with
    the nearest of the other run's (the bodies' vertices where they touch
    come in no order; a vertex on the ranks' border is written by each)."""
    def distance(u, v):
        return max(abs(p - q) for p, q in zip(u, v))
    return max(max(min(distance(u, v) for v in b) for u in a),
               max(min(distance(u, v) for u in a) for v in b))


def displacement_difference(a, b):
    """Over the vertices both meshes have (adapted meshes may differ)."""
    if len(a) != len(b):
        return float("inf")
    scale = max((abs(x) for step in a for vertices in step.values()
                 for u in vertices for x in u), default=0) or 1.
    worst = 0.
    for step_a, step_b in zip(a, b):
        common = step_a.keys() & step_b.keys()
        if not common:
            return float("inf")
        worst = max(worst, max(vertex_difference(step_a[key], step_b[key])
                               for key in common) / scale)
    return worst


def same_meshes(a, b):
    return len(a) == len(b) and all(p.keys() == q.keys() for p, q in zip(a, b))


def measure(contact, scene, path, ranks, fixed_mesh=False, tight=False):
    with tempfile.TemporaryDirectory() as folder:
        code, output, _ = run(text(scene, path, fixed_mesh, tight), ranks, folder, contact)
        forces, displacements = read_run(folder)
    sizes = re.findall(r"d = (\d+) free", output)
    refused = ""
    if code != 0:
        # The program's own line (mpirun adds its banner after it).
        lines = [l for l in output.splitlines() if l.startswith("Error")]
        refused = lines[0] if lines else f"exit code {code}"
    return dict(scene=os.path.basename(scene), ranks=ranks, path=path,
                increments=len(forces[0]) if forces else 0,
                d=int(sizes[-1]) if sizes else "", refused=refused), \
        (forces, displacements) if code == 0 else None


def compare(args, scene, path, ranks, solution, references, row):
    """Fills the differences of @p solution (a run of path on ranks) from
    ML's on one rank into row; returns whether they are within
    --tolerance, or shrink with the Newton tolerance to within it."""
    def reference(fixed_mesh, tight):
        if (fixed_mesh, tight) not in references:
            references[(fixed_mesh, tight)] = measure(
                args.contact, scene, REFERENCE, 1, fixed_mesh, tight)[1]
        return references[(fixed_mesh, tight)]

    fixed_mesh = not same_meshes(reference(False, False)[1], solution[1])
    if fixed_mesh:
        # Adapted meshes differ (the parallel Kelly marking, the multigrid's
        # level rule): their solutions differ by the discretization, so
        # compare on the initial mesh.
        solution = measure(args.contact, scene, path, ranks, True)[1]
    row["mesh"] = "initial" if fixed_mesh else "as shipped"
    base = reference(fixed_mesh, False)
    row["force_difference"] = force_difference(base[0], solution[0])
    row["displacement_difference"] = displacement_difference(base[1], solution[1])
    difference = max(row["force_difference"], row["displacement_difference"])
    if difference > args.tolerance:
        # The solver tolerance times the conditioning (a B-bar body at
        # nu = 0.4999): then the difference falls with the tolerance.
        tight = measure(args.contact, scene, path, ranks, fixed_mesh, True)[1]
        base = reference(fixed_mesh, True)
        row["tight_force_difference"] = force_difference(base[0], tight[0])
        row["tight_displacement_difference"] = displacement_difference(base[1], tight[1])
        difference = max(row["tight_force_difference"],
                         row["tight_displacement_difference"])
    row["same_to_tolerance"] = int(difference <= args.tolerance)
    return row["same_to_tolerance"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenes", default=",".join(
        sorted(glob.glob(os.path.join(ROOT, "parameters", "*.prm")))))
    parser.add_argument("--paths", default=f"{REFERENCE};geometric multigrid;{MATRIX_FREE}")
    parser.add_argument("--ranks", default="1,2")
    parser.add_argument("--tolerance", type=float, default=1e-8)
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks",
                                                      "same-solutions.csv"))
    parser.add_argument("--replace-rows", action="store_true",
                        help="keep the rows of --csv for the scenes not run "
                             "and replace those of the scenes run")
    parser.add_argument("--contact", default=os.path.join(ROOT, "build", "contact"))
    args = parser.parse_args()
    rows, failures = [], 0
    for scene in args.scenes.split(","):
        reference = None
        for ranks in (int(r) for r in args.ranks.split(",")):
            for path in args.paths.split(";"):
                row, solution = measure(args.contact, scene, path, ranks)
                if reference is None:
                    if solution is None:
                        print(f"{row['scene']}: the reference run failed: {row['refused']}")
                        failures += 1
                        break
                    reference = solution
                    references = {(False, False): reference}
                elif solution is not None:
                    failures += 1 - compare(args, scene, path, ranks, solution,
                                            references, row)
                rows.append(row)
                differences = (
                    f", forces {row['force_difference']:.1e}, displacements "
                    f"{row['displacement_difference']:.1e} of the reference"
                    f"{' on the initial mesh' if row['mesh'] == 'initial' else ''}"
                    + (f"; with Tolerance = {TIGHT_TOLERANCE:g} forces "
                       f"{row['tight_force_difference']:.1e}, displacements "
                       f"{row['tight_displacement_difference']:.1e}"
                       if "tight_force_difference" in row else "")
                    if "force_difference" in row else "")
                print(f"{row['scene']}, {ranks} rank(s), {path}: d = {row['d']}, "
                      f"{row['increments']} increments{differences}"
                      f"{', refused: ' + row['refused'] if row['refused'] else ''}",
                      flush=True)
            if reference is None:
                break
    for row in rows:
        for key in ("force_difference", "displacement_difference",
                    "tight_force_difference", "tight_displacement_difference"):
            if isinstance(row.get(key), float):
                row[key] = f"{row[key]:.1e}"
    if args.replace_rows and os.path.exists(args.csv):
        # The rows of the scenes run replace theirs, in place.
        with open(args.csv, newline="") as f:
            kept = list(csv.DictReader(f))
        ran = {row["scene"] for row in rows}
        fresh = {scene: [row for row in rows if row["scene"] == scene] for scene in ran}
        merged = []
        for row in kept:
            if row["scene"] not in ran:
                merged.append(row)
            elif row["scene"] in fresh:
                merged += fresh.pop(row["scene"])
        rows = merged + [row for scene in fresh.values() for row in scene]
    with open(args.csv, "w", newline="") as f:
        writer = csv.DictWriter(f, COLUMNS)
        writer.writeheader()
        writer.writerows({column: row.get(column, "") for column in COLUMNS}
                         for row in rows)
    write_tables()
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
