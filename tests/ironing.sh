#!/usr/bin/env bash
# The ironing scene (parameters/ironing_2d.prm: a rigid cylinder pressed into
# a neo-Hookean block at finite strain and slid along it) on cells of 0.5,
# on 2 ranks, frictionless and with mu = 0.3 (tests/check_ironing.py):
# the nodes that press on the die lie on its surface and no vertex inside it,
# mirrored forces at mirrored die positions without friction, full slip and
# the cone with friction.
# usage: ironing.sh <contact> <source dir> <python3>
set -u
if [ $# -ne 3 ]; then
  sed -n '2,7p' "$0" | sed 's/^# \{0,1\}//'
  [ "${1:-}" = "--help" ] && exit 0 || exit 2
fi
contact=$1; source_dir=$2; python=$3
fail() { echo "*** $1"; exit 1; }
for mu in 0 0.3; do
  rm -rf out-$mu
  cat > mu-$mu.prm <<EOT
include $source_dir/parameters/ironing_2d.prm
set Output directory = out-$mu
subsection Geometry
  subsection Box
    set X repetitions = 18
    set Y repetitions = 6
  end
end
subsection Mesh refinement
  set Global refinements = 0
end
subsection Contact
  set Friction coefficient = $mu
end
include $source_dir/tests/tables_instead_of_vtu.prm
EOT
  mpirun -np 2 "$contact" mu-$mu.prm > mu-$mu.log 2>&1 || { cat mu-$mu.log; fail "the run with mu = $mu failed"; }
done
"$python" "$source_dir/tests/check_ironing.py" out-0 out-0.3 --mu 0.3 || fail "the ironing checks failed"
