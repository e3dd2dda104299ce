#!/usr/bin/env bash
# Runs a command that must fail: passes if it exits with the expected code,
# prints the expected message (an extended regular expression) in a line
# starting with "Error: ", prints no stack trace and leaves the files in the
# current folder as they were. Standard error is kept apart from standard
# output (mpirun forwards the two separately, so their lines may interleave).
# usage: expect_error.sh <ranks> <exit code> <regex> <command> [arguments]
set -u
ranks=$1; expected_code=$2; regex=$3; shift 3

snapshot() { find . -type f ! -name 'output.raw' ! -name 'errors.raw' -exec md5sum {} + 2>/dev/null | sort; }
before=$(snapshot)
if [ "$ranks" -gt 0 ]; then
  mpirun -np "$ranks" "$@" > output.raw 2> errors.raw
else
  "$@" > output.raw 2> errors.raw
fi
code=$?
cat output.raw errors.raw
after=$(snapshot)

fail() { echo "*** $1"; exit 1; }
[ "$code" -eq "$expected_code" ] || fail "exit code $code, expected $expected_code"
grep -E -q "^Error: .*($regex)" errors.raw || fail "no line 'Error: ...' matching: $regex"
errors=$(cat output.raw errors.raw | grep -c '^Error: ')
[ "$errors" -eq 1 ] || fail "the error was printed $errors times, expected once"
grep -q -i -E 'stacktrace|stack trace|MPI_ABORT|Signal:' output.raw errors.raw && fail "a stack trace or abort"
[ "$before" = "$after" ] || fail "files in the run folder changed"
echo "failed as expected"
