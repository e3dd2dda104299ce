#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/table_handler.h>

#include <string>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * The statistics file: one row per increment with documented columns,
   * kept in a TableHandler and rewritten (atomically, by rank 0) after
   * every increment, so that an interrupted run keeps all finished rows.
   */
  class StatisticsFile
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    StatisticsFile(ParameterHandler  &prm,
                   const std::string &output_directory,
                   const MPI_Comm     comm);

    bool
    enabled() const
    {
      return write_file;
    }

    /// Adds a value to the current row (column created on first use).
    template <typename T>
    void
    add(const std::string &column, const T &value)
    {
      table.add_value(column, value);
    }

    /// Like add(), for a double printed in scientific notation.
    void
    add_scientific(const std::string &column, const double value);

    /// Writes the table with all rows so far.
    void
    write() const;

    /// The rows so far, for checkpoints.
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &table;
    }

  private:
    bool        write_file;
    std::string file_name;
    MPI_Comm    comm;
    TableHandler table;
  };
} // namespace FrictionalContact
