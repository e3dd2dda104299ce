#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <frictional_contact/geometry/from_file.h>
#include <frictional_contact/base/plugins.h>

#include <fstream>
#include <set>
#include <sstream>

namespace FrictionalContact
{
  namespace Geometry
  {
    namespace
    {
      const std::string entry_path = "Geometry/From file/";
      constexpr types::manifold_id curved_manifold = 1;

      /// Names and tags of the physical groups of dimension @p group_dim in
      /// a Gmsh file ($PhysicalNames section; absent in other formats).
      std::map<std::string, unsigned int>
      gmsh_physical_names(const std::string &file_name, const int group_dim)
      {
        std::map<std::string, unsigned int> names;
        std::ifstream                       in(file_name);
        std::string                         line;
        while (std::getline(in, line))
          if (line.rfind("$PhysicalNames", 0) == 0)
            {
              unsigned int n = 0;
              in >> n;
              for (unsigned int i = 0; i < n; ++i)
                {
                  int         dimension = -1;
                  long        tag       = -1;
                  std::string name;
                  in >> dimension >> tag;
                  std::getline(in, name);
                  const auto first = name.find('"'), last = name.rfind('"');
                  if (first == std::string::npos || last <= first)
                    break;
                  if (dimension == group_dim && tag >= 0)
                    names[name.substr(first + 1, last - first - 1)] =
                      static_cast<unsigned int>(tag);
                }
              break;
            }
        return names;
      }

      /// The 'name: id' pairs of the entry @p entry (value @p text) into
      /// @p names.
      void
      parse_name_ids(const std::string                   &entry,
                     const std::string                   &text,
                     std::map<std::string, unsigned int> &names)
      {
        for (const std::string &item : Input::split(text, ';'))
          {
            const std::vector<std::string> pair = Input::split(item, ':');
            std::size_t                    end  = 0;
            long                           id   = -1;
            try
              {
                if (pair.size() == 2)
                  id = std::stol(pair[1], &end);
              }
            catch (const std::exception &)
              {}
            if (pair.size() != 2 || pair[0].empty() || end != pair[1].size() ||
                id < 0)
              Input::fail(entry, text, "'name: id' pairs separated by ';' are expected");
            names[pair[0]] = static_cast<unsigned int>(id);
          }
      }
    } // namespace



    template <int dim>
    void
    FromFile<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::Anything(),
                        "The coarse mesh, relative to the parameter file that sets it: "
                        "Gmsh .msh (the physical tags of boundary faces become "
                        "boundary ids, their physical names boundary names; "
                        "named physical groups of cells, surfaces in 2D and "
                        "volumes in 3D, become bodies of those names), "
                        "or any other format deal.II's GridIn reads by "
                        "extension (.inp, .ucd, .vtk, ...). Quadrilaterals in "
                        "2D, hexahedra in 3D.");
      prm.declare_entry("Boundary names",
                        "",
                        Patterns::Anything(),
                        "More names for boundary ids, 'name: id' separated "
                        "by ';' (for formats without names, or to rename).");
      prm.declare_entry("Body names",
                        "",
                        Patterns::Anything(),
                        "More names for the material ids of cells (Gmsh's "
                        "physical tags of cells), 'name: id' separated by "
                        "';': each named id is a body, with its own Material "
                        "entries ('base: 2; block: 1'). Without any name the "
                        "mesh is one body, 'body'.");
      prm.declare_entry("Split bodies",
                        "false",
                        Patterns::Bool(),
                        "What to do where two bodies share vertices (a mesh "
                        "whose parts are conforming at their interface): "
                        "false refuses (bodies in contact are meshed apart), "
                        "true gives each body its own copy of the shared "
                        "vertices, so that they can slide and separate, and "
                        "names the faces between two bodies a and b as the "
                        "boundaries 'a on b' (of a) and 'b on a' (of b), for "
                        "<Contact/Pairs>.");
      prm.declare_entry("Curved boundaries",
                        "",
                        Patterns::Anything(),
                        "Boundaries (names or ids, separated by ';') that lie "
                        "on Curved shape: refinement puts their new vertices "
                        "on that surface instead of on the flat coarse faces.");
      prm.declare_entry("Curved shape",
                        "sphere",
                        Patterns::Selection("sphere|cylinder"),
                        "sphere: a circle (2D) or sphere (3D) around Curved "
                        "center; cylinder (3D): around the line through "
                        "Curved center along Curved axis.");
      prm.declare_entry("Curved center",
                        dim == 2 ? "0, 0" : "0, 0, 0",
                        Patterns::Anything(),
                        "Centre of the sphere, or a point on the cylinder's "
                        "axis (length).");
      prm.declare_entry("Curved axis",
                        dim == 2 ? "0, 1" : "0, 0, 1",
                        Patterns::Anything(),
                        "Direction of the cylinder's axis (3D).");
    }



    template <int dim>
    void
    FromFile<dim>::parse_parameters(ParameterHandler &prm)
    {
      file_name = prm.get("Mesh file");
      if (file_name.empty())
        Input::fail(entry_path + "Mesh file",
                    file_name,
                    "give the file of the mesh");
      if (!std::ifstream(file_name))
        Input::fail(entry_path + "Mesh file",
                    file_name,
                    "the file cannot be opened (a relative path is relative "
                    "to the folder of the parameter file that sets it)");
      std::map<std::string, unsigned int> boundary_ids =
        gmsh_physical_names(file_name, dim - 1);
      parse_name_ids(entry_path + "Boundary names", prm.get("Boundary names"),
                     boundary_ids);
      names.clear();
      names.insert(boundary_ids.begin(), boundary_ids.end());
      std::map<std::string, unsigned int> body_ids =
        gmsh_physical_names(file_name, dim);
      parse_name_ids(entry_path + "Body names", prm.get("Body names"), body_ids);
      bodies.clear();
      bodies.insert(body_ids.begin(), body_ids.end());
      split_bodies = prm.get_bool("Split bodies");
      curved_boundaries = prm.get("Curved boundaries");
      curved_shape      = prm.get("Curved shape");
      curved_center     = Point<dim>(Input::parse_vector<dim>(
        entry_path + "Curved center", prm.get("Curved center")));
      curved_axis = Input::parse_vector<dim>(entry_path + "Curved axis",
                                             prm.get("Curved axis"));
      if (curved_shape == "cylinder" && (dim != 3 || !(curved_axis.norm() > 0)))
        Input::fail(entry_path + "Curved axis",
                    prm.get("Curved axis"),
                    dim == 3 ? "the axis must not be zero" :
                               "a cylinder needs 3D; use sphere in 2D");
      read_mesh();
    }



    namespace
    {
      /// The bodies (material ids) of the cells around each vertex of
      /// @p mesh.
      template <int dim>
      std::vector<std::set<types::material_id>>
      bodies_at_vertices(const Triangulation<dim> &mesh)
      {
        std::vector<std::set<types::material_id>> at(mesh.n_vertices());
        for (const auto &cell : mesh.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            at[cell->vertex_index(v)].insert(cell->material_id());
        return at;
      }

      /// "base" and "block" share 17 vertices; ... for the first pair that
      /// shares any, or an empty text.
      std::string
      describe_shared_vertices(
        const std::vector<std::set<types::material_id>> &at,
        const std::map<std::string, types::material_id> &bodies)
      {
        std::map<std::pair<types::material_id, types::material_id>, unsigned int>
          shared;
        for (const auto &ids : at)
          for (auto a = ids.begin(); a != ids.end(); ++a)
            for (auto b = std::next(a); b != ids.end(); ++b)
              ++shared[{*a, *b}];
        if (shared.empty())
          return "";
        const auto name = [&](const types::material_id id) {
          for (const auto &[body, body_id] : bodies)
            if (body_id == id)
              return body;
          return std::to_string(id);
        };
        const auto &[pair, count] = *shared.begin();
        return "the bodies '" + name(pair.first) + "' and '" + name(pair.second) +
               "' share " + std::to_string(count) + " vertices" +
               (shared.size() > 1 ? " (and " + std::to_string(shared.size() - 1) +
                                      " more pairs of bodies share some)" :
                                    "");
      }
    } // namespace



    template <int dim>
    void
    FromFile<dim>::read_mesh()
    {
      Triangulation<dim> mesh;
      GridIn<dim>        grid_in(mesh);
      const auto         fail_to_read = [&](const std::string &reason) {
        Input::fail(entry_path + "Mesh file",
                    file_name,
                    "the file is not a mesh deal.II can read as " +
                      std::to_string(dim) + "D (" + reason + ")");
      };
      try
        {
          grid_in.read(file_name);
        }
      catch (const ExceptionBase &error)
        {
          // deal.II's own words, without its frame and stack trace.
          std::ostringstream info;
          error.print_info(info);
          fail_to_read(Input::one_line(info.str(), 120));
        }
      catch (const std::exception &error)
        {
          fail_to_read(Input::one_line(error.what(), 120));
        }
      if (mesh.n_active_cells() == 0)
        Input::fail(entry_path + "Mesh file",
                    file_name,
                    "the file holds no " + std::to_string(dim) + "D cells");

      // One body: all cells are it, whatever their tags.
      if (bodies.size() <= 1)
        {
          if (bodies.empty())
            bodies["body"] = 0;
          const types::material_id id = bodies.begin()->second;
          for (const auto &cell : mesh.active_cell_iterators())
            cell->set_material_id(id);
        }
      std::set<types::material_id> named, in_mesh;
      for (const auto &[name, id] : bodies)
        named.insert(id);
      for (const auto &cell : mesh.active_cell_iterators())
        in_mesh.insert(cell->material_id());
      for (const types::material_id id : in_mesh)
        if (named.count(id) == 0)
          Input::fail(entry_path + "Mesh file", file_name,
                      "its cells with the tag " + std::to_string(id) +
                        " belong to no named body: name the group in Gmsh "
                        "(Physical " + (dim == 2 ? "Surface" : "Volume") +
                        "(\"name\", " + std::to_string(id) +
                        ")) or in <Geometry/From file/Body names>");
      for (const auto &[name, id] : bodies)
        if (in_mesh.count(id) == 0)
          Input::fail(entry_path + "Body names", name + ": " + std::to_string(id),
                      "a tag that cells of the mesh have (the body '" + name +
                        "' has no cells)");

      const std::vector<std::set<types::material_id>> at = bodies_at_vertices(mesh);
      if (const std::string shared = describe_shared_vertices(at, bodies);
          !shared.empty() && !split_bodies)
        Input::fail(entry_path + "Mesh file", file_name,
                    shared + ", which joins them (they could neither slide "
                    "nor separate): mesh them apart, or set <Geometry/From "
                    "file/Split bodies> = true to give each its own copy of "
                    "those vertices");

      // The description, with one copy of a shared vertex per body.
      vertices.clear();
      cells.clear();
      faces = SubCellData();
      std::map<std::pair<unsigned int, types::material_id>, unsigned int> copy;
      const auto vertex_of = [&](const unsigned int v, const types::material_id body) {
        const auto [it, inserted] = copy.try_emplace({v, body}, vertices.size());
        if (inserted)
          vertices.push_back(mesh.get_vertices()[v]);
        return it->second;
      };
      types::boundary_id next_id = 0;
      for (const auto &[name, id] : names)
        next_id = std::max<types::boundary_id>(next_id, id + 1);
      for (const types::boundary_id id : mesh.get_boundary_ids())
        next_id = std::max<types::boundary_id>(next_id, id + 1);
      std::map<std::pair<types::material_id, types::material_id>, types::boundary_id>
        between;
      const auto body_name = [&](const types::material_id id) {
        for (const auto &[name, body_id] : bodies)
          if (body_id == id)
            return name;
        return std::to_string(id);
      };
      for (const auto &cell : mesh.active_cell_iterators())
        {
          const types::material_id body = cell->material_id();
          CellData<dim>            data(cell->n_vertices());
          for (const unsigned int v : cell->vertex_indices())
            data.vertices[v] = vertex_of(cell->vertex_index(v), body);
          data.material_id = body;
          data.manifold_id = cell->manifold_id();
          cells.push_back(data);
          for (const unsigned int f : cell->face_indices())
            {
              types::boundary_id id;
              if (cell->at_boundary(f))
                id = cell->face(f)->boundary_id();
              else if (cell->neighbor(f)->material_id() != body)
                {
                  const auto [it, inserted] =
                    between.try_emplace({body, cell->neighbor(f)->material_id()}, next_id);
                  if (inserted)
                    {
                      names[body_name(body) + " on " +
                            body_name(cell->neighbor(f)->material_id())] = next_id;
                      ++next_id;
                    }
                  id = it->second;
                }
              else
                continue;
              CellData<dim - 1> face(cell->face(f)->n_vertices());
              for (unsigned int v = 0; v < face.vertices.size(); ++v)
                face.vertices[v] = vertex_of(cell->face(f)->vertex_index(v), body);
              face.boundary_id = id;
              face.manifold_id = cell->face(f)->manifold_id();
              if constexpr (dim == 2)
                faces.boundary_lines.push_back(face);
              else
                faces.boundary_quads.push_back(face);
            }
        }
    }



    template <int dim>
    void
    FromFile<dim>::create_coarse_mesh(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      triangulation.create_triangulation(vertices, cells, faces);
      if (!curved_boundaries.empty())
        {
          std::set<types::boundary_id> ids;
          for (const auto &face : faces.boundary_lines)
            ids.insert(face.boundary_id);
          for (const auto &face : faces.boundary_quads)
            ids.insert(face.boundary_id);
          const BoundaryNames known(boundary_names(), ids);
          std::set<types::boundary_id> curved;
          for (const std::string &name : Input::split(curved_boundaries, ';'))
            curved.insert(known.id(entry_path + "Curved boundaries", name));
          for (const auto &cell : triangulation.cell_iterators_on_level(0))
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary() && curved.count(face->boundary_id()) > 0)
                face->set_all_manifold_ids(curved_manifold);
        }
      if (curved_shape == "sphere")
        triangulation.set_manifold(curved_manifold,
                                   SphericalManifold<dim>(curved_center));
      else if constexpr (dim == 3)
        triangulation.set_manifold(curved_manifold,
                                   CylindricalManifold<dim>(curved_axis,
                                                            curved_center));
    }



    template <int dim>
    std::map<std::string, types::boundary_id>
    FromFile<dim>::boundary_names() const
    {
      return names;
    }



    template <int dim>
    std::map<std::string, types::material_id>
    FromFile<dim>::body_names() const
    {
      return bodies;
    }

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      FromFile,
      "from file",
      "A mesh read from a file (Gmsh .msh with physical names, or any format "
      "of deal.II's GridIn); boundary names from Gmsh's physical names or "
      "Boundary names, bodies from its named groups of cells or Body names.")
  } // namespace Geometry
} // namespace FrictionalContact
