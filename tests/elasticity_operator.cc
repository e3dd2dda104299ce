// The matrix-free stiffness (ElasticityOperator) against the assembled K
// on shipped meshes: a box in plane stress, a locally refined half disc
// (hanging nodes), a mesh from a Gmsh file, a 3D box, two bodies of
// different materials. For a random x with zero constrained entries,
// max |(K x)_i - (K_mf x)_i| / max |(K x)_i| over the unconstrained rows
// must be round-off (below 1e-12). Then, on the meshes made with levels
// (Preconditioner = geometric multigrid), the V-cycle as the preconditioner
// of CG with K: it converges in few iterations, to the solution.
#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/solver_cg.h>

#include <frictional_contact/driver/simulator.h>
#include <frictional_contact/solvers/elasticity_operator.h>
#include <frictional_contact/solvers/geometric_multigrid.h>

#include <iostream>
#include <random>

using namespace FrictionalContact;

namespace
{
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
           "vtu = false\n end\nend\nsubsection Output\n set Write "
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
