#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>

#include <frictional_contact/contact_operator.h>
#include <frictional_contact/elastic_body.h>

#include <string>
#include <utility>
#include <vector>

namespace FrictionalContact
{
  /// Per-candidate results of an increment, in the order of the contact operator.
  template <int dim>
  struct ContactResults
  {
    /// Total reaction r^{l+1} and its change over the increment, in the
    /// local frame (r_n, r_t).
    std::vector<Tensor<1, dim>> reaction;
    std::vector<Tensor<1, dim>> reaction_increment;
    /// Normal and tangential displacement increment relative to the
    /// obstacle, T_j^T du - T_j^T (obstacle's displacement increment).
    std::vector<Tensor<1, dim>> local_displacement;
    /// Gap remaining after the increment, g_j - t_n,j^T du (linearised).
    std::vector<double>       gap;
    std::vector<ContactState> state;
    /// Contact pressure -r_n / (lumped nodal area) (force/area, >= 0).
    std::vector<double> pressure;
  };

  /**
   * Writes the results of each increment: VTU/PVTU for ParaView (listed
   * with their times in solution.pvd, rewritten after every increment) and,
   * on request, CSV tables of the contact candidates and of all vertices
   * (gathered on rank 0, sorted by coordinates; for small problems).
   */
  template <int dim>
  class OutputWriter
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    static void
    declare_parameters(ParameterHandler &prm);

    OutputWriter(ParameterHandler &prm, const std::string &output_directory);

    /// Whether anything is written at all.
    bool
    writes_files() const
    {
      return write_vtu || write_csv;
    }

    /// "vtu every increment, csv tables", or "" if nothing is written.
    std::string
    describe() const;

    /**
     * Writes increment @p increment (counted from 1) at time @p time, if it
     * is due (every n-th, and the last). @p u is the total displacement.
     */
    void
    write(const unsigned int                increment,
          const double                      time,
          const bool                        last_increment,
          const ElasticBody<dim>           &body,
          const ContactOperator<dim>       &contact,
          const LinearElasticMaterial<dim> &material,
          const Vector                     &u,
          const ContactResults<dim>        &results);

    /// The increments written so far (for solution.pvd), for checkpoints.
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &times_and_names;
    }

  private:
    void
    write_vtu_files(const unsigned int                increment,
                    const double                      time,
                    const bool                        last_increment,
                    const ElasticBody<dim>           &body,
                    const ContactOperator<dim>       &contact,
                    const LinearElasticMaterial<dim> &material,
                    const Vector                     &u,
                    const ContactResults<dim>        &results);

    void
    write_csv_files(const unsigned int          increment,
                    const ElasticBody<dim>     &body,
                    const ContactOperator<dim> &contact,
                    const Vector               &u,
                    const ContactResults<dim>  &results) const;

    std::string directory;
    bool        write_vtu;
    bool        write_csv;
    unsigned int write_every;
    unsigned int n_groups;

    FE_Q<dim>       scalar_fe;
    DoFHandler<dim> scalar_dof_handler;
    /// (time, pvtu file) of every increment written so far.
    std::vector<std::pair<double, std::string>> times_and_names;
  };
} // namespace FrictionalContact
