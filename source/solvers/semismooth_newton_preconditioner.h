#pragma once

#include "semismooth_newton_linearization.h"
#include <frictional_contact/solvers/shifted_stiffness_solver.h>

#include <vector>

namespace FrictionalContact
{
  namespace SemismoothNewton
  {
    /**
     * The preconditioner M of the Newton systems (the Krylov solver applies
     * P M P). With node conditions: the AMG of K plus springs that stand
     * for the conditions (SpringAMG; or the geometric multigrid with the
     * springs on its levels), stiff (spring_factor c_j) in each
     * direction a condition holds, and the Robin term kappa Q across the
     * slip direction of a slipping node; it is made again only when a
     * node's spring changes by more than a tenth. Without (or where the
     * preconditioner of K is not ML's, or the contact map has no nodal
     * blocks): the preconditioner of K itself, which does not see the
     * conditions, so that its Krylov iterations grow with the size of the
     * contact zone and with the slip set (doc/algorithm.md). The
     * stabilisation S of bodies that only contact holds joins the springs
     * (1 x 1 blocks), so that the coarse levels are not singular. Owns the
     * springs the AMG was made for.
     */
    template <int dim>
    class ConditionPreconditioner
    {
    public:
      /// Spring stiffness in a held direction, in units of c_j.
      static constexpr double spring_factor = 10;

      /// With @p with_conditions, the AMG with springs where it can be
      /// made (on all ranks of @p comm). Collective.
      ConditionPreconditioner(ShiftedStiffnessSolver &linear_solver,
                              const ContactMap<dim>  &contact,
                              const bool              with_conditions,
                              const Vector           &stabilization,
                              const MPI_Comm          comm)
        : linear_solver(linear_solver)
        , contact(contact)
        , amg(nullptr)
        , built(contact.n_local())
      {
        if (stabilization.size() > 0)
          {
            const IndexSet owned = stabilization.locally_owned_elements();
            const double  *S     = stabilization.begin();
            for (unsigned int i = 0; i < owned.n_elements(); ++i)
              if (S[i] > 0)
                stabilizing_blocks.push_back({{owned.nth_index_in_set(i)}, {S[i]}});
            // The first update() makes the AMG with them.
            unbuilt = true;
          }
        if (!with_conditions)
          return;
        SpringPreconditioner &candidate = linear_solver.spring_preconditioner();
        NodalBlock probe;
        const bool usable =
          candidate.initialized() &&
          (contact.n_local() == 0 ||
           contact.nodal_block(0, Tensor<2, dim>(), probe));
        if (!Utilities::MPI::logical_or(!usable, comm))
          amg = &candidate;
      }

      /**
       * Makes the AMG for the conditions in @p sets (with the normal
       * stiffnesses @p c; @p coupled: whether the Newton system has the
       * Robin term) if a node's spring differs by more than a tenth from
       * the one it was made for. Returns whether it did. Collective.
       */
      bool
      update(const ActiveSets<dim>     &sets,
             const std::vector<double> &c,
             const bool                 coupled,
             const MPI_Comm             comm)
      {
        if (amg == nullptr)
          return false;
        std::vector<Tensor<2, dim>> springs(c.size());
        bool                        changed = false;
        for (unsigned int j = 0; j < c.size(); ++j)
          {
            springs[j] = spring(sets, j, c[j], coupled);
            changed =
              changed || (springs[j] - built[j]).norm() > 0.1 * built[j].norm() +
                                                             1e-12 * c[j];
          }
        if (!Utilities::MPI::logical_or(changed || unbuilt, comm))
          return false;
        unbuilt = false;
        std::vector<NodalBlock> blocks = stabilizing_blocks;
        for (unsigned int j = 0; j < c.size(); ++j)
          if (springs[j].norm() > 0)
            {
              blocks.emplace_back();
              contact.nodal_block(j, springs[j], blocks.back());
            }
        amg->set_springs(blocks);
        built = springs;
        return true;
      }

      /// dst = M^-1 src.
      void
      vmult(Vector &dst, const Vector &src) const
      {
        if (amg != nullptr)
          amg->vmult(dst, src);
        else
          linear_solver.precondition_stiffness(dst, src);
      }

    private:
      /// The spring of node j, in its local coordinates.
      static Tensor<2, dim>
      spring(const ActiveSets<dim> &sets,
             const unsigned int     j,
             const double           c_j,
             const bool             coupled)
      {
        Tensor<2, dim> s;
        if (sets.conditions[j] == NodeCondition::none)
          return s;
        for (unsigned int a = 0; a < dim; ++a)
          if (a == 0 || sets.conditions[j] == NodeCondition::all_fixed)
            s[a][a] = spring_factor * c_j;
        if (sets.conditions[j] == NodeCondition::normal_fixed && coupled &&
            dim == 3 && sets.robin[j] > 0)
          for (unsigned int a = 1; a < dim; ++a)
            for (unsigned int b = 1; b < dim; ++b)
              s[a][b] += sets.robin[j] *
                         ((a == b ? 1. : 0.) - sets.slip_direction[j][a] *
                                                 sets.slip_direction[j][b]);
        return s;
      }

      ShiftedStiffnessSolver     &linear_solver;
      const ContactMap<dim>      &contact;
      SpringPreconditioner       *amg;
      std::vector<Tensor<2, dim>> built;
      /// S of ContactHeldBodies, one block per dof, and whether the AMG
      /// has not yet been made with it.
      std::vector<NodalBlock> stabilizing_blocks;
      bool                    unbuilt = false;
    };
  } // namespace SemismoothNewton
} // namespace FrictionalContact
