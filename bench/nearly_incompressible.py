#!/usr/bin/env python3
"""Nearly incompressible bodies: accuracy and solver cost against Poisson's
ratio, for the standard Q1 element, the B-bar element solved through the
mixed system (the default) and the B-bar element solved on K itself
(`Linear solver/Nearly incompressible solves = condensed`), side by side in
one run. Writes one CSV row per case, rewrites the marked tables of
doc/performance.md from it (bench/doc_tables.py) and prints those of
doc/validation.md ("Nearly incompressible bodies").

Cases, each at nu in {0.3, 0.49, 0.499, 0.4999}:
- lame: Lame's thick-walled sphere (parameters/lame_3d.prm) at 3 and 4
  global refinements: one elastic solve; errors of the radial displacement
  and of the radial and hoop stress against the exact solution;
- example2: Kanno's example II (3D brick, N_Y = 8 and 12) with the Newton
  method; the contact solve in units of one elastic solve of the same
  mesh, material and solver path;
- hertz_2d: the adaptive Hertz scene of tests/hertz_2d_nu_*.prm; errors of
  the half-width, the peak pressure and the nodal pressure profile;
- hertz_3d: parameters/hertz_3d_rubber.prm (six adaptive cycles) with
  nu changed; --skip-hertz-3d leaves it out (it takes minutes per run).

usage: bench/nearly_incompressible.py [--csv doc/benchmarks/nearly-incompressible.csv]
                                      [--skip-hertz-3d] [--tables-only]
Run from the top of the repository after scripts/setup.sh.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "tests"))
from run_series import parse, run, scene  # noqa: E402
from doc_tables import write_tables  # noqa: E402

POISSON = [0.3, 0.49, 0.499, 0.4999]
# (formulation, solver path) of each variant.
VARIANTS = {"standard": ("standard", "mixed"),
            "B-bar mixed": ("B-bar", "mixed"),
            "B-bar condensed": ("B-bar", "condensed")}
COLUMNS = ["case", "size", "nu", "variant", "d", "converged", "iterations",
           "krylov_iterations", "solve_s", "elastic_krylov_iterations",
           "elastic_s", "ratio_to_elastic", "radial_displacement_error",
           "radial_stress_error", "hoop_stress_error", "radius_error",
           "peak_pressure_error", "profile_error"]


def material(nu, variant):
    formulation, path = VARIANTS[variant]
    return (f"subsection Material\n set Poisson's ratio = {nu}\n"
            f" set Formulation = {formulation}\nend\n"
            f"subsection Linear solver\n set Nearly incompressible solves = {path}\nend\n")


def elastic_iterations(output):
    import re
    match = re.search(r"elastic solve, (\d+) \S+ iterations", output)
    return int(match.group(1)) if match else ""


def check(script, arguments):
    """The percentages a check script prints, by the words before them."""
    import re
    done = subprocess.run([sys.executable, os.path.join(ROOT, "tests", script)]
                          + arguments, capture_output=True, text=True)
    return {m.group(1): float(m.group(2)) for m in re.finditer(
        r"(radial displacement|radial stress|hoop stress|half-width|radius|"
        r"peak pressure|profile) .*?(?:error |by at most )([0-9.]+) %",
        done.stdout)}


def lame(contact, refinements, nu, variant):
    text = (f"include {ROOT}/parameters/lame_3d.prm\nset Output directory = output\n"
            f"subsection Mesh refinement\n set Global refinements = {refinements}\nend\n"
            "subsection Postprocess\n subsection Visualization\n  set Write vtu = false\n"
            "  set Write csv tables = true\n end\nend\n"
            + material(nu, variant))
    with tempfile.TemporaryDirectory() as folder:
        code, output, _ = run(text, 1, folder, contact)
        errors = check("check_lame.py", [os.path.join(folder, "output")]) if code == 0 else {}
    values = parse(output)
    return dict(case="lame", size=refinements, nu=nu, variant=variant, d=values["d"],
                converged=int(code == 0), elastic_krylov_iterations=elastic_iterations(output),
                elastic_s=values["solve_s"],
                radial_displacement_error=errors.get("radial displacement", ""),
                radial_stress_error=errors.get("radial stress", ""),
                hoop_stress_error=errors.get("hoop stress", ""))


def example2(contact, n_y, nu, variant):
    row = dict(case="example2", size=n_y, nu=nu, variant=variant)
    with tempfile.TemporaryDirectory() as folder:
        _, output, _ = run(scene(2, n_y, 0.5, None, False) + material(nu, variant), 1,
                           folder, contact)
    unit = parse(output)
    row.update(elastic_krylov_iterations=elastic_iterations(output), elastic_s=unit["solve_s"])
    with tempfile.TemporaryDirectory() as folder:
        code, output, _ = run(scene(2, n_y, 0.5, "semismooth Newton") + material(nu, variant),
                              1, folder, contact)
    values = parse(output)
    row.update(d=values["d"], converged=int(code == 0), iterations=values.get("iterations", ""),
               krylov_iterations=values.get("cg_iterations", ""), solve_s=values["solve_s"])
    if code == 0 and row["elastic_s"]:
        row["ratio_to_elastic"] = round(values["solve_s"] / row["elastic_s"], 2)
    return row


def hertz(contact, dimension, nu, variant):
    if dimension == 2:
        text = open(os.path.join(ROOT, "tests", "hertz_2d_nu_04999.prm")).read().replace(
            "@PROJECT_SOURCE_DIR@", ROOT)
    else:
        text = (f"include {ROOT}/parameters/hertz_3d_rubber.prm\n"
                "subsection Postprocess\n subsection Visualization\n  set Write vtu = false\n"
                "  set Write csv tables = true\n end\nend\n")
    text += "set Output directory = output\n" + material(nu, variant)
    with tempfile.TemporaryDirectory() as folder:
        code, output, _ = run(text, 1, folder, contact)
        errors = check("check_analytic.py", ["hertz", os.path.join(folder, "output"),
                                             "--profile-tolerance", "1"]) if code == 0 else {}
    values = parse(output)
    return dict(case=f"hertz_{dimension}d", size="adaptive", nu=nu, variant=variant,
                d=values["d"], converged=int(code == 0), iterations=values.get("iterations", ""),
                krylov_iterations=values.get("cg_iterations", ""), solve_s=values["solve_s"],
                radius_error=errors.get("half-width", errors.get("radius", "")),
                peak_pressure_error=errors.get("peak pressure", ""),
                profile_error=errors.get("profile", ""))


def tables(rows):
    def pick(case, size=None):
        return [r for r in rows if r["case"] == case and (size is None or r["size"] == str(size))]

    for size in ("3", "4"):
        print(f"\nLame's sphere, {size} global refinements: elastic solve, "
              "Krylov iterations (seconds); errors in % (u_r, sigma_r, sigma_t)\n")
        print("| nu | standard | B-bar, mixed | B-bar, condensed | errors standard | errors B-bar |")
        print("|---|---|---|---|---|---|")
        for nu in POISSON:
            by = {r["variant"]: r for r in pick("lame", size) if float(r["nu"]) == nu}
            cell = lambda v: (f"{by[v]['elastic_krylov_iterations']} ({float(by[v]['elastic_s']):.3g} s)"
                              if v in by and by[v]["converged"] == "1" else "failed")
            err = lambda v: (", ".join(by[v][k] for k in ("radial_displacement_error",
                                                          "radial_stress_error", "hoop_stress_error"))
                             if v in by and by[v]["converged"] == "1" else "-")
            print(f"| {nu} | {cell('standard')} | {cell('B-bar mixed')} | "
                  f"{cell('B-bar condensed')} | {err('standard')} | {err('B-bar mixed')} |")
    for size in ("8", "12"):
        print(f"\nExample II, N_Y = {size}, Newton: Newton steps / Krylov iterations, "
              "contact solve in elastic solves of the same variant (elastic Krylov iterations)\n")
        print("| nu | standard | B-bar, mixed | B-bar, condensed |")
        print("|---|---|---|---|")
        for nu in POISSON:
            by = {r["variant"]: r for r in pick("example2", size) if float(r["nu"]) == nu}
            cell = lambda v: (f"{by[v]['iterations']} / {by[v]['krylov_iterations']}, "
                              f"{by[v]['ratio_to_elastic']} ({by[v]['elastic_krylov_iterations']})"
                              if v in by and by[v]["converged"] == "1" else "failed")
            print(f"| {nu} | {cell('standard')} | {cell('B-bar mixed')} | {cell('B-bar condensed')} |")
    for case in ("hertz_2d", "hertz_3d"):
        chosen = pick(case)
        if not chosen:
            continue
        print(f"\n{case}: errors against Hertz in % (contact radius, peak pressure, "
              "largest nodal pressure difference within 0.8 a in % of p0); Newton steps / "
              "Krylov iterations, contact solve seconds\n")
        print("| nu | variant | radius | peak | profile | Newton / Krylov | seconds |")
        print("|---|---|---|---|---|---|---|")
        for r in chosen:
            if r["converged"] != "1":
                print(f"| {r['nu']} | {r['variant']} | failed | | | | |")
                continue
            print(f"| {r['nu']} | {r['variant']} | {r['radius_error']} | "
                  f"{r['peak_pressure_error']} | {r['profile_error']} | "
                  f"{r['iterations']} / {r['krylov_iterations']} | {float(r['solve_s']):.3g} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks",
                                                      "nearly-incompressible.csv"))
    parser.add_argument("--skip-hertz-3d", action="store_true")
    parser.add_argument("--tables-only", action="store_true",
                        help="print the tables of an existing CSV")
    parser.add_argument("--contact", default=os.path.join(ROOT, "build", "contact"))
    args = parser.parse_args()
    if not args.tables_only:
        measured = []
        for nu in POISSON:
            for variant in VARIANTS:
                for refinements in (3, 4):
                    measured.append(lame(args.contact, refinements, nu, variant))
                for n_y in (8, 12):
                    measured.append(example2(args.contact, n_y, nu, variant))
                measured.append(hertz(args.contact, 2, nu, variant))
                if not args.skip_hertz_3d and variant != "B-bar condensed":
                    measured.append(hertz(args.contact, 3, nu, variant))
                print(f"nu = {nu}, {variant}: done", flush=True)
        os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
        with open(args.csv, "w", newline="") as f:
            writer = csv.DictWriter(f, COLUMNS, extrasaction="ignore")
            writer.writeheader()
            writer.writerows(measured)
    with open(args.csv) as f:
        tables(list(csv.DictReader(f)))
    write_tables()
    return 0


if __name__ == "__main__":
    sys.exit(main())
