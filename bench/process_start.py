#!/usr/bin/env python3
"""The start of a process of the program: the wall and CPU time of
`contact --help` (the libraries loaded and bound, MPI initialised, every
parameter declared), which every run and every test pays before it
solves anything. Runs the given programs alternately, the median of
--repeat runs each, in the environment of the tests (one process, no
Open MPI daemon), and appends a row per program to
doc/benchmarks/process-start.csv.

Compare the build's program with one linked in the linker's own library
order (a build configured with -DFRICTIONAL_CONTACT_LOADER_ORDER=OFF,
cmake/loader_order.cmake):
  bench/process_start.py --against other-build/contact
With --bindings it also checks, under the system's BLAS and under
LD_LIBRARY_PATH=--other-blas, that every symbol binds to the same
definition in both programs but where all are weak (LD_DEBUG=bindings,
nm), and fails naming those that do not.

usage: bench/process_start.py [--program build/contact] [--against PROGRAM]
                              [--repeat 20] [--csv FILE] [--bindings]
                              [--other-blas DIRS]
"""
import argparse
import functools
import glob
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from doc_tables import append_rows, write_tables  # noqa: E402
from runs import ENVIRONMENT, print_row  # noqa: E402
sys.path.insert(0, os.path.join(ROOT, "cmake"))
import loader_order  # noqa: E402

COLUMNS = ["program", "needed_libraries", "repeat", "wall_s", "cpu_s", "commit"]
# As the tests run the program (tests/CMakeLists.txt): no daemon for a
# process started without mpirun.
START_ENVIRONMENT = dict(ENVIRONMENT, OMPI_MCA_ess_singleton_isolated="1")


def needed_libraries(program):
    """How many libraries the program names itself (readelf)."""
    dynamic = subprocess.run(["readelf", "-d", program], capture_output=True,
                             text=True).stdout
    return dynamic.count("(NEEDED)")


def start(program):
    """One start: (wall, CPU of the child) in seconds."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    begin = time.perf_counter()
    subprocess.run([program, "--help"], stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, env=START_ENVIRONMENT, check=True)
    wall = time.perf_counter() - begin
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def bindings(program, library_path):
    """{(the binding object, symbol): the object it binds to} of a start,
    the program itself named "the program" on both sides."""
    def name(path):
        return "the program" if path == program else path

    pattern = re.compile(r"binding file (\S+) \[0\] to (\S+) \[0\]: "
                         r"normal symbol `([^'@]+)")
    with tempfile.TemporaryDirectory() as folder:
        environment = dict(START_ENVIRONMENT, LD_DEBUG="bindings",
                           LD_DEBUG_OUTPUT=os.path.join(folder, "bindings"))
        if library_path:
            environment["LD_LIBRARY_PATH"] = library_path
        subprocess.run([program, "--help"], stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, env=environment, check=True)
        log = max(glob.glob(os.path.join(folder, "bindings*")), key=os.path.getsize)
        with open(log) as f:
            return {(name(source), symbol): name(target) for source, target, symbol in
                    (m.groups() for m in map(pattern.search, f) if m)}


@functools.lru_cache(maxsize=None)
def weak_definitions(library):
    """{symbol: defined weakly?} of @p library (cmake/loader_order.py)."""
    return loader_order.definitions(library)


def moved_bindings(program, against, library_path):
    """The symbols bound to another definition in @p program than in
    @p against where one of the two is not weak."""
    mine, theirs = bindings(program, library_path), bindings(against, library_path)

    def weak(target, own, symbol):
        return weak_definitions(own if target == "the program" else target).get(symbol, False)
    moved = []
    for (source, symbol), target in mine.items():
        other = theirs.get((source, symbol), target)
        if other != target and not (weak(target, program, symbol) and
                                    weak(other, against, symbol)):
            moved.append(f"{symbol}: {other} -> {target}")
    return len(mine), moved


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog=__doc__)
    parser.add_argument("--program", default=os.path.join(ROOT, "build", "contact"))
    parser.add_argument("--against", help="a second program, started alternately")
    parser.add_argument("--repeat", type=int, default=20)
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks",
                                                      "process-start.csv"))
    parser.add_argument("--bindings", action="store_true",
                        help="also compare what every symbol binds to (needs --against)")
    parser.add_argument("--other-blas", default="/usr/lib/x86_64-linux-gnu/blas:"
                        "/usr/lib/x86_64-linux-gnu/lapack",
                        help="LD_LIBRARY_PATH of the other BLAS for --bindings")
    args = parser.parse_args()
    if args.bindings and not args.against:
        parser.error("--bindings compares two programs: give --against")
    programs = [os.path.abspath(p) for p in [args.program, args.against] if p]
    for p in programs:
        if not os.access(p, os.X_OK):
            sys.exit(f"{p}: no such program; build it first (scripts/setup.sh)")
    times = {p: [] for p in programs}
    for _ in range(args.repeat):
        for p in programs:
            times[p].append(start(p))
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    rows = []
    for p in programs:
        row = {"program": os.path.relpath(p, ROOT) if p.startswith(ROOT) else p,
               "needed_libraries": needed_libraries(p), "repeat": args.repeat,
               "wall_s": round(statistics.median(t[0] for t in times[p]), 3),
               "cpu_s": round(statistics.median(t[1] for t in times[p]), 3),
               "commit": commit}
        print_row(row, COLUMNS)
        rows.append(row)
    append_rows(args.csv, COLUMNS, rows)
    write_tables()
    if args.bindings:
        failed = False
        for blas, path in (("the system's BLAS", ""), ("the other BLAS", args.other_blas)):
            count, moved = moved_bindings(programs[0], programs[1], path)
            print(f"bindings under {blas}: {count}, moved to another non-weak "
                  f"definition: {len(moved)}")
            for line in moved[:20]:
                print("  " + line)
            failed = failed or bool(moved)
        if failed:
            sys.exit("the two programs bind some symbols to different code")


if __name__ == "__main__":
    main()
