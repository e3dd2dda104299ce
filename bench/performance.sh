#!/usr/bin/env bash
# Every figure of doc/performance.md in one run (about 25 minutes on a
# quiet 2-core machine): the semismooth Newton solver on Kanno's example II
# at every size of the paper's series, N_Y = 10, 12, ..., 28 (best of 3),
# and at N_Y = 56 and 80 (d = 1,091,664 and 3,149,280, on 2 MPI ranks;
# even sizes, so that the coarse mesh every rank holds is small), the
# solver settings at N_Y = 20 (best of 2), and 1 against 2 ranks at
# N_Y = 28 (best of 3). Each time also in units of one elastic AMG-CG solve
# of the same mesh, measured the same way. Writes, afresh,
# doc/benchmarks/scale.csv, solver-settings.csv and parallel.csv (or into
# the folder given), plots them into performance.png and prints the tables
# of doc/performance.md.
# usage: bench/performance.sh [folder]   (from the top of the repository,
#        after scripts/setup.sh; N_Y = 80 needs about 16 GB of memory)
set -euo pipefail
cd "$(dirname "$0")/.."
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
folder="${1:-doc/benchmarks}"
mkdir -p "$folder"
rm -f "$folder/scale.csv" "$folder/solver-settings.csv" "$folder/parallel.csv"
# The plots need Debian's python3-matplotlib: a python3 first on PATH
# without it (pyenv, a virtualenv) would lose them at the end of the run.
plot_python=python3
if ! python3 -c "import matplotlib" 2>/dev/null && [ -x /usr/bin/python3 ]; then
  plot_python=/usr/bin/python3
fi

echo "== how the cost grows with d"
python3 bench/run_series.py --series ex2 --solvers newton \
  --sizes 10,12,14,16,18,20,22,24,26,28 --repeat 3 \
  --csv "$folder/scale.csv"
python3 bench/run_series.py --series ex2 --solvers newton --sizes 56,80 \
  --ranks 2 --csv "$folder/scale.csv"

echo "== solver settings at N_Y = 20"
variants="default,AMG of K,fixed 0.01,fixed 0.01+AMG of K,EW 0.01,EW 0.3,EW 0.5"
variants+=",sweeps 1,sweeps 3,threshold 0,threshold 0.02,threshold 0.08"
variants+=",translations,Gauss-Seidel,damping 0,damping 0.67"
python3 bench/solver_settings.py --sizes 20 --repeat 2 --variants "$variants" \
  --csv "$folder/solver-settings.csv"

echo "== 1 against 2 ranks at N_Y = 28"
python3 bench/parallel_efficiency.py --sizes 28 --repeat 3 \
  --csv "$folder/parallel.csv"

echo "== tables and performance.png"
"$plot_python" bench/plot_performance.py "$folder"
