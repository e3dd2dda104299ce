#!/usr/bin/env python3
"""Compares a run's screen output with its expected output by what the
numbers mean, so that the verdict holds on any CPU, either BLAS and any rank
count (this replaces a digit-by-digit numdiff).

Both files must have the same lines with the same words; the numbers on
them are compared by kind, told apart by the words around them:

  Krylov iterations, AMG set-ups   ("241 Krylov iterations", "1 AMG set-ups"):
      not compared (they move with the BLAS and the rank count); they must
      be whole numbers >= 0.
  contact-solver iterations       ("10 Newton iterations",
      "316 primal-dual iterations"): within a band of
      max(2, 10 % of the expected count).
  residuals                       (after "residuals", the sum after
      "= " that closes a force balance line, and the components of that
      line no larger than ten times that sum, which are round-off):
      finite, >= 0 (the sum's parts: in magnitude) and at most
      100 times the largest residual of the same kind in the expected
      output, or the solver tolerance where that is larger. Whether each solve
      met its tolerance is the program's own verdict: a solve that did
      not exits non-zero, and run_test.sh fails on that.
  free/stick/slip counts          ("46/27/0", "(46 / 20 / 7 of 73)") and
      their percentages: within max(1, 1 % of the candidates) nodes, since
      a node on the stick/slip edge may fall either way.
  mesh sizes of an adaptive run   (the cells, d and c of a "mesh
      refinement N:" line): within max(2, 1 %), since Kelly's marking of
      cells with nearly equal estimates follows the last digits of the
      solution; and on such a run every physical number below is compared
      with rtol at least 1e-4 (the discretisation difference of a few
      cells; the physical checks of those runs measure the physics).
  everything else (forces, displacements, eigenvalues, sizes, times):
      |actual - expected| <= rtol * max(|expected|, scale of the line) plus
      one unit in the last printed digit, where rtol = max(1e-6, 1e4 *
      tolerance), the tolerance being the solver's (read from the
      "Solver:" line, 1e-10 if there is none), and the scale of the line
      the largest such number on it (so a force component of 1e-18 beside
      one of 1e-2 is compared at the size of the force); numbers smaller
      than tolerance / 100 (the zeros of round-off, e.g. the forces after
      unloading) match each other.

With FRICTIONAL_CONTACT_UPDATE_OUTPUT=1 in the environment, the output
replaces the expected output instead.

usage: compare_output.py <output> <expected output>
"""
import math
import os
import shutil
import re
import sys

NUMBER = re.compile(r"(?<![A-Za-z_0-9.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
KRYLOV = re.compile(r"^\s*(CG|GMRES|BiCGStab|linear|Krylov)\s+iterations|^\s*AMG set-ups")
CONTACT_ITERATIONS = re.compile(r"^\s*(Newton|primal-dual)\s+iterations")
MESH_REFINEMENT = re.compile(r"^\s*mesh refinement \d+:")
TOLERANCE = re.compile(r"^Solver:.*?(?:tolerance|<=)\s+([0-9.eE+-]+)")


class Number:
    def __init__(self, text, kind, residual_kind=None, candidates=None):
        self.text = text
        self.value = float(text)
        self.kind = kind
        self.residual_kind = residual_kind
        self.candidates = candidates

    def last_digit(self):
        """One unit in the last printed digit of this number."""
        mantissa, _, exponent = self.text.lower().partition("e")
        decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
        return 10.0 ** (-decimals + (int(exponent) if exponent else 0))


def split(line):
    """The words between the numbers, and the numbers, of one line."""
    words, numbers, starts, position = [], [], [], 0
    for match in NUMBER.finditer(line):
        words.append(line[position:match.start()])
        numbers.append(match.group(0))
        starts.append(match.start())
        position = match.end()
    words.append(line[position:])
    return words, numbers, starts


RESIDUAL_NAMES = ["force balance", "complementarity", "penetration"]


def classify(line):
    """The words of @p line and its numbers, each with its kind."""
    words, texts, starts = split(line)
    numbers = []
    residual_index = None
    candidates = None
    counts = re.search(r"free/stick/slip\s+(\d+)/(\d+)/(\d+)", line)
    if counts:
        candidates = sum(int(g) for g in counts.groups())
    of = re.search(r"\(\s*\d+ / \d+ / \d+ of (\d+)\)", line)
    if of:
        candidates = int(of.group(1))
    adapted_mesh = MESH_REFINEMENT.search(line)
    for i, text in enumerate(texts):
        before, after, prefix = words[i], words[i + 1], line[:starts[i]]
        if adapted_mesh and i > 0:
            numbers.append(Number(text, "mesh size"))
            continue
        if re.search(r"[Rr]esiduals:?\s*(force balance\s*)?$", before):
            residual_index = 0
        if KRYLOV.search(after):
            numbers.append(Number(text, "krylov"))
        elif CONTACT_ITERATIONS.search(after):
            numbers.append(Number(text, "iterations"))
        elif residual_index is not None and residual_index < 3 and \
                re.search(r"(^|[ ,:])\s*(force balance|complementarity|penetration)?\s*$",
                          before):
            numbers.append(Number(text, "residual", RESIDUAL_NAMES[residual_index]))
            residual_index += 1
        elif re.search(r"\)\s*=\s*$", before) and "force balance" in line:
            numbers.append(Number(text, "residual", "force sum"))
        elif candidates is not None and (
                re.search(r"free/stick/slip\s+(\d+/){0,2}$", prefix) or
                re.search(r"\((\s*\d+ /){0,2}\s*$", prefix)):
            numbers.append(Number(text, "count", candidates=candidates))
        elif candidates is not None and after.startswith("%"):
            numbers.append(Number(text, "percent", candidates=candidates))
        else:
            numbers.append(Number(text, "physical"))
        if residual_index is not None and residual_index >= 3:
            residual_index = None
    # A force balance line's components no larger than its imbalance are
    # round-off (a body whose forces all cancel): compared as the sum is.
    sums = [n.value for n in numbers if n.residual_kind == "force sum"]
    if sums:
        for n in numbers:
            if n.kind == "physical" and abs(n.value) <= 10 * abs(sums[0]):
                n.kind, n.residual_kind = "residual", "force sum"
    return words, numbers


def solver_tolerance(lines):
    for line in lines:
        match = TOLERANCE.search(line)
        if match:
            try:
                return float(match.group(1))
            except ValueError:
                pass
    return 1e-10


def check_number(actual, expected, rtol, line_scale, residual_limits, tolerance):
    """None if @p actual matches @p expected, else why not."""
    a, e = actual.value, expected.value
    if not math.isfinite(a):
        return f"{actual.text} is not finite"
    if expected.kind == "krylov":
        return None if a >= 0 and a == int(a) else f"{actual.text} is not a count"
    if expected.kind == "iterations":
        band = max(2, math.ceil(0.1 * e))
        return None if abs(a - e) <= band else \
            f"{actual.text} iterations, expected {expected.text} +- {band}"
    if expected.kind == "residual":
        limit = max(100 * residual_limits[expected.residual_kind], tolerance)
        return None if 0 <= a <= limit or (expected.residual_kind == "force sum" and
                                           abs(a) <= limit) else \
            f"residual ({expected.residual_kind}) {actual.text} above {limit:.3g}"
    if expected.kind == "mesh size":
        band = max(2, math.ceil(0.01 * e))
        return None if abs(a - e) <= band else \
            f"{actual.text} (mesh size), expected {expected.text} +- {band}"
    if expected.kind in ("count", "percent"):
        band = max(1, round(0.01 * expected.candidates))
        if expected.kind == "percent":
            band = 100.0 * band / max(expected.candidates, 1) + expected.last_digit()
        return None if abs(a - e) <= band else \
            f"{actual.text} {'%' if expected.kind == 'percent' else 'nodes'}, " \
            f"expected {expected.text} +- {band:g}"
    allowed = rtol * max(abs(e), line_scale) + expected.last_digit() + tolerance / 100
    return None if abs(a - e) <= allowed else \
        f"{actual.text}, expected {expected.text} (allowed difference {allowed:.3g})"


def compare(output_lines, expected_lines):
    """The list of differences; empty if the outputs match."""
    tolerance = solver_tolerance(expected_lines)
    rtol = max(1e-6, 1e4 * tolerance)
    if any(MESH_REFINEMENT.search(l) for l in expected_lines):
        rtol = max(rtol, 1e-4)
    expected_parsed = [classify(l) for l in expected_lines]
    residual_limits = {}
    for _, numbers in expected_parsed:
        for n in numbers:
            if n.kind == "residual":
                residual_limits[n.residual_kind] = max(
                    residual_limits.get(n.residual_kind, 0.0), abs(n.value))
    problems = []
    if len(output_lines) != len(expected_lines):
        problems.append(f"{len(output_lines)} lines, expected {len(expected_lines)}")
    for number, (line, (words, expected)) in enumerate(
            zip(output_lines, expected_parsed), start=1):
        actual_words, actual_texts, _ = split(line)
        if [w.split() for w in actual_words] != [w.split() for w in words]:
            problems.append(f"line {number}: the words differ\n"
                            f"    output:   {line}\n    expected: {expected_lines[number - 1]}")
            continue
        physical = [abs(n.value) for n in expected if n.kind == "physical"]
        line_scale = max(physical) if physical else 0.0
        for text, e in zip(actual_texts, expected):
            why = check_number(Number(text, e.kind), e, rtol, line_scale,
                               residual_limits, tolerance)
            if why:
                problems.append(f"line {number}: {why}\n    output:   {line}\n"
                                f"    expected: {expected_lines[number - 1]}")
    return problems


def main():
    if "--help" in sys.argv or "-h" in sys.argv:
        print(__doc__)
        return 0
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    if os.environ.get("FRICTIONAL_CONTACT_UPDATE_OUTPUT") == "1":
        shutil.copyfile(sys.argv[1], sys.argv[2])
        print(f"updated {sys.argv[2]}")
        return 0
    with open(sys.argv[1], encoding="utf-8", errors="replace") as f:
        output_lines = [l.rstrip("\n") for l in f]
    with open(sys.argv[2], encoding="utf-8", errors="replace") as f:
        expected_lines = [l.rstrip("\n") for l in f]
    problems = compare(output_lines, expected_lines)
    for p in problems:
        print("*** " + p)
    if problems:
        print(f"*** {len(problems)} difference(s) from {sys.argv[2]}")
        return 1
    print(f"output matches {sys.argv[2]} (numbers compared by kind)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
