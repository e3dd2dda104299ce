#!/usr/bin/env bash
# Restart test: run the press-and-drag history once without interruption;
# run it again, killed (SIGKILL) right after the checkpoint of increment 9;
# resume it on 2 MPI ranks; the resumed run must end where the uninterrupted
# one did (statistics and contact tables).
# usage: restart.sh <contact> <source dir> <python3>
set -u
contact=$1; source_dir=$2; python=$3
rm -rf out-whole out-killed
for name in whole killed; do
  cat > $name.prm <<EOT
include $source_dir/parameters/press_and_drag.prm
set Output directory = out-$name
subsection Output
  set Write vtu every = 5
  set Write csv tables = true
end
EOT
done
printf "include killed.prm\nset Resume computation = true\n" > resume.prm

fail() { echo "*** $1"; exit 1; }
"$contact" whole.prm > whole.log 2>&1 || fail "the uninterrupted run failed"
FRICTIONAL_CONTACT_KILL_AFTER_INCREMENT=9 "$contact" killed.prm > killed.log 2>&1
code=$?
[ $code -eq 137 ] || fail "the run to be killed ended with code $code, not 137 (SIGKILL)"
rows=$(grep -c -v '^#' out-killed/statistics)
[ "$rows" -eq 9 ] || fail "the killed run's statistics hold $rows rows, expected 9"
mpirun -np 2 "$contact" resume.prm > resume.log 2>&1 || { cat resume.log; fail "resuming failed"; }
grep -q "Resuming after increment 9" resume.log || fail "the run did not resume"

# Same statistics, apart from wall times and the work of rebuilding the
# AMG after the restart: time, load, iterations, states and forces to 1e-8
# relative; the residuals (round-off, 1e-13) to 1e-10 absolute.
"$python" - out-whole/statistics out-killed/statistics <<'EOT' || fail "the statistics differ"
import sys
def table(path):
    return [[float(x) for x in l.split()] for l in open(path) if not l.startswith("#")]
a, b = table(sys.argv[1]), table(sys.argv[2])
ok = len(a) == len(b) == 20
for c in (1, 2, 3, 6, 13, 14, 15, 16, 17, 18, 10, 11, 12):
    x, y = [row[c - 1] for row in a], [row[c - 1] for row in b]
    difference = max(abs(p - q) for p, q in zip(x, y))
    relative = c not in (10, 11, 12)
    error = difference / max(max(map(abs, x)), 1e-300) if relative else difference
    passed = error <= (1e-8 if relative else 1e-10)
    ok = ok and passed
    print(f"statistics column {c}: {'relative' if relative else 'absolute'} "
          f"difference {error:.1e} {'ok' if passed else 'TOO LARGE'}")
sys.exit(0 if ok else 1)
EOT
"$python" "$source_dir/tests/compare_csv.py" out-whole/contact-00019.csv \
  out-killed/contact-00019.csv --keys x --columns ux,uy,rn,rt1 --states state \
  || fail "the contact states differ"
"$python" "$source_dir/tests/compare_csv.py" out-whole/displacement-00019.csv \
  out-killed/displacement-00019.csv --keys x,y --columns ux,uy || fail "the displacements differ"
# solution.pvd lists the VTU files of increments 5 and 10, 15, 20, written
# before and after the restart.
[ "$(grep -c DataSet out-killed/solution.pvd)" -eq 4 ] || fail "solution.pvd does not list 4 increments"
echo "the resumed run ends where the uninterrupted one does"
