#!/usr/bin/env python3
"""The O-ring (parameters/o_ring_2d.prm, squeezed by 25 %) nearly
incompressible: the compressible neo-Hookean law on the standard element,
and the nearly incompressible (split) neo-Hookean law on the standard
element (its volume ratio at each point: 'split, point') and on the
mean-dilatation element ('split, cell mean'), on 2, 3 and 4 levels, at each Poisson's ratio of --nu: the force at
the end, the increments and cuts the run took, its wall time. A run that
fails or takes longer than --timeout is recorded as such. Rewrites
doc/benchmarks/o-ring-locking.csv and the table of doc/validation.md
("Finite strain").

usage: bench/o_ring_locking.py [--program build/contact] [--nu 0.45,0.49]
                               [--levels 2,3,4] [--timeout 300]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "tests"))
from check_analytic import read_statistics  # noqa: E402
from doc_tables import replace_rows, write_tables  # noqa: E402
from runs import ENVIRONMENT  # noqa: E402

COLUMNS = ["nu", "law", "level", "d", "force", "increments", "cuts", "wall_s", "outcome"]
# (label, the Material entries): the compressible law on the standard
# element, the split law on the standard element (its volume ratio at each
# point) and on the mean-dilatation element (the cell's mean).
LAWS = [("neo-Hookean", "  set Model = neo-Hookean\n"),
        ("split, point", "  set Model = nearly incompressible neo-Hookean\n"
         "  subsection Nearly incompressible neo-Hookean\n"
         "    set Volume ratio = point\n  end\n"),
        ("split, cell mean", "  set Model = nearly incompressible neo-Hookean\n")]


def run(program, nu, law, level, timeout, folder):
    with open(os.path.join(folder, "scene.prm"), "w") as f:
        f.write(f"include {ROOT}/parameters/o_ring_2d.prm\n"
                "set Output directory = output\n"
                f"subsection Mesh refinement\n  set Global refinements = {level}\nend\n"
                "subsection Material\n" + dict(LAWS)[law] +
                f"  set Poisson's ratio = {nu}\nend\n"
                "subsection Postprocess\n  subsection Visualization\n"
                "    set Write vtu = false\n  end\nend\n")
    start = time.time()
    try:
        done = subprocess.run([program, "scene.prm"], cwd=folder, capture_output=True,
                              text=True, env=ENVIRONMENT, timeout=timeout)
        output, outcome = done.stdout + done.stderr, "done" if done.returncode == 0 else "failed"
    except subprocess.TimeoutExpired as expired:
        output = (expired.stdout or b"").decode() if isinstance(expired.stdout, bytes) \
            else (expired.stdout or "")
        outcome = f"stopped after {timeout} s"
    wall = time.time() - start
    rows = read_statistics(os.path.join(folder, "output", "statistics")) \
        if os.path.exists(os.path.join(folder, "output", "statistics")) else []
    finished = rows and outcome == "done"
    return dict(nu=nu, law=law, level=level,
                d=int(re.findall(r"d = (\d+)", output)[0]) if re.findall(r"d = (\d+)", output) else 0,
                force=rows[-1]["Normal contact force"] if finished else float("nan"),
                increments=len(rows), cuts=len(re.findall(r"^Cut in half", output, re.M)),
                wall_s=wall, outcome=outcome)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--program", default=os.path.join(ROOT, "build", "contact"))
    parser.add_argument("--nu", default="0.45,0.49")
    parser.add_argument("--levels", default="2,3,4")
    parser.add_argument("--timeout", type=float, default=300)
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks", "o-ring-locking.csv"))
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        for nu in args.nu.split(","):
            for law, _ in LAWS:
                for level in [int(x) for x in args.levels.split(",")]:
                    folder = os.path.join(scratch, f"{nu}-{len(rows)}")
                    os.makedirs(folder)
                    row = run(args.program, nu, law, level, args.timeout, folder)
                    print(f"nu = {nu}, {law}, {level} levels: force {row['force']:.6g}, "
                          f"{row['increments']} increments, {row['cuts']} cuts, "
                          f"{row['wall_s']:.1f} s, {row['outcome']}", flush=True)
                    rows.append(row)
    replace_rows(args.csv, COLUMNS, rows)
    for line in write_tables():
        print(line)


if __name__ == "__main__":
    main()
