#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/model/body_response.h>
#include <frictional_contact/model/elastic_body.h>
#include <frictional_contact/material/material.h>

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
     * One CSV row per locally owned cell: its centre, the averages over
     * its quadrature points (BodyResponse) of the stress (components xx,
     * yy, [zz,] xy[, xz, yz]; in 2D also zz, the out-of-plane stress), the
     * mean stress, the von Mises stress, the equivalent plastic strain, the
     * plastic strain tensor (3D: epxx, epyy, epzz, epxy, epxz, epyz) and
     * the yield state (0 never yielded, 1 unloaded, 2 on the yield
     * surface). The header is @p header. @p u is the (non-ghosted)
     * displacement.
     */
    template <int dim>
    std::vector<std::string>
    cell_stress_rows(const ElasticBody<dim>              &body,
                     const BodyResponse<dim>             &response,
                     const TrilinosWrappers::MPI::Vector &u,
                     std::string                         &header);
  } // namespace Postprocess
} // namespace FrictionalContact
