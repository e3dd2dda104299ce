// SpringAMG, the preconditioner of the Newton systems, on the stiffness of
// Kanno's example II at N_Y = 8 (d = 3,888) and N_Y = 16 (d = 27,744). ML
// makes two levels or more of both; the first coarse level of N_Y = 8 is
// small enough for ML to factor it, and SpringAMG factors it directly
// after each change of the springs, while that of N_Y = 16 gets an ML
// hierarchy of its own. On both:
// - without springs it is ML's own V-cycle: AMG-CG on K takes as many
//   iterations (within 3) as with ML's preconditioner, or at most 1.6
//   times as many + 2 with a hierarchy of its own on the first coarse
//   level;
// - with stiff springs (10 c_j) in all directions at the bottom candidates
//   (every node sticking) its cheap update is as good (the same bands) as
//   an ML hierarchy built anew on K + S, and at least twice as good as the
//   AMG of K, which does not see the springs;
// - it is symmetric (CG needs that): (x, M y) = (y, M x) to 1e-12;
// - springs in rotated local frames (a sphere's) give the same nodal
//   blocks as T_j B T_j^T computed by hand;
// - K stored in single-precision nodal blocks (NodalBlockMatrix, whose
//   products the V-cycle's fine level takes) multiplies as K does, to
//   single precision.
// Only true/false is printed, so the output holds for any BLAS and rank
// count.
#include <deal.II/base/mpi.h>
#include <deal.II/lac/solver_control.h>

#include <frictional_contact/driver/simulator.h>
#include <frictional_contact/solvers/nodal_block_matrix.h>
#include <frictional_contact/solvers/shifted_stiffness_solver.h>
#include <frictional_contact/solvers/spring_amg.h>

#include <iostream>

#include "with_springs.h"

using namespace FrictionalContact;
using TrilinosVector = TrilinosWrappers::MPI::Vector;

namespace
{
  using SpringMatrix = WithSprings<TrilinosWrappers::SparseMatrix>;

  /// The preconditioner of K that a ShiftedStiffnessSolver made.
  class StiffnessAMG
  {
  public:
    explicit StiffnessAMG(const ShiftedStiffnessSolver &solver)
      : solver(solver)
    {}

    void
    vmult(TrilinosVector &dst, const TrilinosVector &src) const
    {
      solver.precondition_stiffness(dst, src);
    }

  private:
    const ShiftedStiffnessSolver &solver;
  };

  /// The reduction of |b| (b = (K + S) 1) the CG solves below are
  /// counted to.
  constexpr double reduction = 1e-10;

  /// Example II with N_X = 2 N_Y = 2 N_Z.
  std::string
  scene(const unsigned int n_y)
  {
    const std::string n = std::to_string(n_y), n_x = std::to_string(2 * n_y);
    return "include " SOURCE_DIR "/../parameters/example2.prm\n"
           "subsection Geometry\n subsection Box\n  set X repetitions = " +
           n_x + "\n  set Y repetitions = " + n + "\n  set Z repetitions = " +
           n + "\n end\nend\nsubsection Postprocess\n subsection "
           "Visualization\n  set Write vtu = false\n end\nend\n"
           "subsection Output\n set Write statistics = false\nend\n";
  }

  /// Prints the checks above for example II at @p n_y.
  void
  check(const unsigned int n_y)
  {
    const bool     root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    ParameterHandler prm;
    Simulator<3>::declare_parameters(prm);
    prm.parse_input_from_string(scene(n_y));
    Simulator<3> simulator(prm, MPI_COMM_WORLD);
    simulator.setup();
    const ElasticBody<3>                 &body    = simulator.get_model().get_body();
    const ContactOperator<3>             &contact = simulator.get_model().get_contact();
    const TrilinosWrappers::SparseMatrix &K       = body.stiffness().matrix("the test");

    ShiftedStiffnessSolver linear_solver(prm, 3);
    linear_solver.initialize(body.stiffness(), body.rigid_body_modes());
    linear_solver.prepare_stiffness_preconditioner();
    auto &spring_amg = dynamic_cast<SpringAMG &>(linear_solver.spring_preconditioner());

    // The springs of every candidate sticking: 10 c_j in all directions.
    const std::vector<double> c = contact.normal_stiffness(body.stiffness());
    std::vector<NodalBlock>   springs(contact.n_local());
    for (unsigned int j = 0; j < contact.n_local(); ++j)
      contact.nodal_block(j, 10 * c[j] * unit_symmetric_tensor<3>(), springs[j]);

    // ML built anew on K + S, for comparison.
    TrilinosWrappers::SparseMatrix K_with_springs;
    K_with_springs.copy_from(K);
    for (const NodalBlock &block : springs)
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
          K_with_springs.add(block.dofs[a], block.dofs[b], block.values[3 * a + b]);
    K_with_springs.compress(VectorOperation::add);
    ShiftedStiffnessSolver rebuilt(prm, 3);
    const AssembledStiffness with_springs(K_with_springs);
    rebuilt.initialize(with_springs, body.rigid_body_modes());
    rebuilt.prepare_stiffness_preconditioner();

    TrilinosVector ones = body.make_vector();
    ones        = 1;
    const std::vector<NodalBlock> none;
    const SpringMatrix            plain(K, none), sprung(K, springs);

    const unsigned int ml_plain = cg_iterations(plain, StiffnessAMG(linear_solver), ones, reduction);
    spring_amg.set_springs(none);
    const unsigned int ours_plain = cg_iterations(plain, spring_amg, ones, reduction);
    const unsigned int ml_blind   = cg_iterations(sprung, StiffnessAMG(linear_solver), ones, reduction);
    const unsigned int ml_rebuilt = cg_iterations(sprung, StiffnessAMG(rebuilt), ones, reduction);
    spring_amg.set_springs(springs);
    const unsigned int ours_sprung = cg_iterations(sprung, spring_amg, ones, reduction);

    TrilinosVector x = body.make_vector(), y = body.make_vector();
    for (const auto i : body.locally_owned_dofs())
      {
        x[i] = std::sin(1. * i);
        y[i] = std::cos(2. * i);
      }
    TrilinosVector Mx(x), My(y);
    spring_amg.vmult(Mx, x);
    spring_amg.vmult(My, y);
    const double asymmetry = std::abs(x * My - y * Mx) / std::abs(x * My);

    // The nodal blocks against T_j B T_j^T: u^T block u = (T_j^T u)^T B (T_j^T u).
    double block_defect = 0;
    for (unsigned int j = 0; j < contact.n_local(); ++j)
      {
        Tensor<2, 3> B;
        B[0][0] = 3, B[1][1] = 2, B[2][2] = 1, B[0][1] = B[1][0] = 0.5;
        NodalBlock block;
        contact.nodal_block(j, B, block);
        const Tensor<1, 3> local = contact.local_part(j, x);
        double             direct = 0;
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            direct += x[block.dofs[a]] * block.values[3 * a + b] * x[block.dofs[b]];
        block_defect = std::max(block_defect,
                                std::abs(direct - local * (B * local)) /
                                  (1 + std::abs(direct)));
      }
    block_defect = Utilities::MPI::max(block_defect, MPI_COMM_WORLD);

    const NodalBlockMatrix K_in_blocks(K, 3);
    TrilinosVector         Kx(x), difference(x);
    K.vmult(Kx, x);
    if (!K_in_blocks.empty())
      K_in_blocks.vmult(difference, x);
    difference -= Kx;
    const double block_product_error = difference.l2_norm() / Kx.l2_norm();

    // With its own ML hierarchy (plain aggregation below it) the first
    // coarse level is solved less well than by ML's smoothed aggregation:
    // 18 and 19 iterations against 13 at N_Y = 16 on one rank, 20 and 21
    // against 13 and 14 on three.
    const bool direct = spring_amg.factors_first_coarse_level();
    const auto near   = [direct](const unsigned int ours, const unsigned int ml) {
      return direct ? ours <= ml + 3 : 5 * ours <= 8 * ml + 10;
    };
    const std::string band = direct ? "within 3" : "at most 1.6 times + 2";
    if (root)
      std::cout << std::boolalpha << "N_Y = " << n_y << std::endl
                << "two levels: " << spring_amg.initialized() << std::endl
                << "first coarse level factored directly: " << direct
                << std::endl
                << "without springs, as ML's V-cycle (" << band
                << " iterations): "
                << (near(ours_plain, ml_plain) && ml_plain <= ours_plain + 3)
                << std::endl
                << "with springs, as ML built anew on K + S (" << band
                << "): " << near(ours_sprung, ml_rebuilt) << std::endl
                << "with springs, at most half the iterations of the AMG of K: "
                << (2 * ours_sprung <= ml_blind) << std::endl
                << "symmetric: " << (asymmetry < 1e-12) << std::endl
                << "nodal blocks are T_j B T_j^T: " << (block_defect < 1e-12)
                << std::endl
                << "K in nodal blocks: " << !K_in_blocks.empty() << std::endl
                << "K in nodal blocks multiplies as K (to 1e-6): "
                << (block_product_error < 1e-6) << std::endl;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check(8);
  check(16);
  return 0;
}
