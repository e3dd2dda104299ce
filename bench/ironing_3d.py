#!/usr/bin/env python3
"""The ironing scene in 3D with the die a rigid tool from a surface mesh
(tests/ironing_3d.prm: meshes/die_3d.obj, contact by mortar, the block of
unit width in plane strain, on 2 ranks) against the 2D scene
(parameters/ironing_2d.prm: an analytic cylinder, contact at the nodes, 1
rank) on the same cells, for cells of 0.5 and 0.25: the largest difference
of drag and press over the path (of the largest 2D press), the Newton
steps and the solves of the pair's geometry, for the 3D tool with each
<Contact/Rigid tool/Geometry at finite strain>. Rewrites
doc/benchmarks/ironing-3d.csv and the table of doc/validation.md
("Ironing").

usage: bench/ironing_3d.py [--program build/contact] [--cells 18,36]
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
from doc_tables import replace_rows, write_tables  # noqa: E402
from runs import run as run_program, print_row  # noqa: E402

COLUMNS = ["cells_along", "dimension", "tool_geometry", "ranks", "d", "increments",
           "newton_iterations",
           "geometry_solves", "largest_drag_difference", "largest_press_difference",
           "wall_s"]
# The two ways the 3D tool's pair follows the block (<Contact/Rigid
# tool/Geometry at finite strain>).
GEOMETRIES = ["fixed point", "every Newton iterate"]
NO_OUTPUT = ("subsection Postprocess\n  subsection Visualization\n"
             "    set Write vtu = false\n  end\nend\n")


def scene(dimension, along):
    """The scene file's text with `along` cells along the block."""
    if dimension == 2:
        return (f"include {ROOT}/parameters/ironing_2d.prm\n"
                "subsection Geometry\n  subsection Box\n"
                f"    set X repetitions = {along}\n    set Y repetitions = {along // 3}\n"
                "  end\nend\nsubsection Mesh refinement\n  set Global refinements = 0\nend\n")
    with open(os.path.join(ROOT, "tests", "ironing_3d.prm")) as f:
        text = f.read().replace("@PROJECT_SOURCE_DIR@", ROOT)
    return (text.replace("set X repetitions = 18", f"set X repetitions = {along}")
                .replace("set Z repetitions = 6", f"set Z repetitions = {along // 3}"))


def run(program, dimension, along, folder, geometry=""):
    ranks = 2 if dimension == 3 else 1
    with open(os.path.join(folder, "scene.prm"), "w") as f:
        f.write(scene(dimension, along) + "set Output directory = output\n" + NO_OUTPUT)
        if geometry:
            f.write("subsection Contact\n  subsection Rigid tool\n"
                    f"    set Geometry at finite strain = {geometry}\n  end\nend\n")
    output, wall = run_program([program, "scene.prm"], ranks, folder)
    statistics = read_statistics(os.path.join(folder, "output", "statistics"))
    passes = [int(n) for n in re.findall(r"contact pairs' geometry: (\d+) solve", output)]
    return dict(cells_along=along, dimension=dimension, tool_geometry=geometry, ranks=ranks,
                d=int(statistics[0]["Free dofs d"]), increments=len(statistics),
                newton_iterations=sum(int(r["Contact solver iterations"]) for r in statistics),
                geometry_solves=sum(passes) if passes else "",
                wall_s=f"{wall:.1f}"), statistics


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--program", default=os.path.join(ROOT, "build", "contact"))
    parser.add_argument("--cells", default="18,36",
                        help="cells along the block, separated by ',' (a third of them up)")
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks",
                                                      "ironing-3d.csv"))
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        for along in [int(x) for x in args.cells.split(",")]:
            folder = os.path.join(scratch, f"{along}-2")
            os.makedirs(folder)
            flat_row, flat_statistics = run(args.program, 2, along, folder)
            print(", ".join(f"{k} {flat_row.get(k, '')}" for k in COLUMNS), flush=True)
            rows.append(flat_row)
            flat = {round(r["Time"], 9): r for r in flat_statistics}
            for geometry in GEOMETRIES:
                folder = os.path.join(scratch, f"{along}-3-{geometry.replace(' ', '-')}")
                os.makedirs(folder)
                row, statistics = run(args.program, 3, along, folder, geometry)
                solid = {round(r["Time"], 9): r for r in statistics}
                times = sorted(set(flat) & set(solid))
                scale = max(abs(flat[t]["Contact force y"]) for t in times)
                drag = max(abs(solid[t]["Contact force x"] - flat[t]["Contact force x"])
                           for t in times) / scale
                press = max(abs(solid[t]["Contact force z"] - flat[t]["Contact force y"])
                            for t in times) / scale
                row.update(largest_drag_difference=f"{drag:.2e}",
                           largest_press_difference=f"{press:.2e}")
                print_row(row, COLUMNS)
                rows.append(row)
    replace_rows(args.csv, COLUMNS, rows)
    for line in write_tables():
        print(line)


if __name__ == "__main__":
    main()
