#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <frictional_contact/base/files.h>
#include <frictional_contact/postprocess/tables.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace FrictionalContact
{
  namespace Postprocess
  {
    void
    write_sorted_table(const std::string              &file_name,
                       const std::string              &header,
                       const std::vector<std::string> &rows,
                       const unsigned int              dim,
                       const MPI_Comm                  comm)
    {
      // Sorted on rank 0 (the others gather nothing), written there.
      const auto all = Utilities::MPI::gather(comm, rows, 0);
      std::vector<std::pair<std::vector<double>, const std::string *>> sorted;
      for (const auto &rank_rows : all)
        for (const std::string &row : rank_rows)
          {
            std::vector<double> key;
            std::istringstream  in(row);
            std::string         field;
            for (unsigned int d = 0; d < dim && std::getline(in, field, ','); ++d)
              key.insert(key.begin(), std::stod(field));
            sorted.emplace_back(key, &row);
          }
      std::sort(sorted.begin(), sorted.end(), [](const auto &a, const auto &b) {
        return a.first < b.first;
      });
      std::string text = header + "\n";
      for (const auto &[key, row] : sorted)
        text += *row + "\n";
      run_on_root(comm, [&]() { write_file_atomically(file_name, text); });
    }



    template <int dim>
    std::vector<std::string>
    cell_stress_rows(const ElasticBody<dim>              &body,
                     const BodyResponse<dim>             &response,
                     const TrilinosWrappers::MPI::Vector &u,
                     std::string                         &header)
    {
      // The third direction of an axisymmetric scene is the hoop one, t.
      const char *axis = body.get_materials().axisymmetric() ? "xyt" : "xyz";
      header.clear();
      for (unsigned int d = 0; d < dim; ++d)
        header += std::string(d == 0 ? "" : ",") + axis[d];
      for (unsigned int i = 0; i < dim; ++i)
        header += std::string(",s") + axis[i] + axis[i];
      if (dim == 2)
        header += std::string(",s") + axis[2] + axis[2];
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i + 1; j < dim; ++j)
          header += std::string(",s") + axis[i] + axis[j];
      header += ",mean_stress,von_mises_stress,equivalent_plastic_strain";
      for (unsigned int i = 0; i < 3; ++i)
        header += std::string(",ep") + axis[i] + axis[i];
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i + 1; j < 3; ++j)
          header += std::string(",ep") + axis[i] + axis[j];
      header += ",yield_state";
      const bool finite_strain = response.finite_strain();
      if (finite_strain)
        header += ",det_F";

      TrilinosWrappers::MPI::Vector u_ghosted = body.make_ghosted_vector();
      u_ghosted                               = u;
      const std::vector<CellState<dim>> states = response.cell_states(u_ghosted);
      const DoFHandler<dim> &dof_handler = body.get_dof_handler();
      QMidpoint<dim>         centre;
      FEValues<dim> fe_values(dof_handler.get_fe(), centre, update_quadrature_points);
      std::vector<std::string> rows;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            const CellState<dim> &state = states[cell->active_cell_index()];
            std::ostringstream    row;
            row << std::setprecision(17);
            const Point<dim> &x = fe_values.quadrature_point(0);
            for (unsigned int d = 0; d < dim; ++d)
              row << (d == 0 ? "" : ",") << x[d];
            for (unsigned int i = 0; i < dim; ++i)
              row << ',' << state.stress[i][i];
            if (dim == 2)
              row << ',' << state.out_of_plane_stress;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = i + 1; j < dim; ++j)
                row << ',' << state.stress[i][j];
            row << ',' << state.mean_stress << ',' << state.von_mises_stress << ','
                << state.equivalent_plastic_strain;
            for (unsigned int i = 0; i < 3; ++i)
              row << ',' << state.plastic_strain[i][i];
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = i + 1; j < 3; ++j)
                row << ',' << state.plastic_strain[i][j];
            row << ',' << state.yield_state;
            if (finite_strain)
              row << ',' << state.jacobian;
            rows.push_back(row.str());
          }
      return rows;
    }

    template std::vector<std::string>
    cell_stress_rows(const ElasticBody<2> &,
                     const BodyResponse<2> &,
                     const TrilinosWrappers::MPI::Vector &,
                     std::string &);
    template std::vector<std::string>
    cell_stress_rows(const ElasticBody<3> &,
                     const BodyResponse<3> &,
                     const TrilinosWrappers::MPI::Vector &,
                     std::string &);
  } // namespace Postprocess
} // namespace FrictionalContact
