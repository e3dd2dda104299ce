#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/numerics/data_out.h>

#include <frictional_contact/base/files.h>
#include <frictional_contact/base/plugins.h>
#include <frictional_contact/postprocess/output_writer.h>
#include <frictional_contact/postprocess/tables.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <unordered_map>

namespace FrictionalContact
{
  namespace
  {
    const char *state_name(const ContactState state)
    {
      switch (state)
        {
          case ContactState::free:
            return "free";
          case ContactState::stick:
            return "stick";
          case ContactState::slip:
            return "slip";
        }
      return "unknown";
    }
  } // namespace



  template <int dim>
  void
  OutputWriter<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Write vtu",
                      "true",
                      Patterns::Bool(),
                      "Write VTU/PVTU files of every increment for ParaView "
                      "(displacement, contact reactions, gap, contact state), "
                      "listed with their times in solution.pvd.");
    prm.declare_entry("Write vtu every",
                      "1",
                      Patterns::Integer(1),
                      "Write the VTU files of every n-th increment (and of "
                      "the last one).");
    prm.declare_entry("Write csv tables",
                      "false",
                      Patterns::Bool(),
                      "Also write contact-NNNNN.csv (every candidate: "
                      "position, displacement, normal displacement increment, "
                      "gap, reactions, state), displacement-NNNNN.csv "
                      "(every vertex) and stress-NNNNN.csv (every cell: "
                      "the stress at its centre and its mean stress). "
                      "Gathered on one rank: for small problems.");
    prm.declare_entry("Number of grouped files",
                      "1",
                      Patterns::Integer(0),
                      "VTU files per increment (0: one per MPI rank).");
  }



  template <int dim>
  OutputWriter<dim>::OutputWriter()
    : scalar_fe(1)
  {}



  template <int dim>
  void
  OutputWriter<dim>::parse_parameters(ParameterHandler  &prm,
                                      const std::string &output_directory,
                                      const MPI_Comm)
  {
    directory   = output_directory;
    write_vtu   = prm.get_bool("Write vtu");
    write_csv   = prm.get_bool("Write csv tables");
    write_every = prm.get_integer("Write vtu every");
    n_groups    = prm.get_integer("Number of grouped files");
  }



  template <int dim>
  Postprocess::Columns
  OutputWriter<dim>::execute(const Postprocess::IncrementResult<dim> &result)
  {
    const bool vtu_due =
      write_vtu && (result.increment % write_every == 0 || result.last());
    if (!vtu_due && !write_csv)
      return {};
    const Model<dim> &model = result.model;
    run_on_root(model.get_mpi_communicator(), [&]() {
      std::filesystem::create_directories(vtu_due ? directory + "/solution" :
                                                    directory);
    });
    if (vtu_due)
      write_vtu_files(result.increment,
                      result.time,
                      model.get_body(),
                      model.get_contact(),
                      model.get_response(),
                      result.state.u,
                      result.outcome.results);
    if (write_csv)
      write_csv_files(result.increment,
                      model.get_body(),
                      model.get_contact(),
                      model.get_response(),
                      result.state.u,
                      result.outcome.results);
    return {};
  }



  template <int dim>
  std::string
  OutputWriter<dim>::save_state() const
  {
    std::ostringstream            text;
    boost::archive::text_oarchive archive(text);
    archive << times_and_names;
    return text.str();
  }



  template <int dim>
  void
  OutputWriter<dim>::load_state(const std::string &state)
  {
    std::istringstream            text(state);
    boost::archive::text_iarchive archive(text);
    archive >> times_and_names;
  }



  template <int dim>
  std::string
  OutputWriter<dim>::describe() const
  {
    std::string text;
    if (write_vtu)
      text += (write_every == 1 ? std::string("vtu every increment") :
                                  "vtu every " + std::to_string(write_every) +
                                    " increments") +
              " (solution/, solution.pvd)";
    if (write_csv)
      text += std::string(text.empty() ? "" : ", ") +
              "csv tables (contact-, displacement-, stress-NNNNN.csv)";
    return text;
  }



  template <int dim>
  void
  OutputWriter<dim>::write_vtu_files(const unsigned int                increment,
                                     const double                      time,
                                     const ElasticBody<dim>           &body,
                                     const ContactOperator<dim>       &contact,
                                     const BodyResponse<dim>           &response,
                                     const Vector                     &u,
                                     const ContactResults<dim>        &results)
  {
    const DoFHandler<dim> &dof_handler = body.get_dof_handler();
    const MPI_Comm         comm        = body.get_mpi_communicator();
    const auto &triangulation = dof_handler.get_triangulation();
    // Made anew for every output: adaptive refinement changes the mesh.
    scalar_dof_handler.reinit(triangulation);
    scalar_dof_handler.distribute_dofs(scalar_fe);

    Vector u_ghosted = body.make_ghosted_vector();
    u_ghosted        = u;

    // Nodal contact forces in Cartesian components, on both sides of a
    // pair (the master's are those the slave side transfers).
    Vector force = body.make_vector(), force_ghosted = body.make_ghosted_vector();
    Vector increment_force_ghosted = body.make_ghosted_vector();
    contact.forces_on_both_sides(results.reaction, force);
    force_ghosted = force;
    contact.forces_on_both_sides(results.reaction_increment, force);
    increment_force_ghosted = force;

    // Gap and state at the vertices: the solver's linearised gap at the
    // candidates, the signed distance of the displaced vertex elsewhere.
    std::unordered_map<types::global_dof_index, unsigned int> candidate;
    for (unsigned int j = 0; j < contact.n_local(); ++j)
      candidate[contact.first_dof(j)] = j;
    const IndexSet scalar_owned = scalar_dof_handler.locally_owned_dofs();
    const IndexSet scalar_relevant =
      DoFTools::extract_locally_relevant_dofs(scalar_dof_handler);
    Vector gap(scalar_owned, comm), state(scalar_owned, comm),
      pressure(scalar_owned, comm);
    // Each owned vertex once, not once per cell around it.
    std::vector<bool> vertex_done(scalar_owned.n_elements(), false);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const typename DoFHandler<dim>::active_cell_iterator scalar_cell(
            &triangulation, cell->level(), cell->index(), &scalar_dof_handler);
          for (const unsigned int v : cell->vertex_indices())
            {
              const auto s = scalar_cell->vertex_dof_index(v, 0);
              if (!scalar_owned.is_element(s))
                continue;
              const auto position = scalar_owned.index_within_set(s);
              if (vertex_done[position])
                continue;
              vertex_done[position] = true;
              const auto it = candidate.find(cell->vertex_dof_index(v, 0));
              if (it != candidate.end())
                {
                  gap[s]   = results.gap[it->second];
                  state[s] = static_cast<double>(results.state[it->second]);
                  pressure[s] = results.pressure[it->second];
                }
              else
                {
                  Point<dim> x = cell->vertex(v);
                  for (unsigned int c = 0; c < dim; ++c)
                    x[c] += u_ghosted[cell->vertex_dof_index(v, c)];
                  gap[s]   = contact.active() ? contact.distance_to_obstacle(x) : 0.;
                  state[s] = -1;
                }
            }
        }
    gap.compress(VectorOperation::insert);
    state.compress(VectorOperation::insert);
    pressure.compress(VectorOperation::insert);
    Vector gap_ghosted(scalar_owned, scalar_relevant, comm);
    Vector state_ghosted(scalar_owned, scalar_relevant, comm);
    Vector pressure_ghosted(scalar_owned, scalar_relevant, comm);
    gap_ghosted      = gap;
    state_ghosted    = state;
    pressure_ghosted = pressure;

    DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      vector_field(dim, DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(u_ghosted,
                             std::vector<std::string>(dim, "displacement"),
                             DataOut<dim>::type_dof_data,
                             vector_field);
    data_out.add_data_vector(force_ghosted,
                             std::vector<std::string>(dim, "contact_reaction"),
                             DataOut<dim>::type_dof_data,
                             vector_field);
    data_out.add_data_vector(increment_force_ghosted,
                             std::vector<std::string>(dim,
                                                      "contact_reaction_increment"),
                             DataOut<dim>::type_dof_data,
                             vector_field);
    // Cell data: the averages over each cell's quadrature points of the
    // stress (von Mises, mean stress: tension positive, its negative the
    // pressure of an incompressible body; Cauchy's at finite strain) and of
    // the plastic state, det F at finite strain, and the body (material
    // id).
    const std::vector<CellState<dim>> states = response.cell_states(u_ghosted);
    const unsigned int n_cells = triangulation.n_active_cells();
    dealii::Vector<float> von_mises(n_cells), mean_stress(n_cells),
      plastic_strain(n_cells), yield_state(n_cells), body_id(n_cells),
      jacobian(n_cells);
    std::vector<dealii::Vector<float>> plastic_tensor(6, dealii::Vector<float>(n_cells));
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int    c     = cell->active_cell_index();
          const CellState<dim> &state = states[c];
          von_mises[c]      = state.von_mises_stress;
          mean_stress[c]    = state.mean_stress;
          plastic_strain[c] = state.equivalent_plastic_strain;
          yield_state[c]    = state.yield_state;
          jacobian[c]       = state.jacobian;
          body_id[c]        = cell->material_id();
          for (unsigned int k = 0; k < 6; ++k)
            plastic_tensor[k][c] = state.plastic_strain.access_raw_entry(k);
        }
    data_out.add_data_vector(von_mises, "von_mises_stress");
    data_out.add_data_vector(mean_stress, "mean_stress");
    data_out.add_data_vector(plastic_strain, "equivalent_plastic_strain");
    // SymmetricTensor<2, 3>'s order of independent components (the third
    // direction of an axisymmetric section is the hoop one, t).
    const bool  revolved         = body.get_materials().axisymmetric();
    const char *component[6]     = {"xx", "yy", revolved ? "tt" : "zz",
                                    "xy", revolved ? "xt" : "xz", revolved ? "yt" : "yz"};
    for (unsigned int k = 0; k < 6; ++k)
      data_out.add_data_vector(plastic_tensor[k],
                               std::string("plastic_strain_") + component[k]);
    data_out.add_data_vector(yield_state, "yield_state");
    if (response.finite_strain())
      data_out.add_data_vector(jacobian, "det_F");
    data_out.add_data_vector(body_id, "body");
    data_out.add_data_vector(scalar_dof_handler, gap_ghosted, "gap");
    data_out.add_data_vector(scalar_dof_handler,
                             state_ghosted,
                             "contact_state");
    data_out.add_data_vector(scalar_dof_handler,
                             pressure_ghosted,
                             "contact_pressure");
    dealii::Vector<float> subdomain(triangulation.n_active_cells());
    subdomain = static_cast<float>(triangulation.locally_owned_subdomain());
    data_out.add_data_vector(subdomain, "subdomain");
    data_out.build_patches();

    DataOutBase::VtkFlags flags;
    flags.time  = time;
    flags.cycle = increment;
    // zlib's fastest level: deal.II's default (best compression) took
    // three times as long as the files are large (example I, d = 54,600:
    // 0.8 s of output for a 2 s solve).
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    std::string pvtu;
    std::ostringstream name;
    name << directory << "/solution/solution_" << std::setw(5)
         << std::setfill('0') << increment << ".pvtu";
    run_collective_write(comm, name.str(), [&]() {
      pvtu = data_out.write_vtu_with_pvtu_record(
        directory + "/solution/", "solution", increment, comm, 5, n_groups);
    });

    times_and_names.emplace_back(time, "solution/" + pvtu);
    run_on_root(comm, [&]() {
      std::ostringstream pvd;
      DataOutBase::write_pvd_record(pvd, times_and_names);
      write_file_atomically(directory + "/solution.pvd", pvd.str());
    });
    if (contact.rigid_tool().active())
      write_tool_files(contact.rigid_tool(), time, increment, comm);
  }



  template <int dim>
  void
  OutputWriter<dim>::write_tool_files(const RigidTool<dim> &tool,
                                      const double          time,
                                      const unsigned int    increment,
                                      const MPI_Comm        comm) const
  {
    // The tool's surface where it stands, with tool.pvd beside
    // solution.pvd: the same times, tool_NNNNN.vtu for solution_NNNNN.pvtu.
    const auto tool_file = [](const unsigned int n) {
      std::ostringstream name;
      name << "solution/tool_" << std::setw(5) << std::setfill('0') << n << ".vtu";
      return name.str();
    };
    std::vector<std::pair<double, std::string>> tool_times;
    for (const auto &[t, name] : times_and_names)
      tool_times.emplace_back(
        t, tool_file(std::stoul(name.substr(name.rfind('_') + 1))));
    run_on_root(comm, [&]() {
      write_file_atomically(directory + "/" + tool_file(increment), tool.vtu(time));
      std::ostringstream pvd;
      DataOutBase::write_pvd_record(pvd, tool_times);
      write_file_atomically(directory + "/tool.pvd", pvd.str());
    });
  }



  template <int dim>
  void
  OutputWriter<dim>::write_csv_files(const unsigned int          increment,
                                     const ElasticBody<dim>     &body,
                                     const ContactOperator<dim> &contact,
                                     const BodyResponse<dim>           &response,
                                     const Vector               &u,
                                     const ContactResults<dim>  &results) const
  {
    const MPI_Comm comm = body.get_mpi_communicator();
    const char    *axis = "xyz";
    auto           number = [](std::ostringstream &out, const double value) {
      out << ',' << std::setprecision(17) << value;
    };
    std::ostringstream suffix;
    suffix << std::setw(5) << std::setfill('0') << increment << ".csv";

    std::string header;
    for (unsigned int d = 0; d < dim; ++d)
      header += std::string(d == 0 ? "" : ",") + axis[d];
    std::string displacement_header = header;
    for (unsigned int d = 0; d < dim; ++d)
      displacement_header += std::string(",u") + axis[d];

    std::vector<std::string> rows;
    for (unsigned int j = 0; j < contact.n_local(); ++j)
      {
        std::ostringstream row;
        const Point<dim> x = *contact.reference_position(j);
        row << std::setprecision(17) << x[0];
        for (unsigned int d = 1; d < dim; ++d)
          number(row, x[d]);
        const Tensor<1, dim> u_j = contact.nodal_value(j, u);
        for (unsigned int d = 0; d < dim; ++d)
          number(row, u_j[d]);
        number(row, results.local_displacement[j][0]);
        number(row, results.gap[j]);
        for (unsigned int d = 0; d < dim; ++d)
          number(row, results.reaction[j][d]);
        number(row, contact.nodal_area(j));
        number(row, results.pressure[j]);
        row << ',' << state_name(results.state[j]);
        rows.push_back(row.str());
      }
    std::string contact_header = displacement_header + ",un,gap,rn";
    for (unsigned int d = 1; d < dim; ++d)
      contact_header += ",rt" + std::to_string(d);
    Postprocess::write_sorted_table(directory + "/contact-" + suffix.str(),
                       contact_header + ",area,pressure,state",
                       rows,
                       dim,
                       comm);

    rows.clear();
    const IndexSet &owned = body.locally_owned_dofs();
    const double   *values = u.begin();
    std::set<types::global_dof_index> done;
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto first = cell->vertex_dof_index(v, 0);
            if (!owned.is_element(first) || !done.insert(first).second)
              continue;
            std::ostringstream row;
            row << std::setprecision(17) << cell->vertex(v)[0];
            for (unsigned int d = 1; d < dim; ++d)
              number(row, cell->vertex(v)[d]);
            for (unsigned int d = 0; d < dim; ++d)
              number(row,
                     values[owned.index_within_set(cell->vertex_dof_index(v, d))]);
            rows.push_back(row.str());
          }
    Postprocess::write_sorted_table(directory + "/displacement-" + suffix.str(),
                       displacement_header,
                       rows,
                       dim,
                       comm);

    std::string stress_header;
    rows = Postprocess::cell_stress_rows(body, response, u, stress_header);
    Postprocess::write_sorted_table(
      directory + "/stress-" + suffix.str(), stress_header, rows, dim, comm);
  }

  FRICTIONAL_CONTACT_REGISTER_PLUGIN(
    Postprocess::Interface,
    OutputWriter,
    "visualization",
    "VTU/PVTU files for ParaView with solution.pvd, and CSV tables of the "
    "candidates and vertices, as the entries Write vtu and Write csv tables "
    "ask for.")
} // namespace FrictionalContact
