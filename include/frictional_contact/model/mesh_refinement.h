#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/distributed/tria.h>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * The refinement of the geometry's coarse mesh: global refinements, then
   * local ones near a centre (hanging nodes between the levels). Owns the
   * initial-refinement entries of "Mesh refinement" (AdaptiveRefinement
   * owns the adaptive ones) and the memory check that refuses a
   * mesh this machine cannot hold before it is made, with the measured
   * memory per cell of each solver path that Model's automatic choice of
   * the path shares.
   */
  template <int dim>
  class MeshRefinement
  {
  public:
    /// Declares the refinement entries, inside the subsection "Mesh
    /// refinement".
    static void
    declare_parameters(ParameterHandler &prm);

    /// Reads them, inside the subsection "Mesh refinement".
    explicit MeshRefinement(ParameterHandler &prm);

    /// Refines @p mesh globally (after @p built_in_refinements the geometry
    /// asks for), then near the centre; throws an InputError, before
    /// refining, if the estimated mesh would not fit in memory.
    void
    refine(parallel::distributed::Triangulation<dim> &mesh,
           const unsigned int                         built_in_refinements) const;

    /**
     * Moves every hanging vertex to the mean of the vertices it hangs from
     * (the midpoint of its coarse edge, the centre of its coarse face), where
     * its Q1 displacement is the mean of theirs. Refinement puts such a
     * vertex on a curved manifold instead, away from the coarse neighbour's
     * face: the mesh then has a crack there, and the vertex can sink into a
     * plane obstacle while the candidates it hangs from do not. After the
     * move its gap to a plane is the mean of theirs. Call after every
     * change of the mesh (refinement, loading a checkpoint).
     */
    static void
    conform_hanging_vertices(parallel::distributed::Triangulation<dim> &mesh);

    /**
     * Puts the hanging vertices back where refinement placed them, on the
     * manifold: call before adapting a conformed mesh, so that the vertices
     * refinement makes next are where they would be on a mesh refined in
     * one go from the coarse one (as a checkpoint's mesh is when loaded),
     * and a vertex that stops hanging is on the manifold.
     */
    static void
    restore_hanging_vertices(parallel::distributed::Triangulation<dim> &mesh);

    /// The share of the available memory a run may plan to use.
    static constexpr double largest_share = 0.8;

    /// The bytes a mesh of @p n_cells cells needs, with K assembled and ML
    /// or (@p matrix_free) with K matrix-free and the geometric multigrid:
    /// measured per cell.
    static double
    bytes_needed(const double n_cells, const bool matrix_free);

    /// The memory the machines of the run have available (MemAvailable,
    /// read by one rank per machine and summed), in bytes, the same on
    /// every rank; 0 where it is not known.
    static double
    available_memory(const MPI_Comm comm);

    /// The bytes the run plans with: <Memory budget>, or largest_share of
    /// the available memory (0 where it is not known: no check).
    double
    memory_budget(const MPI_Comm comm) const;

    /// Where a @p budget of memory_budget() comes from, for a message: "the
    /// 2 GB of <Mesh refinement/Memory budget>" or "80 % of the 24 GB
    /// available".
    std::string
    describe_budget(const double budget) const;

    /// @p bytes in MB or GB, with two digits.
    static std::string
    describe_bytes(const double bytes);

    /// Whether a mesh of @p n_cells cells fits in @p budget bytes with K
    /// matrix-free, but not with K assembled.
    static bool
    fits_only_matrix_free(const double n_cells, const double budget);

    /// The cells of @p coarse_mesh after its @p built_in_refinements and the
    /// Global refinements (Local refinements add to them).
    double
    cells_after_global_refinement(
      const parallel::distributed::Triangulation<dim> &coarse_mesh,
      const unsigned int                               built_in_refinements) const;

    /// K is not assembled (<Linear solver/Matrix-free stiffness>): a cell
    /// needs less memory.
    void
    set_matrix_free_stiffness(const bool matrix_free)
    {
      matrix_free_stiffness = matrix_free;
    }

  private:
    /// The hanging vertices at the mean of their parents, or (@p
    /// on_manifold) at the manifold's point between them.
    static void
    place_hanging_vertices(parallel::distributed::Triangulation<dim> &mesh,
                           const bool on_manifold);

    /// Throws an InputError if a mesh of @p n_cells cells would not fit in
    /// the memory of this machine.
    void
    check_memory(const double n_cells, const MPI_Comm comm) const;

    /// Refines Local refinements times near Refinement center, after
    /// checking that the estimated mesh fits in memory.
    void
    refine_near_center(parallel::distributed::Triangulation<dim> &mesh) const;

    unsigned int global_refinements;
    bool         matrix_free_stiffness = false;
    /// Cells within local_radius of local_center are split local_refinements
    /// more times.
    unsigned int local_refinements;
    Point<dim>   local_center;
    double       local_radius;
    /// <Memory budget> in GB; 0: auto.
    double memory_budget_gb;
  };
} // namespace FrictionalContact
