#include <deal.II/base/mpi.h>

#include <frictional_contact/base/input.h>
#include <frictional_contact/model/axisymmetry.h>

#include <algorithm>
#include <limits>
#include <cmath>

namespace FrictionalContact
{
  namespace Axisymmetry
  {
    template <int dim>
    double
    check_radii(const DoFHandler<dim> &dof_handler)
    {
      double smallest = std::numeric_limits<double>::max(), largest = 0;
      Point<dim> place;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          for (const unsigned int v : cell->vertex_indices())
            {
              const Point<dim> &x = cell->vertex(v);
              largest             = std::max(largest, std::abs(x[0]));
              if (x[0] < smallest)
                {
                  smallest = x[0];
                  place    = x;
                }
            }
      const MPI_Comm comm = dof_handler.get_communicator();
      largest             = Utilities::MPI::max(largest, comm);
      const double on_axis = 1e-9 * largest;
      const auto   lowest = Utilities::MPI::min_max_avg(smallest, comm);
      if (lowest.min < -on_axis)
        {
          // The place of the lowest vertex, from the rank that has it.
          std::vector<double> coordinates(dim, 0.);
          if (smallest == lowest.min && Utilities::MPI::this_mpi_process(comm) == lowest.min_index)
            for (unsigned int d = 0; d < dim; ++d)
              coordinates[d] = place[d];
          Utilities::MPI::sum(coordinates, comm, coordinates);
          std::string where;
          for (unsigned int d = 0; d < dim; ++d)
            where += (d == 0 ? "(" : ", ") + Input::to_text(coordinates[d]);
          throw InputError("Material/Two-dimensional model = axisymmetric: the "
                           "mesh has a vertex at " + where + ") with x = r < 0; "
                           "an axisymmetric body lies in the half plane x >= 0, "
                           "its axis at x = 0: move or cut the geometry there");
        }
      return on_axis;
    }



    template <int dim>
    void
    hold_axis(const DoFHandler<dim>     &dof_handler,
              const double               on_axis,
              AffineConstraints<double> &constraints)
    {
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          for (const unsigned int v : cell->vertex_indices())
            if (std::abs(cell->vertex(v)[0]) <= on_axis)
              {
                const types::global_dof_index radial = cell->vertex_dof_index(v, 0);
                if (!constraints.is_constrained(radial))
                  constraints.add_line(radial);
              }
    }

    SymmetricTensor<2, 3>
    shape_strain(const FEValues<2> &fe_values, const unsigned int i, const unsigned int q)
    {
      const unsigned int    c = fe_values.get_fe().system_to_component_index(i).first;
      const Tensor<1, 2>    g = fe_values.shape_grad_component(i, q, c);
      SymmetricTensor<2, 3> strain;
      for (unsigned int m = 0; m < 2; ++m)
        strain[c][m] += (c == m ? 1. : 0.5) * g[m];
      if (c == 0)
        strain[2][2] = fe_values.shape_value_component(i, q, 0) / fe_values.quadrature_point(q)[0];
      return strain;
    }



    void
    cell_stiffness(const ElasticConstants<3> &material,
                   const FEValues<2>         &fe_values,
                   FullMatrix<double>        &cell_matrix,
                   std::vector<double>       &divergence_integral,
                   double                    &volume)
    {
      const unsigned int                 n = fe_values.dofs_per_cell;
      const SymmetricTensor<4, 3>       &C = material.stress_strain_tensor();
      std::vector<SymmetricTensor<2, 3>> strain(n);
      cell_matrix = 0;
      std::fill(divergence_integral.begin(), divergence_integral.end(), 0.);
      volume = 0;
      for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          const double w = fe_values.JxW(q) * weight(fe_values.quadrature_point(q));
          volume += w;
          for (unsigned int i = 0; i < n; ++i)
            strain[i] = shape_strain(fe_values, i, q);
          for (unsigned int i = 0; i < n; ++i)
            {
              // B-bar: the shear part here, the bulk part from the cell's
              // integrals below.
              const SymmetricTensor<2, 3> stress_i =
                material.mean_dilatation ? material.stress(strain[i], 0.) :
                                           SymmetricTensor<2, 3>(C * strain[i]);
              divergence_integral[i] += trace(strain[i]) * w;
              for (unsigned int j = 0; j <= i; ++j)
                cell_matrix(i, j) += (stress_i * strain[j]) * w;
            }
        }
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j <= i; ++j)
          {
            if (material.mean_dilatation)
              cell_matrix(i, j) +=
                material.bulk_modulus * divergence_integral[i] * divergence_integral[j] / volume;
            cell_matrix(j, i) = cell_matrix(i, j);
          }
    }



    // In 3D no body is axisymmetric; the dimension-independent callers
    // compile for both.
    template double check_radii(const DoFHandler<2> &);
    template double check_radii(const DoFHandler<3> &);
    template void   hold_axis(const DoFHandler<2> &, const double, AffineConstraints<double> &);
    template void   hold_axis(const DoFHandler<3> &, const double, AffineConstraints<double> &);
  } // namespace Axisymmetry
} // namespace FrictionalContact
