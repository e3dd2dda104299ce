// MortarPreconditioner: the geometric multigrid of K serving K_w = Q^T K Q
// of two bodies (parameters/ball_on_plate.prm with the mesh refined
// locally twice, its mortar rows at the start), on one rank:
// - CG on K_w preconditioned by Q^-1 M^-1 Q^-T takes the iterations of CG
//   on K preconditioned by M (within 2: the spectra are the same);
// - with stiff springs (10 c_j, all directions) at every slave node, the
//   cycle of K alone (what MortarPreconditioner gives the Newton systems)
//   takes fewer iterations on K_w + S than a cycle that carries the
//   springs on the slave dofs, as a single body's cycle does: in u the
//   springs link each slave node to master nodes, which that cycle does
//   not see.
// Only true/false is compared (the counts are printed on a line starting
// with "--", which the comparison leaves out), so the output holds for any
// BLAS.
#include <deal.II/base/mpi.h>
#include <deal.II/lac/solver_control.h>

#include <frictional_contact/driver/simulator.h>
#include <frictional_contact/model/mortar_preconditioner.h>
#include <frictional_contact/solvers/geometric_multigrid.h>

#include <iostream>

#include "with_springs.h"

using namespace FrictionalContact;
using TrilinosVector = TrilinosWrappers::MPI::Vector;

namespace
{
  using SpringOperator = WithSprings<StiffnessOperator>;

  /// The reduction of |b| the CG solves below are counted to.
  constexpr double reduction = 1e-8;

  const std::string scene =
    "include " SOURCE_DIR "/../parameters/ball_on_plate.prm\n"
    "subsection Mesh refinement\n set Local refinements = 2\n"
    " set Cycles = 0\nend\n"
    "subsection Linear solver\n set Preconditioner = geometric multigrid\nend\n"
    "subsection Postprocess\n subsection Visualization\n"
    "  set Write vtu = false\n  set Write csv tables = false\n end\nend\n"
    "subsection Output\n set Write statistics = false\nend\n";
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ParameterHandler                 prm;
  Simulator<3>::declare_parameters(prm);
  prm.parse_input_from_string(scene);
  Simulator<3> simulator(prm, MPI_COMM_WORLD);
  simulator.setup();
  const Model<3>           &model   = simulator.get_model();
  const ElasticBody<3>     &body    = model.get_body();
  const ContactOperator<3> &contact = model.get_contact();
  const MortarBasis<3>      basis(body, contact);

  TrilinosVector x = body.make_vector();
  for (const auto i : body.locally_owned_dofs())
    x[i] = std::sin(1. * i);

  // Stiff springs at every slave node, in w.
  const std::vector<double> c = contact.normal_stiffness(basis.stiffness());
  std::vector<NodalBlock>   springs(contact.n_local());
  for (unsigned int j = 0; j < contact.n_local(); ++j)
    contact.nodal_block(j, 10 * c[j] * unit_symmetric_tensor<3>(), springs[j]);

  GeometricMultigrid<3> cycle, cycle_with_springs;
  cycle.initialize(body.get_dof_handler(),
                   model.held_boundaries(),
                   body.lame_parameters(),
                   body.get_constraints(),
                   body.stiffness(),
                   2);
  cycle_with_springs.initialize_from(cycle);
  cycle_with_springs.set_springs(springs);
  MortarPreconditioner<3> in_w(cycle, basis);
  in_w.set_springs(springs);
  const MortarPreconditioner<3> springs_on_slaves(cycle_with_springs, basis);

  const std::vector<NodalBlock> none;
  const unsigned int on_K   = cg_iterations(SpringOperator(body.stiffness(), none), cycle, x, reduction);
  const unsigned int on_K_w = cg_iterations(SpringOperator(basis.stiffness(), none), in_w, x, reduction);
  const SpringOperator sprung(basis.stiffness(), springs);
  const unsigned int cycle_of_K  = cg_iterations(sprung, in_w, x, reduction);
  const unsigned int with_slaves = cg_iterations(sprung, springs_on_slaves, x, reduction);

  std::cout << std::boolalpha << "levels: " << (cycle.n_levels() > 1) << std::endl
            << "CG on K_w as on K (within 2 iterations): "
            << (on_K_w <= on_K + 2 && on_K <= on_K_w + 2) << std::endl
            << "with springs, the cycle of K alone takes fewer iterations "
               "than with the springs on the slave dofs: "
            << (cycle_of_K < with_slaves) << std::endl
            << "-- iterations: K " << on_K << ", K_w " << on_K_w
            << ", K_w + S: " << cycle_of_K << " with the cycle of K, "
            << with_slaves << " with the springs on the slave dofs" << std::endl;
  return 0;
}
