// The operator x -> (A + S) x of the spring tests (spring_amg,
// mortar_preconditioner): A anything with vmult on Trilinos vectors (the
// assembled K, a StiffnessOperator), S a sum of blocks on this rank's dofs;
// and the preconditioned CG iterations those tests count.
#pragma once

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/solvers/nodal_block.h>

#include <vector>

template <typename Matrix>
class WithSprings
{
public:
  using Vector = dealii::TrilinosWrappers::MPI::Vector;

  WithSprings(const Matrix &A, const std::vector<FrictionalContact::NodalBlock> &springs)
    : A(A)
    , springs(springs)
  {}

  void
  vmult(Vector &dst, const Vector &src) const
  {
    A.vmult(dst, src);
    for (const FrictionalContact::NodalBlock &block : springs)
      {
        const unsigned int n = block.dofs.size();
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int b = 0; b < n; ++b)
            dst[block.dofs[a]] += block.values[a * n + b] * src[block.dofs[b]];
      }
  }

private:
  const Matrix                                     &A;
  const std::vector<FrictionalContact::NodalBlock> &springs;
};


/// Preconditioned CG iterations from zero to reduce |b| by @p reduction,
/// for b = A x.
template <typename Operator, typename Preconditioner>
unsigned int
cg_iterations(const Operator                              &A,
              const Preconditioner                        &M,
              const dealii::TrilinosWrappers::MPI::Vector &x,
              const double                                 reduction)
{
  dealii::TrilinosWrappers::MPI::Vector b(x), solution(x);
  A.vmult(b, x);
  solution = 0;
  dealii::SolverControl                                control(1000, reduction * b.l2_norm());
  dealii::SolverCG<dealii::TrilinosWrappers::MPI::Vector> cg(control);
  cg.solve(A, solution, b, M);
  return control.last_step();
}
