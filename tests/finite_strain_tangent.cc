// The finite-strain element's tangent against central differences of its
// internal force, for each law at finite strain (St. Venant-Kirchhoff, the
// compressible neo-Hookean law, the nearly incompressible one with its
// coupling through the cell's mean volume ratio, or the point's), at the
// Gauss points and at the Gauss-Lobatto points (the corners'), and of J2
// plasticity at small strain on the B-bar element (flowing at every
// point: the consistent tangent of the return map) and at finite strain
// (the exponential map's tangent from a committed plastic state of another
// deformation, on the mean-dilatation element and on the standard one): a ball's
// mesh (distorted cells) under a smooth displacement of 20 % strains, K_T v
// compared with
// (f(u + h v) - f(u - h v)) / 2h for a direction v over every free dof.
#include <deal.II/base/mpi.h>

#include <frictional_contact/driver/increment_response.h>
#include <frictional_contact/driver/simulator.h>
#include <frictional_contact/model/model.h>

#include <cmath>
#include <iostream>

using namespace FrictionalContact;

namespace
{
  template <int dim>
  void
  check(const std::string &law,
        const std::string &volume_ratio = "",
        const std::string &quadrature   = "Gauss",
        const std::string &kinematics   = "finite strain")
  {
    ParameterHandler prm;
    Simulator<dim>::declare_parameters(prm);
    prm.parse_input_from_string("subsection Geometry\n  set Model name = half ball\nend\n"
                                "subsection Mesh refinement\n  set Global refinements = 1\nend\n"
                                "subsection Material\n  set Model = " + law +
                                "\n  set Kinematics = " + kinematics + "\n"
                                "  set Poisson's ratio = 0.45\n" +
                                (kinematics == "finite strain" ?
                                   "  set Quadrature = " + quadrature + "\n" :
                                   std::string()) +
                                (law == "J2 plasticity" ?
                                   "  subsection J2 plasticity\n"
                                   "    set Yield stress = 0.001\n"
                                   "    set Isotropic hardening modulus = 0.05\n  end\n" :
                                   std::string()) +
                                (law == "J2 plasticity" && !volume_ratio.empty() ?
                                   "  set Formulation = " + volume_ratio + "\n" :
                                   std::string()) +
                                (volume_ratio.empty() || law == "J2 plasticity" ?
                                   std::string() :
                                   "  subsection Nearly incompressible neo-Hookean\n"
                                   "    set Volume ratio = " + volume_ratio + "\n  end\n") +
                                "end\n"
                                "subsection Boundary conditions\n  set Fixed boundaries = top\nend\n");
    Model<dim> model(prm, MPI_COMM_WORLD);
    model.setup();
    model.assemble();
    const ElasticBody<dim> &body = model.get_body();

    // u: a smooth field of about 20 % strain; v: another one.
    using Vector = TrilinosWrappers::MPI::Vector;
    Vector u = body.make_vector(), v = body.make_vector(), first = body.make_vector();
    const IndexSet &owned = body.locally_owned_dofs();
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int vertex : cell->vertex_indices())
          for (unsigned int c = 0; c < dim; ++c)
            {
              const auto        g = cell->vertex_dof_index(vertex, c);
              const Point<dim> &x = cell->vertex(vertex);
              if (!owned.is_element(g))
                continue;
              u[g]     = 0.2 * std::sin(1.3 * x[0] + 0.7 * x[dim - 1] + c);
              first[g] = 0.15 * std::sin(0.9 * x[0] - 1.1 * x[dim - 1] + 2. * c);
              v[g] = std::cos(2.1 * x[0] - 0.4 * x[dim - 1] + 2. * c);
            }
    u.compress(VectorOperation::insert);
    first.compress(VectorOperation::insert);
    // The finite-strain plastic law from a committed plastic state of
    // another deformation (Cp^-1 not I, principal axes not those of u's).
    if (law == "J2 plasticity" && kinematics == "finite strain")
      model.commit(first);
    v.compress(VectorOperation::insert);
    body.get_constraints().set_zero(v);

    // K_T(u) v from the response at u (N(du) = f(u + du) - f(u)): started
    // at u with no lifting, then evaluated there with the tangent, so that
    // N is the law's and not its linearisation.
    const Vector           no_motion = body.make_vector();
    Vector                 K_v = body.make_vector(), plus = body.make_vector(),
           minus = body.make_vector();
    IncrementResponse<dim> response(model, nullptr, u, no_motion);
    response.internal_force_change(no_motion, plus, true);
    body.stiffness().vmult(K_v, v);
    // Symmetry: w . K v = v . K w for another direction w (every law here
    // has a potential, the return maps an incremental one).
    const double asymmetry = [&] {
      Vector w = u, K_w = body.make_vector();
      body.get_constraints().set_zero(w);
      body.stiffness().vmult(K_w, w);
      return std::abs(w * K_v - v * K_w) / (K_v.l2_norm() * w.l2_norm());
    }();
    const double h = 1e-6;
    Vector step = v;
    step *= h;
    response.internal_force_change(step, plus, false);
    step *= -1.;
    response.internal_force_change(step, minus, false);
    plus -= minus;
    plus /= 2 * h;
    const double difference = [&] {
      Vector d = plus;
      d -= K_v;
      return d.l2_norm() / K_v.l2_norm();
    }();
    // A plastic law is checked where it flows (the consistent tangent).
    const types::global_dof_index points =
      body.get_dof_handler().get_triangulation().n_global_active_cells() *
      QGauss<dim>(2).size();
    const std::string flow =
      law != "J2 plasticity" ?
        "" :
        response.plastic_points() == points ?
        ", every point flowing" :
        ", " + std::to_string(response.plastic_points()) + " of " +
          std::to_string(points) + " points flowing";
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << dim << "D, " << law
                << (volume_ratio.empty() ? "" :
                    law == "J2 plasticity" ? " (formulation: " + volume_ratio + ")" :
                                             " (volume ratio: " + volume_ratio + ")")
                << (quadrature == "Gauss" ? "" : " (" + quadrature + " points)")
                << (kinematics == "finite strain" ? "" : " (" + kinematics + ", B-bar")
                << flow << (kinematics == "finite strain" ? "" : ")")
                << ": K_T v against central differences: "
                << (difference < 1e-6 ? "agree within 1e-6" : "DIFFER")
                << (asymmetry < 1e-12 ? ", K_T symmetric" : ", K_T NOT SYMMETRIC") << std::endl;
    if (!(asymmetry < 1e-12) && Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << "  asymmetry " << asymmetry << std::endl;
    if (!(difference < 1e-6) && Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << "  relative difference " << difference << std::endl;
  }
} // namespace



int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const std::string law :
       {"linear elastic", "neo-Hookean", "nearly incompressible neo-Hookean"})
    {
      check<2>(law);
      check<3>(law);
    }
  check<2>("nearly incompressible neo-Hookean", "point");
  check<3>("nearly incompressible neo-Hookean", "point");
  for (const std::string law : {"neo-Hookean", "nearly incompressible neo-Hookean"})
    {
      check<2>(law, "", "Gauss-Lobatto");
      check<3>(law, "", "Gauss-Lobatto");
    }
  check<2>("nearly incompressible neo-Hookean", "point", "Gauss-Lobatto");
  check<3>("nearly incompressible neo-Hookean", "point", "Gauss-Lobatto");
  check<2>("J2 plasticity", "", "Gauss", "small strain");
  check<3>("J2 plasticity", "", "Gauss", "small strain");
  // The finite-strain J2 law (Hencky, exponential map) on the
  // mean-dilatation element (auto) and on the standard one.
  for (const std::string formulation : {"auto", "standard"})
    {
      check<2>("J2 plasticity", formulation);
      check<3>("J2 plasticity", formulation);
    }
}
