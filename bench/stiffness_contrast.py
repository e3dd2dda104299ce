#!/usr/bin/env python3
"""Bodies of very different stiffness: the shipped two-body scenes with
only the moduli changed, the slave side's Young's modulus a ratio of the
master's (1e-6: a soft slave on a stiff master; 1e6: a steel part on a
rubber one), without and with friction. Prints and writes, for each run,
the Newton steps and Krylov iterations summed over its increments and its
solve time, and against the same scene at equal moduli (ratio 1) the
ratio of Newton steps and of Krylov iterations per Newton step: the goals
are at most 1.5 and 2. A run that fails is a row with converged = 0; one
that --time-limit stopped also has stopped = 1.

Rows go to doc/benchmarks/stiffness-contrast.csv in place of those of
the same label, scene, ratio, friction and ranks (--label names the
build: run the bench once with the program before a change and once
after, the two labels side by side in the table of doc/performance.md,
"Bodies of very different stiffness").

usage: bench/stiffness_contrast.py [--program build/contact] [--label after]
         [--commit REV] [--scenes block_on_block_2d,...]
         [--ratios 1e-6,1e-3,1,1e3,1e6] [--friction 0,0.5] [--ranks 1]
         [--time-limit 300]
"""
import argparse
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from doc_tables import replace_runs, write_tables  # noqa: E402
from runs import NO_OUTPUT, increment_statistics, print_row, run  # noqa: E402

# scene: (master body, slave body) as the shipped Contact/Pairs has them.
SCENES = {"block_on_block_2d": ("base", "block"),
          "block_on_block_3d": ("base", "block"),
          "bracket_2d": ("base", "bracket"),
          "ball_on_plate": ("plate", "ball")}
COLUMNS = ["label", "scene", "ratio", "friction", "ranks", "converged", "stopped", "d",
           "increments", "newton_iterations", "krylov_iterations", "solve_s",
           "newton_vs_equal", "krylov_per_step_vs_equal", "commit"]
CSV = os.path.join(ROOT, "doc", "benchmarks", "stiffness-contrast.csv")


def commit():
    done = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT,
                          capture_output=True, text=True)
    return done.stdout.strip() or "unknown"


def scene_file(scene, ratio, friction, folder):
    """The scene with the master's modulus 1 and the slave's @p ratio."""
    master, slave = SCENES[scene]
    path = os.path.join(folder, "scene.prm")
    with open(path, "w") as f:
        f.write(f"include {os.path.join(ROOT, 'parameters', scene + '.prm')}\n"
                + NO_OUTPUT +
                f"subsection Material\n  set Young's modulus = {master}: 1; "
                f"{slave}: {ratio}\nend\n"
                f"subsection Contact\n  set Friction coefficient = {friction}\nend\n")
    return path


def measure(program, scene, ratio, friction, ranks, time_limit):
    with tempfile.TemporaryDirectory() as folder:
        path = scene_file(scene, ratio, friction, folder)
        output, _ = run(["timeout", str(time_limit), os.path.abspath(program), path],
                        ranks, folder, may_fail=True)
    # A run that the time limit stopped printed no summary.
    stopped = "-- summary:" not in output
    converged = not stopped and "the solve failed" not in output and "Error" not in output
    row = dict(converged=int(converged), stopped=int(stopped), d="", increments="",
               newton_iterations="", krylov_iterations="", solve_s="")
    if converged:
        row.update(increment_statistics(output))
    return row


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    parser.add_argument("--program", default=os.path.join(ROOT, "build", "contact"))
    parser.add_argument("--label", default="after")
    parser.add_argument("--scenes", default=",".join(SCENES))
    parser.add_argument("--ratios", default="1e-6,1e-3,1,1e3,1e6")
    parser.add_argument("--friction", default="0,0.5")
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--time-limit", type=float, default=300,
                        help="seconds after which a run is stopped (a row with stopped = 1)")
    parser.add_argument("--commit", help="the commit --program was built from "
                        "(default: this checkout's)")
    args = parser.parse_args()
    scenes = args.scenes.split(",")
    unknown = set(scenes) - set(SCENES)
    if unknown:
        parser.error(f"no scene {', '.join(sorted(unknown))}")
    ratios = args.ratios.split(",")
    if "1" not in ratios:
        ratios.insert(0, "1")
    made = []
    for scene in scenes:
        for friction in args.friction.split(","):
            equal = None
            for ratio in ["1"] + [r for r in ratios if r != "1"]:
                row = dict(label=args.label, scene=scene, ratio=ratio, friction=friction,
                           ranks=args.ranks, commit=args.commit or commit(),
                           newton_vs_equal="",
                           krylov_per_step_vs_equal="")
                row.update(measure(args.program, scene, ratio, friction, args.ranks,
                                   args.time_limit))
                if ratio == "1":
                    equal = row
                elif row["converged"] and equal and equal["converged"]:
                    row["newton_vs_equal"] = row["newton_iterations"] / equal["newton_iterations"]
                    row["krylov_per_step_vs_equal"] = (
                        row["krylov_iterations"] / row["newton_iterations"] /
                        (equal["krylov_iterations"] / equal["newton_iterations"]))
                print_row(row, COLUMNS)
                made.append(row)
    replace_runs(CSV, COLUMNS, made, key=lambda r: (r["label"], r["scene"], str(r["ratio"]),
                                                     str(r["friction"]), str(r["ranks"])))
    for line in write_tables():
        print("updated " + line)


if __name__ == "__main__":
    main()
