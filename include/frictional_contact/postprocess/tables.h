#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/model/elastic_body.h>
#include <frictional_contact/model/material.h>

#include <string>
#include <vector>

namespace FrictionalContact
{
  namespace Postprocess
  {
    /**
     * Writes the CSV rows of all ranks from rank 0, sorted by their leading
     * dim coordinates (z, then y, then x), under @p header, atomically.
     * Collective.
     */
    void
    write_sorted_table(const std::string              &file_name,
                       const std::string              &header,
                       const std::vector<std::string> &rows,
                       const unsigned int              dim,
                       const MPI_Comm                  comm);

    /**
     * One CSV row per locally owned cell: its centre, the stress there
     * (components xx, yy, [zz,] xy[, xz, yz]; in 2D also zz, the
     * out-of-plane stress) with the volumetric strain of the element (the
     * cell's mean dilatation for B-bar), and the cell's mean stress. The
     * header is @p header. @p u is the (non-ghosted) displacement.
     */
    template <int dim>
    std::vector<std::string>
    cell_stress_rows(const ElasticBody<dim>              &body,
                     const Materials<dim>                &materials,
                     const TrilinosWrappers::MPI::Vector &u,
                     std::string                         &header);
  } // namespace Postprocess
} // namespace FrictionalContact
