#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/numerics/error_estimator.h>

#include <frictional_contact/base/input.h>
#include <frictional_contact/model/adaptive_refinement.h>

#include <set>

namespace FrictionalContact
{
  template <int dim>
  void
  AdaptiveRefinement<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    prm.declare_entry(
      "Strategy",
      "none",
      Patterns::Selection("none|kelly|contact state|kelly and contact state"),
      "Adaptive refinement between the solves of an increment. none: the "
      "mesh of <Geometry> throughout. kelly: refine the cells with the "
      "largest Kelly estimate of the displacement (jumps of the stress "
      "across faces) and coarsen those with the smallest. contact state: "
      "refine the cells whose contact face has candidates in different "
      "states (the edge of the contact zone, the stick/slip boundary). kelly "
      "and contact state: both (the union of the cells each marks). Each "
      "refinement is followed by a new solve of the same increment from the "
      "state before it, carried over to the new mesh.");
    prm.declare_entry("Refine fraction",
                      "0.3",
                      Patterns::Double(0., 1.),
                      "kelly: the fraction of the cells to refine, those "
                      "with the largest estimates.");
    prm.declare_entry("Coarsen fraction",
                      "0.03",
                      Patterns::Double(0., 1.),
                      "kelly: the fraction of the cells to coarsen, those "
                      "with the smallest estimates.");
    prm.declare_entry("Maximum level",
                      "10",
                      Patterns::Integer(1, 20),
                      "No cell is refined beyond this level (the cells of "
                      "the geometry's coarse mesh are level 0).");
    prm.declare_entry("Maximum dofs",
                      "200000",
                      Patterns::Double(1.),
                      "The dof budget: no refinement once the mesh has this "
                      "many displacement dofs, and the Kelly marking makes "
                      "at most about this many.");
    prm.declare_entry("Refine every",
                      "1",
                      Patterns::Integer(1),
                      "Adapt the mesh after every this many increments.");
    prm.declare_entry("Cycles",
                      "2",
                      Patterns::Integer(0, 20),
                      "How often an increment is refined and solved again "
                      "(at most; the refinement stops earlier when no cell "
                      "is marked or the dof budget is reached). Each solve "
                      "on a refined mesh starts from the last mesh's "
                      "solution, its displacement and contact forces "
                      "carried over (from the increment's start where that "
                      "does not converge).");
    prm.leave_subsection();
  }



  template <int dim>
  AdaptiveRefinement<dim>::AdaptiveRefinement(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    const std::string strategy = prm.get("Strategy");
    by_kelly         = strategy.find("kelly") != std::string::npos;
    by_contact_state = strategy.find("contact state") != std::string::npos;
    refine_fraction  = prm.get_double("Refine fraction");
    coarsen_fraction = prm.get_double("Coarsen fraction");
    maximum_level    = prm.get_integer("Maximum level");
    dof_budget       = prm.get_double("Maximum dofs");
    every            = prm.get_integer("Refine every");
    cycles           = prm.get_integer("Cycles");
    prm.leave_subsection();
    if (refine_fraction + coarsen_fraction > 1)
      Input::fail("Mesh refinement/Coarsen fraction",
                  Input::to_text(coarsen_fraction),
                  "Refine fraction + Coarsen fraction must be at most 1");
  }



  template <int dim>
  bool
  AdaptiveRefinement<dim>::mark(
    parallel::distributed::Triangulation<dim> &mesh,
    const ElasticBody<dim>                    &body,
    const TrilinosWrappers::MPI::Vector       &u_ghosted,
    const ContactOperator<dim>                &contact,
    const ContactResults<dim>                 &results) const
  {
    if (by_kelly)
      {
        Vector<float> estimates(mesh.n_active_cells());
        KellyErrorEstimator<dim>::estimate(body.get_dof_handler(),
                                           QGauss<dim - 1>(2),
                                           {},
                                           u_ghosted,
                                           estimates);
        // A Q1 mesh has about one vertex, so dim dofs, per cell.
        const auto most_cells = static_cast<unsigned int>(
          std::min(dof_budget / dim, 2e9));
        parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
          mesh, estimates, refine_fraction, coarsen_fraction, most_cells);
      }
    if (by_contact_state && contact.active())
      mark_contact_state_changes(body, contact, results);

    bool flagged = false;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          if (cell->level() >= static_cast<int>(maximum_level))
            cell->clear_refine_flag();
          flagged = flagged || cell->refine_flag_set() || cell->coarsen_flag_set();
        }
    return Utilities::MPI::logical_or(flagged, mesh.get_communicator());
  }



  template <int dim>
  void
  AdaptiveRefinement<dim>::mark_contact_state_changes(
    const ElasticBody<dim>                    &body,
    const ContactOperator<dim>                &contact,
    const ContactResults<dim>                 &results) const
  {
    // The state of each candidate, plus one, at its x dof (0 elsewhere), so
    // that a cell can read those of its face's vertices on other ranks.
    TrilinosWrappers::MPI::Vector states = body.make_vector();
    for (unsigned int j = 0; j < contact.n_local(); ++j)
      states[contact.first_dof(j)] = 1. + static_cast<int>(results.state[j]);
    states.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::Vector states_ghosted = body.make_ghosted_vector();
    states_ghosted                               = states;

    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          {
            if (!face->at_boundary())
              continue;
            std::set<int> seen;
            for (const unsigned int v : face->vertex_indices())
              if (const double s = states_ghosted[face->vertex_dof_index(v, 0)];
                  s > 0)
                seen.insert(static_cast<int>(s));
            // The flags belong to the mesh; the dof cell sets them there.
            if (seen.size() > 1)
              {
                cell->clear_coarsen_flag();
                cell->set_refine_flag();
              }
          }
  }



  template <int dim>
  std::string
  AdaptiveRefinement<dim>::describe() const
  {
    if (!active())
      return "none";
    std::string what;
    if (by_kelly)
      what = "Kelly estimate (refine " + Input::to_text(100 * refine_fraction) +
             " %, coarsen " + Input::to_text(100 * coarsen_fraction) +
             " % of the cells)";
    if (by_contact_state)
      what += std::string(by_kelly ? " and " : "") + "contact state changes";
    return what + "; up to " + std::to_string(cycles) + " re-solve" +
           (cycles == 1 ? "" : "s") + " every " +
           (every == 1 ? std::string("increment") :
                         std::to_string(every) + " increments") +
           ", cells up to level " + std::to_string(maximum_level) +
           ", at most " + Input::to_text(dof_budget) + " dofs";
  }

  template class AdaptiveRefinement<2>;
  template class AdaptiveRefinement<3>;
} // namespace FrictionalContact
