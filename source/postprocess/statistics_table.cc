#include <frictional_contact/postprocess/statistics_table.h>

#include <algorithm>
#include <sstream>

namespace FrictionalContact
{
  namespace Postprocess
  {
    void
    StatisticsTable::add_row(const Columns &columns)
    {
      const std::string missing = "-";
      for (const Column &column : columns)
        {
          if (std::find(labels.begin(), labels.end(), column.label) == labels.end())
            {
              for (unsigned int row = 0; row < rows; ++row)
                table.add_value(column.label, missing);
              labels.push_back(column.label);
            }
          if (const auto *count = std::get_if<std::uint64_t>(&column.value))
            table.add_value(column.label, *count);
          else
            {
              // Ten digits: the times of cut increments (0.1611328125)
              // differ in the fifth.
              table.add_value(column.label, std::get<double>(column.value));
              table.set_scientific(column.label, column.scientific);
              table.set_precision(column.label, 10);
            }
        }
      for (const std::string &label : labels)
        if (std::none_of(columns.begin(), columns.end(),
                         [&](const Column &column) { return column.label == label; }))
          table.add_value(label, missing);
      ++rows;
    }



    std::string
    StatisticsTable::text() const
    {
      std::ostringstream out;
      table.write_text(out, TableHandler::table_with_separate_column_description);
      return out.str();
    }



    void
    StatisticsTable::save(boost::archive::text_oarchive &archive) const
    {
      archive << table;
    }



    void
    StatisticsTable::load(boost::archive::text_iarchive &archive)
    {
      archive >> table;
      labels.clear();
      rows = 0;
      std::istringstream lines(text());
      for (std::string line; std::getline(lines, line);)
        if (line.rfind("# ", 0) == 0)
          labels.push_back(line.substr(line.find(": ") + 2));
        else if (!line.empty())
          ++rows;
    }
  } // namespace Postprocess
} // namespace FrictionalContact
