"""The tables of doc/ that quote the bench CSVs: one function per table,
each making its Markdown from one CSV in doc/benchmarks/, and TABLES,
which names them after their markers (`<!-- table: name -->`). Also the
reading of a CSV and the formatting of cells that they share.
bench/doc_tables.py writes these tables into the pages, and the quotes.
"""
import csv
import os


def rows(root, name):
    with open(os.path.join(root, "doc", "benchmarks", name), newline="") as f:
        return list(csv.DictReader(f))


def markdown(header, body):
    lines = ["| " + " | ".join(header) + " |",
             "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(cell) for cell in row) + " |" for row in body]
    return "\n".join(lines)


def thousands(value):
    return f"{int(float(value)):,}"


def seconds(value):
    """Two significant digits (whole seconds from 10 s on)."""
    value = float(value)
    return f"{value:.0f} s" if value >= 10 else f"{value:#.2g} s"


def two_bodies(root):
    body = []
    for r in rows(root, "two-bodies.csv"):
        if r["converged"] != "1":
            body.append([r["size"], r["ranks"], thousands(r["d"]), r["c"],
                         "failed"] + [""] * 7)
            continue
        increments = int(r["increments"])
        kb_per_unknown = float(r["peak_memory_mb"]) * int(r["ranks"]) * 1024 / float(r["d"])
        body.append([r["size"], r["ranks"], thousands(r["d"]), thousands(r["c"]),
                     f"{int(r['newton_iterations']) / increments:.1f}",
                     f"{int(r['krylov_iterations']) / int(r['newton_iterations']):.1f}",
                     seconds(float(r["contact_solve_s"]) / increments),
                     seconds(r["elastic_solve_s"]),
                     r["elastic_solves_per_increment"],
                     seconds(r["elastic_solve_reused_amg_s"]),
                     r["elastic_solves_reused_amg_per_increment"],
                     f"{kb_per_unknown:.1f}"])
    return markdown(["size", "ranks", "d", "c", "Newton steps per increment",
                     "Krylov per Newton step", "contact solve per increment",
                     "elastic solve (unit)", "in units", "elastic solve, AMG reused",
                     "in those", "peak kB per unknown (largest rank x ranks)"], body)


NU = ["0.3", "0.49", "0.499", "0.4999"]
VARIANTS = ["standard", "B-bar mixed", "B-bar condensed"]


def by_key(table):
    return {(r["case"], r["size"], r["nu"], r["variant"]): r for r in table}


def lame_elastic(root):
    table = by_key(rows(root, "nearly-incompressible.csv"))
    sizes = [("3", "5,400 dofs"), ("4", "39,984 dofs")]
    header = ["nu"] + [f"{v}, {label}" if v == "standard" else v
                       for _, label in sizes for v in VARIANTS]
    body = []
    for nu in NU:
        line = [nu]
        for size, _ in sizes:
            for variant in VARIANTS:
                r = table.get(("lame", size, nu, variant))
                line.append(f"{r['elastic_krylov_iterations']} ({seconds(r['elastic_s'])})"
                            if r and r["converged"] == "1" else "failed")
        body.append(line)
    return markdown(header, body)


def example2_newton(root):
    table = by_key(rows(root, "nearly-incompressible.csv"))
    sizes = ["8", "12"]
    header = ["nu"] + [f"N_Y = {s} {v}" if v == "standard" else v
                       for s in sizes for v in VARIANTS]
    body = []
    for nu in NU:
        line = [nu]
        for size in sizes:
            for variant in VARIANTS:
                r = table.get(("example2", size, nu, variant))
                line.append(f"{r['iterations']} / {r['krylov_iterations']}, "
                            f"{r['ratio_to_elastic']} ({r['elastic_krylov_iterations']})"
                            if r and r["converged"] == "1" else "failed")
        body.append(line)
    return markdown(header, body)


def kanno_series(root):
    """One line per size: the default and (where measured) the previous
    inner solves side by side, with the paper's time where it has one."""
    table = rows(root, "kanno-series.csv")
    by_size = {}
    for r in table:
        by_size.setdefault((int(r["example"]), int(r["N_Y"])), {})[r["path"]] = r
    body = []
    for (example, n_y), paths in sorted(by_size.items()):
        new = paths.get("default")
        old = paths.get("previous")
        line = ["I" if example == 1 else "II", n_y]
        if new is None or new["converged"] != "1":
            body.append(line + [""] * 9)
            continue
        line += [thousands(new["d"]), thousands(new["iterations"]),
                 f"{int(new['krylov_iterations']) / int(new['iterations']):.2f}",
                 seconds(new["solve_s"]), f"{float(new['ms_per_iteration']):.3g}",
                 new["ratio_to_elastic"]]
        if old is not None and old["converged"] == "1":
            line += [f"{thousands(old['iterations'])}, {seconds(old['solve_s'])}",
                     f"{float(old['solve_s']) / float(new['solve_s']):.1f}"]
        else:
            line += ["", ""]
        line.append(f"{float(new['paper_s']):.1f} s" if new["paper_s"] else "")
        body.append(line)
    return markdown(["example", "N_Y", "d", "iterations", "Krylov per iteration",
                     "solve", "ms per iteration", "in elastic solves",
                     "previous inner solves: iterations, solve", "speed-up",
                     "paper (Matlab)"], body)


def kanno_variants(root):
    table = rows(root, "kanno-variants.csv")
    body = []
    for r in table:
        if r["converged"] != "1":
            body.append([r["example"], r["initial_alpha"], r["preconditioner"],
                         r["start"], r["tolerance"], "failed", "", ""])
            continue
        body.append(["I, N_Y = 40" if r["example"] == "1" else "II, N_Y = 10",
                     r["initial_alpha"], r["preconditioner"], r["start"],
                     r["tolerance"], thousands(r["iterations"]),
                     r["krylov_per_iteration"], seconds(r["solve_s"])])
    return markdown(["example", "Initial alpha", "preconditioner", "CG start",
                     "primal step tolerance", "iterations", "Krylov per iteration",
                     "solve"], body)


def multigrid(root):
    body = []
    for r in rows(root, "multigrid.csv"):
        if r["converged"] != "1":
            body.append([r["n_y"], r["ranks"], r["path"], thousands(r["d"]) if r["d"] else "", "failed"]
                        + [""] * 6)
            continue
        levels = f"{r['levels']} ({thousands(r['coarse_unknowns'])})" if r["levels"] else ""
        setup = seconds(r["multigrid_setup_s"]) if r["multigrid_setup_s"] else ""
        body.append([r["n_y"], r["ranks"], r["path"], thousands(r["d"]), levels,
                     r["elastic_cg_iterations"], seconds(r["elastic_solve_s"]), setup,
                     f"{r['newton_iterations']} / {r['contact_krylov_iterations']}",
                     r["elastic_solves_per_contact_solve"], r["kb_per_unknown"]])
    return markdown(["N_Y", "ranks", "preconditioner", "d", "levels (coarsest unknowns)",
                     "elastic CG iterations", "elastic solve", "multigrid set-up",
                     "Newton / Krylov iterations", "contact solve in elastic solves",
                     "peak kB per unknown"], body)


def fclib_scenes(root):
    """Per exported file: our Newton method on the path auto chooses and on
    the sparse LU, and the fastest Siconos solver that reached the
    tolerance by the common measure."""
    by_file = {}
    for r in rows(root, "fclib-scenes.csv"):
        by_file.setdefault(r["file"], []).append(r)
    body = []

    def cell(r):
        if r is None:
            return "-"
        if r["success"] != "1":
            return f"- ({r['note'] or 'error ' + r['common_error']})"
        return f"{seconds(r['seconds'])}, {r['iterations']} it."

    for name, runs in by_file.items():
        solvers = {r["solver"]: r for r in runs}
        ours = solvers.get("ours: semismooth Newton")
        lu = solvers.get("ours: semismooth Newton; jacobi")
        siconos = [r for r in runs
                   if r["solver"].startswith("siconos") and r["success"] == "1"]
        best = min(siconos, key=lambda r: float(r["seconds"]), default=None)
        ratio = (f"{float(best['seconds']) / float(ours['seconds']):.1f}"
                 if best and ours and ours["success"] == "1" else "")
        body.append([f"{name.removesuffix('.hdf5')} ({thousands(runs[0]['n'])}, "
                     f"{runs[0]['contacts']})", cell(ours), cell(lu),
                     f"{best['solver'].removeprefix('siconos ')}: {cell(best)}"
                     if best else "none", ratio])
    return markdown(["file (n, contacts)", "ours: Newton (auto)",
                     "ours: Newton, sparse LU", "fastest Siconos solver",
                     "its time / ours"], body)


def preconditioners(root):
    body = []
    for r in rows(root, "preconditioners.csv"):
        if r["converged"] != "1":
            body.append([r["scene"], r["global_refinements"], r["ranks"], r["path"],
                         "failed", "", "", ""])
            continue
        body.append([r["scene"], r["global_refinements"], r["ranks"], r["path"],
                     thousands(r["d"]),
                     f"{r['newton_iterations']} / {r['krylov_iterations']}",
                     seconds(r["contact_solve_s"]), r["time_to_first_path"]])
    return markdown(["scene", "global refinements", "ranks", "preconditioner",
                     "d (last mesh)", "Newton / Krylov iterations", "contact solve",
                     "time / first row's"], body)


def same_solutions(root):
    """One row per scene; per path and rank count the larger of the force
    and displacement differences from ML's run on one rank."""
    table = rows(root, "same-solutions.csv")
    runs = []
    for r in table:
        run = (r["path"], r["ranks"])
        if r["force_difference"] or r["refused"]:
            if run not in runs:
                runs.append(run)
    body = {}
    for r in table:
        row = body.setdefault(r["scene"], {"d": r["d"], "increments": r["increments"]})
        if r["refused"]:
            row[(r["path"], r["ranks"])] = "refused"
        elif r["force_difference"]:
            larger = max(float(r["force_difference"]), float(r["displacement_difference"]))
            tight = (max(float(r["tight_force_difference"]),
                         float(r["tight_displacement_difference"]))
                     if r["tight_force_difference"] else None)
            row[(r["path"], r["ranks"])] = (
                f"{larger:.0e}" + (" (initial mesh)" if r["mesh"] == "initial" else "")
                + (f"; {tight:.0e} at Tolerance 1e-12" if tight is not None else ""))
    return markdown(["scene", "d", "increments"] +
                    [f"{path}, {ranks} rank{'s' if ranks != '1' else ''}"
                     for path, ranks in runs],
                    [[scene, thousands(row["d"]) if row["d"] else "", row["increments"]] +
                     [row.get(run, "") for run in runs]
                     for scene, row in body.items()])


def step42(root):
    """bench/step42.py: step-42 and our program on the same meshes, the
    last row of each (mesh, ranks, program, element)."""
    latest = {}
    for r in rows(root, "step42.csv"):
        latest[(r["mesh"], int(r["cells_per_edge"]), int(r["ranks"]), r["program"],
                r["element"])] = r
    body = []
    for key in sorted(latest, key=lambda k: (k[0], k[1], k[2], k[3] != "step-42", k[4])):
        r = latest[key]
        step42_row = latest.get(key[:3] + ("step-42", "standard"))
        faster = (f"{float(step42_row['compute_s']) / float(r['compute_s']):.1f}"
                  if step42_row and r["program"] != "step-42" else "")
        per_step = r["newton_step_in_elastic_solves"]
        body.append([r["mesh"], key[1], key[2], r["program"], r["element"],
                     thousands(r["d"]), r["newton_steps"], seconds(r["compute_s"]), faster,
                     f"{float(r['peak_mb']):.0f}" if r["peak_mb"] else "",
                     f"{float(r['contact_force']):.4g}", r["plastic_cells"],
                     f"{float(per_step):.2f}" if per_step else ""])
    return markdown(["mesh", "cells per edge", "ranks", "program", "element", "d",
                     "Newton steps", "time (no VTU)", "times faster", "peak MB per rank",
                     "contact force", "plastic cells", "Newton step / elastic solve"],
                    body)


def latest_by_scene(root, name, variant):
    """The last row of each scene and each value of its column @p variant
    in the CSV @p name: {scene: {variant: row}}, in the order first met."""
    latest = {}
    for r in rows(root, name):
        latest.setdefault(r["scene"], {})[r[variant]] = r
    return latest


def linear_speed(root):
    """bench/linear_speed.py: linear elastic scenes with two builds, the
    last pair of rows of each scene."""
    latest = latest_by_scene(root, "linear-speed.csv", "version")
    body = []
    for scene, versions in latest.items():
        for version, r in versions.items():
            body.append([scene, r["ranks"], version, thousands(r["d"]),
                         r["newton_iterations"], seconds(r["wall_s"]),
                         f"{float(r['peak_mb']):.0f}", r["largest_force_difference"]])
    return markdown(["scene", "ranks", "version", "d", "Newton steps", "time",
                     "peak MB per rank", "forces differ by"], body)


def finite_strain(root):
    """bench/finite_strain.py: each scene's last rows, small and finite
    strain (and finite strain with a pair's geometry at every Newton
    iterate)."""
    latest = latest_by_scene(root, "finite-strain.csv", "kinematics")
    body = []
    for scene, variants in latest.items():
        for kinematics, r in variants.items():
            body.append([scene, r["ranks"], kinematics, thousands(r["d"]), r["increments"],
                         r["newton_iterations"], r["increment_in_elastic_solves"],
                         r["finite_over_small"] if kinematics != "small strain" else ""])
    return markdown(["scene", "ranks", "kinematics", "d", "increments", "Newton steps",
                     "increment in elastic solves", "finite / small"], body)


def forming(part):
    """bench/forming.py: the rows of @p part (billet: each mesh level and
    formulation; step42: each kinematics), with the finite / small ratio
    per increment for step42."""
    def table(root):
        chosen = [r for r in rows(root, "forming.csv") if r["part"] == part]
        unit = {r["variant"]: float(r["increment_in_elastic_solves"]) for r in chosen}
        body = []
        for r in chosen:
            row = [r["level"]] if part == "billet" else []
            row += [r["variant"], r["ranks"], thousands(r["d"]), r["increments"],
                    r["newton_iterations"], r["cuts"], f"{float(r['force']):.5g}",
                    r["increment_in_elastic_solves"], r.get("peak_mb") or ""]
            if part.startswith("step42"):
                row.append(f"{unit[r['variant']] / unit['small strain']:.2f}")
            body.append(row)
        header = (["refinements"] if part == "billet" else []) + \
            ["variant", "ranks", "d", "increments", "Newton steps", "cuts", "die force",
             "increment in elastic solves", "peak MB per rank"] + (["/ small strain"] if part.startswith("step42") else [])
        return markdown(header, body)
    return table


def coarse_solver(root):
    """bench/coarse_solver.py: each scene's last pair of rows, MUMPS and
    KLU on ML's coarsest level."""
    latest = latest_by_scene(root, "coarse-solver.csv", "coarse_solver")
    body = []
    for scene, solvers in latest.items():
        for solver, r in solvers.items():
            body.append([scene, f"{r['dim']}D", r["ranks"], solver, thousands(r["d"]),
                         r["newton_iterations"], thousands(r["krylov_iterations"]),
                         seconds(r["solve_s"]), r["klu_over_mumps"]])
    return markdown(["scene", "dim", "ranks", "coarse solver", "d", "Newton steps",
                     "Krylov iterations", "solve", "KLU / MUMPS"], body)


def extrapolated_start(root):
    """bench/extrapolated_start.py: each scene's last pair of rows, with
    the time of the extrapolated start against the start from no motion."""
    latest = latest_by_scene(root, "extrapolated-start.csv", "start")
    body = []
    for scene, starts in latest.items():
        first = starts["no motion"]
        for start, r in starts.items():
            body.append([scene, r["ranks"], start, thousands(r["d"]), r["increments"],
                         thousands(r["iterations"]), thousands(r["krylov_iterations"]),
                         seconds(r["solve_s"]),
                         f"{float(r['solve_s']) / float(first['solve_s']):.2f}"])
    return markdown(["scene", "ranks", "start", "d", "increments",
                     "Newton steps (Kanno: iterations)",
                     "Krylov iterations", "solve", "against no motion"], body)


def ironing(root):
    """bench/ironing.py: each run's drag and press with the die in the
    middle of its slide (t = 1.5), their change from the coarser mesh, and
    the Newton steps of the whole run."""
    runs = {}
    for r in rows(root, "ironing.csv"):
        runs.setdefault((r["mu"], int(r["level"])), []).append(r)
    body, previous = [], {}
    for (mu, level), mine in sorted(runs.items(), key=lambda k: (-float(k[0][0]), k[0][1])):
        middle = min(mine, key=lambda r: abs(float(r["time"]) - 1.5))
        drag, press = float(middle["drag"]), float(middle["press"])
        change = ""
        if mu in previous:
            old_drag, old_press = previous[mu]
            change = (f"{abs(drag - old_drag) / abs(drag):.2%}, "
                      f"{abs(press - old_press) / abs(press):.2%}")
        previous[mu] = (drag, press)
        body.append([level, "frictionless" if float(mu) == 0 else mu, thousands(mine[0]["d"]),
                     f"{drag:.4f}".replace("-0.0000", "0.0000"), f"{press:.4f}", change,
                     sum(int(r["newton_iterations"]) for r in mine), len(mine),
                     seconds(mine[0]["wall_s"])])
    return markdown(["refinements", "friction", "d", "drag at t = 1.5", "press at t = 1.5",
                     "change from the coarser mesh (drag, press)", "Newton steps",
                     "increments", "run"], body)


def ironing_3d(root):
    """bench/ironing_3d.py: the 3D ironing with a tool from a surface mesh
    against the 2D scene on the same cells."""
    body = []
    for r in rows(root, "ironing-3d.csv"):
        three = r["dimension"] == "3"
        die = (f"3D, tool (mortar), geometry {r['tool_geometry'] or 'fixed point'}" if three
               else "2D, cylinder (nodes)")
        body.append([r["cells_along"], die,
                     r["ranks"], thousands(r["d"]), r["increments"], r["newton_iterations"],
                     r["geometry_solves"],
                     f"{float(r['largest_drag_difference']):.2%}, "
                     f"{float(r['largest_press_difference']):.2%}" if three else "",
                     seconds(r["wall_s"])])
    return markdown(["cells along", "die", "ranks", "d", "increments", "Newton steps",
                     "geometry solves", "largest difference from 2D (drag, press)", "run"],
                    body)


def ironing_3d_scale(root):
    """bench/ironing_3d_scale.py: the 3D ironing on a finer mesh, with the
    preconditioner built again on the tangent and without."""
    body = []
    for r in rows(root, "ironing-3d-scale.csv"):
        factor = float(r["tangent_rebuild_factor"])
        hard = int(r["hard_increment_iterations"])
        # "to t": the end asked for, or where a run that stopped got to.
        reached = r["end_time"] if not r["stopped"] else f"{r['reached']} (stopped)"
        body.append([r["cells"], r["ranks"], thousands(r["d"]), reached, r["tool_geometry"],
                     r["quadrature"] + " points",
                     f"after {factor:g} x the Krylov iterations" if factor > 0 else "never",
                     f"after {hard} Newton steps" if hard > 0 else "never",
                     r["increments"], r["cuts"], r["halved_ahead"], r["newton_iterations"],
                     f"{int(r['krylov_iterations']) / max(int(r['newton_iterations']), 1):.1f}",
                     r["amg_setups"], r["geometry_solves"], seconds(r["solve_s"]),
                     r["solve_in_elastic_solves"]])
    return markdown(["cells", "ranks", "d", "to t", "the tool's geometry", "the law at",
                     "AMG built again on the tangent",
                     "next increment halved", "increments", "cuts", "halved ahead", "Newton steps", "Krylov per Newton step", "AMG set-ups",
                     "geometry solves", "solve", "solve in elastic solves"], body)


def o_ring_locking(root):
    """bench/o_ring_locking.py: per Poisson's ratio and law, the force at
    the end on each level (or what stopped the run), with its cuts and
    wall time."""
    runs = {}
    for r in rows(root, "o-ring-locking.csv"):
        runs.setdefault((r["nu"], r["law"]), []).append(r)
    levels = sorted({int(r["level"]) for mine in runs.values() for r in mine})
    body = []
    for (nu, law), mine in runs.items():
        cells = []
        for level in levels:
            r = next((r for r in mine if int(r["level"]) == level), None)
            if r is None:
                cells.append("")
            elif r["outcome"] == "done":
                cells.append(f"{float(r['force']):.4f} ({r['cuts']} cuts, "
                             f"{seconds(r['wall_s'])})")
            else:
                cells.append(f"{r['outcome']} ({r['cuts']} cuts)")
        body.append([nu, law] + cells)
    return markdown(["nu", "law"] + [f"{level} levels: force (cuts, run)" for level in levels],
                    body)


def suite_time(root):
    """The test suite's time by class of test (bench/suite_time.py)."""
    table = rows(root, "suite-time.csv")
    total = next(float(r["slot_seconds"]) for r in table if r["class"] == "all")
    body = []
    for r in table:
        share = f"{100 * float(r['slot_seconds']) / total:.0f} %"
        wall = f"{float(r['wall_s']):.0f} s" if r["wall_s"] else ""
        body.append([r["class"], thousands(r["tests"]), f"{float(r['seconds']):.0f}",
                     f"{float(r['slot_seconds']):.0f}", share, wall])
    return markdown(["tests", "count", "seconds", "slot-seconds", "share", "wall time (-j 2)"],
                    body)


def stiffness_contrast(root):
    """Bodies of very different stiffness (bench/stiffness_contrast.py): per
    scene, friction and ratio of the slave's modulus to the master's, the
    Newton steps and Krylov iterations per Newton step against the same
    scene at equal moduli, before and after the change the labels name."""
    table = rows(root, "stiffness-contrast.csv")
    labels = [label for label in ("before", "after")
              if any(r["label"] == label for r in table)]
    runs = {(r["label"], r["scene"], r["friction"], float(r["ratio"])): r for r in table}

    def cells(r):
        if r is None:
            return ["", ""]
        if r.get("stopped") == "1":
            return ["stopped by the time limit", ""]
        if r["converged"] != "1":
            return ["failed", ""]
        per_step = int(r["krylov_iterations"]) / max(1, int(r["newton_iterations"]))
        if not r["newton_vs_equal"]:
            return [r["newton_iterations"], f"{per_step:.0f}"]
        return [f"{r['newton_iterations']} (x {float(r['newton_vs_equal']):.2f})",
                f"{per_step:.0f} (x {float(r['krylov_per_step_vs_equal']):.2f})"]
    keys = sorted({(r["scene"], r["friction"], float(r["ratio"])) for r in table})
    body = []
    for scene, friction, ratio in keys:
        row = [scene, friction, f"{ratio:g}"]
        for label in labels:
            row += cells(runs.get((label, scene, friction, ratio)))
        body.append(row)
    header = ["scene", "friction", "E slave / E master"]
    for label in labels:
        header += [f"{label}: Newton steps (x equal)", f"{label}: Krylov per step (x equal)"]
    return markdown(header, body)


def axisymmetric(root):
    """bench/axisymmetric.py: each run of the ball on a plate, 3D and
    axisymmetric, by kind and local refinements."""
    body = [[r["kind"], r["level"], r["ranks"], thousands(r["d"]), r["force"],
             r["radius_error_percent"], r["fitted_radius_error_percent"],
             r["pressure_error_percent"], r["setup_and_solve_s"]]
            for r in rows(root, "axisymmetric.csv")]
    return markdown(["kind", "local refinements", "ranks", "d", "P", "radius error % (area)",
                     "radius error % (fitted)", "peak pressure error %",
                     "set-up and solve s"], body)


TABLES = {
    "axisymmetric": axisymmetric,
    "o-ring-locking": o_ring_locking,
    "ironing": ironing,
    "finite-strain": finite_strain,
    "forming-billet": forming("billet"),
    "forming-step42": forming("step42"),
    "forming-step42-shallow": forming("step42 shallow"),
    "coarse-solver": coarse_solver,
    "extrapolated-start": extrapolated_start,
    "ironing-3d": ironing_3d,
    "ironing-3d-scale": ironing_3d_scale,
    "linear-speed": linear_speed,
    "step42": step42,
    "same-solutions": same_solutions,
    "fclib-scenes": fclib_scenes,
    "preconditioners": preconditioners,
    "multigrid": multigrid,
    "kanno-series": kanno_series,
    "kanno-variants": kanno_variants,
    "two-bodies": two_bodies,
    "nearly-incompressible-lame": lame_elastic,
    "nearly-incompressible-example2": example2_newton,
    "suite-time": suite_time,
    "stiffness-contrast": stiffness_contrast,
}
