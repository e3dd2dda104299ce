#pragma once

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/component_mask.h>

#include <frictional_contact/base/input.h>

#include <map>
#include <vector>

namespace FrictionalContact
{
  /**
   * Supports and loads of the elastic body, as read from the subsection
   * "Boundary conditions": boundaries with zero displacement (all or some
   * components), boundaries with a prescribed displacement (a function of
   * position and time), surface tractions and normal pressures per
   * boundary and a body force.
   */
  template <int dim>
  class BoundaryConditions
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    BoundaryConditions(ParameterHandler &prm, const BoundaryNames &names);

    struct FixedBoundary
    {
      types::boundary_id id;
      /// The displacement components held (at zero, or prescribed).
      ComponentMask components;
    };

    std::vector<FixedBoundary>                    fixed_boundaries;
    std::vector<FixedBoundary>                    prescribed_boundaries;
    /// u(x, t) on the prescribed boundaries.
    std::unique_ptr<FunctionParser<dim>>          prescribed_displacement;
    std::map<types::boundary_id, Tensor<1, dim>> tractions;
    /// Normal pressures per boundary (against the outward normal).
    std::map<types::boundary_id, double>          pressures;
    Tensor<1, dim>                                body_force;
    /// One line per boundary component both fixed and prescribed (fixed
    /// wins): the scene's prescribed displacement does not act there.
    std::vector<std::string> overridden;
  };
} // namespace FrictionalContact
