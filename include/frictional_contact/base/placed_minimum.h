#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <frictional_contact/base/input.h>

#include <cmath>
#include <limits>
#include <string>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * The smallest of values met at points (a gap at a node, a det F in a
   * cell) and where it was met: kept while a rank loops over its nodes or
   * cells, then taken over the ranks for a message that names the place,
   * the same on every rank count. Infinite while nothing was met.
   */
  template <int dim>
  struct PlacedMinimum
  {
    double     value = std::numeric_limits<double>::infinity();
    Point<dim> at;

    /// Keeps @p candidate, met at @p where, if it is the smallest so far.
    void
    keep(const double candidate, const Point<dim> &where)
    {
      if (candidate < value)
        {
          value = candidate;
          at    = where;
        }
    }

    /// Whether something was met.
    bool
    met() const
    {
      return std::isfinite(value);
    }

    /// The smallest over the ranks of @p comm, with the point of the
    /// lowest rank that met it. Collective.
    PlacedMinimum
    over_ranks(const MPI_Comm comm) const
    {
      const Utilities::MPI::MinMaxAvg smallest = Utilities::MPI::min_max_avg(value, comm);
      PlacedMinimum result;
      result.value = smallest.min;
      result.at    = Utilities::MPI::broadcast(comm, at, smallest.min_index);
      return result;
    }

    /// The point as "(x, y[, z])".
    std::string
    place() const
    {
      std::string text;
      for (unsigned int d = 0; d < dim; ++d)
        text += (d == 0 ? "(" : ", ") + Input::to_text(at[d]);
      return text + ")";
    }
  };
} // namespace FrictionalContact
