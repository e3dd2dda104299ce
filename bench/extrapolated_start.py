#!/usr/bin/env python3
"""Where each increment's contact solve starts: from no motion beyond the
prescribed one, or from the last increment's motion scaled to this
increment's length where the increment goes on the way the last one went
(<Contact solver/Start from the last increment>, true and false). Each
scene runs both ways, alternately, best of --repeat, in one run of this
script, with the semismooth Newton method and once with Kanno's
accelerated primal-dual method; records the contact solver's iterations
(Newton steps or primal-dual iterations), Krylov iterations and
solve time (the timer's Assembly, Increment start, Elastic solve and
Contact solve), and the largest displacement at the end, which must agree (to 1e-6, or
round-off where the scene unloads). Appends to
doc/benchmarks/extrapolated-start.csv and rewrites the table of
doc/performance.md ("Where an increment starts").

usage: bench/extrapolated_start.py [--program build/contact] [--repeat 2]
                                   [--csv doc/benchmarks/extrapolated-start.csv]
"""
import argparse
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from doc_tables import append_rows, write_tables  # noqa: E402
from runs import NO_OUTPUT, best_alternately, run as run_program, solve_seconds, print_row  # noqa: E402

COLUMNS = ["scene", "ranks", "start", "d", "increments", "iterations",
           "krylov_iterations", "solve_s", "max_u"]
SMALL_STRAIN = ("subsection Material\n  set Model = linear elastic\n"
                "  set Kinematics = small strain\nend\n")
# (name, scene file, ranks, more parameters): scenes of many increments,
# whose motion is smooth across them or turns once (the ironing's die, the
# block dragged after it was pressed).
SCENES = [("o_ring_2d", "o_ring_2d.prm", 1, ""),
          ("o_ring_2d at small strain", "o_ring_2d.prm", 1, SMALL_STRAIN),
          ("ironing_2d", "ironing_2d.prm", 2, ""),
          ("block_on_block_2d", "block_on_block_2d.prm", 1, ""),
          ("press_and_drag", "press_and_drag.prm", 1, ""),
          ("press_and_drag, Kanno's method", "press_and_drag.prm", 1,
           "subsection Contact solver\n  set Method = accelerated primal-dual\nend\n")]
STARTS = {"no motion": "false", "the last increment's": "true"}


def run(program, scene, more, start, ranks, folder):
    with open(os.path.join(folder, "scene.prm"), "w") as f:
        f.write(f"include {ROOT}/parameters/{scene}\n" + more + NO_OUTPUT +
                "subsection Contact solver\n"
                f"  set Start from the last increment = {STARTS[start]}\nend\n")
    output, _ = run_program([program, "scene.prm"], ranks, folder)
    counts = re.findall(r": (\d+) (?:Newton|primal-dual) iterations, (\d+) Krylov iterations",
                        output)
    return dict(d=int(re.findall(r"d = (\d+)", output)[-1]), increments=len(counts),
                iterations=sum(int(n) for n, _ in counts),
                krylov_iterations=sum(int(k) for _, k in counts),
                solve_s=solve_seconds(output),
                max_u=re.findall(r"max \|u\| = (\S+)", output)[-1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog=__doc__)
    parser.add_argument("--program", default=os.path.join(ROOT, "build", "contact"))
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks",
                                                      "extrapolated-start.csv"))
    args = parser.parse_args()
    rows = []
    for name, scene, ranks, more in SCENES:
        best = best_alternately(args.repeat, STARTS, lambda start, folder:
                                run(args.program, scene, more, start, ranks, folder))
        ends = [float(r["max_u"]) for r in best.values()]
        # The same to the solver's tolerance (a scene that unloads ends at
        # round-off).
        if max(ends) - min(ends) > 1e-6 * max(ends) + 1e-12:
            sys.exit(f"{name}: the two starts end at different displacements "
                     f"({', '.join(r['max_u'] for r in best.values())})")
        for start, result in best.items():
            row = dict(result, scene=name, ranks=ranks, start=start,
                       solve_s=f"{result['solve_s']:.4f}")
            rows.append(row)
            print_row(row, COLUMNS)
    append_rows(args.csv, COLUMNS, rows)
    write_tables()


if __name__ == "__main__":
    main()
