#include <frictional_contact/base/input.h>
#include <frictional_contact/driver/loading_history.h>

#include <algorithm>

namespace FrictionalContact
{
  namespace
  {
    /// The defaults of the entries that others replace.
    const std::string default_end_time             = "1";
    const std::string default_number_of_increments = "1";
    const std::string default_load_factor          = "t";
  } // namespace



  void
  LoadingHistory::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("End time",
                      default_end_time,
                      Patterns::Double(0.),
                      "The loading history runs over [0, End time] (> 0).");
    prm.declare_entry("Number of increments",
                      default_number_of_increments,
                      Patterns::Integer(1),
                      "Equal increments that divide [0, End time] (>= 1).");
    prm.declare_entry("Increment times",
                      "",
                      Patterns::Anything(),
                      "If not empty: the end times of the increments, "
                      "increasing and positive, separated by commas; they "
                      "replace End time and Number of increments.");
    prm.declare_entry("Load factor",
                      default_load_factor,
                      Patterns::Anything(),
                      "lambda(t), a muParser expression of the time t that "
                      "scales all loads (tractions, pressures and body force). The "
                      "default reaches the full load at t = 1.");
    prm.declare_entry("Load table",
                      "",
                      Patterns::Anything(),
                      "If not empty: lambda(t) as a piecewise-linear table "
                      "'t_0: lambda_0; t_1: lambda_1; ...' with increasing "
                      "times, constant beyond its ends; replaces Load factor.");
  }



  LoadingHistory::LoadingHistory(ParameterHandler &prm)
  {
    const std::string times_entry = "Loading/Increment times";
    const std::string times_text  = prm.get("Increment times");
    if (Input::split(times_text, ',').empty())
      {
        const double       end_time = prm.get_double("End time");
        const unsigned int n        = prm.get_integer("Number of increments");
        if (!(end_time > 0))
          Input::fail("Loading/End time",
                      prm.get("End time"),
                      "a positive time is expected");
        for (unsigned int l = 1; l <= n; ++l)
          times.push_back(end_time * l / n);
      }
    else
      {
        if (prm.get("End time") != default_end_time ||
            prm.get("Number of increments") != default_number_of_increments)
          overridden.push_back("<Loading/Increment times> replaces <Loading/"
                               "End time> and <Loading/Number of increments>");
        for (const std::string &item : Input::split(times_text, ','))
          {
            const double t = Input::parse_vector<1>(times_entry, item)[0];
            if (!(t > (times.empty() ? 0. : times.back())))
              Input::fail(times_entry,
                          times_text,
                          "positive times in increasing order are expected");
            times.push_back(t);
          }
      }

    const std::string table_entry = "Loading/Load table";
    const std::string table_text  = prm.get("Load table");
    for (const std::string &item : Input::split(table_text, ';'))
      {
        const std::vector<std::string> pair = Input::split(item, ':');
        if (pair.size() != 2)
          Input::fail(table_entry, table_text, "pairs 't: lambda' separated by ';'");
        const double t = Input::parse_vector<1>(table_entry, pair[0])[0];
        if (!factor_table.empty() && !(t > factor_table.back().first))
          Input::fail(table_entry, table_text, "the times must increase");
        factor_table.emplace_back(t, Input::parse_vector<1>(table_entry, pair[1])[0]);
      }
    if (factor_table.empty())
      {
        factor_text     = prm.get("Load factor");
        factor_function = std::make_unique<TimeFunction>("Loading/Load factor",
                                                         factor_text,
                                                         1);
      }
    else
      {
        factor_text = "table " + table_text;
        if (prm.get("Load factor") != default_load_factor)
          overridden.push_back(
            "<Loading/Load table> replaces <Loading/Load factor>");
      }
  }



  double
  LoadingHistory::load_factor(const double t) const
  {
    if (factor_table.empty())
      return factor_function->value(t);
    if (t <= factor_table.front().first)
      return factor_table.front().second;
    if (t >= factor_table.back().first)
      return factor_table.back().second;
    const auto after = std::upper_bound(
      factor_table.begin(), factor_table.end(), t, [](const double t, const auto &entry) {
        return t < entry.first;
      });
    const auto before = after - 1;
    const double w = (t - before->first) / (after->first - before->first);
    return (1 - w) * before->second + w * after->second;
  }



  std::string
  LoadingHistory::describe() const
  {
    return std::to_string(times.size()) + " increment" +
           (times.size() > 1 ? "s" : "") + " to t = " +
           Input::to_text(times.back()) + ", load factor " + factor_text;
  }
} // namespace FrictionalContact
