#!/usr/bin/env python3
"""A new user's first hour, timed: clones the repository's last commit
into a new folder (a clean clone: no build, no output) and runs there the
two commands of README.md's "Quick start", one after the other, as a new
user copies them (the packages are taken as installed: apt-get's part is
not timed). Prints each command's wall time against its goal (150 s for
the first, 600 s for the second, on 2 cores) and writes
doc/benchmarks/first-hour.csv, whose numbers README.md quotes. A suite
that ran to its end with failed tests is timed too; its row says how many
failed (in a clone, the tests of README's quotes fail until this CSV is
committed).

--alone also times the second command in a clone of its own (it builds
the program too, as it does when a user runs it first).

usage: bench/first_hour.py [--alone] [--keep]
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from doc_tables import replace_rows, write_tables  # noqa: E402
from runs import print_row  # noqa: E402

# The two commands as README.md shows them (tests/check_docs.py checks
# that it does, and .ci/run runs the second).
COMMANDS = ["scripts/setup.sh && build/contact parameters/example1.prm",
            "scripts/setup.sh --tests && ctest --test-dir build --output-on-failure -j 2"]
GOALS_S = [150, 600]
COLUMNS = ["command", "after", "seconds", "goal_s", "tests", "failed", "commit"]
CSV = os.path.join(ROOT, "doc", "benchmarks", "first-hour.csv")


def commit():
    return subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT,
                          capture_output=True, text=True).stdout.strip()


def clone(folder):
    subprocess.run(["git", "clone", "--quiet", ROOT, folder], check=True)


def timed(command, folder):
    """Runs @p command in @p folder; returns its wall time and output."""
    start = time.monotonic()
    done = subprocess.run(["bash", "-c", command], cwd=folder, capture_output=True,
                          text=True)
    seconds = time.monotonic() - start
    output = done.stdout + done.stderr
    if done.returncode != 0 and not failed_tests(output):
        sys.exit(f"'{command}' failed in {folder}:\n{output[-3000:]}")
    return seconds, output


def tests_run(output):
    found = re.findall(r"tests passed, \d+ tests failed out of (\d+)", output)
    return found[-1] if found else ""


def failed_tests(output):
    """The tests that failed (a command that ran the suite to its end is
    timed, and its row says how many failed)."""
    found = re.findall(r"tests passed, (\d+) tests failed out of", output)
    return int(found[-1]) if found else 0


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    parser.add_argument("--alone", action="store_true")
    parser.add_argument("--keep", action="store_true", help="keep the clones")
    args = parser.parse_args()
    rows = []
    folder = tempfile.mkdtemp(prefix="first-hour-")
    try:
        clone(folder)
        for index, command in enumerate(COMMANDS):
            seconds, output = timed(command, folder)
            rows.append(dict(command=index + 1, after="" if index == 0 else "1",
                             seconds=round(seconds), goal_s=GOALS_S[index],
                             tests=tests_run(output), failed=failed_tests(output),
                             commit=commit()))
            print_row(rows[-1], COLUMNS)
        if args.alone:
            alone = tempfile.mkdtemp(prefix="first-hour-alone-")
            clone(alone)
            seconds, output = timed(COMMANDS[1], alone)
            rows.append(dict(command=2, after="", seconds=round(seconds),
                             goal_s=GOALS_S[1], tests=tests_run(output),
                             failed=failed_tests(output), commit=commit()))
            print_row(rows[-1], COLUMNS)
            if not args.keep:
                shutil.rmtree(alone, ignore_errors=True)
    finally:
        if not args.keep:
            shutil.rmtree(folder, ignore_errors=True)
    replace_rows(CSV, COLUMNS, rows)
    for line in write_tables():
        print("updated " + line)


if __name__ == "__main__":
    main()
