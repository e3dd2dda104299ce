#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>

#include <frictional_contact/boundary_conditions.h>
#include <frictional_contact/checkpoint.h>
#include <frictional_contact/contact_operator.h>
#include <frictional_contact/elastic_body.h>
#include <frictional_contact/fclib_export.h>
#include <frictional_contact/geometry/interface.h>
#include <frictional_contact/loading_history.h>
#include <frictional_contact/material.h>
#include <frictional_contact/output_writer.h>
#include <frictional_contact/contact_solver.h>
#include <frictional_contact/shifted_stiffness_solver.h>
#include <frictional_contact/statistics.h>

#include <memory>

namespace FrictionalContact
{
  /**
   * One run of a scene: owns the mesh and wires the elastic body, the
   * contact operator, the solvers and the output together, in the order a
   * parameter file describes them. All parameters are read (and checked) in
   * the constructor, before anything is computed or written.
   */
  template <int dim>
  class Simulator
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    Simulator(ParameterHandler &prm, const MPI_Comm comm);

    /// Sets up, solves and writes the results. Throws SolverError on failure.
    void
    run();

    /// Builds the mesh, dofs, constraints, contact candidates, K and p.
    void
    setup();

    const ElasticBody<dim> &
    get_body() const
    {
      return body;
    }

    const ContactOperator<dim> &
    get_contact() const
    {
      return contact;
    }

  private:
    /// Throws an InputError if a mesh of @p n_cells cells would not fit in
    /// the memory of this machine.
    void
    check_memory(const double n_cells) const;

    /// Refines Local refinements times near Refinement center, after
    /// checking that the estimated mesh fits in memory.
    void
    refine_near_center();

    /// Solves increment @p l and adds it to the state; returns its statistics.
    SolveStatistics
    solve_increment(const unsigned int l);

    /// mu_pi, computed when the contact iteration first needs it.
    double
    smallest_eigenvalue_of_K();

    /// Whether no candidate reaches the obstacle after the increment @p du.
    bool
    separates(const IncrementalProblem<dim>       &problem,
              const TrilinosWrappers::MPI::Vector &du) const;

    /// The contact problem of increment @p l, for the load vector @p load,
    /// from the displacement @p start (u^l and the prescribed increment).
    IncrementalProblem<dim>
    incremental_problem(const unsigned int                   l,
                        const TrilinosWrappers::MPI::Vector &load,
                        const TrilinosWrappers::MPI::Vector &start) const;

    /// Writes a checkpoint after increment @p l.
    void
    save_checkpoint(const unsigned int l) const;

    /// Restores the state saved by save_checkpoint(); returns the number of
    /// increments done.
    unsigned int
    load_checkpoint();

    /// Prints the increment's line, writes output and statistics.
    void
    report_increment(const unsigned int                   l,
                     const TrilinosWrappers::MPI::Vector &du,
                     const ContactResults<dim>           &results,
                     const SolveStatistics               &statistics);

    /// Results per candidate for the increment du with reactions r.
    ContactResults<dim>
    contact_results(const IncrementalProblem<dim>       &problem,
                    const TrilinosWrappers::MPI::Vector &du,
                    const std::vector<Tensor<1, dim>>   &r) const;

    MPI_Comm           mpi_communicator;
    ConditionalOStream pcout;
    std::string        output_directory;
    std::string        parameters_as_run;

    parallel::distributed::Triangulation<dim> triangulation;
    std::unique_ptr<Geometry::Interface<dim>> geometry;
    BoundaryNames                             boundary_names;
    LinearElasticMaterial<dim>                material;
    BoundaryConditions<dim>                   boundary_conditions;
    ElasticBody<dim>                          body;
    ContactOperator<dim>                      contact;
    ShiftedStiffnessSolver                    linear_solver;
    std::unique_ptr<ContactSolver<dim>>       contact_solver;
    OutputWriter<dim>                         output;
    StatisticsFile                            statistics;
    FclibExport                               fclib_export;
    LoadingHistory                            loading;
    std::unique_ptr<TimerOutput>              timer;

    /// The state after the last finished increment: total displacement,
    /// and the contact force T_j r_j of each local candidate.
    TrilinosWrappers::MPI::Vector u;
    std::vector<Tensor<1, dim>>   contact_forces;
    double                        sigma_T = 1;
    double                        mu_pi   = 0;

    Checkpoint<dim> checkpoint;
    bool            resume;
    unsigned int    checkpoint_every;
    /// The end times of the increments: those of the loading history, with
    /// halves inserted where an increment failed and was cut.
    std::vector<double> times;
    bool                cut_on_failure;
    unsigned int        maximum_cuts;

    /// Increments finished before this run (when resuming).
    unsigned int    first_increment = 0;

    unsigned int global_refinements;
    /// Cells within local_refinement_radius of local_refinement_center are
    /// split local_refinements more times (hanging nodes between levels).
    unsigned int local_refinements;
    Point<dim>   local_refinement_center;
    double       local_refinement_radius;
    double       eigenvalue_tolerance;
    unsigned int lanczos_vectors;
    bool         try_elastic_first;
    bool         write_history;
  };
} // namespace FrictionalContact
