#!/usr/bin/env bash
# Restart test: run the press-and-drag history once without interruption;
# run it again and kill it (SIGKILL, from outside, at whatever it is doing
# then, a checkpoint write included) once 4 increments are in its
# statistics; resume it on 2 MPI ranks and kill that once 12 are; resume it
# on 3 ranks to the end. The resumed run must end where the uninterrupted
# one did (statistics and contact tables). Then the checkpoint is damaged
# and the scene changed, and resuming must refuse both.
# usage: restart.sh <contact> <source dir> <python3>
set -u
contact=$1; source_dir=$2; python=$3
rm -rf out-whole out-killed
for name in whole killed; do
  cat > $name.prm <<EOT
include $source_dir/parameters/press_and_drag.prm
set Output directory = out-$name
subsection Postprocess
  subsection Visualization
    set Write vtu every = 5
    set Write csv tables = true
  end
end
EOT
done
printf "include killed.prm\nset Resume computation = true\n" > resume.prm

fail() { echo "*** $1"; exit 1; }
# kill_when <rows> <ranks> <scene>: kills the run once <rows> increments
# are in its statistics.
kill_when() {
  local launcher=()
  [ "$2" -gt 1 ] && launcher=(mpirun -np "$2")
  "$source_dir/tests/kill_when.sh" "$1" out-killed/statistics "killed-$1.log" \
    "${launcher[@]}" "$contact" "$3" || fail "could not kill the run on $2 rank(s)"
}

# The uninterrupted run beside the first killed one (both on 1 rank).
"$contact" whole.prm > whole.log 2>&1 &
whole=$!
kill_when 4 1 killed.prm
wait $whole || { cat whole.log; fail "the uninterrupted run failed"; }
kill_when 12 2 resume.prm
grep -q "Resuming after increment" killed-12.log || { cat killed-12.log; fail "the first resume did not resume"; }
mpirun -np 3 "$contact" resume.prm > resume.log 2>&1 || { cat resume.log; fail "resuming failed"; }
grep "Resuming after increment" resume.log || fail "the run did not resume"

# The same statistics (compare_runs.py says within what).
"$python" "$source_dir/tests/compare_runs.py" out-whole/statistics out-killed/statistics 20 \
  || fail "the statistics differ"
"$python" "$source_dir/tests/compare_csv.py" out-whole/contact-00019.csv \
  out-killed/contact-00019.csv --keys x --columns ux,uy,rn,rt1 --states state \
  || fail "the contact states differ"
"$python" "$source_dir/tests/compare_csv.py" out-whole/displacement-00019.csv \
  out-killed/displacement-00019.csv --keys x,y --columns ux,uy || fail "the displacements differ"
# solution.pvd lists the VTU files of increments 5 and 10, 15, 20, written
# before and after the restart.
[ "$(grep -c DataSet out-killed/solution.pvd)" -eq 4 ] || fail "solution.pvd does not list 4 increments"
echo "the resumed run ends where the uninterrupted one does"

# A finished run's checkpoint is of its last increment: nothing to resume.
# (mpirun forwards standard output and error apart: the error is read alone.)
mpirun -np 2 "$contact" resume.prm > finished.log 2> finished.err; code=$?
grep -q "^Error: .*is of the last increment (20 of 20): the run is complete" finished.err \
  && [ $code -eq 1 ] || { cat finished.log finished.err; fail "resuming a finished run (exit code $code)"; }
# Resume computation = auto finds that checkpoint too, and a finished
# history is nothing to do (a requeued batch job ends without a failure).
printf "include killed.prm\nset Resume computation = auto\n" > auto.prm
for ranks in 1 2; do
  mpirun -np $ranks "$contact" auto.prm > auto.log 2> auto.err; code=$?
  grep -q "^Resume computation = auto: the loading history is complete (increment 20 of 20 .*): nothing to do" auto.log \
    && [ $code -eq 0 ] && [ ! -s auto.err ] \
    || { cat auto.log auto.err; fail "Resume computation = auto on a finished run (exit code $code, $ranks rank(s))"; }
done

# The checkpoint refuses another scene, naming the entries that differ.
printf "include resume.prm\nsubsection Contact\n  set Friction coefficient = 0.3\nend\n" > other.prm
"$contact" other.prm > other.log 2>&1; code=$?
grep -q "^Error: .*written for another scene: <Contact/Friction coefficient> was '0.5', is '0.3'" other.log \
  && [ $code -eq 1 ] || { cat other.log; fail "resuming another scene was not refused"; }
# A checkpoint of an older program lacks the entries added since: one at
# its default matches (a new entry keeps the results of before at its
# default; the finished run is then found), one set otherwise is named.
cp -r out-killed/checkpoint saved
sed -i '/^  set Hard increment iterations/d' out-killed/checkpoint/manifest
"$contact" resume.prm > older.log 2>&1; code=$?
grep -q "^Error: .*is of the last increment (20 of 20)" older.log && [ $code -eq 1 ] \
  || { cat older.log; fail "a checkpoint without a new entry at its default was refused"; }
printf "include resume.prm\nsubsection Loading\n  set Hard increment iterations = 7\nend\n" > newer.prm
"$contact" newer.prm > newer.log 2>&1; code=$?
grep -q "^Error: .*written for another scene: <Loading/Hard increment iterations> was '(not there)', is '7'" newer.log \
  && [ $code -eq 1 ] || { cat newer.log; fail "a new entry set otherwise than its default was not named"; }
rm -rf out-killed/checkpoint; mv saved out-killed/checkpoint

# ... and a damaged file, on 1 and 2 ranks, with the same line.
for file in mesh_fixed.data mesh state; do
  cp -r out-killed/checkpoint saved
  size=$(stat -c %s out-killed/checkpoint/$file)
  truncate -s $((size / 2)) out-killed/checkpoint/$file
  for ranks in 1 2; do
    mpirun -np $ranks "$contact" resume.prm > damaged.log 2> damaged.err; code=$?
    grep -q "^Error: .*has a damaged file '$file'" damaged.err && [ $code -eq 1 ] \
      && [ "$(cat damaged.log damaged.err | grep -c '^Error')" -eq 1 ] \
      || { cat damaged.log damaged.err; fail "a truncated $file was not refused on $ranks rank(s)"; }
  done
  rm -rf out-killed/checkpoint; mv saved out-killed/checkpoint
done
# ... a checkpoint that lacks a file, and one of another format.
cp -r out-killed/checkpoint saved
rm out-killed/checkpoint/state
"$contact" resume.prm > missing.log 2>&1; code=$?
grep -q "^Error: .*lacks its file 'state'" missing.log && [ $code -eq 1 ] \
  || { cat missing.log; fail "a checkpoint without its state file was not refused"; }
rm -rf out-killed/checkpoint; cp -r saved out-killed/checkpoint
sed -i '1s/.*/contact checkpoint, format 1/' out-killed/checkpoint/manifest
"$contact" resume.prm > format.log 2>&1; code=$?
grep -q "^Error: .*was written in another format ('contact checkpoint, format 1'" format.log \
  && [ $code -eq 1 ] || { cat format.log; fail "a checkpoint of another format was not refused"; }
rm -rf out-killed/checkpoint; mv saved out-killed/checkpoint
echo "a checkpoint of another scene, of another format, without a file, or with truncated files is refused"
