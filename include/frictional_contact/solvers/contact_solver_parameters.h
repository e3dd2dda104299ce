#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <frictional_contact/solvers/contact_solver.h>

#include <memory>

namespace FrictionalContact
{
  /**
   * The subsection "Contact solver": the method (a plugin with its own
   * subsection) and the entries around it, read in one place for the
   * scenes of a mesh and for FCLIB problems alike.
   */
  template <int dim>
  struct ContactSolverParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    /// Reads the subsection and creates the method, which reports its
    /// progress on @p pcout.
    ContactSolverParameters(ParameterHandler         &prm,
                            const ConditionalOStream &pcout);

    std::string                         method_name;
    std::unique_ptr<ContactSolver<dim>> method;
    /// Relative accuracy of mu_pi and the Lanczos vectors PARPACK keeps.
    double       eigenvalue_tolerance;
    unsigned int lanczos_vectors;
    /// Whether an increment first tries the elastic solution.
    bool try_elastic_first;
    /// Whether a contact solve starts from the last increment's motion.
    bool start_from_last_increment;
  };
} // namespace FrictionalContact
