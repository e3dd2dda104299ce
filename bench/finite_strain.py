#!/usr/bin/env python3
"""Finite strain against small strain on the same scene and mesh: each scene
runs linear elastic at small strain, neo-Hookean at finite strain, and
without contact (one elastic solve: the unit of time), alternately, best of
--repeat, in one run of this script. Records the Newton steps and the
solve time per increment (the timer's Assembly, Increment start, Elastic
solve and Contact solve: no set-up, no output) in elastic solves, and the ratio of the two
kinematics (the goal: at most 2). A scene with a pair of two bodies runs
at finite strain with <Contact/Geometry between bodies> = fixed point
and = every Newton iterate (the default). Appends to
doc/benchmarks/finite-strain.csv and rewrites the table of
doc/performance.md ("Finite strain against small strain").

usage: bench/finite_strain.py [--program build/contact] [--repeat 3]
                              [--csv doc/benchmarks/finite-strain.csv]
                              [--scenes hertz_2d,o_ring_2d]
"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from doc_tables import append_rows, write_tables  # noqa: E402
from runs import (NO_OUTPUT, best_alternately, chosen_scenes, increment_statistics,  # noqa: E402
                  run as run_program, print_row)

COLUMNS = ["scene", "ranks", "kinematics", "d", "increments", "newton_iterations",
           "solve_s", "elastic_solve_s", "increment_in_elastic_solves",
           "finite_over_small"]
# (name, scene file, ranks, more parameters): Hertz at 1 % of the radius
# and the block pressed 1 % into its base and dragged (a contact pair,
# whose geometry finite strain takes again until it settles), where both
# kinematics apply, and the O-ring squeezed by 25 %. The block on block's
# own mesh (d = 572) solves an increment in milliseconds, where fixed
# costs decide; it also runs on cells refined three times.
REFINED_3 = "subsection Mesh refinement\n  set Global refinements = 3\nend\n"
SCENES = [("hertz_2d", "hertz_2d.prm", 1, ""), ("hertz_3d", "hertz_3d.prm", 2, ""),
          ("block_on_block_2d", "block_on_block_2d.prm", 1, ""),
          ("block_on_block_2d refined 3 times", "block_on_block_2d.prm", 1, REFINED_3),
          ("o_ring_2d", "o_ring_2d.prm", 1, "")]
# The scenes with a pair of two bodies, run at finite strain also with the
# pair's geometry taken at every Newton iterate.
PAIR_SCENES = {"block_on_block_2d", "block_on_block_2d refined 3 times"}
WITHIN_NEWTON = "finite strain, pair geometry at every Newton iterate"
VARIANTS = {
    "small strain": "subsection Material\n  set Model = linear elastic\n"
                    "  set Kinematics = small strain\nend\n",
    "finite strain": "subsection Material\n  set Model = neo-Hookean\n"
                     "  set Kinematics = finite strain\nend\n"
                     "subsection Contact\n"
                     "  set Geometry between bodies = fixed point\nend\n",
    WITHIN_NEWTON: "subsection Material\n  set Model = neo-Hookean\n"
                   "  set Kinematics = finite strain\nend\n"
                   "subsection Contact\n"
                   "  set Geometry between bodies = every Newton iterate\nend\n",
    "no contact": "subsection Material\n  set Model = linear elastic\n"
                  "  set Kinematics = small strain\nend\n"
                  "subsection Contact\n  set Contact boundaries =\n"
                  "  set Pairs =\nend\n"
                  "subsection Loading\n  set Number of increments = 1\nend\n",
}


def run(program, scene, more, variant, ranks, folder):
    with open(os.path.join(folder, "scene.prm"), "w") as f:
        f.write(f"include {ROOT}/parameters/{scene}\n" + more + VARIANTS[variant] + NO_OUTPUT)
    output, _ = run_program([program, "scene.prm"], ranks, folder)
    return increment_statistics(output)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog=__doc__)
    parser.add_argument("--program", default=os.path.join(ROOT, "build", "contact"))
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks",
                                                      "finite-strain.csv"))
    parser.add_argument("--scenes", default=",".join(name for name, _, _, _ in SCENES),
                        help="the scenes to run, by name, separated by ','")
    args = parser.parse_args()
    chosen = chosen_scenes(parser, args.scenes, [name for name, _, _, _ in SCENES])
    rows = []
    for name, scene, ranks, more in (s for s in SCENES if s[0] in chosen):
        variants = [v for v in VARIANTS if v != WITHIN_NEWTON or name in PAIR_SCENES]
        kinematics = [v for v in variants if v != "no contact"]
        best = best_alternately(args.repeat, variants, lambda variant, folder:
                                run(args.program, scene, more, variant, ranks, folder))
        unit = best["no contact"]["solve_s"]
        per_increment = {v: best[v]["solve_s"] / best[v]["increments"] for v in kinematics}
        for variant in kinematics:
            ratio = per_increment[variant] / per_increment["small strain"]
            row = dict(best[variant], scene=name, ranks=ranks, kinematics=variant,
                       elastic_solve_s=f"{unit:.4f}",
                       increment_in_elastic_solves=f"{per_increment[variant] / unit:.2f}",
                       finite_over_small=f"{ratio:.2f}" if variant != "small strain" else "")
            row["solve_s"] = f"{row['solve_s']:.4f}"
            rows.append(row)
            print_row(row, COLUMNS)
    append_rows(args.csv, COLUMNS, rows)
    write_tables()


if __name__ == "__main__":
    main()
