#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <frictional_contact/model/axisymmetry.h>
#include <frictional_contact/model/contact_operator.h>
#include <frictional_contact/base/placed_minimum.h>
#include <frictional_contact/base/plugins.h>

#include <algorithm>
#include <map>

namespace FrictionalContact
{



  template <int dim>
  void
  ContactOperator<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry("Contact boundaries",
                      "",
                      Patterns::Anything(),
                      "Boundaries (names or ids, separated by ';') whose "
                      "vertices may touch the obstacle. Empty: no contact, "
                      "a plain linear elastic solve.");
    prm.declare_entry(
      "Pairs",
      "",
      Patterns::Anything(),
      "Contact between two bodies: 'slave boundary : master boundary' "
      "items separated by ';', e.g. 'block bottom : base top'; the master "
      "may also be the rigid tool, by its <Rigid tool/Name>. The slave "
      "side carries the contact forces (dual mortar: one friction cone per "
      "slave node); make it the finer side, and where the bodies differ "
      "much in stiffness and friction acts, the softer one if it is also "
      "the finer (doc/user-guide.md). A third field is the pair's "
      "friction coefficient ('block bottom : base top : 0.3'); without it "
      "the pair has <Friction coefficient>.");
    prm.declare_entry("Interference fit",
                      "false",
                      Patterns::Bool(),
                      "Whether the bodies of a pair may overlap at the "
                      "start: an interference (press or shrink) fit, a "
                      "ring made smaller than the shaft it sits on. The "
                      "first increment pushes the overlap out along the "
                      "slave normals as the contact pressure builds up "
                      "(linear elastic bodies: at once; solve it in "
                      "increments at finite strain). false: an overlap is "
                      "an error of the geometry and stops the run before "
                      "anything is written.");
    prm.declare_entry("Friction coefficient",
                      "0",
                      Patterns::Double(0.),
                      "Coulomb friction coefficient mu (>= 0) of the "
                      "obstacle, and of the pairs that do not give their "
                      "own. 0 is frictionless contact.");
    prm.declare_entry(
      "Geometry between bodies",
      "every Newton iterate",
      Patterns::Selection("fixed point|every Newton iterate"),
      "How a pair of two bodies (its master not the rigid tool) follows "
      "within an increment where a body on it is at finite strain. fixed "
      "point: the increment solved again with the geometry where it ended "
      "until it settles (<Pair geometry>). every Newton iterate: the "
      "mortar segments, rows, normals and gaps taken again at every Newton "
      "iterate and the iterate expressed in their basis, so that one solve "
      "serves the increment (fewer Newton steps and less time on every "
      "pair measured); the tangent takes the rows' sliding under "
      "the reactions, the gaps' change along the slide and the reactions' "
      "turn with the slave normals (doc/formulation.md, \"Finite "
      "strain\"; doc/performance.md, \"Finite strain against small "
      "strain\"). "
      "Pairs with the rigid tool: <Rigid tool/Geometry at finite strain>.");
    prm.enter_subsection("Pair geometry");
    prm.declare_entry(
      "Tolerance",
      "1e-6",
      Patterns::Double(0.),
      "For contact pairs with a body at finite strain, which move within "
      "an increment: the increment is solved again with the mortar "
      "geometry (normals, segments, gaps) of where it ended until no "
      "slave node's unit normal turns by more than this and no gap moves "
      "by more than this times the largest displacement where it ended.");
    prm.declare_entry("Maximum passes",
                      "20",
                      Patterns::Integer(1),
                      "Solves of one increment for its pairs' geometry to "
                      "settle (see Tolerance); an increment that needs more "
                      "fails (and is cut with <Loading/On failure> = cut "
                      "increment).");
    prm.leave_subsection();
    RigidTool<dim>::declare_parameters(prm);
    prm.enter_subsection("Obstacle");
    PluginRegistry<Obstacle::Interface<dim>>::declare_parameters(
      prm, "plane", "The rigid obstacle's shape.");
    prm.declare_entry("Rigid displacement",
                      dim == 2 ? "0; 0" : "0; 0; 0",
                      Patterns::Anything(),
                      "The obstacle's rigid translation as a function of "
                      "time t (muParser, one expression per component, "
                      "separated by ';'), from where its parameters put it. "
                      "Example, pressing and then dragging: "
                      "'0.1 * max(t - 1, 0); -0.01 * min(t, 1)'.");
    prm.leave_subsection();
    prm.leave_subsection();
  }



  template <int dim>
  ContactOperator<dim>::ContactOperator(ParameterHandler    &prm,
                                        const BoundaryNames &names)
  {
    prm.enter_subsection("Contact");
    const double mu  = prm.get_double("Friction coefficient");
    interference_fit = prm.get_bool("Interference fit");
    cones.emplace_back(mu);
    bodies_every_newton_iterate =
      prm.get("Geometry between bodies") == "every Newton iterate";
    prm.enter_subsection("Pair geometry");
    pair_passes.tolerance  = prm.get_double("Tolerance");
    pair_passes.max_passes = prm.get_integer("Maximum passes");
    prm.leave_subsection();
    if (!(pair_passes.tolerance > 0))
      Input::fail("Contact/Pair geometry/Tolerance",
                  Input::to_text(pair_passes.tolerance),
                  "a positive number is expected (a change of exactly 0 is "
                  "never reached in floating point)");
    tool = std::make_unique<RigidTool<dim>>(prm);
    for (const std::string &item :
         Input::split(prm.get("Contact boundaries"), ';'))
      contact_boundaries.insert(
        names.id("Contact/Contact boundaries", item));
    for (const std::string &item : Input::split(prm.get("Pairs"), ';'))
      {
        const std::vector<std::string> sides = Input::split(item, ':');
        if (sides.size() != 2 && sides.size() != 3)
          Input::fail("Contact/Pairs", item,
                      "'slave boundary : master boundary', e.g. "
                      "'block bottom : base top', or with the pair's "
                      "friction coefficient 'block bottom : base top : 0.3'");
        double pair_mu = mu;
        if (sides.size() == 3)
          {
            std::size_t end = 0;
            try
              {
                pair_mu = std::stod(sides[2], &end);
              }
            catch (const std::exception &)
              {
                pair_mu = -1;
              }
            if (end != sides[2].size())
              pair_mu = -1;
          }
        if (!(pair_mu >= 0) || !std::isfinite(pair_mu))
          Input::fail("Contact/Pairs", item,
                      "a friction coefficient >= 0 in the third field");
        cones.emplace_back(pair_mu);
        if (tool->active() && sides[0] == tool->tool_name())
          Input::fail("Contact/Pairs", item,
                      "the rigid tool as the master (second) side: the "
                      "slave side carries the contact forces, a body's "
                      "boundary does");
        const types::boundary_id slave = names.id("Contact/Pairs", sides[0]);
        if (contact_boundaries.count(slave) > 0)
          Input::fail("Contact/Pairs", item,
                      "a slave boundary that is not in <Contact/Contact boundaries>");
        if (tool->active() && sides[1] == tool->tool_name())
          {
            interfaces.emplace_back(slave, numbers::invalid_boundary_id, tool.get());
            continue;
          }
        const types::boundary_id master = names.id("Contact/Pairs", sides[1]);
        if (slave == master || contact_boundaries.count(master) > 0)
          Input::fail("Contact/Pairs", item,
                      "two different boundaries, neither of them in "
                      "<Contact/Contact boundaries>");
        interfaces.emplace_back(slave, master);
      }
    if (tool->active() &&
        std::none_of(interfaces.begin(), interfaces.end(), [](const auto &interface) {
          return interface.has_rigid_master();
        }))
      Input::fail("Contact/Rigid tool/Name", tool->tool_name(),
                  "a tool that a pair of <Contact/Pairs> names as its master "
                  "('slab top : " + tool->tool_name() + "'), or an empty name");
    prm.enter_subsection("Obstacle");
    obstacle = PluginRegistry<Obstacle::Interface<dim>>::create(prm);
    rigid_displacement =
      std::make_unique<TimeFunction>("Contact/Obstacle/Rigid displacement",
                                     prm.get("Rigid displacement"),
                                     dim);
    prm.leave_subsection();
    prm.leave_subsection();
  }



  template <int dim>
  std::set<types::boundary_id>
  ContactOperator<dim>::find_candidates(
    const ElasticBody<dim>                   &body,
    const std::set<types::boundary_id>       &boundaries,
    const int                                 pair,
    std::map<types::global_dof_index, Node> &found) const
  {
    const IndexSet &owned = body.locally_owned_dofs();
    std::map<types::global_dof_index, double> area;
    std::set<types::boundary_id>            boundaries_with_candidates;
    const FiniteElement<dim> &fe = body.get_dof_handler().get_fe();
    FEFaceValues<dim>         face_values(fe,
                                  QGauss<dim - 1>(2),
                                  update_values | update_quadrature_points |
                                    update_JxW_values);
    // An axisymmetric scene's areas are those of the surface of revolution.
    const bool axisymmetric = body.get_materials().axisymmetric();
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              boundaries.count(cell->face(f)->boundary_id()) > 0)
            {
              // Lumped areas: the integral of each vertex's shape function
              // (component 0 of the vector-valued Q1 element) over the face.
              face_values.reinit(cell, f);
              for (const unsigned int v : cell->vertex_indices())
                {
                  const unsigned int i = fe.component_to_system_index(0, v);
                  double             integral = 0;
                  for (const unsigned int q :
                       face_values.quadrature_point_indices())
                    integral += face_values.shape_value(i, q) * face_values.JxW(q) *
                                (axisymmetric ?
                                   Axisymmetry::weight(face_values.quadrature_point(q)) :
                                   1.);
                  if (integral > 0)
                    area[cell->vertex_dof_index(v, 0)] += integral;
                }
            }
    // A hanging vertex is not a candidate: its force acts on the vertices it
    // hangs from, and so does its area, with the same weights. Each
    // candidate's area is then that of its shape function with the
    // constraints applied, and r_n / area its pressure.
    const AffineConstraints<double> &hanging = body.get_hanging_node_constraints();
    for (auto &[dof, hanging_area] : area)
      if (hanging.is_constrained(dof))
        {
          for (const auto &[parent, weight] : *hanging.get_constraint_entries(dof))
            area[parent] += weight * hanging_area;
          hanging_area = 0;
        }
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && boundaries.count(face->boundary_id()) > 0)
            for (const unsigned int v : face->vertex_indices())
              {
                Node node;
                bool all_fixed = true;
                for (unsigned int c = 0; c < dim; ++c)
                  {
                    const auto g = face->vertex_dof_index(v, c);
                    node.dofs[c] = g;
                    node.free[c] = !body.get_constraints().is_constrained(g);
                    all_fixed    = all_fixed && !node.free[c];
                    if (owned.is_element(g))
                      node.local_dofs[c] = owned.index_within_set(g);
                  }
                const auto first_dof = face->vertex_dof_index(v, 0);
                if (all_fixed || !owned.is_element(first_dof))
                  continue;
                boundaries_with_candidates.insert(face->boundary_id());
                node.position = face->vertex(v);
                node.area     = area[first_dof];
                node.pair     = static_cast<std::int16_t>(pair);
                const auto known =
                  std::find(body_ids.begin(), body_ids.end(), cell->material_id());
                node.body = static_cast<std::uint16_t>(known - body_ids.begin());
                const auto [it, inserted] = found.emplace(first_dof, node);
                if (!inserted && it->second.pair != pair)
                  throw InputError(
                    "<Contact/Pairs>: a vertex at " + Input::to_text(node.position[0]) +
                    ", " + Input::to_text(node.position[1]) +
                    (dim == 3 ? ", " + Input::to_text(node.position[dim - 1]) : "") +
                    " is on two contact boundaries; a slave boundary must not "
                    "touch another contact boundary");
              }
    return Utilities::MPI::compute_set_union(boundaries_with_candidates,
                                             body.get_mpi_communicator());
  }



  template <int dim>
  void
  ContactOperator<dim>::setup(const ElasticBody<dim> &body,
                              const BoundaryNames    &names)
  {
    nodes.clear();
    tangents.clear();
    mpi_communicator = body.get_mpi_communicator();

    body_ids.clear();
    for (const auto &[name, id] : body.get_bodies())
      body_ids.push_back(id);
    // Keyed by the first dof of the vertex: each vertex once, in dof order.
    std::map<types::global_dof_index, Node> found;
    std::set<types::boundary_id> with_candidates =
      find_candidates(body, contact_boundaries, -1, found);
    for (unsigned int k = 0; k < interfaces.size(); ++k)
      {
        interfaces[k].setup(body);
        for (const types::material_id id : interfaces[k].slave_bodies())
          if (interfaces[k].master_bodies().count(id) > 0)
            throw InputError(
              "<Contact/Pairs> = '" + pair_name(k, names) +
              "': both sides are on the body '" + body.body_name(id) +
              "'; a pair is between two bodies (the contact of a body with "
              "itself is not supported)");
        const std::set<types::boundary_id> slave = {interfaces[k].slave_boundary()};
        with_candidates.merge(find_candidates(body, slave, k, found));
      }
    std::set<types::boundary_id> boundaries = contact_boundaries;
    for (const MortarInterface<dim> &interface : interfaces)
      boundaries.insert(interface.slave_boundary());
    for (const types::boundary_id id : boundaries)
      if (with_candidates.count(id) == 0)
        throw InputError("<Contact/Contact boundaries> = '" + names.name(id) +
                         "': this boundary has no contact candidate node "
                         "(all its nodes are held by <Boundary conditions/"
                         "Fixed boundaries>); remove it from the list or free "
                         "its nodes");

    nodes.reserve(found.size());
    facing_contact.clear();
    for (const auto &[dof, node] : found)
      {
        nodes.push_back(node);
        facing_contact.insert(body_ids[node.body]);
        // A finite-strain body moves far: its gaps to the obstacle are taken
        // where it is, not linearised at the reference configuration.
        nodes.back().follows =
          node.pair < 0 && body.get_materials().of(body_ids[node.body]).elastic().finite_strain;
      }
    any_follows = Utilities::MPI::logical_or(
      std::any_of(nodes.begin(), nodes.end(), [](const Node &node) { return node.follows; }),
      body.get_mpi_communicator());
    followed_displacements.assign(any_follows ? nodes.size() : 0, Tensor<1, dim>());
    followed_gaps.assign(any_follows ? nodes.size() : 0, 0.);
    normal_gradients.assign(any_follows ? nodes.size() : 0, Tensor<2, dim>());
    any_pair_follows = false;
    for (const MortarInterface<dim> &interface : interfaces)
      {
        facing_contact.insert(interface.master_bodies().begin(),
                              interface.master_bodies().end());
        for (const auto *side : {&interface.slave_bodies(), &interface.master_bodies()})
          for (const types::material_id id : *side)
            any_pair_follows |= body.get_materials().of(id).elastic().finite_strain;
      }
    for (MortarInterface<dim> &interface : interfaces)
      interface.take_tool_frames(pairs_take_tool_frames());
    if (pairs_take_tool_frames())
      normal_gradients.assign(nodes.size(), Tensor<2, dim>());
    facing_contact =
      Utilities::MPI::compute_set_union(facing_contact, body.get_mpi_communicator());
    if (has_friction())
      tangents.resize(nodes.size());
    n_global = Utilities::MPI::sum<types::global_dof_index>(
      nodes.size(), body.get_mpi_communicator());
    move_obstacle(obstacle_displacement(0.));
    check_initial_gaps(body);
  }



  template <int dim>
  void
  ContactOperator<dim>::check_initial_gaps(const ElasticBody<dim> &body)
  {
    if (has_pairs())
      {
        Vector zero = body.make_ghosted_vector();
        update_pairs(body, zero, 0., 0.);
      }
    // Neither the obstacle nor another body may start inside a body.
    PlacedMinimum<dim> deepest[2];
    for (unsigned int j = 0; j < nodes.size(); ++j)
      {
        const unsigned int kind = nodes[j].pair < 0 ? 0 : 1;
        deepest[kind].keep(kind == 0 ? reference_gap(j) : pair_gaps[j], nodes[j].position);
      }
    double extent = 0;
    for (const Node &node : nodes)
      for (unsigned int d = 0; d < dim; ++d)
        extent = std::max(extent, std::abs(node.position[d]));
    extent = Utilities::MPI::max(extent, mpi_communicator);
    const PlacedMinimum<dim> inside = deepest[0].over_ranks(mpi_communicator);
    if (-inside.value > 1e-12 * extent)
      throw InputError("<Contact/Obstacle>: the obstacle starts inside the "
                       "body, " + Input::to_text(-inside.value) +
                       " deep (a negative gap) at the node at " + inside.place() +
                       "; move it so that every gap is >= 0 at t = 0, for a "
                       "plane its Point");
    // A curved master's faces are chords, and the dual basis has negative
    // parts: touching bodies can show weighted gaps of a small negative
    // fraction of the face size. Only a deeper overlap is one.
    double face_size = 0;
    for (const MortarInterface<dim> &interface : interfaces)
      face_size = std::max(face_size, interface.search_distance() / 2);
    const PlacedMinimum<dim> overlapping = deepest[1].over_ranks(mpi_communicator);
    if (-overlapping.value > 1e-2 * face_size && !interference_fit)
      throw InputError("<Contact/Pairs>: the bodies overlap at the start: "
                       "the slave vertex at " + overlapping.place() + " is " +
                       Input::to_text(-overlapping.value) +
                       " inside the other body or tool; move them apart "
                       "(for stacked blocks, <Geometry/Stacked blocks/Block "
                       "offset>; for a tool, <Contact/Rigid tool/Translation> "
                       "at t = 0; or, for a press or shrink fit, "
                       "<Contact/Interference fit> = true)");
  }



  template <int dim>
  std::set<types::material_id>
  ContactOperator<dim>::bodies_held_by(const unsigned int j) const
  {
    std::set<types::material_id> held = {body_ids[nodes[j].body]};
    if (nodes[j].pair >= 0)
      {
        const auto &masters = interfaces[nodes[j].pair].master_bodies();
        held.insert(masters.begin(), masters.end());
      }
    return held;
  }



  template <int dim>
  std::size_t
  ContactOperator<dim>::memory_consumption() const
  {
    return nodes.capacity() * sizeof(Node) +
           tangents.capacity() * sizeof(tangents[0]) +
           pair_gaps.capacity() * sizeof(double) +
           pair_motions.capacity() * sizeof(Tensor<1, dim>);
  }



  template <int dim>
  std::string
  ContactOperator<dim>::describe_friction(const BoundaryNames &names) const
  {
    if (!has_friction())
      return "frictionless (no tangential operator)";
    // The coefficient of the obstacle (or of the first pair), then each
    // pair that has another.
    const double common = contact_boundaries.empty() ? cones[1].mu : cones[0].mu;
    std::string  others;
    for (unsigned int k = 0; k < interfaces.size(); ++k)
      if (cones[k + 1].mu != common)
        others += "; " + Input::to_text(cones[k + 1].mu) + " on '" +
                  pair_name(k, names) + "'";
    return "frictional (mu = " + Input::to_text(common) + others + ")";
  }



  template <int dim>
  std::string
  ContactOperator<dim>::describe_boundaries(const BoundaryNames &names) const
  {
    std::string text;
    for (const types::boundary_id id : contact_boundaries)
      text += (text.empty() ? "" : ", ") + names.name(id);
    for (unsigned int k = 0; k < interfaces.size(); ++k)
      text += (text.empty() ? "" : ", ") + pair_name(k, names);
    return text;
  }



  template <int dim>
  std::string
  ContactOperator<dim>::pair_name(const unsigned int   k,
                                  const BoundaryNames &names) const
  {
    return names.name(interfaces[k].slave_boundary()) + " : " +
           (interfaces[k].has_rigid_master() ?
              tool->tool_name() :
              names.name(interfaces[k].master_boundary()));
  }

  template class ContactOperator<2>;
  template class ContactOperator<3>;
} // namespace FrictionalContact
