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
n_planned=$(grep -c '^Increment ' planned.log)
echo "planned: $n_planned increments"
# check <run> <-lt or -gt: its increments against the planned run's> <its line>
check() {
  local run=$1 relation=$2 line=$3
  local n=$(grep -c '^Increment ' $run.log) n_lines=$(grep -c "^$line" $run.log)
  echo "$run: $n increments ($n_lines lines '$line')"
  [ "$n" "$relation" "$n_planned" ] || fail "the $run run took $n increments, the planned one $n_planned"
  [ "$n_lines" -gt 0 ] || fail "the $run run printed no '$line' line"
  "$python" "$source_dir/tests/compare_csv.py" "$planned" "$(ls out-$run/contact-*.csv | tail -1)" \
    --keys x,y --columns ux,uy,pressure --tolerance 1e-6 || fail "the $run run's end state differs"
}
check grown -lt "Grown past"
check halved -gt "Halved ahead"
