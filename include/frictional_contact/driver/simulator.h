#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <frictional_contact/base/run_control.h>
#include <frictional_contact/driver/checkpoint.h>
#include <frictional_contact/driver/increment_driver.h>
#include <frictional_contact/driver/increment_solver.h>
#include <frictional_contact/driver/pair_geometry.h>
#include <frictional_contact/model/adaptive_refinement.h>
#include <frictional_contact/model/model.h>
#include <frictional_contact/postprocess/manager.h>

#include <memory>
#include <optional>

namespace FrictionalContact
{
  /**
   * One run of a scene, the pipeline of doc/pipeline.md: the Model (mesh,
   * body, contact), the IncrementDriver (times, step cutting), the
   * IncrementSolver (one increment on the model) and the postprocessors,
   * with the run's state (u and the contact forces) and its checkpoints.
   * Owns the top-level entries. All parameters are read (and checked) in
   * the constructor, before anything is computed or written.
   */
  template <int dim>
  class Simulator
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    Simulator(ParameterHandler &prm, const MPI_Comm comm);

    /**
     * Sets up, solves and writes the results. Throws SolverError on failure,
     * WriteError if a write fails (naming the last complete checkpoint),
     * StoppedBySignal after a signal (the checkpoint of the last finished
     * increment written), OutputFolderBusy if another run writes into the
     * output folder.
     */
    void
    run();

    /// Builds the mesh, dofs, constraints, contact candidates, K and p.
    void
    setup();

    const Model<dim> &
    get_model() const
    {
      return model;
    }

  private:
    /// Solves increment @p l (on meshes adapted to it, if asked), adds it
    /// to the state and runs the postprocessors; returns the contact
    /// solver's iterations on the last mesh; throws a SolverError if it
    /// fails.
    unsigned int
    solve_increment(const unsigned int l);

    /// After increment @p l, the times after it settled: its checkpoint
    /// (if due), then a stop if a signal came.
    void
    finish_increment(const unsigned int l);

    /// Solves increment @p l on the current mesh from the state, or from
    /// @p from_coarser (the solve of the mesh before a refinement, carried
    /// over; again from the state if that fails); throws a SolverError
    /// (after the postprocessors of a failed increment) if the contact
    /// solve does not converge.
    IncrementOutcome<dim>
    solve_on_current_mesh(const unsigned int l, const WarmStart<dim> *from_coarser = nullptr);

    /// Adapts the mesh to the solution in @p outcome and carries the state
    /// over, and the solve's increment and contact forces into
    /// @p from_coarser; returns whether the mesh changed (refinement cycle
    /// @p cycle).
    bool
    adapt_mesh(const IncrementOutcome<dim> &outcome,
               const unsigned int           cycle,
               WarmStart<dim>              &from_coarser);

    /// Writes a checkpoint after increment @p l.
    void
    save_checkpoint(const unsigned int l);

    /// Solves the increments from @p first_increment on; stops on a signal
    /// (StoppedBySignal) and names the last checkpoint in a WriteError.
    void
    solve_increments(const unsigned int first_increment);

    /// After a signal: the checkpoint of the last finished increment (if
    /// it is not written yet), then the StoppedBySignal to end the run.
    [[noreturn]] void
    stop_on_signal(const int signal);

    /// What a failed write leaves: "the last complete checkpoint (...)
    /// stays valid: ... resume ..." or that there is none yet.
    std::string
    what_is_left() const;

    /// Restores the state saved by save_checkpoint(); returns the number of
    /// increments done.
    unsigned int
    load_checkpoint();

    /// The one-line summary for scripts: seconds per section, peak memory.
    void
    print_summary() const;

    MPI_Comm           mpi_communicator;
    ConditionalOStream pcout;
    std::string        output_directory;
    /// The parameters as read, written next to the results and kept in
    /// checkpoints to compare scenes.
    std::string parameters_as_run;
    bool        resume;
    /// Whether <Resume computation> is 'auto' (a finished run is then
    /// nothing to do, not an error).
    bool        resume_if_possible;

    Model<dim>                   model;
    AdaptiveRefinement<dim>      adaptivity;
    IncrementDriver              driver;
    IncrementSolver<dim>         increment_solver;
    Postprocess::Manager<dim>    postprocessors;
    Checkpoint<dim>              checkpoint;
    std::unique_ptr<TimerOutput> timer;

    State<dim> state;
    /// Increments finished (of driver.times()), and the last one whose
    /// checkpoint is written (0: none).
    unsigned int n_finished      = 0;
    unsigned int last_checkpoint = 0;
    /// Held while the run may write into the output folder.
    std::optional<OutputLock> lock;
  };
} // namespace FrictionalContact
