// The statistics table of a run resumed from a checkpoint that another
// version of the program wrote: its rows have the columns Increment and
// Time; the resumed run's rows add Smallest det F ("-", no value, in the
// rows before) and then drop Time ("-" from there on). Every column keeps
// every row, so that the file stays a table (a column shorter than the
// others made TableHandler read past its end).
#include <frictional_contact/postprocess/statistics_table.h>

#include <iostream>
#include <sstream>

using namespace FrictionalContact::Postprocess;

int
main()
{
  StatisticsTable written;
  written.add_row({{"Increment", std::uint64_t(1)}, {"Time", 0.5}});
  written.add_row({{"Increment", std::uint64_t(2)}, {"Time", 1.}});
  std::ostringstream checkpoint;
  {
    boost::archive::text_oarchive archive(checkpoint);
    written.save(archive);
  }

  StatisticsTable resumed;
  std::istringstream in(checkpoint.str());
  {
    boost::archive::text_iarchive archive(in);
    resumed.load(archive);
  }
  resumed.add_row({{"Increment", std::uint64_t(3)},
                   {"Time", 1.5},
                   {"Smallest det F", 0.75, true}});
  resumed.add_row({{"Increment", std::uint64_t(4)}, {"Smallest det F", 0.5, true}});
  std::cout << resumed.text();
}
