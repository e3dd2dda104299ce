#!/usr/bin/env python3
"""Compares the statistics of a run that was stopped and resumed with those
of an uninterrupted run of the same scene: the same number of rows (the
third argument) and columns; time, load and forces to 1e-6 relative (the
solver tolerance 1e-10 times a condition number), contact-solver
iterations within max(2, 10 %) and node counts within one node (the
resumed solves may run on other rank counts), residuals below 1e-10. Wall
times and the work of rebuilding the AMG after a restart are not compared.

usage: compare_runs.py WHOLE_STATISTICS RESUMED_STATISTICS ROWS
"""
import argparse
import sys

from statistics_file import names, table
parser = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("whole")
parser.add_argument("resumed")
parser.add_argument("rows", type=int)
arguments = parser.parse_args()
a, b = table(arguments.whole), table(arguments.resumed)
column = names(arguments.whole)
same_columns = column == names(arguments.resumed)
ok = len(a) == len(b) == arguments.rows and same_columns
print(f"{len(a)} and {len(b)} rows, the same columns: {same_columns}")
def check(name, kind, limit, measure):
    global ok
    c = column[name]
    error = max(measure(p[c - 1], q[c - 1], [r[c - 1] for r in a]) for p, q in zip(a, b))
    passed = error <= limit
    ok = ok and passed
    print(f"statistics column {name} ({kind}): {error:.1e} {'ok' if passed else 'TOO LARGE'}")
relative = lambda p, q, values: abs(p - q) / max(max(map(abs, values)), 1e-300)
for name in ("Increment", "Time", "Load factor", "Contact force x", "Contact force y",
             "Contact force z"):
    check(name, "relative difference", 1e-6, relative)
check("Contact solver iterations", "iterations beyond the band", 0,
      lambda p, q, values: max(0, abs(p - q) - max(2, 0.1 * p)))
for name in ("Free nodes", "Stick nodes", "Slip nodes"):
    check(name, "nodes", 1, lambda p, q, values: abs(p - q))
for name in ("Force balance residual", "Complementarity residual", "Penetration residual"):
    check(name, "largest residual", 1e-10, lambda p, q, values: max(abs(p), abs(q)))
sys.exit(0 if ok else 1)
