#pragma once

#include <deal.II/base/table_handler.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace FrictionalContact
{
  namespace Postprocess
  {
    using namespace dealii;

    /// One column of the statistics file: a label and a value.
    struct Column
    {
      std::string                         label;
      std::variant<std::uint64_t, double> value;
      /// Whether a double is printed in scientific notation.
      bool scientific = false;
    };

    using Columns = std::vector<Column>;

    /**
     * The rows of the statistics file, one per increment, in deal.II's
     * TableHandler. Every column keeps every row: a column that the rows
     * of a checkpoint lack (written by another version of the program)
     * reads "-" (no value) in them, and one of theirs that later rows no
     * longer carry reads "-" from there on. Owns the table, its labels in
     * their order and the number of its rows.
     */
    class StatisticsTable
    {
    public:
      void
      add_row(const Columns &columns);

      /// The file's text: a line "# k: label" per column, then the rows.
      std::string
      text() const;

      /// Into a checkpoint: the TableHandler alone (as checkpoints have
      /// always held it).
      void
      save(boost::archive::text_oarchive &archive) const;

      /// From a checkpoint; the labels and rows from the table's text.
      void
      load(boost::archive::text_iarchive &archive);

    private:
      TableHandler             table;
      std::vector<std::string> labels;
      unsigned int             rows = 0;
    };
  } // namespace Postprocess
} // namespace FrictionalContact
