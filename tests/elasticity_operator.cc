// The matrix-free stiffness (ElasticityOperator) against the assembled K
// on shipped meshes: a box in plane stress, a locally refined half disc
// (hanging nodes), a mesh from a Gmsh file, a 3D box, two bodies of
// different materials. For a random x with zero constrained entries,
// max |(K x)_i - (K_mf x)_i| / max |(K x)_i| over the unconstrained rows
// must be round-off (below 1e-12). The same for MatrixFreeStiffness (the
// matrix-free K of <Linear solver/Matrix-free stiffness>) on a vector with
// non-zero constrained entries too, whose rows must be its diagonal times
// x there; and its nodal blocks against K's at every locally owned node
// (the entries of unconstrained dofs), on the meshes without hanging nodes. Then, on the meshes made with levels
// (Preconditioner = geometric multigrid), the V-cycle as the preconditioner
// of CG with K: it converges in few iterations, to the solution.
#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/solver_cg.h>

#include <frictional_contact/driver/simulator.h>
#include <frictional_contact/solvers/elasticity_operator.h>
#include <frictional_contact/solvers/geometric_multigrid.h>
#include <frictional_contact/solvers/matrix_free_stiffness.h>

#include <iostream>
#include <random>
#include <set>

using namespace FrictionalContact;

namespace
{
  template <int dim>
  void
  check_matrix_free_stiffness(const ElasticBody<dim>               &body,
                              const TrilinosWrappers::SparseMatrix &K)
  {
    const AffineConstraints<double> &constraints = body.get_constraints();
    const MatrixFreeStiffness<dim>   K_mf(body.get_dof_handler(), constraints,
                                        body.lame_parameters());
    TrilinosWrappers::MPI::Vector x = body.make_vector(), Kx = body.make_vector(),
                                  y = body.make_vector();
    std::mt19937 random(7 + Utilities::MPI::this_mpi_process(MPI_COMM_WORLD));
    std::uniform_real_distribution<double> uniform(-1., 1.);
    for (const auto i : body.locally_owned_dofs())
      x[i] = uniform(random);
    x.compress(VectorOperation::insert);
    K.vmult(Kx, x);
    K_mf.vmult(y, x);
    double difference = 0, largest = 0;
    bool   constrained_rows = true;
    for (const auto i : body.locally_owned_dofs())
      if (constraints.is_constrained(i))
        constrained_rows = constrained_rows && K_mf.diag_element(i) > 0 &&
                           y[i] == K_mf.diag_element(i) * x[i];
      else
        {
          difference = std::max(difference, std::abs(Kx[i] - y[i]));
          largest    = std::max(largest, std::abs(Kx[i]));
        }
    const bool products = Utilities::MPI::max(difference, MPI_COMM_WORLD) <=
                          1e-12 * Utilities::MPI::max(largest, MPI_COMM_WORLD);
    constrained_rows = !Utilities::MPI::logical_or(!constrained_rows, MPI_COMM_WORLD);

    // The nodal blocks of every locally owned vertex.
    std::vector<std::vector<types::global_dof_index>> nodes;
    std::set<types::global_dof_index>                 seen;
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          if (body.locally_owned_dofs().is_element(cell->vertex_dof_index(v, 0)) &&
              seen.insert(cell->vertex_dof_index(v, 0)).second)
            {
              nodes.emplace_back();
              for (unsigned int c = 0; c < dim; ++c)
                nodes.back().push_back(cell->vertex_dof_index(v, c));
            }
    const auto blocks_mf = K_mf.blocks(nodes);
    const auto blocks    = AssembledStiffness(K).blocks(nodes);
    double     block_difference = 0, block_largest = 0;
    for (unsigned int j = 0; j < nodes.size(); ++j)
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          if (!constraints.is_constrained(nodes[j][a]) &&
              !constraints.is_constrained(nodes[j][b]))
            {
              block_difference =
                std::max(block_difference, std::abs(blocks[j](a, b) - blocks_mf[j](a, b)));
              block_largest = std::max(block_largest, std::abs(blocks[j](a, b)));
            }
    const bool hanging = Utilities::MPI::logical_or(
      body.get_hanging_node_constraints().n_constraints() > 0, MPI_COMM_WORLD);
    const bool same_blocks =
      Utilities::MPI::max(block_difference, MPI_COMM_WORLD) <=
      1e-12 * Utilities::MPI::max(block_largest, MPI_COMM_WORLD);
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::cout << "    MatrixFreeStiffness: K x as assembled to 1e-12: " << products
                  << ", constrained rows its diagonal: " << constrained_rows;
        if (hanging)
          std::cout << ", nodal blocks (hanging nodes: not compared)" << std::endl;
        else
          std::cout << ", nodal blocks as K's to 1e-12: " << same_blocks << std::endl;
      }
  }



  template <int dim>
  void
  check(const std::string &title, const std::string &scene)
  {
    ParameterHandler prm;
    Simulator<dim>::declare_parameters(prm);
    prm.parse_input_from_string(scene);
    Simulator<dim> simulator(prm, MPI_COMM_WORLD);
    simulator.setup();
    const Model<dim>                     &model = simulator.get_model();
    const ElasticBody<dim>               &body  = model.get_body();
    const AffineConstraints<double>      &constraints = body.get_constraints();
    const TrilinosWrappers::SparseMatrix &K = body.stiffness().matrix("the test");

    typename MatrixFree<dim, double>::AdditionalData data;
    data.tasks_parallel_scheme = MatrixFree<dim, double>::AdditionalData::none;
    data.mapping_update_flags  = update_gradients | update_JxW_values;
    auto storage = std::make_shared<MatrixFree<dim, double>>();
    storage->reinit(MappingQ1<dim>(), body.get_dof_handler(), constraints,
                    QGauss<1>(2), data);
    ElasticityOperator<dim, double> op;
    op.initialize(storage);
    op.set_materials(model.get_body().lame_parameters());

    // x random on the unconstrained dofs, zero on the constrained ones.
    LinearAlgebra::distributed::Vector<double> x, Ax;
    storage->initialize_dof_vector(x);
    storage->initialize_dof_vector(Ax);
    TrilinosWrappers::MPI::Vector x_t = body.make_vector(), Kx = body.make_vector();
    std::mt19937                           random(42 + Utilities::MPI::this_mpi_process(MPI_COMM_WORLD));
    std::uniform_real_distribution<double> uniform(-1., 1.);
    for (const auto i : body.locally_owned_dofs())
      if (!constraints.is_constrained(i))
        x_t[i] = uniform(random);
    x_t.compress(VectorOperation::insert);
    for (const auto i : body.locally_owned_dofs())
      x[i] = x_t[i];
    K.vmult(Kx, x_t);
    op.vmult(Ax, x);
    double difference = 0, largest = 0;
    for (const auto i : body.locally_owned_dofs())
      if (!constraints.is_constrained(i))
        {
          difference = std::max(difference, std::abs(Kx[i] - Ax[i]));
          largest    = std::max(largest, std::abs(Kx[i]));
        }
    difference = Utilities::MPI::max(difference, MPI_COMM_WORLD);
    largest    = Utilities::MPI::max(largest, MPI_COMM_WORLD);

    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << title << ": d = " << body.n_free_dofs()
                << ", K x matrix-free as assembled to 1e-12: " << std::boolalpha
                << (difference <= 1e-12 * largest) << std::endl;
    check_matrix_free_stiffness(body, K);
    if (!model.mesh().get_mesh_smoothing() ||
        body.get_dof_handler().get_triangulation().n_global_levels() < 2 ||
        !(model.mesh().get_mesh_smoothing() &
          Triangulation<dim>::limit_level_difference_at_vertices))
      return;

    // The V-cycle as CG's preconditioner for K x = K x_t (x_t as above),
    // to 1e-8: converges in a few iterations, to x_t.
    GeometricMultigrid<dim> multigrid;
    multigrid.initialize(body.get_dof_handler(), model.held_boundaries(),
                         model.get_body().lame_parameters(), constraints, body.stiffness(), 2);
    TrilinosWrappers::MPI::Vector solution = body.make_vector();
    SolverControl control(100, 1e-8 * Kx.l2_norm(), false, false);
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    cg.solve(K, solution, Kx, multigrid);
    solution -= x_t;
    const double error = solution.linfty_norm() / x_t.linfty_norm();
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << "    geometric multigrid (" << multigrid.n_levels()
                << " levels): CG converges in at most 25 iterations: "
                << (control.last_step() <= 25) << ", to the solution: "
                << (error < 1e-5) << std::endl;
  }

  std::string
  scene(const std::string &file, const std::string &extra)
  {
    return "include " SOURCE_DIR "/../parameters/" + file +
           "\nsubsection Postprocess\n subsection Visualization\n  set Write "
           "vtu = false\n  set Write csv tables = false\n end\nend\n"
           "subsection Output\n set Write "
           "statistics = false\nend\n" +
           extra;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string multigrid =
    "subsection Linear solver\n set Preconditioner = geometric multigrid\nend\n";
  check<2>("Example I (box, plane stress)", scene("example1.prm", multigrid));
  check<2>("Hertz 2D (half disc, local refinement)", scene("hertz_2d.prm", multigrid));
  check<2>("Roller 2D (Gmsh mesh)",
           scene("roller_2d.prm",
                 "subsection Geometry\n subsection From file\n  set Mesh file = " SOURCE_DIR
                 "/../meshes/half_disc.msh\n end\nend\n"));
  check<2>("Block on block 2D (two materials)", scene("block_on_block_2d.prm", ""));
  check<3>("Example II (box)", scene("example2.prm", multigrid));
  check<3>("Hertz 3D (half ball, local refinement)", scene("hertz_3d.prm", multigrid));
}
