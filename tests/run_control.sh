#!/usr/bin/env bash
# What a batch scheduler or a user does to a run from outside (issue 34):
# - SIGUSR1 to mpirun (which forwards it, as before a Slurm time limit) on
#   2 ranks, once 2 increments are in the statistics: the run finishes the
#   increment it is in, writes its checkpoint, prints one line and exits
#   with 75; resumed with 'Resume computation = auto', it ends where an
#   uninterrupted run does;
# - SIGTERM to the ranks themselves (as srun or kill does) on 2 ranks, and
#   to the single process on 1 rank: the contact solver stops at its next
#   iteration, the last finished increment is checkpointed, exit 75, and
#   the resumed run ends where the uninterrupted one does;
# - a second run into the folder of a running one is refused with one line
#   naming the holder (exit 75), and takes the folder over once the first
#   has died (SIGKILL: no clean-up).
# usage: run_control.sh <contact> <source dir> <python3>
set -u
contact=$1; source_dir=$2; python=$3
fail() { echo "*** $1"; exit 1; }
rm -rf out-*
increments=4
# Kanno's method on example I in four increments, with slow inner solves
# (AMG-CG from du_k to 1e-6): 0.2 to 1 s each, long enough to be caught
# in the middle of a contact solve.
scene() {
  cat <<EOT
include $source_dir/parameters/example1.prm
set Output directory = out-$1
subsection Loading
  set Number of increments = $increments
end
subsection Linear solver
  set Preconditioner = amg
end
subsection Contact solver
  subsection Accelerated primal-dual
    set Primal step start = previous iterate
    set Primal step tolerance = 1e-6
  end
end
subsection Postprocess
  subsection Visualization
    set Write vtu = false
  end
end
EOT
}
rows() { if [ -f "$1" ]; then grep -c -v '^#' "$1"; else echo 0; fi; }
# wait_rows <statistics> <rows> <pid>: until the file holds that many rows.
wait_rows() {
  while kill -0 $3 2>/dev/null && [ "$(rows $1)" -lt $2 ]; do sleep 0.01; done
  kill -0 $3 2>/dev/null || fail "the run ended before the signal"
}

scene whole > whole.prm
"$contact" whole.prm > whole.log 2>&1 || { cat whole.log; fail "the uninterrupted run failed"; }

# check_stopped <name> <log> <err> <code> <signal> <ranks>
check_stopped() {
  [ "$4" -eq 75 ] || { cat "$2" "$3"; fail "$1: exit code $4, not 75"; }
  [ "$(grep -c '^Stopped: ' "$3")" -eq 1 ] && [ "$(grep -c '^Error: ' "$2" "$3" | awk -F: '{s+=$NF} END {print s}')" -eq 0 ] && grep -q "^Stopped: stopped by $5 after increment [0-9]* of $increments (t = .*), its checkpoint in 'out-$1/checkpoint': run again with 'set Resume computation = auto'" "$3" \
    || { cat "$3"; fail "$1: not the one line of a stop by $5"; }
  printf "include $1.prm\nset Resume computation = auto\n" > resume-$1.prm
  mpirun -np $6 "$contact" resume-$1.prm > resume-$1.log 2>&1 \
    || { cat resume-$1.log; fail "$1: resuming failed"; }
  grep -q "Resuming after increment" resume-$1.log || fail "$1: the run did not resume"
  "$python" "$source_dir/tests/compare_runs.py" out-whole/statistics out-$1/statistics $increments \
    || fail "$1: the resumed run does not end where the uninterrupted one does"
  echo "$1: stopped by $5 ($(head -c 90 "$3")...), resumed to the same end"
}

# SIGUSR1 to mpirun on 2 ranks.
scene usr1 > usr1.prm
mpirun -np 2 "$contact" usr1.prm > usr1.log 2> usr1.err &
pid=$!
wait_rows out-usr1/statistics 2 $pid
kill -USR1 $pid
wait $pid; check_stopped usr1 usr1.log usr1.err $? SIGUSR1 2

# SIGTERM to the 2 ranks themselves (not to mpirun).
scene term2 > term2.prm
mpirun -np 2 "$contact" term2.prm > term2.log 2> term2.err &
pid=$!
wait_rows out-term2/statistics 1 $pid
pkill -TERM -P $pid
wait $pid; check_stopped term2 term2.log term2.err $? SIGTERM 2

# SIGTERM to the one process of a run without mpirun.
scene term1 > term1.prm
"$contact" term1.prm > term1.log 2> term1.err &
pid=$!
wait_rows out-term1/statistics 2 $pid
kill -TERM $pid
wait $pid; check_stopped term1 term1.log term1.err $? SIGTERM 1

# Two runs, one folder: the second is refused while the first runs, on 1
# and 2 ranks; after the first dies (no clean-up), a third takes over. The
# first is stopped (SIGSTOP) once it has written an increment, so that it
# holds the folder however fast the machine is.
scene locked > locked.prm
"$contact" locked.prm > locked.log 2>&1 &
pid=$!
wait_rows out-locked/statistics 1 $pid
kill -STOP $pid
for ranks in 1 2; do
  mpirun -np $ranks "$contact" locked.prm > second.log 2> second.err; code=$?
  [ $code -eq 75 ] && [ "$(grep -c '^Error: ' second.err)" -eq 1 ] \
    && grep -q "^Error: the output folder 'out-locked' is in use by another run (host $(hostname), process $pid, since .*): wait until it ends" second.err \
    || { cat second.log second.err; fail "a second run into the folder of a running one ($ranks rank(s), exit code $code)"; }
done
kill -KILL $pid; wait $pid 2>/dev/null
[ -f out-locked/.lock ] || fail "the killed run left no lock file behind (the test needs one)"
printf "include locked.prm\nset Resume computation = auto\n" > takeover.prm
"$contact" takeover.prm > takeover.log 2>&1 || { cat takeover.log; fail "the folder of a dead run was not taken over"; }
[ ! -e out-locked/.lock ] || fail "the lock file outlived its run"
echo "a second run into a busy folder is refused; the folder of a dead run is taken over"
