#!/usr/bin/env python3
"""Solves an FCLIB problem from outside the project and compares the result
with Siconos' solution of the same file (stored next to it, or '-' for
none): the error measure must be below --limit and the velocities v within
--difference of Siconos' (relative, Euclidean norm).

usage: fclib_external.py <contact> <problem.hdf5> <siconos.hdf5 | ->
                         [--parameters file.prm] [--limit 1e-8]
                         [--difference 1e-6]
"""
import argparse

from fclib_checks import DIFFERENCE, numbers, run, verdict


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("contact")
    parser.add_argument("problem")
    parser.add_argument("siconos")
    parser.add_argument("--parameters")
    parser.add_argument("--limit", type=float, default=1e-8)
    parser.add_argument("--difference", type=float, default=1e-6)
    arguments = parser.parse_args()

    run([arguments.contact, "--fclib", arguments.problem, "--solution",
         "ours.hdf5"] + ([arguments.parameters] if arguments.parameters else []))
    if arguments.siconos == "-":
        output = run([arguments.contact, "--fclib", arguments.problem,
                      "--evaluate", "ours.hdf5"])
        verdict([("FCLIB error", numbers(r"FCLIB error: (\S+)", output)[0],
                  arguments.limit)])
    output = run([arguments.contact, "--fclib", arguments.problem,
                  "--evaluate", "ours.hdf5", "--reference", arguments.siconos])
    error = numbers(r"FCLIB error: (\S+)", output)[0]
    v, r = numbers(DIFFERENCE, output)
    print(f"relative difference to Siconos in r: {r:.3e} (not checked: r is "
          "not unique where contacts share a body)")
    verdict([("FCLIB error", error, arguments.limit),
             ("relative difference to Siconos in v", v, arguments.difference)])


if __name__ == "__main__":
    main()
