#!/usr/bin/env bash
# Restart with a plastic history: step-42's indentation
# (parameters/step42_indentation.prm) pressed in two increments and lifted
# in two, the mesh adapted in every increment (the history of the
# quadrature points goes with the cells), run once without interruption;
# run again, killed once two increments are in its statistics, and resumed
# on 2 MPI ranks (the history comes back from the checkpoint, on another
# partition). The resumed run must end where the uninterrupted one did:
# the same residual impression (displacements at every vertex) and the same
# plastic strain in every cell, to 1e-6 of their largest values. With
# 'finite strain' as the fourth argument, the same at finite strain (the
# law's history is Cp^-1 and alpha there); with 'axisymmetric', the same
# for the shipped axisymmetric ball indentation (finite-strain J2, the
# hoop components in the history), killed after six of its increments.
# usage: restart_plastic.sh <contact> <source dir> <python3> [finite strain | axisymmetric]
set -u
if [ $# -lt 3 ] || [ $# -gt 4 ]; then
  sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'
  [ "${1:-}" = "--help" ] && exit 0 || exit 2
fi
contact=$1; source_dir=$2; python=$3; kinematics=${4:-small strain}
fail() { echo "*** $1"; exit 1; }
rm -rf out-whole out-killed
killed_after=2 keys=x,y,z displacements=ux,uy,uz
plastic=equivalent_plastic_strain,epxx,epyy,epzz,epxy,epxz,epyz
if [ "$kinematics" = axisymmetric ]; then
  killed_after=6 keys=x,y displacements=ux,uy
  plastic=equivalent_plastic_strain,epxx,epyy,eptt,epxy
fi
for name in whole killed; do
  if [ "$kinematics" = axisymmetric ]; then
    cat > $name.prm <<EOT
include $source_dir/parameters/ball_indentation_axisymmetric.prm
set Output directory = out-$name
include $source_dir/tests/tables_instead_of_vtu.prm
EOT
    continue
  fi
  cat > $name.prm <<EOT
include $source_dir/parameters/step42_indentation.prm
set Output directory = out-$name
subsection Geometry
  subsection Box
    set X repetitions = 6
    set Y repetitions = 6
    set Z repetitions = 6
  end
end
subsection Mesh refinement
  set Cycles = 1
  set Maximum dofs = 6000                   # refined twice, then no more
end
subsection Contact
  subsection Obstacle
    set Rigid displacement = 0; 0; -0.005 * min(t, 4 - t)
  end
end
subsection Loading
  set End time = 4
  set Number of increments = 4
end
subsection Material
  set Kinematics = $kinematics
end
include $source_dir/tests/tables_instead_of_vtu.prm
EOT
done
printf "include killed.prm\nset Resume computation = true\n" > resume.prm

"$contact" whole.prm > whole.log 2>&1 &
whole=$!
"$source_dir/tests/kill_when.sh" $killed_after out-killed/statistics killed.log "$contact" killed.prm \
  || fail "could not kill the run"
wait $whole || { cat whole.log; fail "the uninterrupted run failed"; }
[ "$kinematics" = axisymmetric ] || grep -q "mesh refinement 1" whole.log \
  || fail "the mesh was not adapted"
mpirun -np 2 "$contact" resume.prm > resume.log 2>&1 || { cat resume.log; fail "resuming failed"; }
grep "Resuming after increment" resume.log || fail "the run did not resume"

last=$(basename "$(ls out-whole/displacement-*.csv | tail -1)" .csv | sed 's/displacement-//')
"$python" "$source_dir/tests/compare_csv.py" out-whole/displacement-$last.csv \
  out-killed/displacement-$last.csv --keys $keys --columns $displacements \
  --tolerance 1e-6 || fail "the residual displacements differ"
"$python" "$source_dir/tests/compare_csv.py" out-whole/stress-$last.csv \
  out-killed/stress-$last.csv --keys $keys --columns $plastic \
  --tolerance 1e-6 || fail "the plastic strains differ"
"$python" - out-whole/stress-$last.csv <<'PY' || fail "nothing stayed plastic"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
plastic = sum(1 for r in rows if float(r["equivalent_plastic_strain"]) > 0)
print(f"{plastic} of {len(rows)} cells keep a plastic strain after unloading")
sys.exit(0 if plastic > 0 else 1)
PY
echo "the resumed run ends with the plastic history of the uninterrupted one"
