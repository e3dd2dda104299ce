#!/usr/bin/env python3
"""Runs a scene as shipped, with its own output settings, on N MPI ranks
(1: without mpirun) in the current folder, and checks what it wrote: the
run must exit with 0, print no NaN or Inf, and, where its header says it
writes VTU, leave a complete set: the .pvd and every .pvtu and .vtu file
they name. A run that writes no VTU proves nothing about the one that
does.

usage: run_scene.py PROGRAM SCENE RANKS [--sanitized]

--sanitized: PROGRAM is the AddressSanitizer build; its reports fail the
run (Open MPI's own leaks are not checked).
"""
import argparse
import os
import re
import subprocess
import sys


def referenced_files(path):
    """The files a .pvd or .pvtu names, relative to its folder."""
    text = open(path, errors="replace").read()
    names = re.findall(r'(?:file|Source)="([^"]+)"', text)
    return [os.path.join(os.path.dirname(path), name) for name in names]


def check_vtu(output_directory):
    """Problems with the VTU files of a run that writes them (a list)."""
    pvd = [f for f in os.listdir(output_directory) if f.endswith(".pvd")] \
        if os.path.isdir(output_directory) else []
    if not pvd:
        return [f"{output_directory}: no .pvd file"]
    problems, checked = [], 0
    for name in pvd:
        for piece in referenced_files(os.path.join(output_directory, name)):
            if not os.path.isfile(piece):
                problems.append(f"{piece}: missing")
                continue
            if piece.endswith(".pvtu"):
                for vtu in referenced_files(piece):
                    checked += 1
                    if not os.path.isfile(vtu) or os.path.getsize(vtu) == 0:
                        problems.append(f"{vtu}: missing or empty")
    if checked == 0:
        problems.append(f"{output_directory}: the .pvd names no .vtu piece")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("program")
    parser.add_argument("scene")
    parser.add_argument("ranks", type=int)
    parser.add_argument("--sanitized", action="store_true")
    arguments = parser.parse_args()
    environment = dict(os.environ)
    if arguments.sanitized:
        environment.update(
            ASAN_OPTIONS="detect_leaks=0:detect_container_overflow=0",
            UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1")
    # One rank runs as a user runs a scene serially: without mpirun.
    command = ([] if arguments.ranks == 1 else
               ["mpirun", "-np", str(arguments.ranks)]) + \
        [arguments.program, arguments.scene]
    run = subprocess.run(command, env=environment, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True, errors="replace")
    with open("output.raw", "w") as f:
        f.write(run.stdout)
    problems = []
    if run.returncode != 0:
        problems.append(f"exit code {run.returncode}")
    if re.search(r"\b(nan|inf)\b", run.stdout, re.IGNORECASE):
        problems.append("NaN or Inf on the screen")
    if "ERROR: AddressSanitizer" in run.stdout or "runtime error:" in run.stdout:
        problems.append("a sanitizer report")
    header = re.search(r"^Output: (.*) in (\S+)/$", run.stdout, re.MULTILINE)
    if header is None:
        problems.append("no 'Output:' line in the header")
    elif "vtu" in header.group(1):
        problems += check_vtu(header.group(2))
    print(f"{' '.join(command)}: " +
          ("; ".join(problems) if problems else "ran, its files complete"))
    if problems:
        print(run.stdout[-4000:])
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
