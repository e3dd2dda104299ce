#!/usr/bin/env python3
"""Where the ironing stops on fine cells: the 2D ironing scene
(parameters/ironing_2d.prm, mu = 0.3) in 20 increments on cells of 0.125
(the shipped mesh) and 0.0625 with the law at the Gauss points, and on
cells of 0.0625 and 0.03125 at the Gauss-Lobatto points, which include the
cells' corners (<Material/Quadrature>); increments cut on failure, 2 ranks.
For each converged increment the smallest det F of the block (statistics
column 'Smallest det F': at the quadrature points and the cells' corners),
and for each run where it stopped and the cell its failure line names, and
its wall time. Rewrites doc/benchmarks/ironing-fold.csv and the quote of
doc/performance.md that reads it.

usage: bench/ironing_fold.py [--program build/contact]
           [--runs 1:Gauss,2:Gauss,2:Gauss-Lobatto,3:Gauss-Lobatto]
           (refinements of the scene's cells of 0.25 : quadrature)
"""
import argparse
import os
import re
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "tests"))
from check_analytic import read_statistics  # noqa: E402
from doc_tables import replace_runs, write_tables  # noqa: E402
from runs import NO_OUTPUT, run as run_program  # noqa: E402

COLUMNS = ["cell_size", "quadrature", "time", "smallest_det_F", "stopped_at", "failed_cell",
           "wall_s"]


def run(program, level, quadrature, folder):
    with open(os.path.join(folder, "scene.prm"), "w") as f:
        f.write(f"include {ROOT}/parameters/ironing_2d.prm\n" + NO_OUTPUT +
                f"subsection Mesh refinement\n  set Global refinements = {level}\nend\n"
                "subsection Loading\n  set Number of increments = 20\nend\n"
                f"subsection Material\n  set Quadrature = {quadrature}\nend\n")
    output, wall = run_program([program, "scene.prm"], 2, folder, may_fail=True)
    failure = re.findall(r"^Error: .*", output, re.M)
    # The cell the failure line names (an inverted cell, or the smallest
    # det F of a solve that did not converge).
    cells = re.findall(r"cell at (\([^)]*\))", failure[-1]) if failure else []
    statistics = read_statistics(os.path.join(folder, "output", "statistics"))
    stopped = f"{statistics[-1]['Time']:.10g}" if failure else ""
    cell = 0.25 / 2 ** level
    return [dict(cell_size=cell, quadrature=quadrature, time=f"{r['Time']:.10g}",
                 smallest_det_F=f"{r['Smallest det F']:.3e}", stopped_at=stopped,
                 failed_cell=cells[-1] if cells else "", wall_s=f"{wall:.0f}")
            for r in statistics], wall


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--program", default=os.path.join(ROOT, "build", "contact"))
    parser.add_argument("--runs", default="1:Gauss,2:Gauss,2:Gauss-Lobatto,3:Gauss-Lobatto")
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks",
                                                      "ironing-fold.csv"))
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        for text in args.runs.split(","):
            level, quadrature = text.split(":")
            folder = os.path.join(scratch, text.replace(":", "-"))
            os.makedirs(folder)
            mine, wall = run(args.program, int(level), quadrature, folder)
            last = mine[-1]
            print(f"cells of {last['cell_size']}, {quadrature} points: {len(mine)} "
                  f"increments to t = "
                  f"{last['time']}, smallest det F {last['smallest_det_F']}"
                  + (f"; then a failure at the cell at {last['failed_cell']}"
                     if last["stopped_at"] else "")
                  + f" ({wall:.0f} s)")
            rows += mine
    replace_runs(args.csv, COLUMNS, rows,
                 key=lambda r: (float(r["cell_size"]), r["quadrature"]))
    for line in write_tables():
        print(line)


if __name__ == "__main__":
    main()
