#!/usr/bin/env bash
# A full disk (issue 34): press_and_drag (20 increments, a checkpoint after
# each) writes into a 600 kB tmpfs that fills up after a few increments, on
# 1 and 2 ranks. The run must end with one line naming the file and "No
# space left on device" and the last complete checkpoint, exit code 74, no
# rank waiting and no abort; once there is room again, resuming finishes
# the history where an uninterrupted run ends. Mounting a tmpfs needs root
# (as CI has); elsewhere the test says it is skipped (exit code 77).
# usage: full_disk.sh <contact> <source dir> <python3>
set -u
contact=$1; source_dir=$2; python=$3
fail() { echo "*** $1"; exit 1; }
[ "$(id -u)" -eq 0 ] || { echo "skipped: mounting a tmpfs needs root"; exit 77; }
rm -rf disk out-whole; mkdir -p disk
mount -t tmpfs -o size=600k tmpfs disk 2>/dev/null \
  || { echo "skipped: cannot mount a tmpfs here"; exit 77; }
trap 'umount disk 2>/dev/null' EXIT

scene() {
  cat <<EOT
include $source_dir/parameters/press_and_drag.prm
set Output directory = $1
subsection Postprocess
  subsection Visualization
    set Write csv tables = true
  end
end
EOT
}
scene out-whole > whole.prm
"$contact" whole.prm > whole.log 2>&1 || { cat whole.log; fail "the uninterrupted run failed"; }

for ranks in 1 2; do
  rm -rf disk/*
  mount -o remount,size=600k disk || fail "cannot shrink the tmpfs"
  scene disk/out > full.prm
  mpirun -np $ranks "$contact" full.prm > full.log 2> full.err; code=$?
  [ $code -eq 74 ] || { cat full.log full.err; fail "exit code $code on $ranks rank(s), expected 74"; }
  [ "$(grep -c '^Error: ' full.log full.err | awk -F: '{s+=$NF} END {print s}')" -eq 1 ] \
    && grep -E -q "^Error: cannot write (the checkpoint in )?'disk/out/[^']*': No space left on device.*; the last complete checkpoint \(increment [0-9]+, t = [^)]*\) in 'disk/out/checkpoint' stays valid" full.err \
    || { cat full.err; fail "not the one line of a full disk on $ranks rank(s)"; }
  grep -q -i -E 'stacktrace|stack trace|MPI_ABORT|Signal:' full.log full.err \
    && fail "a stack trace or abort on $ranks rank(s)"
  echo "$ranks rank(s): $(grep '^Error: ' full.err | head -c 150)..."
  mount -o remount,size=64m disk || fail "cannot grow the tmpfs"
  printf "include full.prm\nset Resume computation = auto\n" > resume.prm
  mpirun -np $ranks "$contact" resume.prm > resume.log 2>&1 || { cat resume.log; fail "resuming failed on $ranks rank(s)"; }
  grep -q "Resuming after increment" resume.log || fail "the run did not resume on $ranks rank(s)"
  "$python" "$source_dir/tests/compare_runs.py" out-whole/statistics disk/out/statistics 20 \
    || fail "the resumed run does not end where the uninterrupted one does ($ranks rank(s))"
done
# Without checkpoints, the results themselves (VTU files of every
# increment, their .pvd record) fill the disk: the same kind of line,
# saying that there is no checkpoint.
cat > results.prm <<EOT
include $source_dir/parameters/press_and_drag.prm
set Output directory = disk/out
subsection Output
  set Checkpoint every = 100
end
subsection Postprocess
  subsection Visualization
    set Write vtu every = 1
  end
end
EOT
for ranks in 1 2; do
  rm -rf disk/*
  mount -o remount,size=300k disk || fail "cannot shrink the tmpfs"
  mpirun -np $ranks "$contact" results.prm > results.log 2> results.err; code=$?
  [ $code -eq 74 ] && [ "$(grep -c '^Error: ' results.log results.err | awk -F: '{s+=$NF} END {print s}')" -eq 1 ] \
    && grep -E -q "^Error: cannot write 'disk/out/[^']*': No space left on device; no checkpoint was written yet" results.err \
    || { cat results.err; fail "the results filling the disk on $ranks rank(s) (exit code $code)"; }
  echo "$ranks rank(s): $(grep '^Error: ' results.err | head -c 120)..."
done
echo "a full disk ends the run with one line and exit code 74; the resumed run finishes"
