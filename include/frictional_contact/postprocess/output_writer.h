#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>

#include <frictional_contact/postprocess/interface.h>

#include <string>
#include <utility>
#include <vector>

namespace FrictionalContact
{

  /**
   * Writes the results of each increment: VTU/PVTU for ParaView (listed
   * with their times in solution.pvd, rewritten after every increment) and,
   * on request, CSV tables of the contact candidates and of all vertices
   * (gathered on rank 0, sorted by coordinates; for small problems).
   */
  template <int dim>
  class OutputWriter : public Postprocess::Interface<dim>
  {
  public:
    unsigned int
    default_position() const override
    {
      return 4;
    }

    using Vector = TrilinosWrappers::MPI::Vector;

    /// Declares its entries, inside the subsection "Output".
    static void
    declare_parameters(ParameterHandler &prm);

    OutputWriter();

    void
    parse_parameters(ParameterHandler  &prm,
                     const std::string &output_directory,
                     const MPI_Comm     comm) override;

    /// "vtu every increment, csv tables", or "" if nothing is written.
    std::string
    describe() const override;

    /// Writes the files of the increment, if due; no columns.
    Postprocess::Columns
    execute(const Postprocess::IncrementResult<dim> &result) override;

    /// The increments written so far (for solution.pvd).
    std::string
    save_state() const override;

    void
    load_state(const std::string &state) override;

  private:
    void
    write_vtu_files(const unsigned int                increment,
                    const double                      time,
                    const ElasticBody<dim>           &body,
                    const ContactOperator<dim>       &contact,
                    const BodyResponse<dim>           &response,
                    const Vector                     &u,
                    const ContactResults<dim>        &results);

    /// The rigid tool's surface at @p time (solution/tool_NNNNN.vtu) and
    /// tool.pvd, on rank 0.
    void
    write_tool_files(const RigidTool<dim> &tool,
                     const double          time,
                     const unsigned int    increment,
                     const MPI_Comm        comm) const;

    void
    write_csv_files(const unsigned int          increment,
                    const ElasticBody<dim>     &body,
                    const ContactOperator<dim> &contact,
                    const BodyResponse<dim>           &response,
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
