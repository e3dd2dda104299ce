#!/usr/bin/env python3
"""The paper's scaling series, for each contact solver, with the wall time
of one elastic solve on the same mesh as the unit.

Example I: N_Y in {26, 40, 54, 68, 80, 92, 104, 114, 124, 134, 144} (2D);
example II: N_Y in {10, 12, ..., 28} (3D); example II at N_Y = 20 with
mu in {0.5, 1.0, 1.5}. One CSV row per instance and solver, appended as
soon as it is measured; instances already in the CSV are skipped, so an
interrupted run continues where it stopped.

usage: bench/run_series.py [--quick] [--ranks N] [--solvers a,b] [--repeat N]
                           [--series ex1,ex2,mu] [--max-n-y N] [--sizes a,b]
                           [--csv doc/benchmarks/series.csv]
Run from the top of the repository after scripts/setup.sh.
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile
import time

SOLVERS = {"primal-dual": "accelerated primal-dual",
           "newton": "semismooth Newton"}
COLUMNS = ["example", "N_Y", "mu", "ranks", "solver", "d", "c", "iterations",
           "cg_iterations", "amg_setups", "setup_s", "eigenvalue_s", "solve_s",
           "total_s", "peak_memory_mb", "force_balance", "complementarity",
           "penetration", "free_percent", "stick_percent", "slip_percent",
           "elastic_solve_s", "ratio_to_elastic", "converged", "amg_setup_s",
           "krylov_s", "contact_operations_s", "output_s"]


def scene(example, n_y, mu, solver, contact=True):
    """A complete parameter file for the instance: Kanno's example I (2D,
    body 1 x 0.4, N_X = 2.5 N_Y) or II (3D, 2 x 1 x 1, N_X = 2 N_Y = 2 N_Z),
    written out in full so that it does not depend on parameters/."""
    if example == 1:
        text = f"""subsection Geometry
 subsection Box
  set Y extent = 0.4
  set X repetitions = {n_y * 5 // 2}
  set Y repetitions = {n_y}
 end
end
subsection Material
 set Two-dimensional model = plane stress
end
subsection Boundary conditions
 set Fixed boundaries = left
 set Traction = top: 0, -0.01
end
"""
        floor = "0, -0.01"
    else:
        text = f"""set Dimension = 3
subsection Geometry
 subsection Box
  set X extent = 2
  set X repetitions = {2 * n_y}
  set Y repetitions = {n_y}
  set Z repetitions = {n_y}
 end
end
subsection Boundary conditions
 set Fixed boundaries = left
 set Traction = top: 0, 0, -0.005
end
"""
        floor = "0, 0, -0.005"
    text += ("set Output directory = output\nsubsection Postprocess\n"
             " subsection Visualization\n  set Write vtu = false\n end\nend\n")
    if not contact:
        return text
    text += f"""subsection Contact
 set Contact boundaries = bottom
 set Friction coefficient = {mu}
 subsection Obstacle
  subsection Plane
   set Point = {floor}
  end
 end
end
subsection Contact solver
 set Method = {solver}
 subsection Accelerated primal-dual
  set Scaling = paper
 end
end
"""
    return text


def run(text, ranks, folder, contact):
    path = os.path.join(folder, "scene.prm")
    with open(path, "w") as f:
        f.write(text)
    command = [contact, path]
    if ranks > 1:
        command = ["mpirun", "-np", str(ranks)] + command
    environment = dict(os.environ, OMP_NUM_THREADS="1",
                       OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    started = time.time()
    done = subprocess.run(command, cwd=folder, capture_output=True, text=True,
                          env=environment)
    return done.returncode, done.stdout + done.stderr, time.time() - started


def parse(output):
    values = {}
    match = re.search(r"d = (\d+) free", output)
    values["d"] = int(match.group(1)) if match else ""
    match = re.search(r"c = (\d+) candidates", output)
    values["c"] = int(match.group(1)) if match else 0
    match = re.search(r"Increment 1/1, t = 1: (\d+) \S+ iterations, (\d+) Krylov "
                      r"iterations, (\d+) AMG set-ups; residuals (\S+) (\S+) (\S+);"
                      r" free/stick/slip (\d+)/(\d+)/(\d+)", output)
    if match:
        (values["iterations"], values["cg_iterations"], values["amg_setups"],
         values["force_balance"], values["complementarity"],
         values["penetration"]) = match.groups()[:6]
        free, stick, slip = (int(x) for x in match.groups()[6:])
        total = max(free + slip + stick, 1)
        values.update(free_percent=100 * free / total, slip_percent=100 * slip / total,
                      stick_percent=100 * stick / total)
    match = re.search(r"nothing touches, the elastic solution \((\d+) CG", output)
    if match:
        values.update(iterations=0, cg_iterations=match.group(1))
    summary = re.search(r"-- summary:(.*)", output)
    sections = dict(re.findall(r" ([A-Za-z -]+?) = ([0-9.e+-]+) s;", summary.group(1))) if summary else {}
    seconds = {k: float(v) for k, v in sections.items()}
    values["setup_s"] = seconds.get("Setup", 0) + seconds.get("Assembly", 0)
    values["eigenvalue_s"] = seconds.get("Smallest eigenvalue of K", 0)
    values["solve_s"] = (seconds.get("Contact solve", 0) + seconds.get("Elastic solve", 0)
                         + values["eigenvalue_s"])
    # The time split of the solves: AMG set-ups, Krylov solves (AMG
    # applications included), and the rest, the contact operations.
    values["amg_setup_s"] = seconds.get("AMG set-up", "")
    values["krylov_s"] = seconds.get("Krylov solves", "")
    if summary and "Krylov solves" in seconds:
        values["contact_operations_s"] = round(
            values["solve_s"] - seconds["AMG set-up"] - seconds["Krylov solves"], 4)
    values["output_s"] = seconds.get("Output", 0)
    match = re.search(r"peak memory = ([0-9.]+) MB", output)
    values["peak_memory_mb"] = float(match.group(1)) if match else ""
    return values


def best_run(text, ranks, repeat, contact):
    """(exit code, parsed values, output) of the fastest of @p repeat runs of
    the scene (by solve_s), or of the first run that fails; the values also
    hold elastic_s, the wall time of the elastic solve."""
    best = None
    for _ in range(repeat):
        with tempfile.TemporaryDirectory() as folder:
            code, output, total = run(text, ranks, folder, contact)
        values = parse(output)
        values["total_s"] = round(total, 3)
        match = re.search(r"Elastic solve = ([0-9.e+-]+) s", output)
        values["elastic_s"] = float(match.group(1)) if match else float("inf")
        if code != 0:
            return code, values, output
        if best is None or values["solve_s"] < best[1]["solve_s"]:
            best = (code, values, output)
    return best


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true",
                        help="a small subset: example I at N_Y = 26, 40 and "
                             "example II at N_Y = 10, 12")
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--solvers", default="newton,primal-dual")
    parser.add_argument("--series", default="ex1,ex2,mu")
    parser.add_argument("--max-n-y", type=int, default=1000,
                        help="skip larger instances")
    parser.add_argument("--sizes", default="",
                        help="N_Y values (comma-separated) instead of the "
                             "paper's, e.g. --series ex2 --sizes 55 --ranks 2 "
                             "for the scale run (d above 10^6)")
    parser.add_argument("--repeat", type=int, default=1,
                        help="best of this many runs, for the unit and the "
                             "contact solve alike")
    parser.add_argument("--csv", default="doc/benchmarks/series.csv")
    parser.add_argument("--contact", default=os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "build", "contact"),
                        help="the program to measure")
    args = parser.parse_args()

    instances = []
    series = args.series.split(",")
    custom = [int(n) for n in args.sizes.split(",") if n]
    if "ex1" in series:
        sizes = [26, 40] if args.quick else [26, 40, 54, 68, 80, 92, 104, 114, 124, 134, 144]
        instances += [(1, n, 0.5) for n in (custom or sizes)]
    if "ex2" in series:
        sizes = [10, 12] if args.quick else list(range(10, 29, 2))
        instances += [(2, n, 0.5) for n in (custom or sizes)]
    if "mu" in series and not args.quick:
        instances += [(2, 20, mu) for mu in (1.0, 1.5)]
    instances = [i for i in instances if i[1] <= args.max_n_y]

    os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
    done = set()
    if os.path.exists(args.csv):
        with open(args.csv) as f:
            done = {(r["example"], r["N_Y"], r["mu"], r["ranks"], r["solver"])
                    for r in csv.DictReader(f)}
    else:
        with open(args.csv, "w", newline="") as f:
            csv.writer(f).writerow(COLUMNS)

    elastic = {}
    for example, n_y, mu in instances:
        for solver in args.solvers.split(","):
            key = (str(example), str(n_y), str(mu), str(args.ranks), solver)
            if key in done:
                continue
            if (example, n_y) not in elastic:
                _, unit, _ = best_run(scene(example, n_y, mu, None, False),
                                      args.ranks, args.repeat, args.contact)
                elastic[(example, n_y)] = unit["elastic_s"] \
                    if unit["elastic_s"] != float("inf") else ""
            code, values, _ = best_run(scene(example, n_y, mu, SOLVERS[solver]),
                                       args.ranks, args.repeat, args.contact)
            row = dict(example=example, N_Y=n_y, mu=mu, ranks=args.ranks,
                       solver=solver, converged=int(code == 0),
                       elastic_solve_s=elastic[(example, n_y)])
            row.update(values)
            if row["elastic_solve_s"]:
                row["ratio_to_elastic"] = round(row["solve_s"] / row["elastic_solve_s"], 2)
            with open(args.csv, "a", newline="") as f:
                csv.DictWriter(f, COLUMNS, extrasaction="ignore").writerow(row)
            print(f"example {example}, N_Y = {n_y}, mu = {mu}, {solver}: d = {row['d']}, "
                  f"{row.get('iterations', '?')} iterations, solve {row['solve_s']:.3g} s "
                  f"= {row.get('ratio_to_elastic', '?')} elastic solves"
                  f"{'' if code == 0 else ', FAILED (exit code %d)' % code}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
