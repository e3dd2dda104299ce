#pragma once

#include <deal.II/base/conditional_ostream.h>

#include <frictional_contact/postprocess/interface.h>

#include <ostream>
#include <string>

namespace FrictionalContact
{
  namespace Postprocess
  {
    /**
     * The screen lines of an increment: one line with the solver's
     * iterations, residuals and node counts, and after the last increment
     * the state of the run (residuals, candidates, force balance, max |u|).
     */
    template <int dim>
    void
    print_increment(const ConditionalOStream   &out,
                    const IncrementResult<dim> &result,
                    const std::string          &iteration_name,
                    const std::string          &last_linear_solve);

    /// The state after the last increment.
    template <int dim>
    void
    print_final_state(const ConditionalOStream &out, const IncrementResult<dim> &result);
  } // namespace Postprocess
} // namespace FrictionalContact
