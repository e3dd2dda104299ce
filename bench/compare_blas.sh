#!/usr/bin/env bash
# The same instances of the paper's series under OpenBLAS and under
# Debian's reference BLAS (chosen through LD_LIBRARY_PATH, so the machine
# stays as it is), for doc/machine.md: does the BLAS change speed or
# iterations? Writes doc/benchmarks/blas-<name>.csv; about 2 x 1 minute.
# usage: bench/compare_blas.sh   (from the top of the repository, after
#        scripts/setup.sh, which installs both)
set -euo pipefail
cd "$(dirname "$0")/.."
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
libraries=/usr/lib/x86_64-linux-gnu
for blas in openblas reference; do
  if [ $blas = openblas ]; then
    path=$libraries/openblas-pthread
  else
    path=$libraries/blas:$libraries/lapack
  fi
  csv=doc/benchmarks/blas-$blas.csv
  rm -f "$csv"
  echo "== $blas ($path)"
  export LD_LIBRARY_PATH=$path
  python3 bench/run_series.py --series ex1 --sizes 40 --solvers newton,primal-dual --csv "$csv"
  python3 bench/run_series.py --series ex1 --sizes 104 --solvers newton --csv "$csv"
  python3 bench/run_series.py --series ex2 --sizes 10 --solvers newton,primal-dual --csv "$csv"
  python3 bench/run_series.py --series ex2 --sizes 20 --solvers newton --csv "$csv"
done
