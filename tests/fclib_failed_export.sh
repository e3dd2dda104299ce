#!/bin/bash
# An increment whose solve fails is still exported (doc/fclib.md), without
# a solution, so that other solvers can try it: the run exits with code 2,
# the file is a complete FCLIB problem (the program reads it back), and
# --evaluate says it has no solution. Then the export is made to fail
# (its temporary file cannot be created): the run says so, and the file of
# the first run is left as it was.
#
# usage: fclib_failed_export.sh <contact> <project source folder>
set -u
if [ $# -ne 2 ] || [ "$1" = "--help" ]; then
  sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'
  [ $# -eq 1 ] && exit 0 || exit 2
fi
contact=$1
cat > failed_export.prm <<EOT
include $2/parameters/example1.prm
set Output directory = output-failed
subsection Contact solver
  subsection Accelerated primal-dual
    set Maximum iterations = 10
  end
end
subsection Postprocess
  subsection Visualization
    set Write vtu = false
  end
  subsection FCLIB export
    set Increments = 1
  end
end
EOT
rm -rf output-failed
"$contact" failed_export.prm > run.log 2>&1; code=$?
cat run.log
[ $code -eq 2 ] || { echo "FAILED: the run should fail with code 2, not $code"; exit 1; }
file=output-failed/fclib-00001.hdf5
[ -f "$file" ] || { echo "FAILED: $file was not written"; exit 1; }
ls output-failed | grep -q '\.part$\|\.tmp$' && { echo "FAILED: a temporary file was left"; exit 1; }
"$contact" --fclib "$file" --evaluate "$file" > evaluate.log 2>&1; code=$?
cat evaluate.log
[ $code -eq 1 ] && grep -q "^Error: .*has no solution" evaluate.log \
  || { echo "FAILED: the exported problem should have no solution"; exit 1; }
"$contact" --fclib "$file" > solve.log 2>&1 \
  || { cat solve.log; echo "FAILED: the exported problem does not solve"; exit 1; }
grep "FCLIB result" solve.log

# A write that fails never replaces a complete file with a partial one.
cp "$file" first.hdf5
mkdir -p "$file.part/blocked"
"$contact" failed_export.prm > rerun.log 2>&1; code=$?
rm -rf "$file.part"
grep "^Error" rerun.log
[ $code -ne 0 ] && grep -q "cannot write the FCLIB file" rerun.log \
  || { echo "FAILED: the failed write should be reported (exit code $code)"; exit 1; }
cmp -s "$file" first.hdf5 \
  || { echo "FAILED: the failed write changed $file"; exit 1; }
echo "PASSED: the failed increment was exported without a solution, and solves; a failed write left the file as it was"
