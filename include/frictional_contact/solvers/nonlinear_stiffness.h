#pragma once

#include <deal.II/base/types.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * The internal force of bodies whose laws are not linear, as the Newton
   * method sees it over one increment from the configuration u_0:
   * N(du) = f_int(u_0 + du) - f_int(u_0), which for a linear law is K du,
   * and the tangent K_T = dN/d du that the problem's StiffnessOperator then
   * applies. A law's history is read, never written: a failed iteration
   * or a cut increment starts again from the committed state.
   */
  class NonlinearStiffness
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    virtual ~NonlinearStiffness() = default;

    /// @p dst = N(@p du); with @p with_tangent, the problem's stiffness
    /// becomes the tangent at du. Collective.
    virtual void
    internal_force_change(const Vector &du, Vector &dst, const bool with_tangent) = 0;

    /// The size of the forces in the body at the last evaluation (its
    /// elements' forces, which self-equilibrated stresses keep large where
    /// f_int vanishes), which the stopping rule measures the force balance
    /// against: an increment's N(du) and load may be much smaller.
    virtual double
    force_scale() const = 0;

    /// The quadrature points that flowed plastically at the last
    /// evaluation, on all ranks.
    virtual types::global_dof_index
    plastic_points() const = 0;

    /// Whether a solve that starts away from the increment's start makes
    /// its preconditioner before it takes the tangent there, from the
    /// stiffness at the start: a plastic tangent's soft zones spoil the
    /// AMG made from it (on the step-42 scene's last mesh, started from
    /// the coarser mesh's solution, 15 times the Krylov iterations), a
    /// hyperelastic tangent's do not (the O-ring's and the ironing's
    /// Krylov iterations grew by a twentieth the other way).
    virtual bool
    preconditioner_from_start() const
    {
      return false;
    }

    /// Where the laws come nearest to failing at @p du, for the line of a
    /// solve that failed ("the smallest det F, ..., is in the cell at
    /// ..."); empty if they name no place (small strain). Collective.
    virtual std::string
    worst_place(const Vector & /*du*/)
    {
      return {};
    }
  };
} // namespace FrictionalContact
