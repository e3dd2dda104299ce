#!/usr/bin/env bash
# Increments that grow past the loading history's times (<Loading/Grow past
# increment times>) and increments halved ahead after hard ones
# (<Loading/Hard increment iterations> = 3) on the O-ring
# (parameters/o_ring_2d.prm, 2 levels, hyperelastic and frictionless: its
# end state does not depend on the path): the grown run takes fewer
# increments, the halved one more, and both end in the same state as the
# planned one, their contact pressures and displacements to 1e-6.
# usage: grown_increments.sh <contact> <source dir> <python3>
set -u
if [ $# -ne 3 ]; then
  sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'
  [ "${1:-}" = "--help" ] && exit 0 || exit 2
fi
contact=$1; source_dir=$2; python=$3
fail() { echo "*** $1"; exit 1; }
for run in planned grown halved; do
  rm -rf out-$run
  grow=false; easy=0; hard=0
  [ $run = grown ] && { grow=true; easy=10; }
  [ $run = halved ] && hard=3
  cat > $run.prm <<EOT
include $source_dir/parameters/o_ring_2d.prm
set Output directory = out-$run
subsection Mesh refinement
  set Global refinements = 2
end
subsection Loading
  set Easy increment iterations = $easy
  set Grow past increment times = $grow
  set Hard increment iterations = $hard
end
include $source_dir/tests/tables_instead_of_vtu.prm
EOT
  "$contact" $run.prm > $run.log 2>&1 || { cat $run.log; fail "the $run run failed"; }
done
planned=$(ls out-planned/contact-*.csv | tail -1)
grown=$(ls out-grown/contact-*.csv | tail -1)
n_planned=$(grep -c '^Increment ' planned.log)
n_grown=$(grep -c '^Increment ' grown.log)
n_lines=$(grep -c '^Grown past' grown.log)
echo "planned: $n_planned increments; grown: $n_grown increments ($n_lines lines 'Grown past')"
[ "$n_grown" -lt "$n_planned" ] || fail "the grown run took $n_grown increments, the planned one $n_planned"
[ "$n_lines" -gt 0 ] || fail "the grown run printed no 'Grown past' line"
"$python" "$source_dir/tests/compare_csv.py" "$planned" "$grown" --keys x,y \
  --columns ux,uy,pressure --tolerance 1e-6 || fail "the end states differ"
halved=$(ls out-halved/contact-*.csv | tail -1)
n_halved=$(grep -c '^Increment ' halved.log)
n_lines=$(grep -c '^Halved ahead' halved.log)
echo "halved: $n_halved increments ($n_lines lines 'Halved ahead')"
[ "$n_halved" -gt "$n_planned" ] || fail "the halved run took $n_halved increments, the planned one $n_planned"
[ "$n_lines" -gt 0 ] || fail "the halved run printed no 'Halved ahead' line"
"$python" "$source_dir/tests/compare_csv.py" "$planned" "$halved" --keys x,y \
  --columns ux,uy,pressure --tolerance 1e-6 || fail "the halved end state differs"
