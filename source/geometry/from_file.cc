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

      /// Names of the physical groups of dimension dim-1 in a Gmsh file
      /// ($PhysicalNames section; absent in other formats).
      std::map<std::string, types::boundary_id>
      gmsh_physical_names(const std::string &file_name, const int dim)
      {
        std::map<std::string, types::boundary_id> names;
        std::ifstream                             in(file_name);
        std::string                               line;
        while (std::getline(in, line))
          if (line.rfind("$PhysicalNames", 0) == 0)
            {
              unsigned int n = 0;
              in >> n;
              for (unsigned int i = 0; i < n; ++i)
                {
                  int         group_dim = -1;
                  long        tag       = -1;
                  std::string name;
                  in >> group_dim >> tag;
                  std::getline(in, name);
                  const auto first = name.find('"'), last = name.rfind('"');
                  if (first == std::string::npos || last <= first)
                    break;
                  if (group_dim == dim - 1 && tag >= 0)
                    names[name.substr(first + 1, last - first - 1)] =
                      static_cast<types::boundary_id>(tag);
                }
              break;
            }
        return names;
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
                        "boundary ids, their physical names boundary names), "
                        "or any other format deal.II's GridIn reads by "
                        "extension (.inp, .ucd, .vtk, ...). Quadrilaterals in "
                        "2D, hexahedra in 3D.");
      prm.declare_entry("Boundary names",
                        "",
                        Patterns::Anything(),
                        "More names for boundary ids, 'name: id' separated "
                        "by ';' (for formats without names, or to rename).");
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
      names = gmsh_physical_names(file_name, dim);
      for (const std::string &item : Input::split(prm.get("Boundary names"), ';'))
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
            Input::fail(entry_path + "Boundary names",
                        prm.get("Boundary names"),
                        "'name: id' pairs separated by ';' are expected");
          names[pair[0]] = static_cast<types::boundary_id>(id);
        }
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
    }



    template <int dim>
    void
    FromFile<dim>::create_coarse_mesh(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      // The mesh's smoothing (with geometric multigrid: one level between
      // neighbours at a vertex) survives the copy below.
      Triangulation<dim> mesh(triangulation.get_mesh_smoothing());
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

      if (!curved_boundaries.empty())
        {
          const std::vector<types::boundary_id> ids = mesh.get_boundary_ids();
          const BoundaryNames known(boundary_names(), {ids.begin(), ids.end()});
          std::set<types::boundary_id> curved;
          for (const std::string &name : Input::split(curved_boundaries, ';'))
            curved.insert(known.id(entry_path + "Curved boundaries", name));
          for (const auto &face : mesh.active_face_iterators())
            if (face->at_boundary() && curved.count(face->boundary_id()) > 0)
              face->set_all_manifold_ids(curved_manifold);
        }
      triangulation.copy_triangulation(mesh);
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

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      FromFile,
      "from file",
      "A mesh read from a file (Gmsh .msh with physical names, or any format "
      "of deal.II's GridIn); boundary names from Gmsh's physical names or "
      "Boundary names.")
  } // namespace Geometry
} // namespace FrictionalContact
