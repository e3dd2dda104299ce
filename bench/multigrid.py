#!/usr/bin/env python3
"""The geometric multigrid path against ML's, side by side in one run, on
Kanno's example II (3D brick, N_X = 2 N_Y = 2 N_Z, mu = 0.3, the
semismooth Newton method): for each size and path (Linear solver/
Preconditioner = amg | geometric multigrid, and the multigrid with
Linear solver/Matrix-free stiffness = true) an elastic solve of the same
mesh and loads without contact, and the contact solve. The unit of the
contact solve is the elastic solve of its own path (set-up included: ML's
for amg; the multigrid's set-up is counted apart, it is made once per
mesh). Peak memory per rank over d gives kB per unknown. Appends one CSV
row per size, path and rank count and rewrites the table of
doc/performance.md ("Geometric multigrid") from the CSV.

usage: bench/multigrid.py [--sizes 8,12,16,24,28] [--ranks 1] [--paths "amg;..."]
                          [--csv doc/benchmarks/multigrid.csv]
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
from run_series import run, scene  # noqa: E402

COLUMNS = ["n_y", "ranks", "path", "d", "levels", "coarse_unknowns",
           "elastic_cg_iterations", "elastic_solve_s", "multigrid_setup_s",
           "newton_iterations", "contact_krylov_iterations", "contact_solve_s",
           "elastic_solves_per_contact_solve", "peak_memory_mb", "kb_per_unknown",
           "converged"]

MATRIX_FREE = "geometric multigrid, K matrix-free"
PATHS = ("amg", "geometric multigrid", MATRIX_FREE)


def with_path(text, path):
    if path == MATRIX_FREE:
        return text + ("subsection Linear solver\n set Preconditioner = geometric multigrid\n"
                       " set Matrix-free stiffness = true\nend\n")
    return text + f"subsection Linear solver\n set Preconditioner = {path}\nend\n"


def summary_seconds(output):
    summary = re.search(r"-- summary:(.*)", output)
    if not summary:
        return {}
    return {k: float(v) for k, v in
            re.findall(r" ([A-Za-z -]+?) = ([0-9.e+-]+) s;", summary.group(1))}


def peak_memory(output):
    match = re.search(r"peak memory = ([0-9.]+) MB", output)
    return float(match.group(1)) if match else float("nan")


def measure(contact, n_y, ranks, path):
    with tempfile.TemporaryDirectory() as folder:
        code_e, elastic, _ = run(with_path(scene(2, n_y, 0.3, "semismooth Newton",
                                                 contact=False), path),
                                 ranks, folder, contact)
    with tempfile.TemporaryDirectory() as folder:
        code_c, output, _ = run(with_path(scene(2, n_y, 0.3, "semismooth Newton"), path),
                                ranks, folder, contact)
    size = re.search(r"d = (\d+) free", output)
    if not size:
        # Stopped before the mesh was made (the memory check's error).
        return dict(n_y=n_y, ranks=ranks, path=path, d="", converged=0)
    d = int(size.group(1))
    levels = re.search(r"Geometric multigrid: (\d+) levels, (\d+) unknowns", output)
    cg = re.search(r"elastic solve, (\d+) CG iterations", elastic)
    newton = re.search(r"Increment 1/1, t = 1: (\d+) Newton iterations, (\d+) Krylov", output)
    elastic_seconds = summary_seconds(elastic).get("Elastic solve", float("nan"))
    contact_seconds = summary_seconds(output).get("Contact solve", float("nan"))
    # The multigrid's set-up is made in the Setup section, once per mesh.
    setup = re.search(r"multigrid set-up = ([0-9.e+-]+) s", output)
    peak = max(peak_memory(output), peak_memory(elastic))
    return dict(n_y=n_y, ranks=ranks, path=path, d=d,
                levels=int(levels.group(1)) if levels else "",
                coarse_unknowns=int(levels.group(2)) if levels else "",
                elastic_cg_iterations=int(cg.group(1)) if cg else "",
                elastic_solve_s=round(elastic_seconds, 4),
                multigrid_setup_s=float(setup.group(1)) if setup else "",
                newton_iterations=int(newton.group(1)) if newton else "",
                contact_krylov_iterations=int(newton.group(2)) if newton else "",
                contact_solve_s=round(contact_seconds, 4),
                elastic_solves_per_contact_solve=round(contact_seconds / elastic_seconds, 2),
                peak_memory_mb=peak,
                kb_per_unknown=round(1024 * peak * ranks / d, 2),
                converged=int(code_e == 0 and code_c == 0))


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", default="8,12,16,24,28")
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--paths", default=";".join(PATHS),
                        help="';'-separated, of: " + "; ".join(PATHS))
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks",
                                                      "multigrid.csv"))
    parser.add_argument("--contact", default=os.path.join(ROOT, "build", "contact"))
    args = parser.parse_args()
    new = not os.path.exists(args.csv)
    with open(args.csv, "a", newline="") as f:
        writer = csv.DictWriter(f, COLUMNS)
        if new:
            writer.writeheader()
        for n_y in (int(s) for s in args.sizes.split(",")):
            for path in args.paths.split(";"):
                row = measure(args.contact, n_y, args.ranks, path)
                writer.writerow(row)
                f.flush()
                if not row["d"]:
                    print(f"N_Y = {n_y}, {args.ranks} rank(s), {path}: stopped "
                          "before the mesh was made", flush=True)
                    continue
                print(f"N_Y = {n_y}, {args.ranks} rank(s), {path}: d = {row['d']}, "
                      f"elastic solve {row['elastic_solve_s']} s "
                      f"({row['elastic_cg_iterations']} CG iterations), contact solve "
                      f"{row['elastic_solves_per_contact_solve']} elastic solves, "
                      f"{row['kb_per_unknown']} kB per unknown"
                      f"{'' if row['converged'] else ', FAILED'}", flush=True)
    write_tables()
    return 0


if __name__ == "__main__":
    sys.exit(main())
