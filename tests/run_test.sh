#!/usr/bin/env bash
# Runs one test command (under mpirun -np N if N > 0) in the current folder
# and keeps its screen output: 'output.raw' as printed, 'output' without the
# lines that hold versions and timings (starting with "--", "|" or "+").
# Fails if the command fails or prints NaN or Inf. Comparing 'output' with
# the expected output is a test of its own (compare_output.py), so that the
# checks that read the run's files do not hang on the screen's wording.
#
# usage: run_test.sh run <N> <command> [arguments]
#        run_test.sh other-blas <N> <expected output> <command> [arguments]
#
# 'other-blas' runs the command with the BLAS and LAPACK that are installed
# but that it would not load otherwise (reference BLAS or OpenBLAS, chosen
# through LD_LIBRARY_PATH) and compares the output with the expected
# output; it exits 77 (skipped) where only one BLAS is installed.
set -u
mode=$1; ranks=$2; shift 2
expected=""
if [ "$mode" = other-blas ]; then expected=$1; shift; fi

if [ "$mode" = other-blas ]; then
  library_dir=""
  for d in /usr/lib/*-linux-gnu; do
    [ -e "$d/libblas.so.3" ] && library_dir=$d && break
  done
  # The BLAS the command would load as things are (the system's, or the
  # one LD_LIBRARY_PATH already selects), and the other one.
  active=$(readlink -f "$(ldd "$1" | awk '$1 == "libblas.so.3" {print $3}')" 2>/dev/null)
  case "$active" in
    */openblas*) other="$library_dir/blas:$library_dir/lapack" ;;
    *) other="$library_dir/openblas-pthread" ;;
  esac
  if [ -z "$library_dir" ] || [ ! -e "${other%%:*}/libblas.so.3" ]; then
    echo "skipped: only one BLAS is installed ($active); scripts/setup.sh installs both"
    exit 77
  fi
  export LD_LIBRARY_PATH="$other${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  used=$(ldd "$1" | awk '$1 == "libblas.so.3" {print $3}')
  echo "-- BLAS: $used (without LD_LIBRARY_PATH: $active)"
  case "$used" in
    "${other%%:*}"/*) ;;
    *) echo "*** LD_LIBRARY_PATH=$other did not select the other BLAS"; exit 1 ;;
  esac
  # With the reference BLAS, OpenBLAS must not load at all: a program or
  # library that names it would bind the BLAS calls to it all the same.
  case "$other" in
    */blas:*)
      if ldd "$1" | grep -q openblas; then
        echo "*** OpenBLAS still loads with LD_LIBRARY_PATH=$other:" \
          "$(ldd "$1" | grep openblas | awk '{print $1}' | tr '\n' ' ')(named by the program or a library it loads)"
        exit 1
      fi ;;
  esac
fi

forward=()
[ -n "${LD_LIBRARY_PATH:-}" ] && forward=(-x LD_LIBRARY_PATH)
if [ "$ranks" -gt 0 ]; then
  mpirun "${forward[@]}" -np "$ranks" "$@" > output.raw 2>&1
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
if [ "$mode" = other-blas ]; then
  exec python3 "$(dirname "$0")/compare_output.py" output "$expected"
fi
echo "ran: $(wc -l < output) lines of output"
