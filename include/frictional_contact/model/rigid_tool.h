#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <frictional_contact/base/time_function.h>
#include <frictional_contact/model/mortar_segments.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace FrictionalContact
{
  /**
   * A rigid tool: a surface read from a file (a Gmsh surface mesh of lines
   * in 2D, of triangles or quads in 3D; an STL, OFF or OBJ file in 3D)
   * that moves by a prescribed rigid motion y(X, t) = c + a(t) + R(t)(X - c),
   * a translation a(t) and a rotation R(t) by an angle theta(t) about an
   * axis through the centre c. Contact pairs name it as their master
   * (`Contact/Pairs = slab top : punch`): the mortar code integrates the
   * slave surface against its faces, with the master's displacement given.
   *
   * Owns the surface: its vertices in the file's coordinates and its faces
   * as segments (2D) or quads in deal.II's vertex order (3D; a triangle is
   * cut into three quads from its centroid), each face's outward normal
   * (out of the tool) following the vertex order of the file.
   */
  template <int dim>
  class RigidTool
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    /// Reads the subsection "Contact/Rigid tool" (the caller is in
    /// "Contact") and, if it names a tool, reads and checks its surface.
    explicit RigidTool(ParameterHandler &prm);

    /// Whether the scene has a tool (<Name> is not empty).
    bool
    active() const
    {
      return !name.empty();
    }

    /// The name by which <Contact/Pairs> refers to the tool.
    const std::string &
    tool_name() const
    {
      return name;
    }

    /// Whether the pairs with the tool take their geometry, in the tool's
    /// frames, at every Newton iterate (<Geometry at finite strain>).
    bool
    geometry_at_every_newton_iterate() const
    {
      return newton_geometry;
    }

    /// The translation a(t) and the angle theta(t) of the tool's motion.
    Tensor<1, dim>
    translation_at(const double t) const;
    double
    angle_at(const double t) const;

    /// The tool's faces at time @p t.
    std::vector<MortarSegments::FaceVertices<dim>>
    faces_at(const double t) const;

    /// The unit normals at the vertices of each face at time @p t (in the
    /// order of faces_at()): at each vertex the mean of the outward
    /// normals of the faces around it, a normal field that turns smoothly
    /// over the faceted surface.
    std::vector<std::array<Tensor<1, dim>, dim == 2 ? 2 : 4>>
    vertex_normals_at(const double t) const;

    /// Number of faces (a triangle of the file counts as three).
    std::size_t
    n_faces() const
    {
      return faces.size();
    }

    /// The tool's surface at time @p t as the text of a VTK unstructured
    /// grid file (.vtu, for ParaView).
    std::string
    vtu(const double t) const;

  private:
    /// Reads the surface into vertices and faces; throws an InputError
    /// naming the file and the problem if it is not a usable surface.
    void
    read(const std::string &file_name);

    void
    read_with_grid_in(const std::string &file_name);

    void
    read_polygon_soup(const std::string &file_name);

    /// Adds a face of the file from its vertex indices in its order
    /// (a segment in 2D; a triangle or a quad in 3D, counterclockwise
    /// seen from outside the tool).
    void
    add_face(const std::vector<unsigned int> &polygon);

    /// Throws an InputError if a face is degenerate, a vertex not finite,
    /// or two faces that share an edge are oriented oppositely.
    void
    check_surface(const std::vector<std::vector<unsigned int>> &polygons) const;

    std::string                                           name;
    std::string                                           file;
    std::vector<Point<dim>>                               vertices;
    std::vector<std::array<unsigned int, dim == 2 ? 2 : 4>> faces;
    /// At each vertex the unit mean of the normals of the faces around it,
    /// in the file's frame.
    std::vector<Tensor<1, dim>> vertex_normals;
    Point<dim>                                            center;
    Tensor<1, dim>                                        axis;
    std::unique_ptr<TimeFunction>                         translation;
    std::unique_ptr<TimeFunction>                         angle;
    bool                                                  newton_geometry = false;
  };
} // namespace FrictionalContact
