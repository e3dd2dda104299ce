#pragma once

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <frictional_contact/base/time_function.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * The loading history: the times t_1 < ... < t_n that end the increments
   * (a uniform division of [0, End time], or an explicit list) and the load
   * factor lambda(t) that scales all loads (tractions and body force),
   * given as a muParser expression of t or as a piecewise-linear table.
   */
  class LoadingHistory
  {
  public:
    /// Declares the entries of the times and the load factor, inside the
    /// subsection "Loading" (which IncrementDriver owns).
    static void
    declare_parameters(ParameterHandler &prm);

    /// Reads them, inside the subsection "Loading".
    explicit LoadingHistory(ParameterHandler &prm);

    /// End times of the increments, increasing, all > 0.
    const std::vector<double> &
    increment_times() const
    {
      return times;
    }

    double
    load_factor(const double t) const;

    /// "10 increments to t = 4, load factor: t"
    std::string
    describe() const;

    /// One line per entry the scene sets that another entry replaces.
    const std::vector<std::string> &
    overridden_entries() const
    {
      return overridden;
    }

  private:
    std::vector<double>                      times;
    /// One line per entry the scene sets that another entry replaces.
    std::vector<std::string>                 overridden;
    std::string                              factor_text;
    std::unique_ptr<TimeFunction>            factor_function;
    std::vector<std::pair<double, double>>   factor_table;
  };

} // namespace FrictionalContact
