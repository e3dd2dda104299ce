"""Runs a program of a bench, on one rank or through mpirun, timed: the one
place where the benches written with nonlinear laws start a run, read
its solve time and print a result."""
import os
import re
import subprocess
import sys
import tempfile

# Parameters that make a run write its statistics into output/ and no
# VTU: what a bench reads without the cost of writing the fields.
NO_OUTPUT = """set Output directory = output
subsection Postprocess
  subsection Visualization
    set Write vtu = false
  end
end
"""

# One thread per rank, root allowed (containers), Open MPI's own
# point-to-point layer (one node: no UCX probing).
ENVIRONMENT = dict(os.environ, OMP_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_pml="ob1")


def run(command, ranks, folder, may_fail=False):
    """Runs @p command in @p folder (through mpirun on @p ranks > 1); returns
    its output (standard output and error) and its wall time in seconds.
    Exits with the end of the output if it fails, unless @p may_fail."""
    if ranks > 1:
        command = ["mpirun", "-np", str(ranks)] + command
    command = ["/usr/bin/time", "-f", "WALL %e"] + command
    done = subprocess.run(command, cwd=folder, capture_output=True, text=True,
                          env=ENVIRONMENT)
    output = done.stdout + done.stderr
    if done.returncode != 0 and not may_fail:
        sys.exit(f"{' '.join(command)} failed:\n{output[-3000:]}")
    return output, float(re.findall(r"WALL ([0-9.]+)", output)[-1])


def best_alternately(repeat, variants, run_variant, key="solve_s"):
    """Runs each of @p variants @p repeat times, one variant after the
    other (so that a slow spell of the machine hits them all), each run
    in a new folder: @p run_variant(variant, folder) returns a dict of
    results. Returns {variant: the run with the smallest @p key}."""
    best = {}
    for _ in range(repeat):
        for variant in variants:
            with tempfile.TemporaryDirectory() as folder:
                result = run_variant(variant, folder)
            if variant not in best or result[key] < best[variant][key]:
                best[variant] = result
    return best


def increment_statistics(output):
    """A run's unknowns d (on its last mesh), its increments, and the
    Newton steps and Krylov iterations of its increment lines, summed;
    with solve_s, its solve time (solve_seconds())."""
    return dict(d=int(re.findall(r"d = (\d+)", output)[-1]),
                increments=len(re.findall(r"^Increment \d+/", output, re.M)),
                newton_iterations=sum(int(n) for n in
                                      re.findall(r": (\d+) Newton iterations", output)),
                krylov_iterations=sum(int(n) for n in
                                      re.findall(r"(\d+) Krylov iterations", output)),
                solve_s=solve_seconds(output))


def chosen_scenes(parser, text, names):
    """The scene names of --scenes @p text (separated by ','), or the
    parser's error naming those not among @p names."""
    chosen = text.split(",")
    unknown = set(chosen) - set(names)
    if unknown:
        parser.error(f"no scene {', '.join(sorted(unknown))}")
    return chosen


def solve_seconds(output):
    """The solve time of a run from its output's summary line: the timer's
    Assembly, Increment start, Elastic solve and Contact solve (no set-up,
    no output; runs before 2026-11-30 had no Increment start, whose work
    was in Assembly for nonlinear laws and untimed for linear ones)."""
    summary = re.findall(r"-- summary: (.*)", output)[-1]
    sections = dict((name.strip(), float(value)) for name, value in
                    re.findall(r"([A-Za-z ]+) = ([0-9.e+-]+) s", summary))
    timed = ("Assembly", "Increment start", "Elastic solve", "Contact solve")
    return sum(sections.get(k, 0.) for k in timed)


def print_row(row, columns):
    """Prints one result of a bench as 'column value' pairs, as it comes."""
    print(", ".join(f"{k} {row.get(k, '')}" for k in columns), flush=True)
