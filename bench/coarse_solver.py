#!/usr/bin/env python3
"""The direct solver of ML's coarsest level, MUMPS against KLU, on shipped
scenes in 2D and 3D: each scene runs with <Linear solver/AMG coarse
solver> = MUMPS and = KLU, alternately, best of --repeat, in one run of
this script. The Newton method's preconditioner refactors that level at
every change of the node conditions and applies it at every Krylov
iteration; on a mesh below ML's coarse size (2000 dofs) the level is the
whole K + S. Records the Newton steps, the Krylov iterations and the solve
time (the timer's Assembly, Increment start, Elastic solve and Contact
solve) and the ratio KLU / MUMPS: what the default <AMG coarse solver =
auto> (KLU in 2D, MUMPS in 3D) is chosen from. Appends to doc/benchmarks/coarse-solver.csv
and rewrites the table of doc/performance.md ("The coarse solver").

usage: bench/coarse_solver.py [--program build/contact] [--repeat 3]
                              [--csv doc/benchmarks/coarse-solver.csv]
                              [--scenes hertz_2d,roller_3d]
"""
import argparse
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from doc_tables import append_rows, write_tables  # noqa: E402
from runs import (NO_OUTPUT, best_alternately, chosen_scenes, increment_statistics,  # noqa: E402
                  run as run_program, print_row)

COLUMNS = ["scene", "dim", "ranks", "coarse_solver", "d", "newton_iterations",
           "krylov_iterations", "solve_s", "klu_over_mumps"]
# (scene, ranks): small and larger meshes, one and two bodies, elastic,
# neo-Hookean and elasto-plastic, in 2D and 3D.
SCENES = [("flat_punch_2d", 1), ("sliding_block", 1), ("press_and_drag", 1),
          ("block_on_block_2d", 1), ("roller_2d", 1), ("cattaneo_2d", 1),
          ("bracket_2d", 1), ("o_ring_2d", 1), ("hertz_2d", 1), ("ironing_2d", 1),
          ("block_on_block_3d", 1), ("roller_3d", 1), ("cattaneo_3d", 1),
          ("hertz_3d", 2)]
SOLVERS = ["MUMPS", "KLU"]


def run(program, scene, solver, ranks, folder):
    with open(os.path.join(folder, "scene.prm"), "w") as f:
        f.write(f"include {ROOT}/parameters/{scene}.prm\n" + NO_OUTPUT +
                f"subsection Linear solver\n  set AMG coarse solver = {solver}\nend\n")
    output, _ = run_program([program, "scene.prm"], ranks, folder)
    return dict(increment_statistics(output),
                dim=int(re.findall(r"Scene: (\d)D", output)[-1]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog=__doc__)
    parser.add_argument("--program", default=os.path.join(ROOT, "build", "contact"))
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks",
                                                      "coarse-solver.csv"))
    parser.add_argument("--scenes", default=",".join(name for name, _ in SCENES),
                        help="the scenes to run, by name, separated by ','")
    args = parser.parse_args()
    chosen = chosen_scenes(parser, args.scenes, [name for name, _ in SCENES])
    rows = []
    for scene, ranks in (s for s in SCENES if s[0] in chosen):
        best = best_alternately(args.repeat, SOLVERS, lambda solver, folder:
                                run(args.program, scene, solver, ranks, folder))
        ratio = best["KLU"]["solve_s"] / best["MUMPS"]["solve_s"]
        for solver in SOLVERS:
            row = dict(best[solver], scene=scene, ranks=ranks, coarse_solver=solver,
                       klu_over_mumps=f"{ratio:.2f}" if solver == "KLU" else "")
            row["solve_s"] = f"{row['solve_s']:.4f}"
            rows.append(row)
            print_row(row, COLUMNS)
    append_rows(args.csv, COLUMNS, rows)
    write_tables()


if __name__ == "__main__":
    main()
