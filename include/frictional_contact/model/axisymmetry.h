#pragma once

#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>

#include <frictional_contact/material/material.h>

#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * What an axisymmetric scene (<Material/Two-dimensional model> =
   * axisymmetric) adds to a 2D mesh: x is the radius r, y the axis. Every
   * integral over the section carries the weight 2 pi r (forces and areas
   * are totals over the revolution), the vertices on the axis keep u_r = 0,
   * and no vertex may lie at r < 0. The strain's hoop part u_r / r is the
   * element's (ElasticBody, BodyResponse).
   */
  namespace Axisymmetry
  {
    /// A total of nodal forces of the section as a total over the
    /// revolution: their radial parts cancel about the axis.
    template <int dim>
    inline Tensor<1, dim>
    revolution_total(Tensor<1, dim> total)
    {
      total[0] = 0;
      return total;
    }

    /// 2 pi r at @p point.
    template <int dim>
    inline double
    weight(const Point<dim> &point)
    {
      return 2. * numbers::PI * point[0];
    }

    /**
     * Refuses, in one line on every rank, a mesh with a vertex at r < 0 (a
     * body across the axis); returns the distance below which a vertex
     * lies on the axis (a small fraction of the mesh's radial extent).
     * Collective.
     */
    template <int dim>
    double
    check_radii(const DoFHandler<dim> &dof_handler);

    /// Adds u_r = 0 to @p constraints at each vertex of the locally
    /// relevant cells within @p on_axis of the axis that no constraint
    /// holds already (hanging vertices follow their parents).
    template <int dim>
    void
    hold_axis(const DoFHandler<dim>     &dof_handler,
              const double               on_axis,
              AffineConstraints<double> &constraints);

    /**
     * The strain of the shape function @p i of the vector-valued Q1
     * element at point @p q of @p fe_values (values, gradients, points):
     * its in-plane symmetric gradient, and for a radial component the hoop
     * strain N_i / r in the (2, 2) entry.
     */
    SymmetricTensor<2, 3>
    shape_strain(const FEValues<2> &fe_values, const unsigned int i, const unsigned int q);

    /**
     * The stiffness of linear elasticity of the cell at which @p fe_values
     * stand, of the body's 3D elastic constants @p material (the standard
     * or the B-bar element), into @p cell_matrix; the integrals of the
     * shape functions' divergences (the hoop strain included) and the
     * cell's volume of revolution into @p divergence_integral and
     * @p volume.
     */
    void
    cell_stiffness(const ElasticConstants<3> &material,
                   const FEValues<2>         &fe_values,
                   FullMatrix<double>        &cell_matrix,
                   std::vector<double>       &divergence_integral,
                   double                    &volume);
  } // namespace Axisymmetry
} // namespace FrictionalContact
