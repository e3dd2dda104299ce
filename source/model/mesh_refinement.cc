#include <deal.II/base/mpi.h>

#include <frictional_contact/base/input.h>
#include <frictional_contact/model/mesh_refinement.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <vector>

namespace FrictionalContact
{
  namespace
  {
    /// <Mesh refinement/Memory budget> in GB; 0 for auto.
    double
    parse_memory_budget(const std::string &text)
    {
      if (Input::trim(text) == "auto")
        return 0;
      const std::string allowed = "auto or a number of GB > 0";
      const double      gigabytes =
        Input::parse_number("Mesh refinement/Memory budget", text, allowed);
      if (!(gigabytes > 0))
        Input::fail("Mesh refinement/Memory budget", text, allowed);
      return gigabytes;
    }
  } // namespace



  template <int dim>
  void
  MeshRefinement<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Global refinements",
                      "0",
                      Patterns::Integer(0, 12),
                      "How often every cell of the geometry's mesh is split "
                      "in 2^dim (0 to 12).");
    prm.declare_entry("Local refinements",
                      "0",
                      Patterns::Integer(0, 12),
                      "After the global refinements, how often the cells "
                      "near Refinement center are split again (0 to 12), "
                      "for example around the contact zone. Hanging nodes "
                      "between the levels are constrained; keep them out "
                      "of the contact zone (they are not contact "
                      "candidates).");
    prm.declare_entry("Refinement center",
                      dim == 2 ? "0, 0" : "0, 0, 0",
                      Patterns::Anything(),
                      "Centre of the region of local refinement (length).");
    prm.declare_entry("Memory budget",
                      "auto",
                      Patterns::Anything(),
                      "The memory a run plans with, before it makes its "
                      "mesh: auto: 80 % of the memory the machines of the "
                      "run report available (MemAvailable, summed over "
                      "them); or a number of GB, for example a batch job's "
                      "memory limit, which MemAvailable does not show. A "
                      "mesh that would need more stops the run with a "
                      "line that says so; with Linear solver/Preconditioner "
                      "= auto, a 3D mesh that fits only without the "
                      "assembled K takes the geometric multigrid with K "
                      "matrix-free.");
    prm.declare_entry("Refinement radius",
                      "0",
                      Patterns::Double(0.),
                      "Cells reaching closer than this to Refinement center "
                      "are refined locally (length, >= 0).");
  }



  template <int dim>
  MeshRefinement<dim>::MeshRefinement(ParameterHandler &prm)
    : global_refinements(prm.get_integer("Global refinements"))
    , local_refinements(prm.get_integer("Local refinements"))
    , local_center(Input::parse_vector<dim>("Mesh refinement/Refinement center",
                                            prm.get("Refinement center")))
    , local_radius(prm.get_double("Refinement radius"))
    , memory_budget_gb(parse_memory_budget(prm.get("Memory budget")))
  {
    if (local_refinements > 0 && !(local_radius > 0))
      Input::fail("Mesh refinement/Refinement radius",
                  prm.get("Refinement radius"),
                  "Local refinements > 0 needs a positive radius");
  }



  template <int dim>
  void
  MeshRefinement<dim>::refine(parallel::distributed::Triangulation<dim> &mesh,
                              const unsigned int built_in_refinements) const
  {
    check_memory(cells_after_global_refinement(mesh, built_in_refinements),
                 mesh.get_communicator());
    mesh.refine_global(built_in_refinements + global_refinements);
    refine_near_center(mesh);
  }



  template <int dim>
  double
  MeshRefinement<dim>::bytes_needed(const double n_cells, const bool matrix_free)
  {
    // Measured: about 3 kB per cell in 2D and 14 kB in 3D (matrix, AMG,
    // vectors, mesh), 4 kB in 3D without K (the multigrid path with K
    // matrix-free, at d = 1.6M on 2 ranks), on top of some 180 MB per
    // rank for the libraries; planned with a tenth more.
    const double per_cell = dim == 2 ? 3e3 : matrix_free ? 4.4e3 : 1.4e4;
    return n_cells * per_cell;
  }



  template <int dim>
  double
  MeshRefinement<dim>::available_memory(const MPI_Comm comm)
  {
    // One rank per machine reads it; the run has the sum.
    MPI_Comm machine;
    MPI_Comm_split_type(comm,
                        MPI_COMM_TYPE_SHARED,
                        Utilities::MPI::this_mpi_process(comm),
                        MPI_INFO_NULL,
                        &machine);
    const bool reads = Utilities::MPI::this_mpi_process(machine) == 0;
    MPI_Comm_free(&machine);
    double available = 0;
    if (reads)
      {
        std::ifstream meminfo("/proc/meminfo");
        std::string   key;
        double        kilobytes;
        while (meminfo >> key >> kilobytes)
          if (key == "MemAvailable:")
            available = 1024 * kilobytes;
          else
            meminfo.ignore(1000, '\n');
      }
    return Utilities::MPI::sum(available, comm);
  }



  template <int dim>
  double
  MeshRefinement<dim>::memory_budget(const MPI_Comm comm) const
  {
    return memory_budget_gb > 0 ? 1e9 * memory_budget_gb :
                                  largest_share * available_memory(comm);
  }



  template <int dim>
  std::string
  MeshRefinement<dim>::describe_budget(const double budget) const
  {
    return memory_budget_gb > 0 ?
             "the " + describe_bytes(budget) +
               " of <Mesh refinement/Memory budget>" :
             Input::to_text(100 * largest_share) + " % of the " +
               describe_bytes(budget / largest_share) + " available";
  }



  template <int dim>
  std::string
  MeshRefinement<dim>::describe_bytes(const double bytes)
  {
    std::ostringstream text;
    text << std::setprecision(2) << (bytes >= 1e9 ? bytes / 1e9 : bytes / 1e6)
         << (bytes >= 1e9 ? " GB" : " MB");
    return text.str();
  }



  template <int dim>
  bool
  MeshRefinement<dim>::fits_only_matrix_free(const double n_cells,
                                             const double budget)
  {
    return budget > 0 && bytes_needed(n_cells, false) > budget &&
           bytes_needed(n_cells, true) <= budget;
  }



  template <int dim>
  double
  MeshRefinement<dim>::cells_after_global_refinement(
    const parallel::distributed::Triangulation<dim> &coarse_mesh,
    const unsigned int                               built_in_refinements) const
  {
    return coarse_mesh.n_global_active_cells() *
           std::pow(2., dim * (built_in_refinements + global_refinements));
  }



  template <int dim>
  void
  MeshRefinement<dim>::check_memory(const double n_cells, const MPI_Comm comm) const
  {
    const double budget = memory_budget(comm);
    const double needed = bytes_needed(n_cells, matrix_free_stiffness);
    if (budget > 0 && needed > budget)
      {
        // In 3D the path without K may still fit.
        const bool matrix_free_fits =
          !matrix_free_stiffness && fits_only_matrix_free(n_cells, budget);
        throw InputError(
          "<Geometry>: the mesh would have " + Input::to_text(n_cells) +
          " cells and need about " + describe_bytes(needed) + ", more than " +
          describe_budget(budget) +
          "; use fewer cells (repetitions, <Mesh "
          "refinement/Global refinements>, <Local refinements>)" +
          (matrix_free_fits ?
             std::string(", or set <Linear solver/Preconditioner> = geometric "
                         "multigrid and <Linear solver/Matrix-free stiffness> = "
                         "true (about " +
                         describe_bytes(bytes_needed(n_cells, true)) + ")") :
             std::string()));
      }
  }



  template <int dim>
  void
  MeshRefinement<dim>::refine_near_center(
    parallel::distributed::Triangulation<dim> &mesh) const
  {
    if (local_refinements == 0)
      return;
    const MPI_Comm comm = mesh.get_communicator();
    const auto     near = [&](const auto &cell) {
      return cell->center().distance(local_center) <
             local_radius + 0.5 * cell->diameter();
    };
    // Before each level, the final size is estimated from the cells near
    // the center now: each becomes 2^dim per level left, in a band around
    // the disc that narrows with the cells. Measured on the Hertz scenes,
    // the estimate is within 10 % in 2D and up to 1.9 times low in 3D
    // (p4est's 2:1 balance adds cells) from the coarse mesh, and closer at
    // every level, so a mesh that cannot fit is refused while the mesh made
    // so far is still small.
    for (unsigned int i = 0; i < local_refinements; ++i)
      {
        double n_near = 0, diameter = 0;
        for (const auto &cell : mesh.active_cell_iterators())
          if (cell->is_locally_owned() && near(cell))
            {
              ++n_near;
              diameter = std::max(diameter, cell->diameter());
            }
        n_near   = Utilities::MPI::sum(n_near, comm);
        diameter = Utilities::MPI::max(diameter, comm);
        const unsigned int levels_left = local_refinements - i;
        const double       band =
          std::pow((local_radius + 0.5 * diameter / std::pow(2., levels_left)) /
                     (local_radius + 0.5 * diameter),
                   dim);
        check_memory(mesh.n_global_active_cells() +
                       n_near * (std::pow(2., dim * levels_left) - 1) * band,
                     comm);

        for (const auto &cell : mesh.active_cell_iterators())
          if (cell->is_locally_owned() && near(cell))
            cell->set_refine_flag();
        mesh.execute_coarsening_and_refinement();
      }
    check_memory(mesh.n_global_active_cells(), comm);
  }

  template <int dim>
  void
  MeshRefinement<dim>::conform_hanging_vertices(
    parallel::distributed::Triangulation<dim> &mesh)
  {
    place_hanging_vertices(mesh, false);
  }



  template <int dim>
  void
  MeshRefinement<dim>::restore_hanging_vertices(
    parallel::distributed::Triangulation<dim> &mesh)
  {
    place_hanging_vertices(mesh, true);
  }



  template <int dim>
  void
  MeshRefinement<dim>::place_hanging_vertices(
    parallel::distributed::Triangulation<dim> &mesh,
    const bool                                 on_manifold)
  {
    // Coarser cells first: a vertex a hanging vertex is placed from may
    // itself hang from a coarser cell.
    std::vector<typename Triangulation<dim>::active_cell_iterator> cells;
    for (const auto &cell : mesh.active_cell_iterators())
      if (!cell->is_artificial())
        cells.push_back(cell);
    std::stable_sort(cells.begin(), cells.end(), [](const auto &a, const auto &b) {
      return a->level() < b->level();
    });

    for (const auto &cell : cells)
      {
        // The midpoint of a refined edge of an active cell hangs (in 2D the
        // edges are the faces); refinement put it where the manifold says.
        for (unsigned int l = 0; l < cell->n_lines(); ++l)
          if (const auto line = cell->line(l); line->has_children())
            line->child(0)->vertex(1) =
              on_manifold ? line->center(true) :
                            0.5 * (line->vertex(0) + line->vertex(1));
        // In 3D, so does the centre of a refined face.
        if (dim == 3)
          for (const auto &face : cell->face_iterators())
            if (face->has_children())
              {
                Point<dim> centre;
                for (const unsigned int v : face->vertex_indices())
                  centre += 0.25 * face->vertex(v);
                face->child(0)->vertex(3) =
                  on_manifold ? face->center(true, true) : centre;
              }
      }
  }



  template class MeshRefinement<2>;
  template class MeshRefinement<3>;
} // namespace FrictionalContact
