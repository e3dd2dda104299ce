#!/usr/bin/env python3
"""Linear elastic scenes before and after a change of the program: the same
scenes run with two builds, alternately, best of --repeat, in one run of
this script. Checks that the results agree (the statistics' contact forces
to 1e-8 of their largest value) and records the whole process's time and
peak memory of each. Appends to doc/benchmarks/linear-speed.csv and
rewrites the table of doc/performance.md ("Linear elastic scenes before
and after nonlinear laws").

usage: bench/linear_speed.py --before OLD/contact --after build/contact
                             [--label-before 8d0393f] [--label-after HEAD]
                             [--repeat 3] [--csv doc/benchmarks/linear-speed.csv]
Build the older version in a folder of its own (git worktree add ... and
cmake there) first.
"""
import argparse
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from doc_tables import append_rows, write_tables  # noqa: E402
from runs import NO_OUTPUT, best_alternately, run as run_program, print_row  # noqa: E402

COLUMNS = ["scene", "ranks", "version", "d", "newton_iterations", "wall_s",
           "peak_mb", "largest_force_difference"]
# (name, text of the scene, ranks): example II at N_Y = 20 (d = 52,920)
# with the semismooth Newton method, Hertz in 3D, and two bodies.
SCENES = [
    ("example2 N_Y = 20", f"""include {ROOT}/parameters/example2.prm
subsection Geometry
  subsection Box
    set X repetitions = 40
    set Y repetitions = 20
    set Z repetitions = 20
  end
end
subsection Contact solver
  set Method = semismooth Newton
end
""", 1),
    ("hertz_3d", f"include {ROOT}/parameters/hertz_3d.prm\n", 2),
    ("block_on_block_3d", f"include {ROOT}/parameters/block_on_block_3d.prm\n", 2),
]


def run(program, text, ranks, folder):
    with open(os.path.join(folder, "scene.prm"), "w") as f:
        f.write(text + NO_OUTPUT)
    output, wall = run_program([program, "scene.prm"], ranks, folder)
    forces = []
    statistics = os.path.join(folder, "output", "statistics")
    names = [l for l in open(statistics) if l.startswith("#")]
    columns = [int(re.match(r"# *(\d+):", l).group(1)) - 1 for l in names
               if "Contact force" in l]
    for line in open(statistics):
        if not line.startswith("#"):
            values = line.split()
            forces.append([float(values[c]) for c in columns])
    return dict(wall_s=wall,
                peak_mb=float(re.findall(r"peak memory = ([0-9.]+) MB", output)[-1]),
                d=int(re.findall(r"d = (\d+)", output)[-1]),
                newton_iterations=sum(int(n) for n in re.findall(r": (\d+) Newton iterations", output)),
                forces=forces)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog=__doc__)
    parser.add_argument("--before", required=True)
    parser.add_argument("--after", required=True)
    parser.add_argument("--label-before", default="before")
    parser.add_argument("--label-after", default="after")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks",
                                                      "linear-speed.csv"))
    args = parser.parse_args()
    rows = []
    for name, text, ranks in SCENES:
        programs = {args.label_before: args.before, args.label_after: args.after}
        best = best_alternately(args.repeat, list(programs), lambda label, folder:
                                run(programs[label], text, ranks, folder), key="wall_s")
        a, b = best[args.label_before]["forces"], best[args.label_after]["forces"]
        scale = max([abs(v) for row in a for v in row] + [1e-300])
        difference = max(abs(p - q) for ra, rb in zip(a, b) for p, q in zip(ra, rb)) / scale
        for label in (args.label_before, args.label_after):
            row = dict(best[label], scene=name, ranks=ranks, version=label,
                       largest_force_difference=f"{difference:.1e}")
            rows.append(row)
            print_row(row, COLUMNS)
    append_rows(args.csv, COLUMNS, rows)
    write_tables()


if __name__ == "__main__":
    main()
