#include <frictional_contact/model/mortar_basis.h>
#include <frictional_contact/model/pair_couplings.h>

#include <limits>


namespace FrictionalContact
{
  template <int dim>
  bool
  MortarBasis<dim>::make_basis(const ElasticBody<dim>     &body,
                               const ContactOperator<dim> &contact)
  {
    const IndexSet &owned = body.locally_owned_dofs();
    const MPI_Comm  comm  = body.get_mpi_communicator();

    // E: P_jl into the columns of the master unknowns (the contact
    // operator resolves hanging and held master dofs, on any rank).
    const auto E = PairCouplings<dim>(contact).basis();
    basis.take(owned, comm, E, true);
    return Utilities::MPI::sum(E.size(), comm) == 0;
  }



  template <int dim>
  std::vector<double>
  MortarBasis<dim>::master_stiffness(const ElasticBody<dim>     &body,
                                     const ContactOperator<dim> &contact) const
  {
    const VolumetricSplit                 volumetric = body.volumetric_split();
    const TrilinosWrappers::SparseMatrix &K =
      volumetric.reduced_stiffness != nullptr ?
        *volumetric.reduced_stiffness :
        body.stiffness().matrix("contact pairs (<Contact/Pairs>)");
    const unsigned int  n = contact.n_local();
    std::vector<double> stiffness(n, std::numeric_limits<double>::infinity());

    // E = Q - I: slave rows, master columns. a_S: D_jj on slave node j's
    // dofs; A = E^T a_S (A_l = sum_j D_jj P_jl = sum_j M_jl).
    Vector slave_area = body.make_vector(), master_area = body.make_vector();
    for (unsigned int j = 0; j < n; ++j)
      if (contact.acts_between_bodies(j))
        for (unsigned int c = 0; c < dim; ++c)
          slave_area[contact.dof(j, c)] = contact.nodal_area(j);
    slave_area.compress(VectorOperation::insert);
    basis.matrix.Tvmult(master_area, slave_area);
    master_area -= slave_area;

    // K_ll / A_l at the master dofs, then sum_l P_jl K_ll / A_l at the
    // slave dofs (E of it).
    Vector per_area = body.make_vector(), seen = body.make_vector();
    for (const types::global_dof_index i : body.locally_owned_dofs())
      if (master_area[i] > 0)
        per_area[i] = K.diag_element(i) / master_area[i];
    per_area.compress(VectorOperation::insert);
    basis.matrix.vmult(seen, per_area);
    seen -= per_area;

    for (unsigned int j = 0; j < n; ++j)
      if (contact.acts_between_bodies(j))
        {
          Tensor<1, dim> e;
          e[0]                    = 1;
          const Tensor<1, dim> nj = contact.to_cartesian(j, e);
          double               m  = 0;
          for (unsigned int c = 0; c < dim; ++c)
            m += nj[c] * nj[c] * seen[contact.dof(j, c)];
          m *= contact.nodal_area(j);
          if (m > 0)
            stiffness[j] = m;
        }
    return stiffness;
  }



  template <int dim>
  MortarBasis<dim>::MortarBasis(const ElasticBody<dim>     &body,
                                const ContactOperator<dim> &contact,
                                const bool                  with_stiffness)
  {
    const bool identity = make_basis(body, contact);
    // Rows that change within Newton need a body at finite strain on a
    // pair, whose law leaves K without a volumetric split: the mixed
    // solves, which keep the basis of the increment's start, never meet
    // them.
    Assert(!contact.mortar_rows_change_within_newton() ||
             body.volumetric_split().reduced_stiffness == nullptr,
           ExcInternalError());
    const TrilinosWrappers::SparseMatrix &stiffness =
      body.stiffness().matrix("contact pairs (<Contact/Pairs>)");
    const VolumetricSplit volumetric = body.volumetric_split();
    has_stiffness = with_stiffness || volumetric.reduced_stiffness != nullptr;
    // Q = I for the whole increment: rows that change within Newton may
    // reach a master's unknowns at the next iterate.
    if (identity && !contact.mortar_rows_change_within_newton())
      {
        if (has_stiffness)
          transformed_stiffness.copy_from(stiffness);
        // The tangents of nonlinear laws are made in that same matrix.
        tangent_itself = std::make_unique<AssembledStiffness>(stiffness);
      }
    else if (has_stiffness)
      transform_to_basis(basis.matrix, stiffness, transformed_stiffness);

    if (volumetric.reduced_stiffness != nullptr)
      {
        transform_to_basis(basis.matrix, *volumetric.reduced_stiffness, transformed_reduced_stiffness);
        volumetric.divergence->mmult(transformed_divergence, basis.matrix);
        split                    = volumetric;
        split.reduced_stiffness  = &transformed_reduced_stiffness;
        split.divergence         = &transformed_divergence;
        split.stiffness_bound    = transformed_stiffness.linfty_norm();
      }
  }



  template <int dim>
  void
  MortarBasis<dim>::update_tangent(const TrilinosWrappers::SparseMatrix &tangent,
                                   const bool                            make_entries)
  {
    has_tangent = true;
    if (tangent_itself)
      {
        AssertThrow(&tangent == &tangent_itself->matrix("the tangent"), ExcInternalError());
        return;
      }
    tangent_operator.take(tangent, make_entries);
  }



  template <int dim>
  void
  MortarBasis<dim>::follow_rows(const ElasticBody<dim>     &body,
                                const ContactOperator<dim> &contact)
  {
    Assert(!tangent_itself, ExcInternalError());
    make_basis(body, contact);
    if (has_tangent)
      tangent_operator.take(body.stiffness().matrix("contact pairs"), false);
  }



  template <int dim>
  void
  MortarBasis<dim>::follow_reactions(const ElasticBody<dim>            &body,
                                     const ContactOperator<dim>        &contact,
                                     const std::vector<Tensor<1, dim>> &forces,
                                     const Vector                      &iterate)
  {
    if (!has_tangent || tangent_itself)
      return;
    sliding.take(body.locally_owned_dofs(), body.get_mpi_communicator(),
                 PairCouplings<dim>(contact).sliding(forces), false);
    turns.take(body.locally_owned_dofs(), body.get_mpi_communicator(),
               PairCouplings<dim>(contact).turns(nullptr), false);
    turning.take(body.locally_owned_dofs(), body.get_mpi_communicator(),
                 PairCouplings<dim>(contact).turns(&forces), false);
    tangent_operator.take_geometry(&sliding.matrix, &turning.matrix);
    sliding_origin = iterate;
  }



  template <int dim>
  void
  MortarBasis<dim>::add_geometry_change(const Vector &w,
                                        Vector       &force_w,
                                        const double  sign) const
  {
    if (sliding_origin.size() == 0)
      return;
    slide = w;
    slide -= sliding_origin;
    slide *= sign;
    sliding.matrix.Tvmult_add(force_w, slide);
  }



  template <int dim>
  void
  MortarBasis<dim>::frame_turns(const ContactOperator<dim>  &contact,
                                const Vector                &step,
                                std::vector<Tensor<1, dim>> &node_turns) const
  {
    node_turns.assign(contact.n_local(), Tensor<1, dim>());
    if (sliding_origin.size() == 0)
      return;
    if (step_in_u.size() != step.size())
      {
        step_in_u.reinit(step, true);
        turn_of_step.reinit(step, true);
      }
    basis.matrix.vmult(step_in_u, step);
    turns.matrix.vmult(turn_of_step, step_in_u);
    for (unsigned int j = 0; j < contact.n_local(); ++j)
      node_turns[j] = contact.nodal_value(j, turn_of_step);
  }



  template <int dim>
  void
  MortarBasis<dim>::force_to_w(const Vector &force, Vector &force_w) const
  {
    basis.matrix.Tvmult(force_w, force);
  }



  template <int dim>
  void
  MortarBasis<dim>::force_to_u(const Vector &force_w, Vector &force) const
  {
    // (I - E^T) f_w = 2 f_w - Q^T f_w.
    basis.matrix.Tvmult(force, force_w);
    force.sadd(-1., 2., force_w);
  }



  template <int dim>
  void
  MortarBasis<dim>::displacement_to_u(const Vector &w, Vector &u) const
  {
    basis.matrix.vmult(u, w);
  }



  template <int dim>
  void
  MortarBasis<dim>::displacement_to_w(const Vector &u, Vector &w) const
  {
    // (I - E) u = 2 u - Q u.
    basis.matrix.vmult(w, u);
    w.sadd(-1., 2., u);
  }



  template <int dim>
  std::vector<std::vector<double>>
  MortarBasis<dim>::modes_to_w(const std::vector<std::vector<double>> &modes) const
  {
    const IndexSet &owned = basis.matrix.locally_owned_domain_indices();
    std::vector<std::vector<double>> transformed;
    Vector u(owned, basis.matrix.get_mpi_communicator()), w(u);
    for (const std::vector<double> &mode : modes)
      {
        std::copy(mode.begin(), mode.end(), u.begin());
        displacement_to_w(u, w);
        transformed.emplace_back(w.begin(), w.end());
      }
    return transformed;
  }

  template class MortarBasis<2>;
  template class MortarBasis<3>;
} // namespace FrictionalContact
