#!/usr/bin/env python3
"""Checks relations between the columns of a statistics file.

usage: check_statistics.py statistics --rows FIRST-LAST
           --ratio "numerator column" "denominator column" VALUE [--tolerance 1e-6]
Passes if numerator / denominator = VALUE within the relative tolerance on
every row of the range (rows counted from 1, as the increments).
"""
import argparse
import re
import sys


def read_statistics(path):
    columns, rows = {}, []
    with open(path) as f:
        for line in f:
            match = re.match(r"#\s*(\d+):\s*(.*?)\s*$", line)
            if match:
                columns[match.group(2)] = int(match.group(1)) - 1
            elif line.strip() and not line.startswith("#"):
                rows.append(line.split())
    return columns, rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("statistics")
    parser.add_argument("--rows", required=True)
    parser.add_argument("--ratio", nargs=3, required=True)
    parser.add_argument("--tolerance", type=float, default=1e-6)
    args = parser.parse_args()

    columns, rows = read_statistics(args.statistics)
    first, last = (int(x) for x in args.rows.split("-"))
    numerator, denominator, value = args.ratio
    ok = len(rows) >= last
    for row in rows[first - 1:last]:
        ratio = float(row[columns[numerator]]) / float(row[columns[denominator]])
        error = abs(ratio - float(value)) / abs(float(value))
        passed = error <= args.tolerance
        ok = ok and passed
        print(f"increment {row[0]}: {numerator} / {denominator} = {ratio:.10f} "
              f"(relative error {error:.1e}, {'ok' if passed else 'ABOVE'} "
              f"{args.tolerance:g})")
    print("PASSED" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
