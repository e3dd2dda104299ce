#!/usr/bin/env python3
"""Our solver and Siconos' global solvers side by side on FCLIB problems.

For each FCLIB global problem (files given, the exported increment of each
--scene and of Kanno's example II at each of --example2-sizes, or by
default tests/fclib/data), runs

  - contact --fclib with each of our methods of --methods: the semismooth
    Newton method (the default, stopped at --tolerance) and Kanno's
    Algorithm 2 (its own stopping rule), with the settings of --parameters;
    "method; preconditioner" sets <Linear solver/Preconditioner> too
    ("semismooth Newton; jacobi" is the sparse LU path, doc/fclib.md),
  - build/siconos_gfc3d with each Siconos solver of --siconos-solvers, at
    --tolerance (optional: skipped if Siconos was not found at build time),

and writes one CSV row per file and solver: time, iterations, the solver's
own error, the common error measure computed by the same code for every
solver (contact --evaluate, doc/fclib.md), success (common error <=
--tolerance), and the relative difference of v to the solution of our
first method.

usage: python3 bench/fclib_side_by_side.py [problem.hdf5 ...]
           [--scene scene.prm ...] [--example2-sizes 8,12] [--increment 1]
           [--parameters file.prm]
           [--methods "semismooth Newton,accelerated primal-dual"]
           [--siconos-solvers NSN_AC,ADMM,NSGS_WR,IPM] [--tolerance 1e-8]
           [--max-iterations 10000] [--timeout 300]
           [--csv doc/benchmarks/fclib.csv] [--replace-rows] [--build build]
"""
import argparse
import csv
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from doc_tables import write_tables  # noqa: E402
from run_series import scene as series_scene  # noqa: E402
COLUMNS = ["file", "n", "contacts", "solver", "converged", "success",
           "iterations", "seconds", "own_error", "common_error",
           "v_difference_to_ours", "note"]


def run(command, timeout, cwd=None):
    """(exit code, output) of the command; exit code None on a timeout."""
    environment = dict(os.environ, OMP_NUM_THREADS="1",
                       OMPI_ALLOW_RUN_AS_ROOT="1",
                       OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    try:
        result = subprocess.run(command, capture_output=True, text=True,
                                timeout=timeout, cwd=cwd, env=environment)
        return result.returncode, result.stdout + result.stderr
    except subprocess.TimeoutExpired:
        return None, ""


def result_line(output):
    match = re.search(r"FCLIB result: method=(.*?) converged=(\d) "
                      r"iterations=(\d+) seconds=(\S+) error=(\S+)", output)
    if not match:
        return None
    return {"converged": int(match.group(2)), "iterations": int(match.group(3)),
            "seconds": float(match.group(4)), "own_error": float(match.group(5))}


def error_line(output):
    match = re.search(r"^Error: (.*)$", output, re.MULTILINE)
    return match.group(1) if match else ""


def evaluate(contact, problem, solution, reference, timeout):
    """The common error of a stored solution and its v difference to ours."""
    command = [contact, "--fclib", problem, "--evaluate", solution]
    if reference and os.path.exists(reference):
        command += ["--reference", reference]
    code, output = run(command, timeout)
    error = re.search(r"FCLIB error: (\S+)", output or "")
    difference = re.search(r"Relative difference to the solution in \S+: "
                           r"v ([^,\s]+)", output or "")
    return (float(error.group(1)) if error else "",
            float(difference.group(1)) if difference else "")


def sizes(output):
    """n and the number of contacts, from the header of our solve."""
    match = re.search(r"n = (\d+) unknowns, (\d+) contacts", output)
    return (int(match.group(1)), int(match.group(2))) if match else ("", "")


def write_settings(path, method, arguments):
    """A parameter file for one of our methods (with --parameters included)."""
    method, _, preconditioner = (part.strip() for part in method.partition(";"))
    with open(path, "w") as out:
        if arguments.parameters:
            out.write(f"include {os.path.abspath(arguments.parameters)}\n")
        out.write(f"subsection Contact solver\n  set Method = {method}\n")
        if method == "semismooth Newton":
            out.write(f"  subsection Semismooth Newton\n"
                      f"    set Tolerance = {arguments.tolerance}\n  end\n")
        out.write("end\n")
        if preconditioner:
            out.write(f"subsection Linear solver\n"
                      f"  set Preconditioner = {preconditioner}\nend\n")


def export_scene(contact, scene, increment, folder, timeout):
    """The scene's exported increment, as <folder>/<scene name>.hdf5."""
    name = os.path.splitext(os.path.basename(scene))[0]
    scene_folder = os.path.join(folder, name)
    os.makedirs(scene_folder)
    code, output = run([contact, "--fclib-export", str(increment),
                        os.path.abspath(scene)], timeout, cwd=scene_folder)
    files = glob.glob(os.path.join(scene_folder, "**",
                                   f"fclib-{increment:05d}.hdf5"),
                      recursive=True)
    if code != 0 or not files:
        sys.exit(f"exporting {scene} failed:\n{output}")
    return shutil.copy(files[0], os.path.join(folder, name + ".hdf5"))


def example2_scene(n_y, folder):
    """Kanno's example II (2 x 1 x 1, mu = 0.5) at N_Y = n_y."""
    path = os.path.join(folder, f"example2_ny{n_y}.prm")
    with open(path, "w") as out:
        out.write(series_scene(2, n_y, 0.5, "semismooth Newton"))
    return path


def merged_rows(path, rows):
    """The rows of the CSV at @p path with those of each file in @p rows
    replaced by the new ones, in the old order (new files at the end)."""
    with open(path, newline="") as f:
        old = list(csv.DictReader(f))
    new_by_file = {}
    for row in rows:
        new_by_file.setdefault(row["file"], []).append(row)
    merged = []
    for row in old:
        if row["file"] not in new_by_file:
            merged.append(row)
        elif new_by_file[row["file"]] is not None:
            merged.extend(new_by_file[row["file"]])
            new_by_file[row["file"]] = None
    for file_rows in new_by_file.values():
        if file_rows is not None:
            merged.extend(file_rows)
    return merged


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("problems", nargs="*")
    parser.add_argument("--scene", action="append", default=[])
    parser.add_argument("--example2-sizes", default="")
    parser.add_argument("--increment", type=int, default=1)
    parser.add_argument("--parameters")
    parser.add_argument("--methods",
                        default="semismooth Newton,accelerated primal-dual")
    parser.add_argument("--siconos-solvers", default="NSN_AC,ADMM,NSGS_WR,IPM")
    parser.add_argument("--tolerance", type=float, default=1e-8)
    parser.add_argument("--max-iterations", type=int, default=10000)
    parser.add_argument("--timeout", type=float, default=300)
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks",
                                                      "fclib.csv"))
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--replace-rows", action="store_true",
                        help="keep the rows of --csv for the files not run "
                             "and replace those of the files run")
    arguments = parser.parse_args()

    contact = os.path.join(arguments.build, "contact")
    siconos = os.path.join(arguments.build, "siconos_gfc3d")
    if not os.path.exists(siconos):
        print("Siconos was not found at build time "
              "(apt-get install libsiconos-numerics-dev): our solver only")
        siconos = None
    work = tempfile.mkdtemp(prefix="fclib-side-by-side-")
    problems = list(arguments.problems)
    scenes = arguments.scene + [
        example2_scene(int(n_y), work)
        for n_y in arguments.example2_sizes.split(",") if n_y]
    for scene in scenes:
        problems.append(export_scene(contact, scene, arguments.increment, work,
                                     arguments.timeout))
    if not problems:
        problems = sorted(f for f in glob.glob(
            os.path.join(ROOT, "tests", "fclib", "data", "*.hdf5"))
            if not f.endswith(".siconos.hdf5"))

    rows = []
    for problem in problems:
        name = os.path.basename(problem)
        ours = None
        for method in arguments.methods.split(","):
            label = re.sub(r"\W+", "_", method)
            solution = os.path.join(work, f"{name}.{label}.hdf5")
            settings = os.path.join(work, label + ".prm")
            write_settings(settings, method, arguments)
            code, output = run([contact, "--fclib", problem, "--solution",
                                solution, settings], arguments.timeout)
            n, contacts = sizes(output)
            row = {"file": name, "n": n, "contacts": contacts,
                   "solver": f"ours: {method}"}
            result = result_line(output)
            if result:
                row.update(result)
                row["common_error"] = result["own_error"]
            row["note"] = ("timeout" if code is None else
                           error_line(output) if code != 0 else "")
            if ours is None:
                ours = solution
            elif os.path.exists(solution):
                row["v_difference_to_ours"] = evaluate(
                    contact, problem, solution, ours, arguments.timeout)[1]
            rows.append(row)

        for solver in arguments.siconos_solvers.split(",") if siconos else []:
            solution = os.path.join(work, f"{name}.{solver}.hdf5")
            code, output = run([siconos, problem, solver,
                                str(arguments.tolerance),
                                str(arguments.max_iterations), solution],
                               arguments.timeout)
            row = {"file": name, "n": n, "contacts": contacts,
                   "solver": f"siconos {solver}"}
            result = result_line(output)
            if result:
                row.update(result)
            if code is None:
                row["note"] = "timeout"
            elif code < 0:
                row["note"] = f"crashed (signal {-code})"
            elif code != 0 or not result:
                row["note"] = output.strip().splitlines()[-1] if output else ""
            if os.path.exists(solution):
                row["common_error"], row["v_difference_to_ours"] = evaluate(
                    contact, problem, solution, ours, arguments.timeout)
            rows.append(row)

    for row in rows:
        common = row.get("common_error", "")
        row["success"] = int(common != "" and common <= arguments.tolerance)
    os.makedirs(os.path.dirname(os.path.abspath(arguments.csv)), exist_ok=True)
    written = rows
    if arguments.replace_rows and os.path.exists(arguments.csv):
        written = merged_rows(arguments.csv, rows)
    with open(arguments.csv, "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=COLUMNS)
        writer.writeheader()
        for row in written:
            writer.writerow({column: row.get(column, "") for column in COLUMNS})

    print("| file | solver | success | iterations | seconds | common error "
          "| v difference to ours | note |")
    print("|---|---|---|---|---|---|---|---|")
    for row in rows:
        def show(key, form="{:.3g}"):
            value = row.get(key, "")
            return form.format(value) if isinstance(value, float) else str(value)
        print(f"| {row['file']} | {row['solver']} | {row['success']} "
              f"| {show('iterations')} | {show('seconds')} "
              f"| {show('common_error', '{:.2e}')} "
              f"| {show('v_difference_to_ours', '{:.2e}')} "
              f"| {row.get('note', '')[:80]} |")
    print(f"CSV: {arguments.csv}")
    write_tables()


if __name__ == "__main__":
    main()
