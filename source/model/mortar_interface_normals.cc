#include <deal.II/base/symmetric_tensor.h>

#include <frictional_contact/model/mortar_interface.h>

namespace FrictionalContact
{
  // How the slave nodes' averaged normals turn as the slave surface
  // moves: the Newton tangent's part from the turning frames of the pairs
  // whose rows follow the iterates (PairCouplings::turns()).



  template <int dim>
  void
  MortarInterface<dim>::take_normal_derivatives(const Vector &u_ghosted)
  {
    // Every face at a node, of any cell this rank sees: a node this rank
    // owns has all of its cells here, its own or ghosts.
    struct Sum
    {
      Tensor<1, dim>                                         normal;
      std::map<types::global_dof_index, std::pair<NodeDofs, Tensor<2, dim>>> derivatives;
    };
    std::map<types::global_dof_index, Sum> sums;
    for (const Face &face : slave_faces)
      {
        std::array<SlaveNode *, n_face_vertices> at;
        bool                                      any = false;
        for (unsigned int a = 0; a < n_face_vertices; ++a)
          {
            const auto found = nodes.find(face.dofs[a][0]);
            at[a] = found != nodes.end() && found->second.weight > 0 ? &found->second : nullptr;
            any   = any || at[a] != nullptr;
          }
        if (!any)
          continue;
        const MortarSegments::FaceVertices<dim> x = current_vertices(face, u_ghosted);
        const Tensor<1, dim> normal = outward_normal(x, face.orientation);
        const auto           D      = MortarSegments::unit_normal_derivatives<dim>(x);
        for (unsigned int a = 0; a < n_face_vertices; ++a)
          if (at[a] != nullptr)
            {
              Sum &sum = sums[face.dofs[a][0]];
              sum.normal += normal;
              for (unsigned int v = 0; v < n_face_vertices; ++v)
                {
                  auto &[dofs, derivative] = sum.derivatives[face.dofs[v][0]];
                  dofs = face.dofs[v];
                  derivative += face.orientation * D[v];
                }
            }
      }
    // n = N / |N| of the sum N of the faces' unit normals.
    for (auto &[dof, sum] : sums)
      {
        SlaveNode           &node   = nodes.at(dof);
        const double         length = sum.normal.norm();
        const Tensor<1, dim> n      = sum.normal / length;
        const Tensor<2, dim> across =
          (Tensor<2, dim>(unit_symmetric_tensor<dim>()) - outer_product(n, n)) / length;
        node.normal_derivatives.clear();
        for (const auto &[vertex, entry] : sum.derivatives)
          node.normal_derivatives.emplace_back(entry.first, across * entry.second);
      }
  }

  template void
  MortarInterface<2>::take_normal_derivatives(const Vector &);
  template void
  MortarInterface<3>::take_normal_derivatives(const Vector &);
} // namespace FrictionalContact
