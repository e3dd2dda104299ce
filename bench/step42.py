#!/usr/bin/env python3
"""deal.II's contact tutorial step-42 beside our program on the same meshes:
the elasto-plastic unit cube indented by a rigid ball
(parameters/step42_indentation.prm). step-42 is built from the source that
Debian's libdeal.ii-doc ships (its examples folder; nothing of it is copied
into this tree) into <build>/step42, and both programs run in this script,
one after the other, on 2^k cells per edge (global refinement; step-42:
initial refinements k and one cycle) and, with --adaptive, on step-42's
adaptive sequence (Kelly, refine 30 %, coarsen 3 %; ours with the same
fractions, re-solving the increment on each adapted mesh).

For each run: the whole process's wall time, the time of step-42's VTU
output (which it cannot switch off; subtracted, ours writes none), the
peak memory per rank, the Newton steps, the contact force, the vertical
displacement at the top face's centre, and the cells that flow plastically
at the end (step-42: a positive fraction_of_plastic_q_points in its VTU,
read with VTK's Python module where /usr/bin/python3 has it; ours:
yield_state 2 in stress-NNNNN.csv). Ours runs with the standard Q1
element, as step-42 does, and with the B-bar element that Formulation =
auto takes for plastic flow. The unit of time is one elastic solve of the
same mesh in the same run (AMG set-up and CG, the cube under a pressure
without contact); the time per Newton step of a plastic increment is
measured in it. Appends to doc/benchmarks/step42.csv and rewrites the
table of doc/performance.md ("step-42 side by side").

usage: bench/step42.py [--sizes 4,5] [--ranks 1,2] [--adaptive 4] [--large 70]
                       [--build build] [--csv doc/benchmarks/step42.csv]
"""
import argparse
import csv
import glob
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from doc_tables import append_rows, write_tables  # noqa: E402
from runs import run  # noqa: E402

STEP42_SOURCE = "/usr/share/doc/libdeal.ii-doc/examples/step-42"
COLUMNS = ["mesh", "cells_per_edge", "ranks", "program", "element", "cells", "d",
           "newton_steps", "wall_s", "output_s", "compute_s", "peak_mb",
           "contact_force", "uz_centre", "plastic_cells", "elastic_solve_s",
           "newton_step_in_elastic_solves"]
def build_step42(build):
    folder = os.path.join(build, "step42")
    program = os.path.join(folder, "step-42")
    if not os.path.isdir(STEP42_SOURCE):
        sys.exit("step-42's source is missing: apt-get install libdeal.ii-doc")
    os.makedirs(folder, exist_ok=True)
    if not os.path.exists(program):
        for command in (["cmake", "-DCMAKE_BUILD_TYPE=Release", STEP42_SOURCE],
                        ["make", "-j2"]):
            subprocess.run(command, cwd=folder, check=True, capture_output=True)
    return program


def step42_plastic_cells_and_uz(folder):
    """From step-42's last VTU (its mesh moved by the displacement): the cells
    with plastic points and u_z at the top face's centre; None without VTK."""
    script = r"""
import glob, sys, vtk
name = sorted(glob.glob(sys.argv[1] + "/solution_*.pvtu"))[-1]
reader = vtk.vtkXMLPUnstructuredGridReader(); reader.SetFileName(name); reader.Update()
grid = reader.GetOutput()
# DataOut writes cell data at each cell's own patch vertices.
fraction = grid.GetPointData().GetArray("fraction_of_plastic_q_points")
plastic = sum(1 for i in range(grid.GetNumberOfCells())
              if fraction.GetValue(grid.GetCell(i).GetPointId(0)) > 0)
u = grid.GetPointData().GetArray("displacement")
best, best_key = None, None
for i in range(grid.GetNumberOfPoints()):
    x = grid.GetPoint(i); d = u.GetTuple3(i)
    X = [x[k] - d[k] for k in range(3)]
    key = (abs(X[0] - 0.5) + abs(X[1] - 0.5) + abs(X[2] - 1.0))
    if best_key is None or key < best_key: best, best_key = d[2], key
print(plastic, best)
"""
    done = subprocess.run(["/usr/bin/python3", "-c", script, folder],
                          capture_output=True, text=True)
    if done.returncode != 0:
        return "", ""
    plastic, uz = done.stdout.split()
    return int(plastic), float(uz)


def run_step42(program, level, cycles, strategy, ranks):
    with tempfile.TemporaryDirectory() as folder:
        with open(os.path.join(folder, "run.prm"), "w") as f:
            f.write(f"""set polynomial degree = 1
set number of initial refinements = {level}
set number of cycles = {cycles}
set refinement strategy = {strategy}
set obstacle = sphere
set output directory = {folder}/
""")
        output, wall = run([program, "run.prm"], ranks, folder)
        plastic, uz = step42_plastic_cells_and_uz(folder)
    last_cycle = output.split("Cycle ")[-1]
    cells = int(re.findall(r"Number of active cells: +(\d+)", output)[-1])
    d = int(re.findall(r"Number of degrees of freedom: +(\d+)", output)[-1])
    graphical = re.search(r"\| Graphical output +\| +\d+ \| +([0-9.]+)s", output)
    memory = re.findall(r"Peak virtual memory used, resident in kB: +\d+ +(\d+)", output)
    output_s = float(graphical.group(1)) if graphical else 0.0
    return dict(program="step-42", element="standard", cells=cells, d=d,
                newton_steps=last_cycle.count("Newton iteration"), wall_s=wall,
                output_s=output_s, compute_s=wall - output_s,
                peak_mb=int(memory[-1]) / 1024 if memory else "",
                contact_force=float(re.findall(r"Contact force = (\S+)", output)[-1]),
                uz_centre=uz, plastic_cells=plastic)


def our_scene(cells_per_edge, element, cycles, pressure_only=False):
    text = f"""include {ROOT}/parameters/step42_indentation.prm
set Output directory = output
subsection Geometry
  subsection Box
    set X repetitions = {cells_per_edge}
    set Y repetitions = {cells_per_edge}
    set Z repetitions = {cells_per_edge}
  end
end
subsection Mesh refinement
  set Strategy = {'kelly' if cycles > 0 else 'none'}
  set Cycles = {cycles}
  set Refine fraction = 0.3
  set Coarsen fraction = 0.03
  set Maximum dofs = 1e8
end
subsection Material
  set Formulation = {element}
end
subsection Postprocess
  subsection Visualization
    set Write vtu = false
    set Write csv tables = true
  end
end
"""
    if pressure_only:
        text += """subsection Material
  set Model = linear elastic
end
subsection Contact
  set Contact boundaries =
end
subsection Boundary conditions
  set Pressure = top: 100
end
"""
    return text


def run_ours(contact, cells_per_edge, element, cycles, ranks, law="J2 plasticity"):
    with tempfile.TemporaryDirectory() as folder:
        with open(os.path.join(folder, "scene.prm"), "w") as f:
            f.write(our_scene(cells_per_edge, element, cycles, pressure_only=True))
        elastic, _ = run([contact, "scene.prm"], ranks, folder)
        with open(os.path.join(folder, "scene.prm"), "w") as f:
            f.write(our_scene(cells_per_edge, element, cycles) +
                    f"subsection Material\n  set Model = {law}\nend\n")
        output, wall = run([contact, "scene.prm"], ranks, folder)
        statistics = os.path.join(folder, "output", "statistics")
        plastic, uz = 0, ""
        stress = sorted(glob.glob(os.path.join(folder, "output", "stress-*.csv")))[-1]
        with open(stress) as f:
            plastic = sum(1 for row in csv.DictReader(f) if row["yield_state"] == "2")
        table = sorted(glob.glob(os.path.join(folder, "output", "displacement-*.csv")))[-1]
        with open(table) as f:
            for row in csv.DictReader(f):
                if all(abs(float(row[c]) - v) < 1e-9 for c, v in (("x", .5), ("y", .5), ("z", 1.))):
                    uz = float(row["uz"])
        force = ""
        with open(statistics) as f:
            names = [l for l in f if l.startswith("#")]
        force_column = [int(re.match(r"# *(\d+):", l).group(1)) - 1 for l in names
                        if "Contact force z" in l]
        rows = [l.split() for l in open(statistics) if not l.startswith("#")]
        if force_column and rows:
            force = abs(float(rows[-1][force_column[0]]))
    steps = int(re.findall(r"Increment 1/1, t = 1: (\d+) Newton", output)[-1])
    summary = dict(re.findall(r" ([A-Za-z -]+?) = ([0-9.e+-]+) s;", output.split("-- summary:")[-1]))
    elastic_summary = dict(re.findall(r" ([A-Za-z -]+?) = ([0-9.e+-]+) s;",
                                      elastic.split("-- summary:")[-1]))
    elastic_solve = float(elastic_summary.get("Elastic solve", "nan"))
    newton = float(summary.get("Contact solve", "nan")) / steps
    cells = int(re.findall(r"(\d+) cells[;,]", output)[-1])
    d = int(re.findall(r"d = (\d+)", output)[-1])
    memory = re.findall(r"peak memory = ([0-9.]+) MB", output)
    return dict(program="contact" if law == "J2 plasticity" else "contact, elastic",
                element=element, cells=cells, d=d, newton_steps=steps,
                wall_s=wall, output_s=0.0, compute_s=wall,
                peak_mb=float(memory[-1]) if memory else "", contact_force=force,
                uz_centre=uz, plastic_cells=plastic, elastic_solve_s=elastic_solve,
                newton_step_in_elastic_solves=newton / elastic_solve)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog=__doc__)
    parser.add_argument("--sizes", default="4,5")
    parser.add_argument("--ranks", default="1,2")
    parser.add_argument("--adaptive", type=int, default=0,
                        help="step-42's adaptive sequence with this many cycles")
    parser.add_argument("--large", type=int, default=0,
                        help="also ours alone at this many cells per edge (70: d = 1.07 "
                        "million) on the largest rank count, plastic and elastic, for "
                        "the memory per unknown")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks", "step42.csv"))
    args = parser.parse_args()
    contact = os.path.join(args.build, "contact")
    step42 = build_step42(args.build)
    rows = []
    plan = [("global", 2 ** int(k), int(k), 1, "global") for k in args.sizes.split(",")]
    if args.adaptive:
        plan.append(("adaptive", 8, 3, args.adaptive, "percentage"))
    for mesh, per_edge, level, cycles, strategy in plan:
        for ranks in (int(r) for r in args.ranks.split(",")):
            ours_cycles = 0 if mesh == "global" else cycles - 1
            results = [run_step42(step42, level, cycles, strategy, ranks)]
            for element in ("standard", "B-bar"):
                results.append(run_ours(contact, per_edge, element, ours_cycles, ranks))
            for result in results:
                result.update(mesh=mesh, cells_per_edge=per_edge, ranks=ranks)
                rows.append(result)
                print(", ".join(f"{k} {result.get(k, '')}" for k in COLUMNS), flush=True)
    if args.large:
        ranks = max(int(r) for r in args.ranks.split(","))
        for law in ("J2 plasticity", "linear elastic"):
            result = run_ours(contact, args.large, "B-bar", 0, ranks, law)
            result.update(mesh="global", cells_per_edge=args.large, ranks=ranks)
            rows.append(result)
            print(", ".join(f"{k} {result.get(k, '')}" for k in COLUMNS), flush=True)
    append_rows(args.csv, COLUMNS, rows)
    write_tables()


if __name__ == "__main__":
    main()
