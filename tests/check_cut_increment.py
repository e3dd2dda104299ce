#!/usr/bin/env python3
"""Checks the screen output of a run with `Loading/On failure = cut
increment` by what the policy promises, not by which increments happened to
need a cut (that moves with the last digits of the linear algebra):

  - at least one increment was cut, each cut for lack of convergence, at
    most `Maximum cuts` in a row, each cut halving the increment it names;
  - the increments that converged march in strictly increasing times to
    the end time, each numbered one more than the one before;
  - the run ends with the state at the end time, its forces in balance;
  - with a statistics file, its rows have the times of the converged
    increments (the cut times included), one row each (to the six digits
    the screen prints).

usage: check_cut_increment.py <screen output> <end time> <maximum cuts>
                              [statistics]
"""
import re
import sys

CUT = re.compile(r"^Cut in half \((\d+) of at most (\d+) cuts in a row\), now (\d+) "
                 r"increments, because increment (\d+) \(t = ([0-9.e+-]+)\): no convergence")
DONE = re.compile(r"^Increment (\d+)/(\d+), t = ([0-9.e+-]+): ")
BALANCE = re.compile(r"force balance: load \(([^)]*)\) \+ contact \(([^)]*)\) \+ "
                     r"supports \(([^)]*)\) = ([0-9.e+-]+)")


def main():
    if "--help" in sys.argv or "-h" in sys.argv:
        print(__doc__)
        return 0
    if len(sys.argv) not in (4, 5):
        print(__doc__)
        return 2
    lines = open(sys.argv[1], encoding="utf-8").read().splitlines()
    end_time, maximum_cuts = float(sys.argv[2]), int(sys.argv[3])
    problems, cuts, times = [], 0, []
    expected_number = 1
    for line in lines:
        cut = CUT.match(line)
        done = DONE.match(line)
        if cut:
            cuts += 1
            in_a_row, at_most = int(cut.group(1)), int(cut.group(2))
            if at_most != maximum_cuts or in_a_row > maximum_cuts:
                problems.append(f"cut {in_a_row} of at most {at_most}: {line}")
            if int(cut.group(4)) != expected_number:
                problems.append(f"cut names increment {cut.group(4)}, "
                                f"expected {expected_number}: {line}")
        elif done:
            number, t = int(done.group(1)), float(done.group(3))
            if number != expected_number:
                problems.append(f"increment {number}, expected {expected_number}: {line}")
            if times and t <= times[-1]:
                problems.append(f"time {t} after {times[-1]}: {line}")
            times.append(t)
            expected_number = number + 1
    if cuts == 0:
        problems.append("no increment was cut")
    if not times or abs(times[-1] - end_time) > 1e-12 * max(1.0, end_time):
        problems.append(f"the last increment ends at {times[-1] if times else None}, "
                        f"not at {end_time}")
    if f"State at t = {end_time:g}:" not in lines:
        problems.append(f"no line 'State at t = {end_time:g}:'")
    balance = [BALANCE.search(l) for l in lines if BALANCE.search(l)]
    if not balance:
        problems.append("no force balance line")
    else:
        forces = [float(x) for g in balance[-1].groups()[:3] for x in g.split(",")]
        scale = max(abs(f) for f in forces)
        if not float(balance[-1].group(4)) <= 1e-8 * scale:
            problems.append(f"forces out of balance: {balance[-1].group(0)}")
    if len(sys.argv) == 5:
        rows = [l.split() for l in open(sys.argv[4], encoding="utf-8")
                if l.strip() and not l.startswith("#")]
        recorded = [float(row[1]) for row in rows]
        if len(recorded) != len(times) or any(
                abs(a - b) > 5e-6 * abs(b) for a, b in zip(recorded, times)):
            problems.append(f"the statistics have the times {recorded}, the "
                            f"screen {times}")
    for p in problems:
        print("*** " + p)
    print(f"{cuts} cuts, {len(times)} converged increments to t = "
          f"{times[-1] if times else None}: {'FAILED' if problems else 'as the policy says'}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
