#!/usr/bin/env python3
"""Where the test suite's time goes: runs the suite as the README's test
command does (`ctest --test-dir build -j 2`, on a build that command's
setup made), or reads the output of such a run with --log, and sums
the tests' times by what they are, in seconds and in slot-seconds (a
test's time times the slots it holds: its PROCESSORS, at most the 2 of
-j 2), against the goal of 6 minutes of wall time.
The classes: the other BLAS (a solver test run again under the other
BLAS), the shipped scenes run on 1, 2 and 3 ranks and under the
sanitizers, the fuzz test, and everything else. Replaces
doc/benchmarks/suite-time.csv and rewrites the table of doc/performance.md
("The test suite's time").

usage: bench/suite_time.py [--build build] [--log ctest-output.txt --commit REV]
"""
import argparse
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from doc_tables import replace_rows, write_tables  # noqa: E402
from runs import ENVIRONMENT, print_row  # noqa: E402

COLUMNS = ["class", "tests", "seconds", "slot_seconds", "wall_s", "commit"]
SLOTS = 2
GOAL_S = 360
CLASSES = [("other BLAS", re.compile(r"\.other_blas$")),
           ("scenes on 1 rank", re.compile(r"^scenes/.*\.serial$")),
           ("scenes sanitized", re.compile(r"^scenes/.*\.sanitized")),
           ("scenes on 2 ranks", re.compile(r"^scenes/.*\.mpirun=2$")),
           ("scenes on 3 ranks", re.compile(r"^scenes/.*\.mpirun=3$")),
           ("fuzz", re.compile(r"^fuzz")),
           ("everything else", re.compile(r""))]
RESULT = re.compile(r"Test +#\d+: (\S+) \.*\s*\S+.*?\s([0-9.]+) sec")


def processors(build):
    """Each test's PROCESSORS, from CTest."""
    listing = subprocess.run(["ctest", "--test-dir", build, "--show-only=json-v1"],
                             capture_output=True, text=True, check=True).stdout
    found = {}
    for test in json.loads(listing)["tests"]:
        found[test["name"]] = next((int(p["value"]) for p in test.get("properties", [])
                                    if p["name"] == "PROCESSORS"), 1)
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog=__doc__)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--log", help="the output of a whole run of the suite, instead of running it")
    parser.add_argument("--commit", help="with --log: the commit that run tested")
    parser.add_argument("--csv", default=os.path.join(ROOT, "doc", "benchmarks",
                                                      "suite-time.csv"))
    args = parser.parse_args()
    # Asked before the run: CTest's listing writes its LastTest.log anew.
    slots = processors(args.build)
    if args.log:
        with open(args.log) as f:
            output = f.read()
    else:
        output = subprocess.run(["ctest", "--test-dir", args.build, "-j", str(SLOTS)],
                                capture_output=True, text=True, env=ENVIRONMENT).stdout
    times = dict((name, float(s)) for name, s in RESULT.findall(output))
    wall = re.findall(r"Total Test time \(real\) = +([0-9.]+) sec", output)
    if not times or not wall:
        sys.exit("no test results in the suite's output: is it a whole run of ctest?")
    # The run's verdict, and which tests failed (any end but a skip): their
    # times count all the same.
    print("\n".join(re.findall(r"^\d+% tests passed.*$|^\s+\d+ - \S+ \((?!Skipped|Disabled).*\)$",
                               output, re.M)))
    commit = args.commit or ("" if args.log else subprocess.run(
        ["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
        capture_output=True, text=True).stdout.strip())
    sums = {name: [0, 0., 0.] for name, _ in CLASSES}
    for test, seconds in times.items():
        name = next(name for name, pattern in CLASSES if pattern.search(test))
        sums[name][0] += 1
        sums[name][1] += seconds
        sums[name][2] += seconds * min(slots.get(test, 1), SLOTS)
    rows = [dict(zip(COLUMNS, [name, n, f"{s:.0f}", f"{slot:.0f}", "", commit]))
            for name, (n, s, slot) in sums.items()]
    rows.append(dict(zip(COLUMNS, ["all", len(times),
                                   f"{sum(v[1] for v in sums.values()):.0f}",
                                   f"{sum(v[2] for v in sums.values()):.0f}",
                                   f"{float(wall[-1]):.0f}", commit])))
    for row in rows:
        print_row(row, COLUMNS)
    print(f"goal: {GOAL_S} s of wall time with -j {SLOTS}, "
          f"at most {GOAL_S * SLOTS} slot-seconds")
    replace_rows(args.csv, COLUMNS, rows)
    for line in write_tables():
        print(line)


if __name__ == "__main__":
    main()
