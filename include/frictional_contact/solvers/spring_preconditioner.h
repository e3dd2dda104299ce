#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/solvers/nodal_block.h>

#include <vector>

namespace FrictionalContact
{
  /**
   * A preconditioner of K + S, where S is a sum of small symmetric blocks
   * on the dofs of single nodes: the stiff springs that stand for the node
   * conditions of a Newton system (ConditionPreconditioner). SpringAMG
   * builds it from ML's hierarchy of K, GeometricMultigrid puts the springs
   * on the levels of the mesh.
   */
  class SpringPreconditioner
  {
  public:
    using Vector = dealii::TrilinosWrappers::MPI::Vector;

    virtual ~SpringPreconditioner() = default;

    /// Whether it can be used (it was built).
    virtual bool
    initialized() const = 0;

    /// Makes the preconditioner for K + the sum of @p springs. Collective.
    virtual void
    set_springs(const std::vector<NodalBlock> &springs) = 0;

    /// dst = M^-1 src.
    virtual void
    vmult(Vector &dst, const Vector &src) const = 0;
  };
} // namespace FrictionalContact
