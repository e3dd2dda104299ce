#pragma once

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/model/quadrature_history.h>

#include <string>
#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * The checkpoint of a run after a finished increment, in
   * <output directory>/checkpoint: the refined mesh (p4est), nodal vectors
   * (moved with the cells, so a run may resume on another number of MPI
   * ranks), a text blob with the rest of the state, and last a manifest:
   * the format version, the scene it was written for, and the size and
   * CRC-32 of every file. A new checkpoint is written next to the old one
   * and then put in its place, so a run killed while writing keeps the
   * previous checkpoint; verify() refuses one that is incomplete, damaged,
   * of another format or of another scene before anything is read.
   */
  template <int dim>
  class Checkpoint
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    Checkpoint(const std::string &output_directory, const MPI_Comm comm);

    /// Whether a checkpoint is there (its manifest, written last).
    bool
    exists() const;

    /// Saves the mesh, the @p vectors (with ghost entries), the material
    /// laws' @p history, @p state and the manifest with @p scene (the
    /// parameters as run, ShortPRM), after reserving the space they need;
    /// throws a WriteError, leaving the last checkpoint as it was, if the
    /// reservation or a write fails. The history comes back with
    /// QuadratureHistory::unpack() after load_vectors().
    void
    save(const parallel::distributed::Triangulation<dim> &triangulation,
         const DoFHandler<dim>                           &dof_handler,
         const std::vector<const Vector *>               &vectors,
         QuadratureHistory<dim>                          &history,
         const std::string                               &state,
         const std::string                               &scene) const;

    /**
     * Checks, before anything is loaded, that the checkpoint is there, of
     * this format, complete and unchanged (sizes and checksums), and that
     * it was written for @p scene in every entry that changes the result
     * (all but the output entries). An entry the checkpoint lacks (a
     * program before the entry was written it) matches where @p scene has
     * it at its value in @p defaults (the defaults, ShortPRM): a new entry
     * keeps the results of before at its default. Every rank throws the
     * same InputError, naming what is wrong and the entries that differ.
     */
    void
    verify(const std::string &scene, const std::string &defaults) const;

    /// Refines the coarse mesh @p triangulation as it was saved.
    void
    load_mesh(parallel::distributed::Triangulation<dim> &triangulation) const;

    /// Fills @p vectors (without ghost entries, on the distributed dofs of
    /// the loaded mesh), in the order they were saved.
    void
    load_vectors(const DoFHandler<dim> &dof_handler,
                 std::vector<Vector *> &vectors) const;

    std::string
    load_state() const;

    std::string
    path() const
    {
      return directory;
    }

  private:
    /// Bytes to reserve for a checkpoint of this mesh with @p n_vectors
    /// vectors and @p text_bytes of text.
    std::uintmax_t
    expected_size(const parallel::distributed::Triangulation<dim> &triangulation,
                  const DoFHandler<dim>                           &dof_handler,
                  const unsigned int                               n_vectors,
                  const std::uintmax_t text_bytes) const;

    std::string directory;
    MPI_Comm    comm;
  };
} // namespace FrictionalContact
