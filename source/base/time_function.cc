#include <frictional_contact/base/input.h>
#include <frictional_contact/base/time_function.h>

#include <cmath>

namespace FrictionalContact
{
  TimeFunction::TimeFunction(const std::string &entry,
                             const std::string &expression,
                             const unsigned int n_components)
    : entry(entry)
    , function(std::make_unique<FunctionParser<1>>(n_components))
  {
    try
      {
        function->initialize("x,t", expression, {{"pi", M_PI}}, true);
        // muParser finds most mistakes only when evaluating.
        for (unsigned int c = 0; c < n_components; ++c)
          function->value(Point<1>(), c);
      }
    catch (const ExceptionBase &)
      {
        Input::fail(entry,
                    expression,
                    "a muParser expression in t is expected" +
                      std::string(n_components > 1 ?
                                    ", with " + std::to_string(n_components) +
                                      " components separated by ';'" :
                                    "") +
                      " (e.g. 'min(t, 1)', 'if(t < 2, 0, 0.1 * (t - 2))')");
      }
  }



  double
  TimeFunction::value(const double t, const unsigned int component) const
  {
    function->set_time(t);
    const double result = function->value(Point<1>(), component);
    Input::require_finite(result, entry, t);
    return result;
  }
} // namespace FrictionalContact
