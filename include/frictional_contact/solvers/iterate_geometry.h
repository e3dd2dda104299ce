#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * The contact geometry of an increment as the Newton method sees it
   * where it follows the iterates (finite strain against a curved
   * obstacle, contact pairs at finite strain): the gaps, frames and
   * obstacle slip taken at each iterate, and where the unknowns' basis
   * changes with the geometry (mortar rows of two bodies) the iterate
   * expressed in the new basis. The solvers see only this; the driver
   * implements it on the model's contact operator.
   */
  template <int dim>
  class IterateGeometry
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    virtual ~IterateGeometry() = default;

    /**
     * Takes the geometry at the iterate @p du into the problem and
     * expresses the reactions @p r in the new frames; where the basis
     * changes, also @p du, @p K_du (N(du) for nonlinear laws) and the
     * problem's load. Collective.
     */
    virtual void
    follow(Vector &du, std::vector<Tensor<1, dim>> &r, Vector &K_du) = 0;

    /// Whether the frames of pairs of two bodies turn within Newton (the
    /// mortar rows follow the iterates): pair_frame_turns() then gives
    /// their turns, in place of ContactMap::normal_turns().
    virtual bool
    turns_pair_frames() const = 0;

    /// Each node's frame turn for a @p step, as ContactMap::normal_turns()
    /// gives it for an obstacle's frames. Collective.
    virtual void
    pair_frame_turns(const Vector &step, std::vector<Tensor<1, dim>> &turns) const = 0;
  };
} // namespace FrictionalContact
