#pragma once

#include <deal.II/base/mpi.h>

#include <vector>

namespace FrictionalContact
{
  /**
   * Every rank's @p local doubles, on every rank, in rank order: one
   * MPI_Allgatherv (Utilities::MPI::all_gather would serialize and
   * compress them through boost, a fixed cost that the mortar geometry,
   * gathered at every Newton iterate at finite strain, pays many times).
   */
  inline std::vector<std::vector<double>>
  gather_doubles(const MPI_Comm comm, const std::vector<double> &local)
  {
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    if (n_ranks == 1)
      return {local};
    const int        n_local = local.size();
    std::vector<int> counts(n_ranks);
    int error = MPI_Allgather(&n_local, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
    AssertThrowMPI(error);
    std::vector<int> offsets(n_ranks + 1, 0);
    for (unsigned int r = 0; r < n_ranks; ++r)
      offsets[r + 1] = offsets[r] + counts[r];
    std::vector<double> all(offsets.back());
    error = MPI_Allgatherv(local.data(), n_local, MPI_DOUBLE, all.data(), counts.data(),
                           offsets.data(), MPI_DOUBLE, comm);
    AssertThrowMPI(error);
    std::vector<std::vector<double>> parts(n_ranks);
    for (unsigned int r = 0; r < n_ranks; ++r)
      parts[r].assign(all.begin() + offsets[r], all.begin() + offsets[r + 1]);
    return parts;
  }
} // namespace FrictionalContact
