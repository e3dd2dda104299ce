#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/model/contact_operator.h>
#include <frictional_contact/model/contact_results.h>
#include <frictional_contact/model/elastic_body.h>

#include <string>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * Which cells to refine and coarsen between the solves of an increment,
   * as in deal.II's step-42 but for friction: by the Kelly estimate of the
   * displacement (a fixed number of cells, as GridRefinement counts them),
   * and on the contact boundary wherever the contact state changes along a
   * face (the edge of the contact zone, the stick/slip boundary). Owns the
   * subsection "Mesh refinement" and nothing of the mesh: the Model
   * refines it and carries the fields over.
   */
  template <int dim>
  class AdaptiveRefinement
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    explicit AdaptiveRefinement(ParameterHandler &prm);

    /// Whether the mesh changes at all.
    bool
    active() const
    {
      return by_kelly || by_contact_state;
    }

    /// Whether to adapt after solve number @p cycle (from 0) of increment
    /// @p increment (from 1), on a mesh of @p n_dofs dofs.
    bool
    due(const unsigned int increment,
        const unsigned int cycle,
        const double       n_dofs) const
    {
      return active() && increment % every == 0 && cycle < cycles &&
             n_dofs < dof_budget;
    }

    /**
     * Flags the cells of @p mesh (the mesh of @p body) to refine and to
     * coarsen, for the displacement @p u_ghosted and the contact states in
     * @p results. Returns whether any cell on any rank is flagged.
     */
    bool
    mark(parallel::distributed::Triangulation<dim> &mesh,
         const ElasticBody<dim>                    &body,
         const TrilinosWrappers::MPI::Vector       &u_ghosted,
         const ContactOperator<dim>                &contact,
         const ContactResults<dim>                 &results) const;

    /// "Kelly and contact state, 2 cycles every increment, ..." for the
    /// header of a run.
    std::string
    describe() const;

  private:
    /// Flags the locally owned cells whose contact face has candidates in
    /// different states (free, stick, slip).
    void
    mark_contact_state_changes(const ElasticBody<dim>     &body,
                               const ContactOperator<dim> &contact,
                               const ContactResults<dim>  &results) const;

    bool         by_kelly;
    bool         by_contact_state;
    double       refine_fraction;
    double       coarsen_fraction;
    unsigned int maximum_level;
    double       dof_budget;
    unsigned int every;
    unsigned int cycles;
  };
} // namespace FrictionalContact
