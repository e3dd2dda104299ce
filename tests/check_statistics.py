#!/usr/bin/env python3
"""Checks relations between the columns of a statistics file.

usage: check_statistics.py statistics --rows FIRST-LAST
           --ratio "numerator column" "denominator column" VALUE [--tolerance 1e-6]
       check_statistics.py statistics --rows FIRST-LAST
           --same-as OTHER_STATISTICS "column" [--tolerance 0.1]
       check_statistics.py statistics --rows FIRST-LAST --at-most "column" VALUE
       check_statistics.py statistics --rows 1-1 --same-columns OTHER_STATISTICS
       check_statistics.py statistics --rows FIRST-LAST --between "column" LOW HIGH
       check_statistics.py statistics --rows FIRST-LAST
           --total-at-most-times OTHER_STATISTICS "column" FACTOR
Passes if numerator / denominator = VALUE within the relative tolerance on
every row of the range (rows counted from 1, as the increments); or if the
column equals that of the other file within the relative tolerance; or if
the column is at most VALUE on every row of the range; or if both files
have the same columns in the same order (a 2D and a 3D run, say); or if
the column's sum over the rows is at most FACTOR times the other file's
(the Newton steps of a run against those of a reference run).
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
    parser.add_argument("--ratio", nargs=3)
    parser.add_argument("--ratio-between", nargs=4,
                        metavar=("NUMERATOR", "DENOMINATOR", "LOW", "HIGH"),
                        help="numerator / denominator in [LOW, HIGH)")
    parser.add_argument("--same-as", nargs=2)
    parser.add_argument("--at-most", nargs=2, metavar=("COLUMN", "VALUE"))
    parser.add_argument("--same-columns")
    parser.add_argument("--between", nargs=3, metavar=("COLUMN", "LOW", "HIGH"))
    parser.add_argument("--total-at-most-times", nargs=3,
                        metavar=("OTHER_STATISTICS", "COLUMN", "FACTOR"))
    parser.add_argument("--tolerance", type=float, default=1e-6)
    args = parser.parse_args()

    columns, rows = read_statistics(args.statistics)
    first, last = (int(x) for x in args.rows.split("-"))
    if args.same_as:
        other_columns, other_rows = read_statistics(args.same_as[0])
        column = args.same_as[1]
        ok = len(rows) >= last and len(other_rows) >= last
        for row, other in zip(rows[first - 1:last], other_rows[first - 1:last]):
            a, b = float(row[columns[column]]), float(other[other_columns[column]])
            error = abs(a - b) / max(abs(b), 1e-300)
            passed = error <= args.tolerance
            ok = ok and passed
            print(f"increment {row[0]}: {column} {a:g} against {b:g} "
                  f"(relative difference {error:.1e}, {'ok' if passed else 'ABOVE'} "
                  f"{args.tolerance:g})")
        print("PASSED" if ok else "FAILED")
        return 0 if ok else 1
    if args.total_at_most_times:
        other_path, column, factor = args.total_at_most_times
        other_columns, other_rows = read_statistics(other_path)
        ok = len(rows) >= last and len(other_rows) >= last
        total = sum(float(row[columns[column]]) for row in rows[first - 1:last])
        reference = sum(float(row[other_columns[column]]) for row in other_rows[first - 1:last])
        ok = ok and total <= float(factor) * reference
        print(f"{column}, increments {first} to {last}: {total:g} against {reference:g} "
              f"of {other_path} ({total / max(reference, 1e-300):.2f} times; "
              f"{'at most' if ok else 'ABOVE'} {float(factor):g})")
        print("PASSED" if ok else "FAILED")
        return 0 if ok else 1
    if args.same_columns:
        other, _ = read_statistics(args.same_columns)
        order = sorted(columns, key=columns.get)
        other_order = sorted(other, key=other.get)
        ok = order == other_order and len(order) > 0
        for a, b in zip(order, other_order):
            print(f"{a!r} {'==' if a == b else '!='} {b!r}")
        if len(order) != len(other_order):
            print(f"{len(order)} columns against {len(other_order)}")
        print("PASSED" if ok else "FAILED")
        return 0 if ok else 1
    if args.between or args.at_most:
        # --at-most COLUMN VALUE is --between COLUMN -inf VALUE.
        column, low, high = (args.between if args.between else
                             [args.at_most[0], "-inf", args.at_most[1]])
        low, high = float(low), float(high)
        ok = len(rows) >= last
        for row in rows[first - 1:last]:
            value = float(row[columns[column]])
            passed = low <= value <= high
            ok = ok and passed
            print(f"increment {row[0]}: {column} {value:.6g} "
                  f"({'in' if passed else 'NOT in'} [{low:g}, {high:g}])")
        print("PASSED" if ok else "FAILED")
        return 0 if ok else 1
    if args.ratio_between:
        numerator, denominator, low, high = args.ratio_between
        ok = len(rows) >= last
        for row in rows[first - 1:last]:
            ratio = float(row[columns[numerator]]) / float(row[columns[denominator]])
            passed = float(low) <= ratio < float(high)
            ok = ok and passed
            print(f"increment {row[0]}: {numerator} / {denominator} = {ratio:.10f} "
                  f"({'in' if passed else 'NOT in'} [{low}, {high}))")
        print("PASSED" if ok else "FAILED")
        return 0 if ok else 1
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
