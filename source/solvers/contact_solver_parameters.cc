#include <frictional_contact/base/plugins.h>
#include <frictional_contact/solvers/contact_solver_parameters.h>

namespace FrictionalContact
{
  template <int dim>
  void
  ContactSolverParameters<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact solver");
    PluginRegistry<ContactSolver<dim>>::declare_parameters(
      prm,
      "semismooth Newton",
      "The method that solves each incremental contact problem.",
      "Method");
    prm.declare_entry("Report every",
                      "0",
                      Patterns::Integer(0),
                      "Print the residuals every this many iterations of the "
                      "contact solver (0: only one line per increment).");
    prm.declare_entry("Eigenvalue tolerance",
                      "1e-8",
                      Patterns::Double(0., 1.),
                      "Relative accuracy of mu_pi, the smallest eigenvalue "
                      "of K, which sets the acceleration of Algorithm 2.");
    prm.declare_entry("Try the elastic solution first",
                      "true",
                      Patterns::Bool(),
                      "Before the contact iteration of an increment, solve "
                      "K du = p once: if no candidate then reaches the "
                      "obstacle, this is the solution (every node free, "
                      "r = 0) and the iteration is skipped. Algorithm 2 "
                      "converges very slowly when nothing touches. The "
                      "semismooth Newton method never tries it: its first "
                      "iteration is that elastic solve, and a body that "
                      "touches nothing converges with every node free.");
    prm.declare_entry("Start from the last increment",
                      "auto",
                      Patterns::Selection("auto|true|false"),
                      "Start each increment's contact solve from the last "
                      "increment's displacement increment, scaled by the "
                      "ratio of their lengths in time (a linear "
                      "extrapolation of the motion), instead of from no "
                      "displacement beyond the prescribed one, where the "
                      "increment goes on the way the last one went: the "
                      "prescribed displacements, the load factor and the "
                      "obstacle's and tool's motions each point within 25 "
                      "degrees of the last increment's, at a pace within a "
                      "factor 2. The solution is the same; where the motion "
                      "is smooth across increments it takes fewer "
                      "iterations (doc/performance.md). Not after a change "
                      "of the mesh, at the first increment, or at the first "
                      "increment of a resumed run; where such a start does "
                      "not converge, the increment is solved again from no "
                      "motion before it is cut. auto: true for the "
                      "semismooth Newton method; false for Kanno's methods, "
                      "which take about as many iterations from either start "
                      "and start from no motion, as the paper does.");
    prm.declare_entry("Lanczos vectors",
                      "20",
                      Patterns::Integer(4),
                      "Lanczos vectors PARPACK keeps while computing mu_pi "
                      "(>= 4).");
    prm.leave_subsection();
  }



  template <int dim>
  ContactSolverParameters<dim>::ContactSolverParameters(
    ParameterHandler         &prm,
    const ConditionalOStream &pcout)
  {
    prm.enter_subsection("Contact solver");
    method_name = prm.get("Method");
    method      = PluginRegistry<ContactSolver<dim>>::create(prm, "Method");
    method->set_output(pcout, prm.get_integer("Report every"));
    eigenvalue_tolerance = prm.get_double("Eigenvalue tolerance");
    lanczos_vectors      = prm.get_integer("Lanczos vectors");
    try_elastic_first    = prm.get_bool("Try the elastic solution first");
    const std::string start = prm.get("Start from the last increment");
    start_from_last_increment =
      start == "true" || (start == "auto" && method->gains_from_last_increment_start());
    prm.leave_subsection();
  }

  template struct ContactSolverParameters<2>;
  template struct ContactSolverParameters<3>;
} // namespace FrictionalContact
