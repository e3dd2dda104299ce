#!/usr/bin/env python3
"""How much faster 2 ranks are than 1: example II with the Newton solver,
best of --repeat runs per rank count, with the time split of the run
(set-up and assembly, AMG set-up, Krylov solves, contact operations,
output) and the elastic solve on the same ranks as the unit.

Measure on a quiet machine: other work on the 2 cores slows the 2-rank run
most.

usage: bench/parallel_efficiency.py [--sizes 20,28] [--ranks 1,2]
           [--repeat 3] [--vtu] [--csv doc/benchmarks/parallel.csv]
Run from the top of the repository after scripts/setup.sh.
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_series import best_run, scene  # noqa: E402

COLUMNS = ["N_Y", "ranks", "d", "iterations", "krylov_iterations", "setup_s",
           "amg_setup_s", "krylov_s", "contact_operations_s", "solve_s",
           "output_s", "elastic_solve_s", "ratio_to_elastic", "speed_up",
           "peak_memory_mb", "converged"]


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", default="20,28")
    parser.add_argument("--ranks", default="1,2")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--vtu", action="store_true",
                        help="write the VTU output too (its time is output_s)")
    parser.add_argument("--csv", default="doc/benchmarks/parallel.csv")
    parser.add_argument("--contact", default=os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "build", "contact"))
    args = parser.parse_args()

    if not os.path.exists(args.csv):
        with open(args.csv, "w", newline="") as f:
            csv.writer(f).writerow(COLUMNS)
    for n_y in (int(n) for n in args.sizes.split(",")):
        one_rank = None
        for ranks in (int(r) for r in args.ranks.split(",")):
            contact_scene = scene(2, n_y, 0.5, "semismooth Newton")
            if args.vtu:
                contact_scene += ("subsection Postprocess\n subsection Visualization\n"
                                  "  set Write vtu = true\n end\nend\n")
            _, elastic, _ = best_run(scene(2, n_y, 0.5, None, False), ranks,
                                     args.repeat, args.contact)
            code, values, _ = best_run(contact_scene, ranks, args.repeat,
                                       args.contact)
            if one_rank is None:
                one_rank = values["solve_s"]
            row = dict(values, N_Y=n_y, ranks=ranks, converged=int(code == 0),
                       krylov_iterations=values.get("cg_iterations", ""),
                       elastic_solve_s=elastic["elastic_s"],
                       ratio_to_elastic=round(values["solve_s"] / elastic["elastic_s"], 2),
                       speed_up=round(one_rank / values["solve_s"], 3))
            with open(args.csv, "a", newline="") as f:
                csv.DictWriter(f, COLUMNS, extrasaction="ignore").writerow(row)
            print(", ".join(f"{k} = {row.get(k, '')}" for k in COLUMNS), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
