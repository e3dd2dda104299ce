#!/usr/bin/env python3
"""Compares two CSV tables of nodal results row by row, matching rows by
their coordinates, and fails if a compared column differs by more than a
relative tolerance (max |a - b| over the rows, divided by max |a|).

usage: compare_csv.py A.csv B.csv --keys x,y --columns ux,uy[,...]
           [--rename A_name=B_name ...] [--tolerance 1e-8] [--states state]
       compare_csv.py A.csv --exact "ux=0.05*x" "uy=-0.0125*y" [--tolerance]
The second form compares columns of A with formulas of its coordinates.
"""
import argparse
import csv
import sys


def read(path, rename):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return [{rename.get(k, k): v for k, v in row.items()} for row in rows]


def compare_with_formulas(rows, args):
    ok = True
    for item in args.exact:
        column, formula = item.split("=", 1)
        exact = [eval(formula, {}, {c: float(row[c]) for c in "xyz" if c in row})
                 for row in rows]
        scale = max(abs(e) for e in exact) or 1.0
        error = max(abs(float(row[column]) - e)
                    for row, e in zip(rows, exact)) / scale
        passed = error <= args.tolerance
        ok = ok and passed
        print(f"{column} against {formula}: relative difference {error:.2e} "
              f"({'within' if passed else 'ABOVE'} {args.tolerance:g})")
    print("PASSED" if ok else "FAILED")
    return 0 if ok else 1


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("a")
    parser.add_argument("b", nargs="?")
    parser.add_argument("--keys")
    parser.add_argument("--columns")
    parser.add_argument("--exact", nargs="*", default=[],
                        help="column=formula in x, y, z")
    parser.add_argument("--rename", nargs="*", default=[],
                        help="column renames for the first file, old=new")
    parser.add_argument("--tolerance", type=float, default=1e-8)
    parser.add_argument("--scale-b", type=float, default=1.0,
                        help="multiply the compared columns of B by this")
    parser.add_argument("--key-scale-b", type=float, default=1.0,
                        help="multiply the key columns of B by this")
    parser.add_argument("--states", default=None,
                        help="a column of contact states to compare exactly")
    args = parser.parse_args()

    rename = dict(item.split("=") for item in args.rename)
    if args.exact:
        return compare_with_formulas(read(args.a, rename), args)
    a_rows, b_rows = read(args.a, rename), read(args.b, {})
    keys = args.keys.split(",")

    def key(row, scale=1.0):
        return tuple(round(scale * float(row[k]), 9) for k in keys)

    b_by_key = {key(row, args.key_scale_b): row for row in b_rows}
    if len(a_rows) != len(b_rows) or set(map(key, a_rows)) != set(b_by_key):
        print(f"FAILED: the tables hold different nodes "
              f"({len(a_rows)} rows in {args.a}, {len(b_rows)} in {args.b})")
        return 1

    ok = True
    for column in args.columns.split(","):
        scale = max(abs(float(row[column])) for row in a_rows) or 1.0
        error = max(abs(float(row[column]) -
                        args.scale_b * float(b_by_key[key(row)][column]))
                    for row in a_rows) / scale
        passed = error <= args.tolerance
        ok = ok and passed
        print(f"{column}: relative difference {error:.2e} "
              f"({'within' if passed else 'ABOVE'} {args.tolerance:g})")
    if args.states:
        aliases = {"slide": "slip"}
        differing = sum(
            aliases.get(row[args.states], row[args.states])
            != aliases.get(b_by_key[key(row)][args.states],
                           b_by_key[key(row)][args.states])
            for row in a_rows)
        print(f"{args.states}: {differing} of {len(a_rows)} nodes differ")
        ok = ok and differing == 0
    print("PASSED" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
