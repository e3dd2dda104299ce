#pragma once

#include <deal.II/base/function_parser.h>

#include <memory>
#include <string>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * A scalar or vector function of time only, from a muParser expression
   * (components separated by ';'). Bad expressions are reported as an
   * InputError naming @p entry, values that are not finite as a
   * NonFiniteInput naming @p entry and the time.
   */
  class TimeFunction
  {
  public:
    TimeFunction(const std::string &entry,
                 const std::string &expression,
                 const unsigned int n_components);

    double
    value(const double t, const unsigned int component = 0) const;

  private:
    std::string                        entry;
    std::unique_ptr<FunctionParser<1>> function;
  };
} // namespace FrictionalContact
