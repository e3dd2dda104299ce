#!/usr/bin/env python3
"""How long each shipped scene takes as shipped: runs every file in
parameters/ (or --scenes) with its own output settings, in a new folder,
on --ranks ranks (1: without mpirun, as a user runs a scene first), and
records its wall time (process start to exit), its unknowns d on its
last mesh and its increments. Writes doc/benchmarks/scene-times.csv in
place of the rows of the same scene and ranks; README.md's table of the
scenes quotes the times of one rank.

usage: bench/scene_times.py [--program build/contact] [--scenes a,b] [--ranks 1]
"""
import argparse
import glob
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from doc_tables import replace_runs, write_tables  # noqa: E402
from runs import chosen_scenes, increment_statistics, print_row, run  # noqa: E402

COLUMNS = ["scene", "ranks", "wall_s", "d", "increments", "commit"]
CSV = os.path.join(ROOT, "doc", "benchmarks", "scene-times.csv")


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    parser.add_argument("--program", default=os.path.join(ROOT, "build", "contact"))
    parser.add_argument("--scenes")
    parser.add_argument("--ranks", type=int, default=1)
    args = parser.parse_args()
    names = sorted(os.path.basename(p)[:-4]
                   for p in glob.glob(os.path.join(ROOT, "parameters", "*.prm")))
    scenes = chosen_scenes(parser, args.scenes, names) if args.scenes else names
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT,
                            capture_output=True, text=True).stdout.strip()
    rows = []
    for scene in scenes:
        with tempfile.TemporaryDirectory() as folder:
            output, seconds = run([os.path.abspath(args.program),
                                   os.path.join(ROOT, "parameters", scene + ".prm")],
                                  args.ranks, folder)
        statistics = increment_statistics(output)
        rows.append(dict(scene=scene, ranks=args.ranks, wall_s=f"{seconds:.1f}",
                         d=statistics["d"], increments=statistics["increments"],
                         commit=commit))
        print_row(rows[-1], COLUMNS)
    replace_runs(CSV, COLUMNS, rows, key=lambda r: (r["scene"], str(r["ranks"])))
    for line in write_tables():
        print("updated " + line)


if __name__ == "__main__":
    main()
