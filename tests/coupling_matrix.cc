// CouplingMatrix keeps its pattern while it holds the new entries: split
// over two ranks, entries that leave positions of the last pattern add
// none and take none away, those positions then hold zero, or one on the
// diagonal of a matrix with the identity; an entry at a new position adds
// just that one (the new pattern keeps the old positions), so that
// entries coming back add none. Each matrix is compared with a dense one
// of the entries it was given.
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>

#include <frictional_contact/model/pair_couplings.h>

#include <cmath>
#include <iostream>
#include <string>

using namespace FrictionalContact;

namespace
{
  constexpr unsigned int dofs_per_rank = 4;

  // Rows of this rank, columns anywhere: the entry (i, j) for each row i
  // of this rank and each listed offset, with values from the seed.
  Couplings
  entries_of(const IndexSet &owned, const std::vector<int> &offsets, const double seed)
  {
    Couplings couplings;
    for (const auto i : owned)
      for (const int offset : offsets)
        {
          const auto j = static_cast<types::global_dof_index>(
            (static_cast<int>(i) + offset + static_cast<int>(owned.size())) %
            static_cast<int>(owned.size()));
          couplings[{i, j}] = seed + 0.1 * i + 0.01 * j;
        }
    return couplings;
  }

  // The largest difference, over this rank's rows, between the matrix and
  // the entries plus (optionally) the identity where no entry is.
  double
  difference(const TrilinosWrappers::SparseMatrix &matrix,
             const IndexSet                       &owned,
             const Couplings                      &entries,
             const bool                            identity)
  {
    double largest = 0;
    for (const auto i : owned)
      for (types::global_dof_index j = 0; j < owned.size(); ++j)
        {
          const auto   entry    = entries.find({i, j});
          const double expected = entry != entries.end() ? entry->second :
                                  identity && i == j     ? 1. :
                                                           0.;
          largest = std::max(largest, std::abs(matrix.el(i, j) - expected));
        }
    return Utilities::MPI::max(largest, MPI_COMM_WORLD);
  }

  void
  check(const bool identity)
  {
    const MPI_Comm     comm   = MPI_COMM_WORLD;
    const unsigned int rank   = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_dofs = dofs_per_rank * Utilities::MPI::n_mpi_processes(comm);
    IndexSet           owned(n_dofs);
    owned.add_range(rank * dofs_per_rank, (rank + 1) * dofs_per_rank);
    owned.compress();

    CouplingMatrix coupling;
    // How many positions the take added to the pattern (all of them at
    // the first), over all ranks: a pattern made anew with fewer
    // positions than before would give a negative count.
    long long  positions = 0;
    const auto take      = [&](const Couplings &entries) {
      coupling.take(owned, comm, entries, identity);
      const auto now   = static_cast<long long>(coupling.matrix.n_nonzero_elements());
      const auto added = now - positions;
      positions        = now;
      return added;
    };
    const auto say = [&](const std::string &what, const long long added, const Couplings &entries) {
      const double error = difference(coupling.matrix, owned, entries, identity);
      if (rank == 0)
        std::cout << (identity ? "with identity, " : "entries only, ") << what
                  << ": positions added " << added << ", entries "
                  << (error == 0 ? "exact" : "WRONG by " + std::to_string(error))
                  << std::endl;
    };

    // Entries on the diagonal and beside it, across the ranks' borders.
    const Couplings first = entries_of(owned, {0, 1, -1, 5}, 1.);
    say("first entries", take(first), first);
    // The same positions, other values.
    const Couplings again = entries_of(owned, {0, 1, -1, 5}, 2.);
    say("same positions", take(again), again);
    // Fewer positions (the diagonal gone): zero or the identity's one there.
    const Couplings fewer = entries_of(owned, {1, 5}, 3.);
    say("fewer positions", take(fewer), fewer);
    // One rank's entry at a new position: every rank makes a new pattern.
    Couplings grown = entries_of(owned, {1}, 4.);
    if (rank == 0)
      grown[{0, n_dofs - 2}] = 9.;
    say("a new position on rank 0", take(grown), grown);
    // The old positions are kept in the new pattern: entries back there
    // need none.
    const Couplings back = entries_of(owned, {0, -1, 5}, 5.);
    say("old positions again", take(back), back);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check(false);
  check(true);
  return 0;
}
