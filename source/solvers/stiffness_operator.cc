#include <frictional_contact/solvers/stiffness_operator.h>

namespace FrictionalContact
{
  std::vector<FullMatrix<double>>
  AssembledStiffness::blocks(
    const std::vector<std::vector<types::global_dof_index>> &nodes) const
  {
    std::vector<FullMatrix<double>> result;
    result.reserve(nodes.size());
    for (const auto &dofs : nodes)
      {
        FullMatrix<double> block(dofs.size(), dofs.size());
        for (unsigned int a = 0; a < dofs.size(); ++a)
          for (unsigned int b = 0; b < dofs.size(); ++b)
            block(a, b) = K.el(dofs[a], dofs[b]);
        result.push_back(std::move(block));
      }
    return result;
  }
} // namespace FrictionalContact
