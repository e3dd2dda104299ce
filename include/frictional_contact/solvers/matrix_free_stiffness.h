#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <frictional_contact/solvers/elasticity_operator.h>
#include <frictional_contact/solvers/stiffness_operator.h>

#include <memory>

namespace FrictionalContact
{
  /**
   * K without assembling it: the ElasticityOperator in double on the active
   * mesh, with the body's constraints (hanging nodes, held boundaries),
   * applied to Trilinos vectors through copies of their locally owned
   * entries. The row of a constrained dof is the identity times the mean of
   * K's diagonal, as the assembled K's hold a diagonal entry of that size
   * only. Owns the MatrixFree data, the operator and two work vectors.
   */
  template <int dim>
  class MatrixFreeStiffness : public StiffnessOperator
  {
  public:
    /// Collective.
    MatrixFreeStiffness(const DoFHandler<dim>           &dof_handler,
                        const AffineConstraints<double> &constraints,
                        const LameParameters            &lame);

    void
    vmult(Vector &dst, const Vector &src) const override;

    double
    diag_element(const types::global_dof_index i) const override;

    std::vector<FullMatrix<double>>
    blocks(const std::vector<std::vector<types::global_dof_index>> &nodes) const override;

    IndexSet
    locally_owned_domain_indices() const override
    {
      return owned_dofs;
    }

    MPI_Comm
    get_mpi_communicator() const override
    {
      return dof_handler.get_communicator();
    }

    bool
    is_assembled() const override
    {
      return false;
    }

    const TrilinosWrappers::SparseMatrix &
    matrix(const std::string &purpose) const override;

  private:
    using LocalVector = LinearAlgebra::distributed::Vector<double>;

    const DoFHandler<dim>                       &dof_handler;
    IndexSet                                     owned_dofs;
    std::shared_ptr<MatrixFree<dim, double>>     storage;
    ElasticityOperator<dim, double>              K;
    /// Local indices of the locally owned constrained dofs.
    std::vector<unsigned int>                    constrained;
    double                                       constrained_diagonal = 1;
    mutable LocalVector                          src_copy, dst_copy;
  };
} // namespace FrictionalContact
