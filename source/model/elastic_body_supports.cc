#include <deal.II/base/function_parser.h>
#include <deal.II/numerics/vector_tools.h>

#include <frictional_contact/model/axisymmetry.h>
#include <frictional_contact/model/elastic_body.h>

// The body's supports: the reactions they take and the displacements they
// prescribe (members of ElasticBody kept apart from its assembly).
namespace FrictionalContact
{
  template <int dim>
  Tensor<1, dim>
  ElasticBody<dim>::support_reaction(const Vector  &u,
                                     const double   load_factor,
                                     const Supports supports) const
  {
    // The force at a hanging node acts on the nodes it hangs from.
    Vector residual(owned_dofs, mpi_communicator);
    element_forces(u, load_factor, hanging_node_constraints, residual);
    return sum_at_fixed_dofs(residual, supports);
  }



  template <int dim>
  Tensor<1, dim>
  ElasticBody<dim>::support_reaction_of(const Vector  &internal_force,
                                        const double   load_factor,
                                        const Supports supports) const
  {
    // The load's part: element_forces() of a zero displacement, -p.
    Vector residual(owned_dofs, mpi_communicator);
    element_forces(make_ghosted_vector(), load_factor, hanging_node_constraints, residual);
    residual += internal_force;
    return sum_at_fixed_dofs(residual, supports);
  }



  template <int dim>
  Tensor<1, dim>
  ElasticBody<dim>::sum_at_fixed_dofs(const Vector  &residual,
                                      const Supports supports) const
  {
    // Only the dofs held by a fixed boundary carry a support reaction.
    Tensor<1, dim> reaction_here;
    for (unsigned int c = 0; c < dim; ++c)
      for (const auto g : component_dofs[c])
        if (is_fixed(g) &&
            (supports == Supports::all || prescribed_dofs.is_element(g)))
          reaction_here[c] += residual[g];
    const Tensor<1, dim> reaction = Utilities::MPI::sum(reaction_here, mpi_communicator);
    return materials.axisymmetric() ? Axisymmetry::revolution_total(reaction) : reaction;
  }



  template <int dim>
  void
  ElasticBody<dim>::prescribed_increment(const double t_old,
                                         const double t_new,
                                         Vector      &increment) const
  {
    increment = 0;
    FunctionParser<dim> &u_D = *conditions.prescribed_displacement;
    /// u_D(x, t_new) - u_D(x, t_old).
    class Difference : public Function<dim>
    {
    public:
      Difference(FunctionParser<dim> &u, const double t_old, const double t_new)
        : Function<dim>(dim)
        , u(u)
        , t_old(t_old)
        , t_new(t_new)
      {}

      double
      value(const Point<dim> &p, const unsigned int c) const override
      {
        u.set_time(t_new);
        const double after = u.value(p, c);
        u.set_time(t_old);
        return after - u.value(p, c);
      }

    private:
      FunctionParser<dim> &u;
      const double         t_old, t_new;
    } difference(u_D, t_old, t_new);

    for (const auto &prescribed : conditions.prescribed_boundaries)
      {
        std::map<types::global_dof_index, double> values;
        VectorTools::interpolate_boundary_values(
          dof_handler, prescribed.id, difference, values, prescribed.components);
        for (const auto &[dof, value] : values)
          if (prescribed_dofs.is_element(dof))
            increment[dof] = value;
      }
    increment.compress(VectorOperation::insert);
    // A hanging vertex on a prescribed boundary is no prescribed dof: it
    // moves with the vertices it hangs from.
    hanging_node_constraints.distribute(increment);
  }



  template Tensor<1, 2>
  ElasticBody<2>::support_reaction(const Vector &, const double, const Supports) const;
  template Tensor<1, 2>
  ElasticBody<2>::support_reaction_of(const Vector &, const double, const Supports) const;
  template Tensor<1, 2>
  ElasticBody<2>::sum_at_fixed_dofs(const Vector &, const Supports) const;
  template void
  ElasticBody<2>::prescribed_increment(const double, const double, Vector &) const;
  template Tensor<1, 3>
  ElasticBody<3>::support_reaction(const Vector &, const double, const Supports) const;
  template Tensor<1, 3>
  ElasticBody<3>::support_reaction_of(const Vector &, const double, const Supports) const;
  template Tensor<1, 3>
  ElasticBody<3>::sum_at_fixed_dofs(const Vector &, const Supports) const;
  template void
  ElasticBody<3>::prescribed_increment(const double, const double, Vector &) const;
} // namespace FrictionalContact
