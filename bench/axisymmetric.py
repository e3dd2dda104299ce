#!/usr/bin/env python3
"""The ball on a plate in 3D against its axisymmetric section: what each
costs to reach Hertz's contact radius within 1 %.

- 3D: parameters/ball_on_plate.prm (a quarter of the ball and plate,
  adapted by Kelly and the contact state) on --ranks-3d ranks, with its
  local refinements --levels-3d;
- axisymmetric: parameters/ball_on_plate_axisymmetric.prm (the section
  x = r of both bodies) on --ranks-axisymmetric ranks, with its local
  refinements --levels-axisymmetric.

Each run: the unknowns d, the total normal force P, the contact radius
and the peak pressure against Hertz's for P (tests/check_analytic.py), and
its set-up and solve time (the timer's Setup, Mesh refinement, Assembly,
Increment start and Contact solve: no process start, no output), best of
--repeat. Two contact radii: that of the contact area (the nodes in
contact: it moves by up to half a cell from one mesh to the next, most
for the section's one line of nodes) and that of Hertz's profile fitted
to every node's pressure. A kind reaches 1 % at the coarsest mesh of its
ladder from which every finer one stays within 1 % in the fitted radius;
the times of those two runs give the ratio (the goal: at least 50; both
kinds on one rank by default, one core each). Rewrites
doc/benchmarks/axisymmetric.csv and the table of doc/performance.md
("Axisymmetric bodies").

usage: bench/axisymmetric.py [--program build/contact] [--repeat 3]
                             [--levels-3d 1,2,3,4,5] [--levels-axisymmetric 2,3,4,5,6,7]
                             [--ranks-3d 1] [--ranks-axisymmetric 1]
"""
import argparse
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "tests"))
from check_analytic import Scene, hertz, radius_of_profile  # noqa: E402
from doc_tables import replace_runs, write_tables  # noqa: E402
from runs import NO_OUTPUT, best_alternately, print_row, run as run_program  # noqa: E402

COLUMNS = ["kind", "level", "ranks", "d", "force", "radius_error_percent",
           "fitted_radius_error_percent", "pressure_error_percent", "setup_and_solve_s",
           "commit"]
CSV = os.path.join(ROOT, "doc", "benchmarks", "axisymmetric.csv")
SCENES = {"3D": "ball_on_plate.prm", "axisymmetric": "ball_on_plate_axisymmetric.prm"}
TIMED = ("Setup", "Mesh refinement", "Assembly", "Increment start", "Contact solve")


def setup_and_solve_seconds(output):
    summary = re.findall(r"-- summary: (.*)", output)[-1]
    sections = dict((name.strip(), float(value)) for name, value in
                    re.findall(r"([A-Za-z ]+) = ([0-9.e+-]+) s", summary))
    return sum(sections.get(k, 0.) for k in TIMED)


def run(program, kind, level, ranks, folder):
    with open(os.path.join(folder, "scene.prm"), "w") as f:
        f.write(f"include {ROOT}/parameters/{SCENES[kind]}\n"
                f"subsection Mesh refinement\n  set Local refinements = {level}\nend\n"
                + NO_OUTPUT + "subsection Postprocess\n  subsection Visualization\n"
                "    set Write csv tables = true\n  end\nend\n")
    output, _ = run_program([program, "scene.prm"], ranks, folder)
    scene = Scene(os.path.join(folder, "output"))
    P, a, a_hertz, p0, p_hertz = hertz(scene)
    return dict(d=int(re.findall(r"d = (\d+)", output)[-1]), force=P,
                radius_error=abs(a - a_hertz) / a_hertz,
                fitted_radius_error=abs(radius_of_profile(scene) - a_hertz) / a_hertz,
                pressure_error=abs(p0 - p_hertz) / p_hertz,
                seconds=setup_and_solve_seconds(output))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog=__doc__)
    parser.add_argument("--program", default=os.path.join(ROOT, "build", "contact"))
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--levels-3d", default="1,2,3,4,5")
    parser.add_argument("--levels-axisymmetric", default="2,3,4,5,6,7")
    parser.add_argument("--ranks-3d", type=int, default=1)
    parser.add_argument("--ranks-axisymmetric", type=int, default=1)
    args = parser.parse_args()
    program = os.path.abspath(args.program)
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT,
                            capture_output=True, text=True).stdout.strip()
    ladders = {"3D": (args.levels_3d, args.ranks_3d),
               "axisymmetric": (args.levels_axisymmetric, args.ranks_axisymmetric)}
    runs = [(kind, int(level), ranks) for kind, (levels, ranks) in ladders.items()
            for level in levels.split(",")]
    best = best_alternately(args.repeat, runs, lambda r, folder: run(program, *r, folder),
                            key="seconds")
    rows = []
    for (kind, level, ranks), result in best.items():
        row = dict(kind=kind, level=level, ranks=ranks, d=result["d"],
                   force=f"{result['force']:.6g}",
                   radius_error_percent=f"{100 * result['radius_error']:.2f}",
                   fitted_radius_error_percent=f"{100 * result['fitted_radius_error']:.2f}",
                   pressure_error_percent=f"{100 * result['pressure_error']:.2f}",
                   setup_and_solve_s=f"{result['seconds']:.3f}", commit=commit)
        rows.append(row)
        print_row(row, COLUMNS)
    reached = {}
    for kind in ladders:
        ladder = sorted((level, result) for (k, level, _), result in best.items() if k == kind)
        for i, (level, result) in enumerate(ladder):
            if all(r["fitted_radius_error"] <= 0.01 for _, r in ladder[i:]):
                reached[kind] = result
                break
    if len(reached) == 2:
        print(f"within 1 % in the fitted radius from: 3D {reached['3D']['seconds']:.3f} s, "
              f"axisymmetric {reached['axisymmetric']['seconds']:.3f} s: "
              f"{reached['3D']['seconds'] / reached['axisymmetric']['seconds']:.0f} times less")
    replace_runs(CSV, COLUMNS, rows,
                 key=lambda r: (r["kind"], str(r["level"]), str(r["ranks"])))
    for line in write_tables():
        print("updated " + line)


if __name__ == "__main__":
    main()
