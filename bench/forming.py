#!/usr/bin/env python3
"""Forming at finite strain: what J2 plasticity at finite strain costs and
how its results settle. Two parts, in one run of this script:

- billet: parameters/billet_upsetting.prm (the quarter billet upset by 50 %
  with friction 0.1) on --levels of global refinement, with the pressure
  of the cell's mean volume ratio (Formulation = auto, the default) and of
  each point's det F (standard): the die force at the end, the increments,
  Newton steps and cuts, and the solve time per increment in units of one
  elastic solve of the same mesh (the billet linear elastic at small
  strain, its top face moved by a thousandth of its height, no contact);
- step42: deal.II's step-42 indentation (parameters/step42_indentation.prm)
  on one mesh (its first refined once, not adapted) at small and at
  finite strain: the Newton steps and the solve time per increment, in
  elastic solves of that mesh, and the ratio of the two kinematics (the
  goal: at most 1.5); 'step42 shallow' the same with the ball pressed a
  fifth as deep (plastic strains below 1 %: small deformation).

Solve time: the timer's Assembly, Increment start, Elastic solve and
Contact solve (no set-up, no output). Best of --repeat, the variants of a
mesh alternately. Rewrites doc/benchmarks/forming.csv (the rows of the
same part, mesh and variant) and the tables of doc/performance.md
("Forming").

The peak memory per rank (the largest) is recorded with each run.

usage: bench/forming.py [--program build/contact] [--ranks 2] [--repeat 1]
                        [--levels 0,1,2,3] [--parts billet,step42]
                        [--variants "mean volume ratio"]
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
from check_analytic import read_statistics  # noqa: E402
from doc_tables import replace_runs, write_tables  # noqa: E402
from runs import (NO_OUTPUT, best_alternately, chosen_scenes, increment_statistics,  # noqa: E402
                  print_row, run as run_program)

COLUMNS = ["part", "level", "variant", "ranks", "d", "increments", "newton_iterations",
           "cuts", "force", "solve_s", "elastic_solve_s", "increment_in_elastic_solves",
           "peak_mb", "commit"]
CSV = os.path.join(ROOT, "doc", "benchmarks", "forming.csv")

# One elastic solve of a scene's mesh: linear elastic at small strain, no
# contact, its contact face moved down a little in one increment.
ELASTIC = """subsection Material
  set Model = linear elastic
  set Kinematics = small strain
end
subsection Contact
  set Contact boundaries =
end
subsection Loading
  set Number of increments = 1
end
"""
BILLET_ELASTIC = ELASTIC + """subsection Boundary conditions
  set Prescribed boundaries = top: z
  set Prescribed displacement = 0; 0; -0.01 * t
end
"""
# step-42 on one mesh, its first refined once (d about 14,000), for every
# variant: the kinematics compared on the same mesh.
STEP42_MESH = """subsection Mesh refinement
  set Strategy = none
  set Global refinements = 1
end
"""
# The ball pressed a fifth as deep: plastic strains below 1 %.
SHALLOW = """subsection Contact
  subsection Obstacle
    set Rigid displacement = 0; 0; -0.002 * t
  end
end
"""
STEP42_ELASTIC = ELASTIC + """subsection Boundary conditions
  set Prescribed boundaries = top: z
  set Prescribed displacement = 0; 0; -0.0001 * t
end
"""
PARTS = {
    "billet": ("billet_upsetting.prm", "Contact force z", {
        "mean volume ratio": "",
        "standard": "subsection Material\n  set Formulation = standard\nend\n",
        "elastic solve": BILLET_ELASTIC}),
    "step42": ("step42_indentation.prm", "Contact force z", {
        "small strain": STEP42_MESH,
        "finite strain": STEP42_MESH +
        "subsection Material\n  set Kinematics = finite strain\nend\n",
        "elastic solve": STEP42_MESH + STEP42_ELASTIC}),
    "step42 shallow": ("step42_indentation.prm", "Contact force z", {
        "small strain": STEP42_MESH + SHALLOW,
        "finite strain": STEP42_MESH + SHALLOW +
        "subsection Material\n  set Kinematics = finite strain\nend\n",
        "elastic solve": STEP42_MESH + STEP42_ELASTIC}),
}


def run(program, scene, more, ranks, folder, column):
    with open(os.path.join(folder, "scene.prm"), "w") as f:
        f.write(f"include {ROOT}/parameters/{scene}\n" + more + NO_OUTPUT)
    output, _ = run_program([program, "scene.prm"], ranks, folder)
    result = increment_statistics(output)
    rows = read_statistics(os.path.join(folder, "output", "statistics"))
    result["force"] = abs(rows[-1][column]) if rows else float("nan")
    result["cuts"] = output.count("Cut in half")
    result["peak_mb"] = float(re.findall(r"peak memory = ([0-9.]+) MB", output)[-1])
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog=__doc__)
    parser.add_argument("--program", default=os.path.join(ROOT, "build", "contact"))
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--levels", default="0,1,2,3")
    parser.add_argument("--parts", default=",".join(PARTS))
    parser.add_argument("--variants", help="only these variants (and the elastic "
                        "solve), separated by ','")
    args = parser.parse_args()
    program = os.path.abspath(args.program)
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT,
                            capture_output=True, text=True).stdout.strip()
    rows = []
    for part in chosen_scenes(parser, args.parts, list(PARTS)):
        scene, column, variants = PARTS[part]
        if args.variants:
            variants = {name: text for name, text in variants.items()
                        if name in args.variants.split(",") + ["elastic solve"]}
        levels = [int(x) for x in args.levels.split(",")] if part == "billet" else [None]
        for level in levels:
            refined = "" if level is None else \
                f"subsection Mesh refinement\n  set Global refinements = {level}\nend\n"
            best = best_alternately(args.repeat, list(variants), lambda variant, folder:
                                    run(program, scene, refined + variants[variant],
                                        args.ranks, folder, column))
            unit = best.pop("elastic solve")["solve_s"]
            for variant, result in best.items():
                per_increment = result["solve_s"] / result["increments"]
                row = dict(part=part, level="" if level is None else level, variant=variant,
                           ranks=args.ranks, d=result["d"], increments=result["increments"],
                           newton_iterations=result["newton_iterations"], cuts=result["cuts"],
                           force=f"{result['force']:.6g}", solve_s=f"{result['solve_s']:.3f}",
                           elastic_solve_s=f"{unit:.4f}",
                           increment_in_elastic_solves=f"{per_increment / unit:.2f}",
                           peak_mb=f"{result['peak_mb']:.0f}", commit=commit)
                rows.append(row)
                print_row(row, COLUMNS)
    replace_runs(CSV, COLUMNS, rows,
                 key=lambda r: (r["part"], str(r["level"]), r["variant"], str(r["ranks"])))
    for line in write_tables():
        print("updated " + line)


if __name__ == "__main__":
    main()
