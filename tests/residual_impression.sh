#!/usr/bin/env bash
# The residual impression of step-42's indentation
# (parameters/step42_indentation.prm): the ball pressed 0.01 into the cube
# and lifted off again, on 4, 8 and 16 cells per edge (global meshes, the
# B-bar element). After unloading the top face's centre keeps a permanent
# dent, which converges with the mesh: each refinement changes it less than
# the one before, and the last by less than a tenth of the dent.
# usage: residual_impression.sh <contact> <source dir> <python3>
set -u
if [ $# -ne 3 ]; then
  sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'
  [ "${1:-}" = "--help" ] && exit 0 || exit 2
fi
contact=$1; source_dir=$2; python=$3
fail() { echo "*** $1"; exit 1; }
for n in 4 8 16; do
  rm -rf out-$n
  cat > mesh-$n.prm <<EOT
include $source_dir/parameters/step42_indentation.prm
set Output directory = out-$n
subsection Geometry
  subsection Box
    set X repetitions = $n
    set Y repetitions = $n
    set Z repetitions = $n
  end
end
subsection Mesh refinement
  set Strategy = none
end
subsection Contact
  subsection Obstacle
    set Rigid displacement = 0; 0; -0.01 * min(t, 2 - t)
  end
end
subsection Loading
  set End time = 2
  set Number of increments = 2
end
include $source_dir/tests/tables_instead_of_vtu.prm
EOT
  "$contact" mesh-$n.prm > mesh-$n.log 2>&1 || { cat mesh-$n.log; fail "the run on $n cells per edge failed"; }
done
"$python" - <<'PY' || fail "the residual impression does not converge with the mesh"
import csv
dents = []
for n in (4, 8, 16):
    rows = csv.DictReader(open(f"out-{n}/displacement-00002.csv"))
    dents.append(next(float(r["uz"]) for r in rows
                      if all(abs(float(r[c]) - v) < 1e-9
                             for c, v in (("x", .5), ("y", .5), ("z", 1.)))))
changes = [abs(dents[1] - dents[0]), abs(dents[2] - dents[1])]
print("residual impression at 4, 8, 16 cells per edge: "
      + ", ".join(f"{d:.6g}" for d in dents)
      + f"; changes {changes[0]:.3g}, {changes[1]:.3g}")
ok = dents[-1] < 0 and changes[1] < changes[0] and changes[1] < 0.1 * abs(dents[-1])
raise SystemExit(0 if ok else 1)
PY
echo "the residual impression converges with the mesh"
