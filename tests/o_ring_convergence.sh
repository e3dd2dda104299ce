#!/usr/bin/env bash
# The O-ring (parameters/o_ring_2d.prm, neo-Hookean at finite strain,
# squeezed by 25 %) on 2, 3 and 4 levels of global refinement: the contact
# force at the end converges with the mesh. Each refinement changes it less
# than half as much as the one before, and the last by less than 0.1 %.
# usage: o_ring_convergence.sh <contact> <source dir> <python3>
set -u
if [ $# -ne 3 ]; then
  sed -n '2,6p' "$0" | sed 's/^# \{0,1\}//'
  [ "${1:-}" = "--help" ] && exit 0 || exit 2
fi
contact=$1; source_dir=$2; python=$3
fail() { echo "*** $1"; exit 1; }
for level in 2 3 4; do
  rm -rf out-$level
  cat > level-$level.prm <<EOT
include $source_dir/parameters/o_ring_2d.prm
set Output directory = out-$level
subsection Mesh refinement
  set Global refinements = $level
end
subsection Postprocess
  subsection Visualization
    set Write vtu = false
  end
end
EOT
  "$contact" level-$level.prm > level-$level.log 2>&1 || { cat level-$level.log; fail "the run on $level levels failed"; }
done
"$python" - "$source_dir/tests" <<'PY' || fail "the O-ring's force does not converge with the mesh"
import sys
sys.path.insert(0, sys.argv[1])
from check_analytic import read_statistics
forces = [read_statistics(f"out-{level}/statistics")[-1]["Normal contact force"]
          for level in (2, 3, 4)]
changes = [abs(forces[1] - forces[0]), abs(forces[2] - forces[1])]
print("contact force at 2, 3, 4 levels: " + ", ".join(f"{f:.8g}" for f in forces)
      + f"; changes {changes[0]:.3g}, {changes[1]:.3g} (ratio {changes[0] / changes[1]:.2f})")
sys.exit(0 if changes[1] < changes[0] / 2 and changes[1] < 1e-3 * forces[2] else 1)
PY
echo "the force converges with the mesh"
