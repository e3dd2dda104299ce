#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/model/contact_operator.h>
#include <frictional_contact/model/elastic_body.h>
#include <frictional_contact/model/mortar_basis.h>
#include <frictional_contact/solvers/contact_problem.h>
#include <frictional_contact/solvers/iterate_geometry.h>

#include <vector>

namespace FrictionalContact
{
  /**
   * The contact geometry of one increment at the Newton iterates, on the
   * model's contact operator: owns the configuration the increment starts
   * from; takes the obstacle's gaps and frames and the pairs' mortar data
   * at each iterate into the increment's problem, and where the mortar
   * rows change with them (pairs of two bodies) the change of the
   * unknowns' basis (MortarBasis). Made for an increment whose geometry
   * follows the iterates (ContactOperator::geometry_follows_iterates()).
   */
  template <int dim>
  class ContactGeometryAtIterates : public IterateGeometry<dim>
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /// The increment from @p t_start to @p t_end of @p problem (whose
    /// load is @p load), from the displacement @p start, the obstacle
    /// moving by @p obstacle_motion over it; @p mortar is the pairs'
    /// basis (null without pairs).
    ContactGeometryAtIterates(ContactOperator<dim>    &contact,
                              IncrementalProblem<dim> &problem,
                              const ElasticBody<dim>  &body,
                              MortarBasis<dim>        *mortar,
                              Vector                  &load,
                              const Vector            &start,
                              const double             t_start,
                              const double             t_end,
                              const Tensor<1, dim>    &obstacle_motion);

    /**
     * Takes the gaps and frames at the iterate (start + du) into the
     * problem and expresses @p r in the new frames: the obstacle's of the
     * candidates that follow the configuration (gaps linearised there, the
     * tangential motion obstacle_motion in the new frames), and the pairs'
     * geometry where it follows within Newton. Where the mortar rows
     * change with it, the mortar basis takes them and @p du, @p K_du and
     * the load are expressed in the new basis (the same u and forces in
     * u). Collective.
     */
    void
    follow(Vector &du, std::vector<Tensor<1, dim>> &r, Vector &K_du) override;

    bool
    turns_pair_frames() const override;

    void
    pair_frame_turns(const Vector &step, std::vector<Tensor<1, dim>> &turns) const override;

  private:
    ContactOperator<dim>    &contact;
    IncrementalProblem<dim> &problem;
    const ElasticBody<dim>  &body;
    MortarBasis<dim>        *mortar;
    Vector                  &load;
    const Vector             start;
    /// start with ghost entries, for the pairs' gaps at the start.
    Vector               start_ghosted;
    const double         t_start, t_end;
    const Tensor<1, dim> obstacle_motion;
  };
} // namespace FrictionalContact
