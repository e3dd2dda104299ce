#pragma once

#include <deal.II/base/types.h>

#include <vector>

namespace FrictionalContact
{
  /// A symmetric block on the dofs of one node (of this rank), such as a
  /// spring that stands for a node condition in a preconditioner.
  struct NodalBlock
  {
    std::vector<dealii::types::global_dof_index> dofs;
    /// Row-major, dofs.size() x dofs.size().
    std::vector<double> values;
  };
} // namespace FrictionalContact
