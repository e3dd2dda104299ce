#!/usr/bin/env python3
"""The Newton solver and ML under different settings, measured on the same
scenes: the preconditioner of the Newton systems (with the node conditions
or the AMG of K alone), the forcing term of the inexact Newton method and
ML's smoother, sweeps, aggregation threshold, prolongator damping and near
null space. "fixed 0.01+AMG of K" is the solver before issue 19.

For each instance (example II at --sizes, friction --mu) and each variant,
runs the elastic scene (no contact: the unit, with the variant's ML
settings, so that the ratio stays honest) and the contact scene, best of
--repeat wall times, and appends one CSV row: d, Newton and Krylov
iterations, AMG set-ups, the elastic solve and the contact solve (seconds),
their ratio, and the peak memory per rank (MB and bytes per unknown).
A variant "a+b" combines the settings of a and b.

usage: bench/solver_settings.py [--sizes 14,20] [--mu 0.5] [--ranks 1]
           [--variants name,name+name] [--repeat 2]
           [--csv doc/benchmarks/solver-settings.csv]
Run from the top of the repository after scripts/setup.sh.
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_series import best_run, scene  # noqa: E402

NEWTON = "subsection Contact solver\n subsection Semismooth Newton\n{}\n end\nend\n"
LINEAR = "subsection Linear solver\n{}\nend\n"

# name -> (Newton settings, Linear solver settings): what differs from the
# defaults.
VARIANTS = {
    "default": ("", ""),
    "AMG of K": ("  set Preconditioner = AMG of K", ""),
    "fixed 0.01": ("  set Forcing term = fixed\n  set Linear reduction = 0.01", ""),
    "EW 0.01": ("  set Linear reduction = 0.01", ""),
    "EW 0.3": ("  set Linear reduction = 0.3", ""),
    "EW 0.5": ("  set Linear reduction = 0.5", ""),
    "sweeps 1": ("", " set AMG smoother sweeps = 1"),
    "sweeps 3": ("", " set AMG smoother sweeps = 3"),
    "threshold 0": ("", " set AMG aggregation threshold = 0"),
    "threshold 0.02": ("", " set AMG aggregation threshold = 0.02"),
    "threshold 0.08": ("", " set AMG aggregation threshold = 0.08"),
    "translations": ("", " set AMG near null space = translations"),
    "Gauss-Seidel": ("", " set AMG smoother type = symmetric Gauss-Seidel"),
    "damping 0": ("", " set AMG prolongator damping = 0"),
    "damping 0.67": ("", " set AMG prolongator damping = 0.67"),
}

COLUMNS = ["N_Y", "mu", "ranks", "variant", "d", "iterations", "krylov_iterations",
           "amg_setups", "elastic_solve_s", "solve_s", "ratio_to_elastic",
           "peak_memory_mb", "bytes_per_unknown", "converged"]


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", default="14,20")
    parser.add_argument("--mu", type=float, default=0.5)
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--variants", default=",".join(VARIANTS))
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--csv", default="doc/benchmarks/solver-settings.csv")
    parser.add_argument("--contact", default=os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "build", "contact"))
    args = parser.parse_args()

    new_file = not os.path.exists(args.csv)
    with open(args.csv, "a", newline="") as f:
        if new_file:
            csv.writer(f).writerow(COLUMNS)
    for n_y in (int(n) for n in args.sizes.split(",")):
        for name in args.variants.split(","):
            # "a+b": the settings of both variants.
            parts = [VARIANTS[part] for part in name.split("+")]
            newton = "\n".join(p[0] for p in parts if p[0])
            linear = "\n".join(p[1] for p in parts if p[1])
            extra = (NEWTON.format(newton) if newton else "") + \
                (LINEAR.format(linear) if linear else "")
            _, elastic, _ = best_run(scene(2, n_y, args.mu, None, False) + extra,
                                     args.ranks, args.repeat, args.contact)
            code, values, output = best_run(
                scene(2, n_y, args.mu, "semismooth Newton") + extra,
                args.ranks, args.repeat, args.contact)
            if code != 0:
                print(output[-2000:])
            row = dict(N_Y=n_y, mu=args.mu, ranks=args.ranks, variant=name,
                       d=values["d"], iterations=values.get("iterations", ""),
                       krylov_iterations=values.get("cg_iterations", ""),
                       amg_setups=values.get("amg_setups", ""),
                       elastic_solve_s=elastic["elastic_s"],
                       solve_s=round(values["solve_s"], 4),
                       peak_memory_mb=values["peak_memory_mb"],
                       converged=int(code == 0))
            row["ratio_to_elastic"] = round(row["solve_s"] / row["elastic_solve_s"], 2)
            if values["d"] and values["peak_memory_mb"]:
                row["bytes_per_unknown"] = round(
                    values["peak_memory_mb"] * 2**20 * args.ranks / values["d"])
            with open(args.csv, "a", newline="") as f:
                csv.DictWriter(f, COLUMNS, extrasaction="ignore").writerow(row)
            print(f"N_Y = {n_y}, {name}: d = {row['d']}, {row['iterations']} Newton, "
                  f"{row['krylov_iterations']} Krylov, {row['amg_setups']} AMG set-ups, "
                  f"solve {row['solve_s']} s = {row['ratio_to_elastic']} elastic solves "
                  f"({row['elastic_solve_s']} s), {row['peak_memory_mb']} MB"
                  f"{'' if code == 0 else ', FAILED'}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
