#include <deal.II/base/data_out_base.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>

#include <frictional_contact/base/input.h>
#include <frictional_contact/model/rigid_tool.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace FrictionalContact
{
  namespace
  {
    const std::string entry_path = "Contact/Rigid tool/";

    /// Whether @p file_name ends in @p extension (".msh").
    bool
    has_extension(const std::string &file_name, const std::string &extension)
    {
      return file_name.size() >= extension.size() &&
             file_name.compare(file_name.size() - extension.size(),
                               extension.size(),
                               extension) == 0;
    }

    /// @p v rotated by @p angle about the unit @p axis (Rodrigues; in 2D
    /// counterclockwise in the plane).
    template <int dim>
    Tensor<1, dim>
    rotate(const Tensor<1, dim> &v, const Tensor<1, dim> &axis, const double angle)
    {
      const double c = std::cos(angle), s = std::sin(angle);
      Tensor<1, dim> w;
      if constexpr (dim == 2)
        {
          (void)axis;
          w[0] = c * v[0] - s * v[1];
          w[1] = s * v[0] + c * v[1];
        }
      else
        w = c * v + s * cross_product_3d(axis, v) + (1 - c) * (axis * v) * axis;
      return w;
    }
  } // namespace



  template <int dim>
  void
  RigidTool<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Rigid tool");
    prm.declare_entry("Name",
                      "",
                      Patterns::Anything(),
                      "The name by which <Contact/Pairs> makes the tool the "
                      "master of a pair ('slab top : punch'). Empty: no tool.");
    prm.declare_entry(
      "Surface mesh",
      "",
      Patterns::Anything(),
      std::string("The tool's surface: ") +
        (dim == 2 ? "a Gmsh file (.msh) of line elements. Each segment's "
                    "outward normal (out of the tool) points to the right "
                    "of its direction: a closed outline runs counterclockwise." :
                    "a Gmsh file (.msh) of triangles or quads, or an STL, OFF "
                    "or OBJ file. Each face's outward normal (out of the "
                    "tool) follows its vertex order by the right-hand rule, "
                    "as STL files have it.") +
        " A relative path is relative to the folder of the parameter file "
        "that sets it.");
    prm.declare_entry("Reverse orientation",
                      "false",
                      Patterns::Bool(),
                      "Whether the file's normals point into the tool; then "
                      "they are reversed.");
    prm.declare_entry("Translation",
                      dim == 2 ? "0; 0" : "0; 0; 0",
                      Patterns::Anything(),
                      "The tool's translation a(t) from where the file puts "
                      "it (muParser, one expression of t per component, "
                      "separated by ';'): y = c + a(t) + R(t) (X - c).");
    prm.declare_entry("Rotation angle",
                      "0",
                      Patterns::Anything(),
                      "The angle theta(t) of the rotation R(t), in radians "
                      "(muParser expression of t)" +
                        std::string(dim == 2 ? ", counterclockwise." :
                                               ", about <Rotation axis> by "
                                               "the right-hand rule."));
    prm.declare_entry("Rotation center",
                      dim == 2 ? "0, 0" : "0, 0, 0",
                      Patterns::Anything(),
                      "The point c of the file's coordinates about which the "
                      "tool turns; it moves with the translation.");
    prm.declare_entry(
      "Geometry at finite strain",
      "fixed point",
      Patterns::Selection("fixed point|every Newton iterate"),
      "How the pairs with the tool follow a body at finite strain within "
      "an increment. fixed point: the slave surface's normals, the "
      "increment solved again with the geometry where it ended until it "
      "settles (<Contact/Pair geometry>). every Newton iterate: the tool's "
      "own normals (its vertex normals, integrated as its points are), the "
      "gaps measured along them, the geometry taken at every Newton iterate "
      "and the tool's curvature in the tangent, as against an obstacle: "
      "fewer Newton steps, one solve per increment (doc/performance.md, "
      "\"The 3D ironing at scale\"). Pairs whose slave body is at small "
      "strain take their geometry once per increment either way.");
    if (dim == 3)
      prm.declare_entry("Rotation axis",
                        "0, 0, 1",
                        Patterns::Anything(),
                        "The direction of the rotation's axis.");
    prm.leave_subsection();
  }



  template <int dim>
  RigidTool<dim>::RigidTool(ParameterHandler &prm)
  {
    prm.enter_subsection("Rigid tool");
    name = Input::trim(prm.get("Name"));
    file = prm.get("Surface mesh");
    center = Point<dim>(Input::parse_vector<dim>(entry_path + "Rotation center",
                                                 prm.get("Rotation center")));
    if constexpr (dim == 3)
      {
        axis = Input::parse_vector<dim>(entry_path + "Rotation axis",
                                        prm.get("Rotation axis"));
        if (!(axis.norm() > 0))
          Input::fail(entry_path + "Rotation axis",
                      prm.get("Rotation axis"),
                      "a direction, not the zero vector");
        axis /= axis.norm();
      }
    translation = std::make_unique<TimeFunction>(entry_path + "Translation",
                                                 prm.get("Translation"),
                                                 dim);
    angle = std::make_unique<TimeFunction>(entry_path + "Rotation angle",
                                           prm.get("Rotation angle"),
                                           1);
    const bool reverse = prm.get_bool("Reverse orientation");
    newton_geometry    = prm.get("Geometry at finite strain") == "every Newton iterate";
    prm.leave_subsection();
    if (name.empty())
      return;
    if (file.empty())
      Input::fail(entry_path + "Surface mesh", file, "give the file of the tool's surface");
    if (!std::ifstream(file))
      Input::fail(entry_path + "Surface mesh",
                  file,
                  "the file cannot be opened (a relative path is relative to "
                  "the folder of the parameter file that sets it)");
    read(file);
    if (reverse)
      for (auto &face : faces)
        {
          if constexpr (dim == 2)
            std::swap(face[0], face[1]);
          else
            std::swap(face[1], face[2]); // lexicographic: the transposed quad
        }
    // The faces' normals summed at the vertices, in the file's frame.
    vertex_normals.assign(vertices.size(), Tensor<1, dim>());
    for (const auto &face : faces)
      {
        MortarSegments::FaceVertices<dim> x;
        for (unsigned int v = 0; v < face.size(); ++v)
          x[v] = vertices[face[v]];
        const Tensor<1, dim> normal = MortarSegments::unit_normal<dim>(x);
        for (const unsigned int v : face)
          vertex_normals[v] += normal;
      }
    for (Tensor<1, dim> &normal : vertex_normals)
      normal /= normal.norm();
  }



  template <int dim>
  void
  RigidTool<dim>::read(const std::string &file_name)
  {
    if (has_extension(file_name, ".msh") || dim == 2)
      read_with_grid_in(file_name);
    else
      read_polygon_soup(file_name);
    if (faces.empty())
      Input::fail(entry_path + "Surface mesh",
                  file_name,
                  std::string("a broken surface mesh: the file holds no ") +
                    (dim == 2 ? "line elements" : "triangles or quads"));
  }



  template <int dim>
  void
  RigidTool<dim>::read_with_grid_in(const std::string &file_name)
  {
    Triangulation<dim - 1, dim> surface;
    GridIn<dim - 1, dim>        grid_in(surface);
    const auto                  fail = [&](const std::string &reason) {
      Input::fail(entry_path + "Surface mesh",
                  file_name,
                  "a broken surface mesh: deal.II's GridIn cannot read it as " +
                    std::string(dim == 2 ? "lines in 2D" : "a surface in 3D") +
                    " (" + reason + ")" +
                    (dim == 2 ? "" : "; .stl, .off and .obj files are read by CGAL"));
    };
    try
      {
        std::ifstream in(file_name);
        grid_in.read_msh(in);
      }
    catch (const ExceptionBase &error)
      {
        std::ostringstream info;
        error.print_info(info);
        fail(Input::one_line(info.str(), 120));
      }
    catch (const std::exception &error)
      {
        fail(Input::one_line(error.what(), 120));
      }
    // GridIn keeps each cell's vertices in the file's order (a quad's in
    // deal.II's lexicographic order); polygons go counterclockwise.
    vertices = surface.get_vertices();
    std::vector<std::vector<unsigned int>> polygons;
    for (const auto &cell : surface.active_cell_iterators())
      {
        std::vector<unsigned int> polygon;
        for (const unsigned int v : cell->vertex_indices())
          polygon.push_back(cell->vertex_index(v));
        if (polygon.size() == 4)
          std::swap(polygon[2], polygon[3]);
        polygons.push_back(polygon);
      }
    check_surface(polygons);
    for (const auto &polygon : polygons)
      add_face(polygon);
  }



  template <int dim>
  void
  RigidTool<dim>::read_polygon_soup(const std::string &file_name)
  {
    using CgalPoint = CGAL::Simple_cartesian<double>::Point_3;
    std::vector<CgalPoint>                 points;
    std::vector<std::vector<std::size_t>>  soup;
    bool                                   read = false;
    try
      {
        read = CGAL::IO::read_polygon_soup(file_name, points, soup);
      }
    catch (const std::exception &)
      {}
    if (!read)
      Input::fail(entry_path + "Surface mesh",
                  file_name,
                  "a broken surface mesh: CGAL cannot read it (an STL, OFF "
                  "or OBJ file is expected, or a Gmsh .msh)");
    for (const CgalPoint &p : points)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = p[d];
        vertices.push_back(x);
      }
    std::vector<std::vector<unsigned int>> polygons;
    for (const auto &polygon : soup)
      polygons.emplace_back(polygon.begin(), polygon.end());
    check_surface(polygons);
    for (const auto &polygon : polygons)
      add_face(polygon);
  }



  template <int dim>
  void
  RigidTool<dim>::check_surface(
    const std::vector<std::vector<unsigned int>> &polygons) const
  {
    const auto fail = [&](const std::string &problem) {
      Input::fail(entry_path + "Surface mesh", file, "a broken surface mesh: " + problem);
    };
    const auto where = [](const Point<dim> &x) {
      std::string text = "(";
      for (unsigned int d = 0; d < dim; ++d)
        text += (d == 0 ? "" : ", ") + Input::to_text(x[d]);
      return text + ")";
    };
    double extent = 0;
    for (const Point<dim> &x : vertices)
      {
        for (unsigned int d = 0; d < dim; ++d)
          if (!std::isfinite(x[d]))
            fail("a vertex has a coordinate that is not a finite number");
        extent = std::max(extent, x.distance(vertices[0]));
      }
    // Each directed edge once: two faces that share an edge run it in
    // opposite directions if their normals agree.
    std::map<std::pair<unsigned int, unsigned int>, std::size_t> edges;
    for (std::size_t k = 0; k < polygons.size(); ++k)
      {
        const std::vector<unsigned int> &polygon = polygons[k];
        const std::size_t expected_min = dim == 2 ? 2 : 3;
        const std::size_t expected_max = dim == 2 ? 2 : 4;
        if (polygon.size() < expected_min || polygon.size() > expected_max)
          fail("face " + std::to_string(k + 1) + " has " +
               std::to_string(polygon.size()) + " vertices; " +
               (dim == 2 ? "segments of 2 are expected" :
                           "triangles and quads are expected"));
        for (const unsigned int v : polygon)
          if (v >= vertices.size())
            fail("face " + std::to_string(k + 1) + " names a vertex that does not exist");
        // The size of the face: its length in 2D, its area in 3D (Newell).
        double size = 0;
        if constexpr (dim == 2)
          size = vertices[polygon[0]].distance(vertices[polygon[1]]) / extent;
        else
          {
            Tensor<1, dim> normal;
            for (std::size_t a = 0; a < polygon.size(); ++a)
              normal += cross_product_3d(vertices[polygon[a]],
                                         vertices[polygon[(a + 1) % polygon.size()]]);
            size = normal.norm() / (extent * extent);
          }
        if (!(size > 1e-10))
          fail("face " + std::to_string(k + 1) + " at " + where(vertices[polygon[0]]) +
               " has no " + (dim == 2 ? "length" : "area"));
        // In 2D a vertex starts one segment and ends one: the keys are
        // (vertex, 0) for a start and (vertex, 1) for an end.
        const std::size_t n_edges = dim == 2 ? 2 : polygon.size();
        for (std::size_t a = 0; a < n_edges; ++a)
          {
            const auto edge =
              dim == 2 ? std::make_pair(polygon[a], static_cast<unsigned int>(a)) :
                         std::make_pair(polygon[a], polygon[(a + 1) % polygon.size()]);
            const auto [it, inserted] = edges.emplace(edge, k);
            if (!inserted)
              fail("faces " + std::to_string(it->second + 1) + " and " +
                   std::to_string(k + 1) + " that meet at " +
                   where(vertices[edge.first]) + " are oriented oppositely (or "
                   "the surface has a non-manifold edge); orient all faces the "
                   "same way, e.g. with Gmsh's Reverse or by exporting the surface "
                   "of a volume");
          }
      }
  }



  template <int dim>
  void
  RigidTool<dim>::add_face(const std::vector<unsigned int> &polygon)
  {
    if constexpr (dim == 2)
      faces.push_back({{polygon[0], polygon[1]}});
    else if (polygon.size() == 4) // counterclockwise to lexicographic
      faces.push_back({{polygon[0], polygon[1], polygon[3], polygon[2]}});
    else
      {
        // A triangle a, b, c: three quads from its centroid g through the
        // midpoints of its edges, each counterclockwise like the triangle.
        const auto add_vertex = [&](const Point<dim> &x) {
          vertices.push_back(x);
          return static_cast<unsigned int>(vertices.size() - 1);
        };
        // Copies: adding vertices may move the others.
        const Point<dim> a = vertices[polygon[0]], b = vertices[polygon[1]],
                         c = vertices[polygon[2]];
        const unsigned int g  = add_vertex(Point<dim>((a + b + c) / 3.));
        const unsigned int ab = add_vertex(Point<dim>((a + b) / 2.));
        const unsigned int bc = add_vertex(Point<dim>((b + c) / 2.));
        const unsigned int ca = add_vertex(Point<dim>((c + a) / 2.));
        const std::array<std::array<unsigned int, 4>, 3> quads = {
          {{{polygon[0], ab, g, ca}}, {{polygon[1], bc, g, ab}}, {{polygon[2], ca, g, bc}}}};
        for (const auto &q : quads)
          faces.push_back({{q[0], q[1], q[3], q[2]}});
      }
  }



  template <int dim>
  Tensor<1, dim>
  RigidTool<dim>::translation_at(const double t) const
  {
    Tensor<1, dim> shift;
    for (unsigned int d = 0; d < dim; ++d)
      shift[d] = translation->value(t, d);
    return shift;
  }



  template <int dim>
  double
  RigidTool<dim>::angle_at(const double t) const
  {
    return angle->value(t);
  }



  template <int dim>
  std::vector<MortarSegments::FaceVertices<dim>>
  RigidTool<dim>::faces_at(const double t) const
  {
    // The motion at t once, then every vertex: y = c + a(t) + R(t)(X - c).
    const Tensor<1, dim>    shift = translation_at(t);
    const double            theta = angle_at(t);
    std::vector<Point<dim>> moved;
    moved.reserve(vertices.size());
    for (const Point<dim> &X : vertices)
      moved.push_back(center + shift + rotate<dim>(X - center, axis, theta));
    std::vector<MortarSegments::FaceVertices<dim>> result;
    result.reserve(faces.size());
    for (const auto &face : faces)
      {
        MortarSegments::FaceVertices<dim> y;
        for (unsigned int v = 0; v < face.size(); ++v)
          y[v] = moved[face[v]];
        result.push_back(y);
      }
    return result;
  }



  template <int dim>
  std::vector<std::array<Tensor<1, dim>, dim == 2 ? 2 : 4>>
  RigidTool<dim>::vertex_normals_at(const double t) const
  {
    // Turned by the rotation R(t); a translation does not turn them.
    const double theta = angle_at(t);
    std::vector<std::array<Tensor<1, dim>, dim == 2 ? 2 : 4>> result;
    result.reserve(faces.size());
    for (const auto &face : faces)
      {
        std::array<Tensor<1, dim>, dim == 2 ? 2 : 4> normals;
        for (unsigned int v = 0; v < face.size(); ++v)
          normals[v] = rotate<dim>(vertex_normals[face[v]], axis, theta);
        result.push_back(normals);
      }
    return result;
  }



  template <int dim>
  std::string
  RigidTool<dim>::vtu(const double t) const
  {
    std::vector<DataOutBase::Patch<dim - 1, dim>> patches;
    for (const MortarSegments::FaceVertices<dim> &y : faces_at(t))
      {
        DataOutBase::Patch<dim - 1, dim> patch;
        for (unsigned int v = 0; v < y.size(); ++v)
          patch.vertices[v] = y[v];
        patch.patch_index    = patches.size();
        patch.reference_cell = ReferenceCells::get_hypercube<dim - 1>();
        patches.push_back(patch);
      }
    std::ostringstream out;
    DataOutBase::write_vtu(
      patches,
      std::vector<std::string>(),
      std::vector<std::tuple<unsigned int,
                             unsigned int,
                             std::string,
                             DataComponentInterpretation::DataComponentInterpretation>>(),
      DataOutBase::VtkFlags(t),
      out);
    return out.str();
  }



  template class RigidTool<2>;
  template class RigidTool<3>;
} // namespace FrictionalContact
