#!/usr/bin/env python3
"""Shipped scenes under each preconditioner path, side by side in one run:
for each scene file of --scenes, each number of global refinements of
--refinements (Mesh refinement/Global refinements) and each path of
--paths (Linear solver/Preconditioner), the whole run with the semismooth
Newton method: unknowns of the last mesh, Newton and Krylov iterations of
all increments and mesh cycles, the contact solve's seconds and its ratio
to the first path's. For what the scene files' own benches do not show:
contact pairs, adapted meshes and B-bar bodies under the geometric
multigrid (doc/performance.md, "Geometric multigrid"). A scene written
file@1 takes those refinements instead of --refinements. Rewrites
doc/benchmarks/preconditioners.csv (or --csv) and the tables of doc/ from
the CSVs.

usage: bench/preconditioners.py [--scenes parameters/ball_on_plate.prm,...]
                                [--refinements 1,2]
                                [--paths "amg;geometric multigrid"] [--ranks 1]
Run from the top of the repository after scripts/setup.sh.
"""
import argparse
import csv
import os
import re
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from doc_tables import write_tables  # noqa: E402
from run_series import run  # noqa: E402

COLUMNS = ["scene", "global_refinements", "ranks", "path", "d", "newton_iterations",
           "krylov_iterations", "contact_solve_s", "time_to_first_path",
           "peak_memory_mb", "converged"]


def text(scene, refinements, path):
    return (f"include {os.path.abspath(scene)}\n"
            "set Output directory = output\n"
            f"subsection Mesh refinement\n set Global refinements = {refinements}\nend\n"
            f"subsection Contact solver\n set Method = semismooth Newton\nend\n"
            f"subsection Linear solver\n set Preconditioner = {path}\nend\n"
            "subsection Postprocess\n subsection Visualization\n"
            "  set Write vtu = false\n end\nend\n")


def measure(contact, scene, refinements, path, ranks):
    with tempfile.TemporaryDirectory() as folder:
        code, output, _ = run(text(scene, refinements, path), ranks, folder, contact)
    steps = re.findall(r"Increment \d+/\d+, t = [^:]*: (\d+) Newton iterations, "
                       r"(\d+) Krylov", output)
    sizes = re.findall(r"d = (\d+)", output)
    solve = re.search(r"Contact solve = ([0-9.e+-]+) s", output)
    peak = re.search(r"peak memory = ([0-9.]+) MB", output)
    return dict(scene=os.path.basename(scene), global_refinements=refinements,
                ranks=ranks, path=path, d=int(sizes[-1]) if sizes else "",
                newton_iterations=sum(int(s[0]) for s in steps),
                krylov_iterations=sum(int(s[1]) for s in steps),
                contact_solve_s=float(solve.group(1)) if solve else "",
                peak_memory_mb=float(peak.group(1)) if peak else "",
                converged=int(code == 0))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenes", default="parameters/ball_on_plate.prm,"
                                            "parameters/hertz_3d.prm,"
                                            "parameters/hertz_3d_rubber.prm@1")
    parser.add_argument("--refinements", default="1,2")
    parser.add_argument("--paths", default="amg;geometric multigrid")
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks",
                                                      "preconditioners.csv"))
    parser.add_argument("--contact", default=os.path.join(ROOT, "build", "contact"))
    args = parser.parse_args()
    rows = []
    for entry in args.scenes.split(","):
        scene, _, own = entry.partition("@")
        for refinements in (own or args.refinements).split(","):
            first = None
            for path in args.paths.split(";"):
                row = measure(args.contact, scene, int(refinements), path, args.ranks)
                if first is None:
                    first = row
                if row["converged"] and first["converged"]:
                    row["time_to_first_path"] = round(
                        row["contact_solve_s"] / first["contact_solve_s"], 2)
                rows.append(row)
                print(f"{row['scene']}, {refinements} global refinement(s), {path}: "
                      f"d = {row['d']}, {row['newton_iterations']} Newton / "
                      f"{row['krylov_iterations']} Krylov iterations, contact solve "
                      f"{row['contact_solve_s']} s"
                      f"{'' if row['converged'] else ', FAILED'}", flush=True)
    with open(args.csv, "w", newline="") as f:
        writer = csv.DictWriter(f, COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    write_tables()
    return 0


if __name__ == "__main__":
    sys.exit(main())
