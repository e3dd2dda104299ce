#include <deal.II/base/timer.h>

#include <frictional_contact/solvers/nodal_block_matrix.h>
#include <frictional_contact/solvers/spring_amg.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_FECrsMatrix.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>
#include <Epetra_Vector.h>
#include <ml_MultiLevelPreconditioner.h>
#include <ml_epetra_utils.h>

#include <algorithm>

namespace FrictionalContact
{
  namespace
  {
    /// A view of @p v with the map @p map (the same layout).
    Epetra_Vector
    view(const Epetra_BlockMap &map, const TrilinosWrappers::MPI::Vector &v)
    {
      return Epetra_Vector(View, map, const_cast<double *>(v.begin()));
    }

    /// Copies the values of @p source into @p target (the same graph).
    void
    copy_values(const Epetra_CrsMatrix &source, Epetra_CrsMatrix &target)
    {
      for (int row = 0; row < source.NumMyRows(); ++row)
        {
          int     n_source, n_target;
          double *values, *target_values;
          source.ExtractMyRowView(row, n_source, values);
          target.ExtractMyRowView(row, n_target, target_values);
          std::copy(values, values + n_source, target_values);
        }
    }

    /// The Epetra copy of an operator of ML's hierarchy.
    std::unique_ptr<Epetra_CrsMatrix>
    to_epetra(ML_Operator *op)
    {
      Epetra_CrsMatrix *matrix = nullptr;
      ML_Operator2EpetraCrsMatrix(op, matrix);
      return std::unique_ptr<Epetra_CrsMatrix>(matrix);
    }

    /// Amesos's name of ML's direct solver of the coarsest level and the
    /// largest level it takes, as ML keeps them in @p parameters once it
    /// has read them ("coarse: list"); "" for another kind of solver.
    std::pair<std::string, int>
    coarsest_solver(const Teuchos::ParameterList &parameters)
    {
      if (!parameters.isSublist("coarse: list"))
        return {"", 0};
      Teuchos::ParameterList coarse = parameters.sublist("coarse: list");
      const std::string type = coarse.get("smoother: type", std::string());
      const int max_size     = coarse.get("smoother: max size", 0);
      if (type == "Amesos-KLU")
        return {"Amesos_Klu", max_size};
      if (type == "Amesos-MUMPS")
        return {"Amesos_Mumps", max_size};
      return {"", 0};
    }
  } // namespace



  SpringAMG::SpringAMG() = default;

  SpringAMG::~SpringAMG() = default;



  void
  SpringAMG::clear()
  {
    K = nullptr;
    fine_blocks.reset();
    coarse_solver.reset();
    direct_solver.reset();
    direct_problem.reset();
    coarse_matrix.reset();
    galerkin_matrix.reset();
    prolongator.reset();
    coarse_null_space.reset();
    coarse_residual.reset();
    coarse_correction.reset();
  }



  void
  SpringAMG::initialize(const TrilinosWrappers::SparseMatrix    &stiffness,
                        const TrilinosWrappers::PreconditionAMG &amg_of_K,
                        const std::vector<std::vector<double>>  &rigid_body_modes,
                        const unsigned int                       smoother_sweeps)
  {
    const Timer timer;
    clear();
    const auto *ml_preconditioner =
      dynamic_cast<const ML_Epetra::MultiLevelPreconditioner *>(
        &amg_of_K.trilinos_operator());
    if (ml_preconditioner == nullptr || ml_preconditioner->GetML() == nullptr)
      return;
    K      = &stiffness;
    degree = smoother_sweeps;
    Teuchos::ParameterList list =
      const_cast<ML_Epetra::MultiLevelPreconditioner *>(ml_preconditioner)
        ->GetList();
    chebyshev_ratio = list.get("smoother: Chebyshev alpha", 20.);
    ML *ml = const_cast<ML *>(ml_preconditioner->GetML());
    const bool two_levels = ml->ML_num_actual_levels >= 2;
    if (two_levels && !take_first_level(*ml_preconditioner, rigid_body_modes))
      {
        clear(); // not initialized(): the Newton method uses ML's own AMG
        return;
      }
    if (!two_levels)
      {
        // One level: ML solves K directly, and so do we with K + S.
        galerkin_matrix =
          std::make_unique<Epetra_CrsMatrix>(stiffness.trilinos_matrix());
        coarse_block_size = list.get("PDE equations", 1);
        coarse_null_space = std::make_unique<Epetra_MultiVector>(
          galerkin_matrix->RowMap(), rigid_body_modes.size());
        for (unsigned int m = 0; m < rigid_body_modes.size(); ++m)
          std::copy(rigid_body_modes[m].begin(),
                    rigid_body_modes[m].end(),
                    (*coarse_null_space)[m]);
      }
    coarse_parameters = list;
    coarse_parameters.set("ML output", 0);
    coarse_parameters.set("PDE equations", static_cast<int>(coarse_block_size));
    coarse_parameters.set("null space: type", "pre-computed");
    coarse_parameters.set("null space: dimension",
                          coarse_null_space->NumVectors());
    coarse_parameters.set("null space: vectors", coarse_null_space->Values());
    // Plain aggregation below the first level: a new S then costs half as
    // much (0.03 instead of 0.07 s at d = 52,920) for 10 % more Krylov
    // iterations (doc/performance.md).
    if (two_levels)
      coarse_parameters.set("aggregation: damping factor", 0.);

    coarse_matrix =
      std::make_unique<Epetra_FECrsMatrix>(Copy, galerkin_matrix->Graph());
    coarse_matrix->FillComplete(galerkin_matrix->DomainMap(),
                                galerkin_matrix->RangeMap());
    // ML would only factor a coarse matrix no larger than its coarsest
    // level, and its graph stays: one symbolic analysis serves every new S
    // (a third of each update's MUMPS time at d = 7,260, doc/performance.md).
    const auto [direct_name, direct_max_size] = coarsest_solver(list);
    if (!direct_name.empty() &&
        coarse_matrix->NumGlobalRows64() <= direct_max_size)
      {
        direct_problem = std::make_unique<Epetra_LinearProblem>();
        direct_problem->SetOperator(coarse_matrix.get());
        Amesos factory;
        direct_solver.reset(factory.Create(direct_name, *direct_problem));
        // MUMPS's row and column scaling (a sixth of its time here) does
        // nothing for these well-scaled symmetric positive definite levels,
        // nor does KLU's search for new pivots at each refactorization.
        Teuchos::ParameterList direct_parameters;
        direct_parameters.sublist("mumps").set("ICNTL(8)", 0);
        direct_parameters.set("Refactorize", true);
        direct_solver->SetParameters(direct_parameters);
      }

    if (two_levels)
      {
        fine_blocks = std::make_unique<NodalBlockMatrix>(
          stiffness, list.get("PDE equations", 1));
        if (fine_blocks->empty())
          fine_blocks.reset();
      }
    diagonal_of_K.reinit(stiffness.locally_owned_range_indices(),
                         stiffness.get_mpi_communicator());
    for (const auto i : stiffness.locally_owned_range_indices())
      diagonal_of_K[i] = stiffness.diag_element(i);
    diagonal_of_K.compress(VectorOperation::insert);
    inverse_diagonal.reinit(diagonal_of_K);
    residual.reinit(diagonal_of_K);
    direction.reinit(diagonal_of_K);
    scratch.reinit(diagonal_of_K);
    const Epetra_Map &coarse_map = galerkin_matrix->DomainMap();
    coarse_residual   = std::make_unique<Epetra_Vector>(coarse_map);
    coarse_correction = std::make_unique<Epetra_Vector>(coarse_map);
    setup_seconds += timer.wall_time();
    set_springs({});
  }



  bool
  SpringAMG::take_first_level(
    const ML_Epetra::MultiLevelPreconditioner &ml_preconditioner,
    const std::vector<std::vector<double>>    &rigid_body_modes)
  {
    ML                 *ml        = const_cast<ML *>(ml_preconditioner.GetML());
    const ML_Aggregate *aggregate = ml_preconditioner.GetML_Aggregate();
    if (aggregate == nullptr ||
        aggregate->P_tentative == nullptr ||
        aggregate->nullspace_dim != static_cast<int>(rigid_body_modes.size()))
      return false;
    const int fine   = ml->LevelID[0];
    const int coarse = ml->LevelID[1];
    if (aggregate->P_tentative[coarse] == nullptr)
      return false;

    prolongator     = to_epetra(&ml->Pmat[coarse]);
    galerkin_matrix = to_epetra(&ml->Amat[coarse]);
    // ML's estimate of the largest eigenvalue of D^-1 K, as its smoother
    // uses; 3 is about what it finds for Q1 elasticity.
    lambda_max = ml->Amat[fine].lambda_max > 0 ? ml->Amat[fine].lambda_max : 3.;

    // The rigid-body modes on the first coarse level: the tentative
    // prolongator reproduces them and has orthonormal columns per
    // aggregate, so they are its transpose applied to the fine modes.
    const std::unique_ptr<Epetra_CrsMatrix> tentative =
      to_epetra(aggregate->P_tentative[coarse]);
    const int          n_modes = rigid_body_modes.size();
    Epetra_MultiVector fine_modes(tentative->RangeMap(), n_modes);
    for (int m = 0; m < n_modes; ++m)
      std::copy(rigid_body_modes[m].begin(),
                rigid_body_modes[m].end(),
                fine_modes[m]);
    Epetra_MultiVector on_tentative(tentative->DomainMap(), n_modes);
    tentative->Multiply(true, fine_modes, on_tentative);
    coarse_null_space =
      std::make_unique<Epetra_MultiVector>(galerkin_matrix->RowMap(), n_modes);
    for (int m = 0; m < n_modes; ++m)
      std::copy(on_tentative[m],
                on_tentative[m] + on_tentative.MyLength(),
                (*coarse_null_space)[m]);
    coarse_block_size = n_modes;
    return true;
  }



  void
  SpringAMG::set_springs(const std::vector<NodalBlock> &springs)
  {
    Assert(initialized(), ExcInternalError());
    const Timer timer;
    set_fine_springs(springs);
    copy_values(*galerkin_matrix, *coarse_matrix);
    for (const NodalBlock &block : springs)
      add_coarse_spring(block);
    coarse_matrix->GlobalAssemble(false);
    update_coarse_solver();
    setup_seconds += timer.wall_time();
  }



  void
  SpringAMG::update_coarse_solver()
  {
    if (direct_solver)
      {
        // The first call also analyses the graph. Should a factorization
        // fail, ML's hierarchy takes over as it would without this path.
        const int error = direct_solver->NumericFactorization();
        if (Utilities::MPI::max(error != 0 ? 1 : 0,
                                K->get_mpi_communicator()) == 0)
          return;
        direct_solver.reset();
        direct_problem.reset();
      }
    coarse_solver.reset();
    coarse_solver = std::make_unique<ML_Epetra::MultiLevelPreconditioner>(
      *coarse_matrix, coarse_parameters);
  }



  void
  SpringAMG::solve_coarse(const Epetra_Vector &b, Epetra_Vector &x) const
  {
    if (!direct_solver)
      {
        coarse_solver->ApplyInverse(b, x);
        return;
      }
    direct_problem->SetRHS(const_cast<Epetra_Vector *>(&b));
    direct_problem->SetLHS(&x);
    const int error = direct_solver->Solve();
    AssertThrow(error == 0, LACExceptions::ExcTrilinosError(error));
  }



  void
  SpringAMG::set_fine_springs(const std::vector<NodalBlock> &springs)
  {
    const Epetra_Map &rows = K->trilinos_matrix().RowMap();
    spring_rows.clear();
    spring_columns.clear();
    spring_values.clear();
    inverse_diagonal = diagonal_of_K;
    for (const NodalBlock &block : springs)
      {
        const unsigned int n = block.dofs.size();
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int b = 0; b < n; ++b)
            if (block.values[a * n + b] != 0)
              {
                spring_rows.push_back(rows.LID(static_cast<int>(block.dofs[a])));
                spring_columns.push_back(
                  rows.LID(static_cast<int>(block.dofs[b])));
                spring_values.push_back(block.values[a * n + b]);
                if (a == b)
                  inverse_diagonal[block.dofs[a]] += block.values[a * n + b];
              }
      }
    for (double &d : inverse_diagonal)
      d = d != 0 ? 1. / d : 0.;
  }



  void
  SpringAMG::add_coarse_spring(const NodalBlock &block)
  {
    const unsigned int n = block.dofs.size();
    if (!prolongator)
      {
        // One level: the block itself.
        std::vector<int> columns(block.dofs.begin(), block.dofs.end());
        for (unsigned int a = 0; a < n; ++a)
          coarse_matrix->SumIntoGlobalValues(columns[a],
                                             n,
                                             &block.values[a * n],
                                             columns.data());
        return;
      }
    // P_j^T B P_j with P_j the rows of P at the block's dofs, over the
    // coarse dofs those rows touch.
    const Epetra_Map &rows = K->trilinos_matrix().RowMap();
    const Epetra_Map &coarse_columns = prolongator->ColMap();
    std::vector<int>     lengths(n);
    std::vector<double *> values(n);
    std::vector<int *>    indices(n);
    std::vector<int>      columns;
    for (unsigned int a = 0; a < n; ++a)
      {
        prolongator->ExtractMyRowView(rows.LID(static_cast<int>(block.dofs[a])),
                                      lengths[a],
                                      values[a],
                                      indices[a]);
        for (int k = 0; k < lengths[a]; ++k)
          columns.push_back(coarse_columns.GID(indices[a][k]));
      }
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
    const unsigned int  m = columns.size();
    std::vector<double> rows_of_P(n * m, 0.);
    for (unsigned int a = 0; a < n; ++a)
      for (int k = 0; k < lengths[a]; ++k)
        {
          const auto position =
            std::lower_bound(columns.begin(),
                             columns.end(),
                             coarse_columns.GID(indices[a][k])) -
            columns.begin();
          rows_of_P[a * m + position] = values[a][k];
        }
    std::vector<double> product(m * m, 0.);
    for (unsigned int a = 0; a < n; ++a)
      for (unsigned int b = 0; b < n; ++b)
        if (const double s = block.values[a * n + b]; s != 0)
          for (unsigned int i = 0; i < m; ++i)
            if (const double left = s * rows_of_P[a * m + i]; left != 0)
              for (unsigned int j = 0; j < m; ++j)
                product[i * m + j] += left * rows_of_P[b * m + j];
    for (unsigned int i = 0; i < m; ++i)
      coarse_matrix->SumIntoGlobalValues(columns[i],
                                         m,
                                         &product[i * m],
                                         columns.data());
  }



  void
  SpringAMG::apply_matrix(Vector &dst, const Vector &src) const
  {
    if (fine_blocks)
      fine_blocks->vmult(dst, src);
    else
      K->vmult(dst, src);
    const double *x = src.begin();
    double       *y = dst.begin();
    for (unsigned int k = 0; k < spring_values.size(); ++k)
      y[spring_rows[k]] += spring_values[k] * x[spring_columns[k]];
  }



  void
  SpringAMG::smooth(Vector &x, Vector &r) const
  {
    // Chebyshev iteration (Saad, Iterative Methods, Algorithm 12.1) on
    // D^-1 (K + S) over [1.1 lambda_max / ratio, 1.1 lambda_max], as ML's
    // smoother, from a zero correction: degree - 1 products with K + S.
    const double       upper = 1.1 * lambda_max;
    const double       lower = upper / chebyshev_ratio;
    const double       theta = 0.5 * (upper + lower);
    const double       delta = 0.5 * (upper - lower);
    const double       sigma = theta / delta;
    double             rho   = 1. / sigma;
    const unsigned int n     = x.locally_owned_size();
    const double      *D     = inverse_diagonal.begin();
    double            *d     = direction.begin();
    double            *xs    = x.begin();
    double            *rs    = r.begin();
    const double      *Ad    = scratch.begin();
    for (unsigned int i = 0; i < n; ++i)
      {
        d[i] = D[i] * rs[i] / theta;
        xs[i] += d[i];
      }
    for (unsigned int k = 1; k < degree; ++k)
      {
        apply_matrix(scratch, direction);
        const double rho_next = 1. / (2. * sigma - rho);
        const double a = rho_next * rho, b = 2. * rho_next / delta;
        for (unsigned int i = 0; i < n; ++i)
          {
            rs[i] -= Ad[i];
            d[i] = a * d[i] + b * D[i] * rs[i];
            xs[i] += d[i];
          }
        rho = rho_next;
      }
  }



  void
  SpringAMG::residual_of(const Vector &x, const Vector &b) const
  {
    apply_matrix(scratch, x);
    const unsigned int n  = x.locally_owned_size();
    const double      *bs = b.begin();
    const double      *Ax = scratch.begin();
    double            *rs = residual.begin();
    for (unsigned int i = 0; i < n; ++i)
      rs[i] = bs[i] - Ax[i];
  }



  void
  SpringAMG::vmult(Vector &dst, const Vector &src) const
  {
    if (!prolongator)
      {
        const Epetra_Vector b = view(coarse_matrix->RangeMap(), src);
        Epetra_Vector       x = view(coarse_matrix->DomainMap(), dst);
        solve_coarse(b, x);
        return;
      }
    // Pre-smoothing.
    dst      = 0;
    residual = src;
    smooth(dst, residual);
    // Coarse correction: P (A_1 + P^T S P)^-1 P^T (src - (K + S) dst).
    residual_of(dst, src);
    const Epetra_Vector fine_residual = view(prolongator->RangeMap(), residual);
    prolongator->Multiply(true, fine_residual, *coarse_residual);
    solve_coarse(*coarse_residual, *coarse_correction);
    Epetra_Vector fine_correction = view(prolongator->RangeMap(), scratch);
    prolongator->Multiply(false, *coarse_correction, fine_correction);
    dst += scratch;
    // Post-smoothing.
    residual_of(dst, src);
    smooth(dst, residual);
  }
} // namespace FrictionalContact
