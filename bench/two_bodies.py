#!/usr/bin/env python3
"""Two deformable bodies at growing size: parameters/block_on_block_3d.prm
(a block pressed on a stiffer base, then dragged twice with mu = 0.3: at
the end every slave node slips), the base in 4s x 4s x s cells and the
block in (3s+1) x (3s+1) x 2s (non-matching), with the semismooth Newton
method. The unit is the elastic solve of the same mesh and loads without
the contact pair (the block hangs from its top face), in the same run:
its first increment is the project's unit (ML set-up plus AMG-CG, as in
bench/run_series.py), its later ones reuse the AMG and give a second,
stricter unit, since the contact solves of the later increments reuse the
AMG of K_w too. Appends one CSV row per size and rank count and rewrites
the table of doc/performance.md ("Two bodies") from the CSV.

usage: bench/two_bodies.py [--sizes 4,8,12,16] [--ranks 1]
                           [--csv doc/benchmarks/two-bodies.csv]
Run from the top of the repository after scripts/setup.sh; a size of 22
makes d = 1.13 million (about 6 GB per rank on 2 ranks).
"""
import argparse
import csv
import os
import re
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from doc_tables import write_tables  # noqa: E402
from run_series import parse, run  # noqa: E402

COLUMNS = ["size", "ranks", "d", "c", "increments", "newton_iterations",
           "krylov_iterations", "contact_solve_s", "elastic_solve_s",
           "elastic_solves_per_increment", "elastic_solve_reused_amg_s",
           "elastic_solves_reused_amg_per_increment", "amg_setup_s", "krylov_s",
           "peak_memory_mb", "converged"]


def scene(size, pairs):
    s = size
    return f"""include {ROOT}/parameters/block_on_block_3d.prm
set Output directory = output
subsection Geometry
  subsection Stacked blocks
    set Base repetitions = {4 * s}, {4 * s}, {s}
    set Block repetitions = {3 * s + 1}, {3 * s + 1}, {2 * s}
  end
end
subsection Contact
  set Pairs = {pairs}
end
subsection Postprocess
  subsection Visualization
    set Write vtu = false
  end
end
"""


def seconds(output, section):
    match = re.search(section + r" = ([0-9.e+-]+) s", output)
    return float(match.group(1)) if match else float("nan")


def measure(contact, size, ranks):
    with tempfile.TemporaryDirectory() as folder:
        _, elastic, _ = run(scene(size, ""), ranks, folder, contact)
    with tempfile.TemporaryDirectory() as folder:
        code, output, _ = run(scene(size, "block bottom : base top"), ranks, folder, contact)
    steps = re.findall(r"Increment \d+/(\d+), t = [^:]*: (\d+) Newton iterations, "
                       r"(\d+) Krylov", output)
    increments = len(steps)
    # "-- increment N solve wall time X s": the first with ML's set-up.
    elastic_times = [float(t) for t in
                     re.findall(r"-- increment \d+ solve wall time ([0-9.e+-]+) s", elastic)]
    unit = elastic_times[0]
    reused = sum(elastic_times[1:]) / max(len(elastic_times) - 1, 1)
    values = parse(output)
    solve = seconds(output, "Contact solve")
    return dict(size=size, ranks=ranks, d=values["d"], c=values["c"],
                increments=increments,
                newton_iterations=sum(int(s[1]) for s in steps),
                krylov_iterations=sum(int(s[2]) for s in steps),
                contact_solve_s=solve, elastic_solve_s=round(unit, 4),
                elastic_solves_per_increment=round(solve / max(increments, 1) / unit, 2),
                elastic_solve_reused_amg_s=round(reused, 4),
                elastic_solves_reused_amg_per_increment=round(
                    solve / max(increments, 1) / reused, 2),
                amg_setup_s=values.get("amg_setup_s", ""),
                krylov_s=values.get("krylov_s", ""),
                peak_memory_mb=values.get("peak_memory_mb", ""),
                converged=int(code == 0))


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", default="4,8,12,16")
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks",
                                                      "two-bodies.csv"))
    parser.add_argument("--contact", default=os.path.join(ROOT, "build", "contact"))
    args = parser.parse_args()
    new = not os.path.exists(args.csv)
    with open(args.csv, "a", newline="") as f:
        writer = csv.DictWriter(f, COLUMNS)
        if new:
            writer.writeheader()
        for size in (int(s) for s in args.sizes.split(",")):
            row = measure(args.contact, size, args.ranks)
            writer.writerow(row)
            f.flush()
            print(f"size {size}, {args.ranks} rank(s): d = {row['d']}, c = {row['c']}, "
                  f"{row['newton_iterations']} Newton iterations in {row['increments']} "
                  f"increments, {row['elastic_solves_per_increment']} elastic solves per "
                  f"increment ({row['elastic_solves_reused_amg_per_increment']} with the AMG "
                  f"reused){'' if row['converged'] else ', FAILED'}", flush=True)
    write_tables()
    return 0


if __name__ == "__main__":
    sys.exit(main())
