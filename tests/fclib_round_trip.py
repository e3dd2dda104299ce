#!/usr/bin/env python3
"""The FCLIB round trip: a scene exports an increment as an FCLIB global
problem with its solution; the stored solution must pass FCLIB's error
measure, and the program, solving the file again from scratch with the
semismooth Newton method (the default), with it on the AMG path (the
parameter file of --amg) and with the accelerated primal-dual method (that
of --primal-dual), must find the same solution.

usage: fclib_round_trip.py <contact> <scene.prm> --primal-dual <file.prm>
                           --amg <file.prm> [--ranks N] [--limit 1e-8]
Runs in the current folder; the scene writes output-fclib/fclib-00001.hdf5.
"""
import argparse

from fclib_checks import DIFFERENCE, numbers, run, verdict


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("contact")
    parser.add_argument("scene")
    parser.add_argument("--primal-dual", required=True)
    parser.add_argument("--amg", required=True)
    parser.add_argument("--ranks", type=int, default=0)
    parser.add_argument("--limit", type=float, default=1e-8)
    arguments = parser.parse_args()
    contact, ranks, limit = arguments.contact, arguments.ranks, arguments.limit
    exported = "output-fclib/fclib-00001.hdf5"

    run([contact, arguments.scene], ranks)
    stored = run([contact, "--fclib", exported, "--evaluate", exported], 0)
    checks = [("FCLIB error of the exported solution",
               numbers(r"FCLIB error: (\S+)", stored)[0], limit)]
    for method, settings in [("Newton", []),
                             ("Newton with ML", [arguments.amg]),
                             ("primal-dual", [arguments.primal_dual])]:
        solution = f"imported-{method.replace(' ', '-')}.hdf5"
        imported = run([contact, "--fclib", exported, "--solution", solution]
                       + settings, ranks)
        compared = run([contact, "--fclib", exported, "--evaluate", solution,
                        "--reference", exported], 0)
        v, r = numbers(DIFFERENCE, compared)
        checks += [
            (f"FCLIB error of the imported problem's solution ({method})",
             numbers(r"FCLIB error: (\S+)", imported)[0], limit),
            (f"relative difference in v ({method})", v, limit),
            (f"relative difference in r ({method})", r, limit),
        ]
    verdict(checks)


if __name__ == "__main__":
    main()
