#!/usr/bin/env python3
"""The 3D ironing (tests/ironing_3d.prm: a neo-Hookean block, the die a
rigid tool from a surface mesh, mortar contact, mu = 0.3) on a finer mesh
than its test, on 2 ranks: what a solve of it costs and where that goes.
Runs it with the pairs' geometry as a fixed point over solves of each
increment, with the preconditioner built again on the tangent as the
Krylov iterations grow (<Linear solver/Tangent rebuild factor>, the
default 2) and never (0), and with the geometry taken at every Newton
iterate in the tool's frames (<Contact/Rigid tool/Geometry at finite
strain>), with the block's law at the Gauss points or at the Gauss-Lobatto
points, which include the cells' corners (<Material/Quadrature>), and
once without contact for the unit of time (one elastic
solve on the same mesh), in one run of this script. Records the
increments, cuts, Newton steps, Krylov iterations, solves of the pairs'
geometry, and the solve time (the timer's Assembly, Increment start,
Elastic solve and Contact solve) in seconds and in elastic solves. Replaces the rows of
this mesh and quadrature in doc/benchmarks/ironing-3d-scale.csv (the
others stay: the last run of each) and rewrites the table of doc/performance.md
("The 3D ironing at scale").

With --end-time T (< 2), the run stops there, its increments as long as
the test's (0.1): on fine cells the last part of the slide pushes the
material against the block's far end until a cell folds at a corner
between its Gauss points (det F = 0 there) and the solve stalls, before
t = 2, unless the law is evaluated at the Gauss-Lobatto points
(doc/performance.md, "The 3D ironing at scale").
With --hard-iterations M, an increment whose solve took more than M
Newton steps has the next one halved, and the increments after it keep
that length (<Loading/Hard increment iterations>); with --folder, the
runs are made there (and kept: their statistics files show a long run's
progress) instead of in a temporary folder.

usage: bench/ironing_3d_scale.py [--program build/contact] [--cells 72,8,24]
           [--variants "fixed point:2,fixed point:0,every Newton iterate:2"]
           (a variant may name a quadrature: "every Newton iterate:2:Gauss-Lobatto")
           [--end-time 2] [--hard-iterations 0] [--folder DIR]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from doc_tables import replace_runs, write_tables  # noqa: E402
from runs import run as run_program, solve_seconds, print_row  # noqa: E402

COLUMNS = ["cells", "ranks", "d", "end_time", "reached", "stopped", "tool_geometry",
           "quadrature",
           "tangent_rebuild_factor",
           "hard_increment_iterations", "increments", "cuts", "halved_ahead",
           "newton_iterations", "krylov_iterations", "amg_setups", "geometry_solves",
           "solve_s", "elastic_solve_s", "solve_in_elastic_solves"]
NO_OUTPUT = ("set Output directory = output\nsubsection Postprocess\n"
             "  subsection Visualization\n    set Write vtu = false\n  end\nend\n")
# The unit: the block linear elastic, its top pressed down, no contact.
ELASTIC = ("subsection Material\n  set Model = linear elastic\n"
           "  set Kinematics = small strain\nend\n"
           "subsection Boundary conditions\n  set Prescribed boundaries = top: z\n"
           "  set Prescribed displacement = 0; 0; -0.1 * t\nend\n"
           "subsection Contact\n  set Pairs =\n"
           "  subsection Rigid tool\n    set Name =\n  end\nend\n"
           "subsection Loading\n  set Number of increments = 1\nend\n")


def scene(folder, cells):
    """The test's scene on @p cells (along, across, up), with a die of 480
    facets around (its facets shorter than the cells)."""
    subprocess.run([sys.executable, "-c",
                    open(os.path.join(ROOT, "meshes", "die_3d.py")).read()
                    .replace("AROUND, ALONG = 120, 3", "AROUND, ALONG = 480, 3")],
                   cwd=folder, check=True)
    with open(os.path.join(ROOT, "tests", "ironing_3d.prm")) as f:
        text = f.read()
    along, across, up = cells
    return (text.replace("@PROJECT_SOURCE_DIR@/meshes/die_3d.obj",
                         os.path.join(folder, "die_3d.obj"))
                .replace("set X repetitions = 18", f"set X repetitions = {along}")
                .replace("set Y repetitions = 1", f"set Y repetitions = {across}")
                .replace("set Z repetitions = 6", f"set Z repetitions = {up}")) + NO_OUTPUT


def run(program, text, folder, may_fail=False):
    """One run's figures; with @p may_fail, a run that stops (a folded
    cell, a failed solve) is recorded with the time it reached, its failure
    line, and the sum of its increments' solve wall times (it prints no
    summary)."""
    with open(os.path.join(folder, "scene.prm"), "w") as f:
        f.write(text)
    output, _ = run_program([program, "scene.prm"], 2, folder, may_fail=may_fail)
    failure = re.findall(r"^Error: .*", output, re.M)
    increments = re.findall(r"^Increment \d+/\d+, t = \S+: (\d+) Newton iterations, "
                            r"(\d+) Krylov iterations, (\d+) AMG set-ups", output, re.M)
    reached = re.findall(r"^Increment \d+/\d+, t = ([^:]+):", output, re.M)
    geometry = [int(n) for n in re.findall(r"contact pairs' geometry: (\d+) solve", output)]
    return dict(d=int(re.findall(r"d = (\d+)", output)[-1]),
                increments=len(increments),
                cuts=len(re.findall(r"^Cut in half", output, re.M)),
                halved_ahead=len(re.findall(r"^Halved ahead", output, re.M)),
                newton_iterations=sum(int(n) for n, _, _ in increments),
                krylov_iterations=sum(int(k) for _, k, _ in increments),
                amg_setups=sum(int(a) for _, _, a in increments),
                geometry_solves=sum(geometry),
                # A run that stops (a cell folded, a solve that failed) has
                # no summary: the sum of its increments' solve times.
                solve_s=solve_seconds(output) if not failure else
                sum(float(t) for t in re.findall(r"solve wall time ([0-9.e+-]+) s", output)),
                reached=reached[-1] if reached else "0",
                stopped=failure[-1][len("Error: "):] if failure else "")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog=__doc__)
    parser.add_argument("--program", default=os.path.join(ROOT, "build", "contact"))
    parser.add_argument("--cells", default="72,8,24",
                        help="cells along, across and up the block of 9 x 1 x 3")
    parser.add_argument("--variants",
                        default="fixed point:2,fixed point:0,every Newton iterate:2",
                        help="<Contact/Rigid tool/Geometry at finite strain>:<Linear "
                             "solver/Tangent rebuild factor>[:<Material/Quadrature>], "
                             "separated by ','")
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks",
                                                      "ironing-3d-scale.csv"))
    parser.add_argument("--end-time", type=float, default=2.,
                        help="<Loading/End time>, with increments of 0.1")
    parser.add_argument("--hard-iterations", type=int, default=0,
                        help="<Loading/Hard increment iterations> (0: never)")
    parser.add_argument("--folder", help="run here instead of in a temporary folder")
    args = parser.parse_args()
    cells = [int(n) for n in args.cells.split(",")]
    rows = []
    with tempfile.TemporaryDirectory() as temporary:
        folder = args.folder or temporary
        os.makedirs(folder, exist_ok=True)
        text = scene(folder, cells)
        unit = run(args.program, text + ELASTIC, folder)["solve_s"]
        for variant in args.variants.split(","):
            geometry, factor, *rule = variant.split(":")
            quadrature = rule[0] if rule else "Gauss"
            result = run(args.program, text + "subsection Loading\n"
                         f"  set End time = {args.end_time:g}\n"
                         f"  set Number of increments = {round(args.end_time / 0.1)}\n"
                         f"  set Hard increment iterations = {args.hard_iterations}\nend\n"
                         "subsection Linear solver\n"
                         f"  set Tangent rebuild factor = {factor}\nend\n"
                         "subsection Contact\n  subsection Rigid tool\n"
                         f"    set Geometry at finite strain = {geometry}\n  end\nend\n"
                         f"subsection Material\n  set Quadrature = {quadrature}\nend\n",
                         folder, may_fail=True)
            row = dict(result, cells=" x ".join(map(str, cells)), ranks=2,
                       end_time=f"{args.end_time:g}",
                       tool_geometry=geometry, quadrature=quadrature,
                       tangent_rebuild_factor=factor,
                       hard_increment_iterations=args.hard_iterations,
                       elastic_solve_s=f"{unit:.3f}",
                       solve_in_elastic_solves=f"{result['solve_s'] / unit:.0f}")
            row["solve_s"] = f"{result['solve_s']:.1f}"
            print_row(row, COLUMNS)
            rows.append(row)
    replace_runs(args.csv, COLUMNS, rows, key=lambda r: (r["cells"], r["quadrature"]))
    for line in write_tables():
        print(line)


if __name__ == "__main__":
    main()
