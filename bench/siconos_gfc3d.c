/* siconos_gfc3d: solve one FCLIB global frictional-contact problem with a
 * Siconos (numerics 4.4) gfc3d solver, for comparison with our solvers.
 *
 *   siconos_gfc3d <problem.hdf5> <solver> <tolerance> <max iterations> [<solution.hdf5>]
 *
 * Starts from r = 0, u = 0, v = 0, times gfc3d_driver only (wall clock) and
 * prints one line
 *   FCLIB result: method=siconos-<solver> converged=<0|1> iterations=<n> seconds=<t> error=<e>
 * where iterations and error are what the solver reports in
 * iparam[SICONOS_IPARAM_ITER_DONE] and dparam[SICONOS_DPARAM_RESIDU].
 * With <solution.hdf5>, that file is replaced by a copy of the problem plus
 * the solution (v, u, r), readable by fclib_read_solution.
 * Exit status: 0 if the solver ran (converged or not), 2 on bad input,
 * 1 if the solution file could not be written.
 *
 * Debian's Siconos is built without FCLIB support, so the problem is read
 * with libfclib and converted here.  libfclib uses the serial HDF5, so link
 * that one (pkg-config fclib would add the MPI flavour as well).  Build:
 *   gcc -O2 -Wall bench/siconos_gfc3d.c -o /tmp/siconos_gfc3d \
 *       -I/usr/include/siconos/numerics -I/usr/include/siconos \
 *       $(pkg-config --cflags --libs hdf5-serial) -lfclib -lsiconos_numerics -lm
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <fcntl.h>
#include <unistd.h>

#include <fclib.h>
#include <hdf5.h>

#include "Friction_cst.h"
#include "GlobalFrictionContactProblem.h"
#include "NonSmoothDrivers.h"
#include "NumericsMatrix.h"
#include "NumericsVerbose.h"
#include "SolverOptions.h"

struct solver
{
  const char *name;
  int id;
};

static const struct solver solvers[] = {
  {"NSN_AC", SICONOS_GLOBAL_FRICTION_3D_NSN_AC},
  {"ADMM", SICONOS_GLOBAL_FRICTION_3D_ADMM},
  {"NSGS_WR", SICONOS_GLOBAL_FRICTION_3D_NSGS_WR},
  {"IPM", SICONOS_GLOBAL_FRICTION_3D_IPM},
  {"VI_EG", SICONOS_GLOBAL_FRICTION_3D_VI_EG},
  {"VI_FPP", SICONOS_GLOBAL_FRICTION_3D_VI_FPP},
};
static const size_t n_solvers = sizeof solvers / sizeof solvers[0];

static void usage(void)
{
  fprintf(stderr, "usage: siconos_gfc3d <problem.hdf5> <solver> <tolerance> "
                  "<max iterations> [<solution.hdf5>]\n  solvers:");
  for (size_t k = 0; k < n_solvers; ++k)
    fprintf(stderr, " %s", solvers[k].name);
  fprintf(stderr, "\n");
}

static const struct solver *find_solver(const char *name)
{
  for (size_t k = 0; k < n_solvers; ++k)
    if (strcmp(solvers[k].name, name) == 0)
      return &solvers[k];
  return NULL;
}

/* fclib exits on HDF5 errors, so first check the file holds a global problem. */
static int has_global_problem(const char *path)
{
  if (H5Fis_hdf5(path) <= 0)
    return 0;
  hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0)
    return 0;
  int found = H5Lexists(file, "/fclib_global", H5P_DEFAULT) > 0;
  H5Fclose(file);
  return found;
}

static int in_range(int k, int size)
{
  return k >= 0 && k < size;
}

/* Triplet (nz >= 0: i = rows, p = columns), CSC (nz = -1) or CSR (nz = -2),
 * with every index inside the matrix. */
static int valid_matrix(const struct fclib_matrix *a)
{
  if (a->nz >= 0)
  {
    for (int k = 0; k < a->nz; ++k)
      if (!in_range(a->i[k], a->m) || !in_range(a->p[k], a->n))
        return 0;
    return 1;
  }
  if (a->nz != -1 && a->nz != -2)
    return 0;
  int outer = a->nz == -1 ? a->n : a->m, inner = a->nz == -1 ? a->m : a->n;
  if (a->p[0] != 0 || a->p[outer] > a->nzmax)
    return 0;
  for (int j = 0; j < outer; ++j)
    if (a->p[j + 1] < a->p[j])
      return 0;
  for (int k = 0; k < a->p[outer]; ++k)
    if (!in_range(a->i[k], inner))
      return 0;
  return 1;
}

/* Returns what is wrong with the problem, or NULL if gfc3d can solve it. */
static const char *check_problem(const struct fclib_global *p)
{
  if (p->spacedim != 3)
    return "spacedim is not 3";
  if (p->G)
    return "equality constraints (G, b) are not supported by gfc3d";
  if (p->M->m != p->M->n)
    return "M is not square";
  if (p->H->m != p->M->n)
    return "H does not have as many rows as M";
  if (p->H->n % 3 != 0)
    return "the number of columns of H is not a multiple of 3";
  if (!valid_matrix(p->M) || !valid_matrix(p->H))
    return "bad sparse storage or index out of range in M or H";
  return NULL;
}

/* FCLIB matrix (checked by valid_matrix) -> Siconos sparse matrix in
 * triplet form. */
static NumericsMatrix *to_numerics(const struct fclib_matrix *a)
{
  NumericsMatrix *A = NM_create(NM_SPARSE, a->m, a->n);
  int nnz = a->nz >= 0 ? a->nz : a->p[a->nz == -1 ? a->n : a->m];
  NM_triplet_alloc(A, nnz);
  A->matrix2->origin = NSM_TRIPLET;
  if (a->nz >= 0)
    for (int k = 0; k < a->nz; ++k)
      NM_entry(A, a->i[k], a->p[k], a->x[k]);
  else
  {
    int outer = a->nz == -1 ? a->n : a->m;
    for (int j = 0; j < outer; ++j)
      for (int k = a->p[j]; k < a->p[j + 1]; ++k)
        if (a->nz == -1)
          NM_entry(A, a->i[k], j, a->x[k]);
        else
          NM_entry(A, j, a->i[k], a->x[k]);
  }
  return A;
}

static double norm2(int n, const double *x)
{
  double s = 0.0;
  for (int k = 0; k < n; ++k)
    s += x[k] * x[k];
  return sqrt(s);
}

/* The Siconos problem shares the vectors f, w, mu with the FCLIB one. */
static GlobalFrictionContactProblem *to_siconos(struct fclib_global *p)
{
  GlobalFrictionContactProblem *g = globalFrictionContactProblem_new();
  g->dimension = 3;
  g->numberOfContacts = p->H->n / 3;
  g->M = to_numerics(p->M);
  g->H = to_numerics(p->H);
  g->q = p->f;
  g->b = p->w;
  g->mu = p->mu;
  g->norm_q = norm2(p->M->n, p->f);
  g->norm_b = norm2(p->H->n, p->w);
  return g;
}

static double now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* Runs gfc3d_driver with stdout sent to /dev/null, since IPM prints its
 * iterations there whatever the verbosity.  Returns the driver's info (0 if
 * converged) and the wall time of the call in *seconds. */
static int solve_quietly(GlobalFrictionContactProblem *problem, double *r,
                         double *u, double *v, SolverOptions *options,
                         double *seconds)
{
  fflush(stdout);
  int saved = dup(STDOUT_FILENO);
  int devnull = open("/dev/null", O_WRONLY);
  if (saved >= 0 && devnull >= 0)
    dup2(devnull, STDOUT_FILENO);
  double start = now();
  int info = gfc3d_driver(problem, r, u, v, options);
  *seconds = now() - start;
  fflush(stdout);
  if (saved >= 0 && devnull >= 0)
    dup2(saved, STDOUT_FILENO);
  if (saved >= 0)
    close(saved);
  if (devnull >= 0)
    close(devnull);
  return info;
}

/* fclib_write_solution needs a file holding the problem and no solution yet,
 * so write a fresh copy of the problem first. */
static int write_solution(struct fclib_global *p, double *v, double *u,
                          double *r, const char *path)
{
  struct fclib_solution sol = {.v = v, .u = u, .r = r, .l = NULL};
  remove(path);
  return fclib_write_global(p, path) && fclib_write_solution(&sol, path);
}

int main(int argc, char **argv)
{
  if (argc != 5 && argc != 6)
  {
    usage();
    return 2;
  }
  const char *path = argv[1];
  const struct solver *solver = find_solver(argv[2]);
  char *end_tol, *end_iter;
  double tol = strtod(argv[3], &end_tol);
  long max_iter = strtol(argv[4], &end_iter, 10);
  if (!solver)
  {
    fprintf(stderr, "siconos_gfc3d: unknown solver '%s'\n", argv[2]);
    usage();
    return 2;
  }
  if (*end_tol || !(tol > 0.0) || *end_iter || max_iter <= 0)
  {
    fprintf(stderr, "siconos_gfc3d: tolerance must be > 0 and max iterations "
                    "a positive integer\n");
    usage();
    return 2;
  }

  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  struct fclib_global *fp = has_global_problem(path) ? fclib_read_global(path) : NULL;
  if (!fp)
  {
    fprintf(stderr, "siconos_gfc3d: cannot read an FCLIB global problem from '%s'\n", path);
    return 2;
  }
  const char *bad = check_problem(fp);
  if (bad)
  {
    fprintf(stderr, "siconos_gfc3d: '%s': %s\n", path, bad);
    return 2;
  }
  GlobalFrictionContactProblem *problem = to_siconos(fp);
  int n = fp->M->n, m = fp->H->n;

  numerics_set_verbose(0);
  SolverOptions *options = solver_options_create(solver->id);
  options->iparam[SICONOS_IPARAM_MAX_ITER] = (int)max_iter;
  options->dparam[SICONOS_DPARAM_TOL] = tol;
  /* By default IPM solves the convex relaxation (no mu |u_T| term in the
   * normal velocity); ask it to update that term so it solves Coulomb's law. */
  if (solver->id == SICONOS_GLOBAL_FRICTION_3D_IPM)
    options->iparam[SICONOS_FRICTION_3D_ADMM_IPARAM_UPDATE_S] =
      SICONOS_FRICTION_3D_ADMM_UPDATE_S_YES;

  double *v = calloc(n, sizeof *v);
  double *u = calloc(m, sizeof *u);
  double *r = calloc(m, sizeof *r);
  double seconds;
  int info = solve_quietly(problem, r, u, v, options, &seconds);

  printf("FCLIB result: method=siconos-%s converged=%d iterations=%d "
         "seconds=%.6g error=%.6e\n",
         solver->name, info == 0, options->iparam[SICONOS_IPARAM_ITER_DONE],
         seconds, options->dparam[SICONOS_DPARAM_RESIDU]);
  fflush(stdout);

  if (argc == 6 && !write_solution(fp, v, u, r, argv[5]))
  {
    fprintf(stderr, "siconos_gfc3d: could not write the solution to '%s'\n", argv[5]);
    return 1;
  }
  return 0;
}
