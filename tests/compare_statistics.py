#!/usr/bin/env python3
"""Compares named columns of two statistics files row by row: the largest
difference, relative to the largest magnitude of the column in the first
file, must be at most the tolerance. A column whose values stay below a
hundredth of the largest of all the named columns is compared against
that hundredth: a solve to a relative 1e-10 knows every force to about
1e-10 of the largest, so a small column (a symmetric scene's zero force,
round-off on both sides: 8e-16 apart where the largest is 6e-3) cannot
agree to 1e-8 of itself.
Both files must have the same rows.

usage: compare_statistics.py A B --columns "Contact force x" ... --tolerance 1e-3
"""
import argparse
import sys

from statistics_file import names, table
parser = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("a")
parser.add_argument("b")
parser.add_argument("--columns", nargs="+", required=True)
parser.add_argument("--tolerance", type=float, required=True)
arguments = parser.parse_args()
a, b = table(arguments.a), table(arguments.b)
column_a, column_b = names(arguments.a), names(arguments.b)
ok = len(a) == len(b) > 0
largest = max((abs(row[column_a[name] - 1]) for name in arguments.columns
               if name in column_a for row in a), default=0)
print(f"{len(a)} and {len(b)} rows")
for name in arguments.columns:
    if name not in column_a or name not in column_b:
        print(f"column {name}: missing")
        ok = False
        continue
    x = [row[column_a[name] - 1] for row in a]
    y = [row[column_b[name] - 1] for row in b]
    scale = max(max(map(abs, x)), 1e-2 * largest, 1e-300)
    error = max(abs(p - q) for p, q in zip(x, y)) / scale
    passed = error <= arguments.tolerance
    ok = ok and passed
    print(f"column {name}: largest difference {error:.2e} of its largest value "
          f"{scale:.4e}, {'ok' if passed else 'TOO LARGE'}")
sys.exit(0 if ok else 1)
