#!/usr/bin/env bash
# Runs one test command (under mpirun -np N if N > 0) in the current folder,
# keeps its screen output in 'output', normalises it and compares it with
# the expected output by numdiff. Exits non-zero if the command fails or the
# outputs differ.
# usage: run_test.sh <N> <expected output> <numdiff> <command> [arguments]
set -u
ranks=$1; expected=$2; numdiff=$3; shift 3

if [ "$ranks" -gt 0 ]; then
  mpirun -np "$ranks" "$@" > output.raw 2>&1
else
  "$@" > output.raw 2>&1
fi
status=$?

# Versions, timings and TimerOutput tables vary from machine to machine.
grep -v -E '^(--|\||\+)' output.raw > output

if [ $status -ne 0 ]; then
  echo "*** the command failed with exit code $status:"; cat output.raw
  exit 1
fi
if grep -q -i -w -E -e '-?(nan|inf)' output; then
  echo "*** the output contains NaN or Inf:"; grep -i -w -E -e '-?(nan|inf)' output
  exit 1
fi
if [ "${FRICTIONAL_CONTACT_UPDATE_OUTPUT:-0}" = 1 ]; then
  cp output "$expected"; echo "updated $expected"; exit 0
fi
if ! "$numdiff" -q -a 1e-10 -r 1e-6 -s ' \t\n:<>=,;()/%' output "$expected" > /dev/null; then
  echo "*** output differs from $expected:"
  "$numdiff" -a 1e-10 -r 1e-6 -s ' \t\n:<>=,;()/%' output "$expected"
  exit 1
fi
echo "output matches $expected"
