#!/usr/bin/env bash
# Restart after adaptive increments: Cattaneo-Mindlin in 3D
# (parameters/cattaneo_3d.prm) on a mesh adapted in every increment, run
# once without interruption; run again, killed once two increments are in
# its statistics (the checkpoint of the first is then whole; the second's
# may be half-written, the row is written before it), and resumed on 2
# MPI ranks. The resumed run must end where
# the uninterrupted one did: the same contact nodes (the same adapted mesh)
# with the same displacements and reactions, and the same forces. The
# stick zone of the uninterrupted run is checked against Mindlin's
# (check_analytic.py cattaneo).
# usage: restart_adaptive.sh <contact> <source dir> <python3>
set -u
if [ $# -ne 3 ]; then
  sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'
  [ "${1:-}" = "--help" ] && exit 0 || exit 2
fi
contact=$1; source_dir=$2; python=$3
fail() { echo "*** $1"; exit 1; }
rm -rf out-whole out-killed
for name in whole killed; do
  cat > $name.prm <<EOT
include $source_dir/parameters/cattaneo_3d.prm
set Output directory = out-$name
subsection Mesh refinement
  set Local refinements = 2
  set Refinement radius = 0.3
  set Strategy = kelly and contact state
  set Refine fraction = 0.1
  set Cycles = 1
end
include $source_dir/tests/tables_instead_of_vtu.prm
EOT
done
printf "include killed.prm\nset Resume computation = true\n" > resume.prm

# The uninterrupted run and the run that is killed, side by side (the test
# holds two processors for the resumed run on 2 ranks).
"$contact" whole.prm > whole.log 2>&1 &
whole=$!
"$source_dir/tests/kill_when.sh" 2 out-killed/statistics killed.log "$contact" killed.prm \
  || fail "could not kill the run"
wait $whole || { cat whole.log; fail "the uninterrupted run failed"; }
grep -q "mesh refinement 1" whole.log || fail "the mesh was not adapted"
"$python" "$source_dir/tests/check_analytic.py" cattaneo out-whole --rows 2-3 \
  || fail "the stick zone on the adapted mesh is not Mindlin's"
mpirun -np 2 "$contact" resume.prm > resume.log 2>&1 || { cat resume.log; fail "resuming failed"; }
grep "Resuming after increment" resume.log || fail "the run did not resume"

# Displacements and reactions to 1e-6 of their largest values (the solver
# tolerance 1e-10 times a condition number), at the same nodes.
"$python" "$source_dir/tests/compare_csv.py" out-whole/contact-00003.csv \
  out-killed/contact-00003.csv --keys x,y,z --columns ux,uy,uz,rn,rt1,rt2 \
  --tolerance 1e-6 || fail "the contact nodes or their results differ"
"$python" "$source_dir/tests/check_statistics.py" out-killed/statistics --rows 1-3 \
  --same-as out-whole/statistics "Normal contact force" --tolerance 1e-6 \
  || fail "the forces differ"
echo "the resumed run ends on the same adapted mesh where the uninterrupted one does"
