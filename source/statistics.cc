#include <deal.II/base/mpi.h>

#include <frictional_contact/files.h>
#include <frictional_contact/statistics.h>

#include <sstream>

namespace FrictionalContact
{
  void
  StatisticsFile::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Write statistics",
                      "true",
                      Patterns::Bool(),
                      "Write the file 'statistics': one row per increment "
                      "(columns are described in its header).");
    prm.leave_subsection();
  }



  StatisticsFile::StatisticsFile(ParameterHandler  &prm,
                                 const std::string &output_directory,
                                 const MPI_Comm     comm)
    : file_name(output_directory + "/statistics")
    , comm(comm)
  {
    prm.enter_subsection("Output");
    write_file = prm.get_bool("Write statistics");
    prm.leave_subsection();
  }



  void
  StatisticsFile::add_scientific(const std::string &column, const double value)
  {
    table.add_value(column, value);
    table.set_scientific(column, true);
    table.set_precision(column, 10);
  }



  void
  StatisticsFile::write() const
  {
    if (!write_file)
      return;
    run_on_root(comm, [&]() {
      std::ostringstream out;
      table.write_text(out, TableHandler::table_with_separate_column_description);
      write_file_atomically(file_name, out.str());
    });
  }
} // namespace FrictionalContact
