#pragma once

#include "semismooth_newton_linearization.h"

#include <array>
#include <functional>
#include <limits>
#include <vector>

namespace FrictionalContact
{
  namespace SemismoothNewton
  {
    /**
     * The merit of the line search at the point t of the segment from the
     * previous iterate (du_0, r_0) to the new one (du_1, r_1): the squared
     * complementarity functions of all nodes, each over its c_j, plus the
     * squared force balance residual, each dof's over K's diagonal there
     * (@p balance_weight, 1 / K_ii): both energies, which weigh a stiff
     * body's force residuals as they weigh a soft one's (with one scale
     * for all, the mean c, a slave a million times stiffer than its master
     * had its residuals, large forces of tiny displacement errors, decide
     * every line search; doc/algorithm.md, "Bodies of very different
     * stiffness"). For a linear
     * law the residual and the reactions are linear along the segment. For
     * a nonlinear one, @p nonlinear_residual gives the residual at t,
     * N(du) - p - T ((1 - t) r_0 + t r_1) (nullptr where a cell inverts),
     * and the reactions of the nodes in contact (@p conditions) take, as r_1
     * did at t = 1, its part that the straight line misses, N(du) - (1 - t)
     * N(du_0) - t N(du_1): with the reactions interpolated alone, a long
     * Newton step's curvature entered every short step's merit to first
     * order, and the merit rose along steps that descend. Where the frames
     * turn along the step, the reactions' components in the turned frames
     * are what the contact conditions judge, and the part of the turning
     * force that a node's frame cannot carry (facing an obstacle without
     * friction, its frame is a normal alone) turns the force itself, as
     * taking the geometry again at the point will
     * (ContactMap::add_force_beyond_frames()): left out, the force balance
     * of a frictionless node sliding over a curved obstacle was judged
     * without its normal's turn, which the Newton step has, and the merit
     * along a full step came back to where it started, so that each step
     * was halved and the iterates converged linearly. Collective.
     */
    template <int dim>
    class MeritAlongStep
    {
    public:
      MeritAlongStep(const IncrementalProblem<dim>     &problem,
                     const std::vector<NodeCondition>  &conditions,
                     const std::vector<double>         &c,
                     const std::vector<double>         &c_t,
                     const bool                         friction,
                     const double                       mean_c,
                     const Vector                      &balance_weight,
                     const Vector                      &du_0,
                     const Vector                      &du_1,
                     const std::vector<Tensor<1, dim>> &r_0,
                     const std::vector<Tensor<1, dim>> &r_1,
                     const Vector                      &balance_0,
                     const Vector                      &balance_1,
                     Vector                            &scratch,
                     std::function<const Vector *(double)> nonlinear_residual = {})
        : problem(problem)
        , conditions(conditions)
        , c(c)
        , c_t(c_t)
        , friction(friction)
        , mean_c(mean_c)
        , balance_weight(balance_weight)
        , weighted(balance_weight)
        , du_0(du_0)
        , du_1(du_1)
        , r_0(r_0)
        , r_1(r_1)
        , balance_0(balance_0)
        , balance_1(balance_1)
        , scratch(scratch)
        , nonlinear_residual(std::move(nonlinear_residual))
        , frames_turn(problem.contact.frames_follow_configuration() ||
                      (problem.geometry && problem.geometry->turns_pair_frames()))
      {
        // The nodes in contact's parts of both ends' residuals, for the
        // reactions the straight line misses (nonlinear laws).
        if (this->nonlinear_residual)
          {
            balance_at_nodes.resize(c.size());
            for (unsigned int j = 0; j < c.size(); ++j)
              if (conditions[j] != NodeCondition::none)
                balance_at_nodes[j] = {{problem.contact.local_part(j, balance_0),
                                        problem.contact.local_part(j, balance_1)}};
          }
        // Frames that follow the configuration turn along the step as the
        // Newton tangent has them turn (to first order).
        if (frames_turn)
          {
            scratch = du_1;
            scratch -= du_0;
            if (problem.geometry && problem.geometry->turns_pair_frames())
              problem.geometry->pair_frame_turns(scratch, step_turns);
            else
              problem.contact.normal_turns(scratch, step_turns);
          }
        balance_a = weighted_product(balance_0, balance_0);
        balance_b = weighted_product(balance_0, balance_1) - balance_a;
        scratch   = balance_1;
        scratch -= balance_0;
        balance_c = weighted_product(scratch, scratch);
      }

      double
      operator()(const double t) const
      {
        const bool    inside   = nonlinear_residual && t > 0 && t < 1;
        const Vector *residual = inside ? nonlinear_residual(t) : nullptr;
        if (inside && residual == nullptr)
          return std::numeric_limits<double>::infinity();
        if (inside)
          scratch = *residual;
        // The reactions before the frames turn, for their force beyond
        // the frames.
        std::vector<Tensor<1, dim>> held_reactions(frames_turn ? c.size() : 0);
        double sum = 0;
        for (unsigned int j = 0; j < c.size(); ++j)
          {
            Tensor<1, dim> missed;
            if (inside && conditions[j] != NodeCondition::none)
              {
                const ContactMap<dim> &contact = problem.contact;
                missed = contact.local_part(j, *residual) -
                         (1 - t) * balance_at_nodes[j][0] -
                         t * balance_at_nodes[j][1];
                contact.add_reaction(j, -missed, scratch);
              }
            const NodeAtStep at = node_at(j, t, missed);
            if (!held_reactions.empty())
              held_reactions[j] = at.held_r;
            const double phi_n = at.r[0] - std::min(0., at.augmented_normal);
            Tensor<1, dim> z     = at.z;
            if (z.norm() > at.bound)
              z *= at.bound / z.norm();
            Tensor<1, dim> phi_t = at.r - z;
            phi_t[0]             = 0;
            // A node whose normal direction a support holds has c_j = 0
            // (no free normal component): the mean scale serves it.
            sum += (phi_n * phi_n + phi_t * phi_t) / (c[j] > 0 ? c[j] : mean_c);
          }
        // The same on every rank (a rank without candidates has no turns).
        const bool turns = frames_turn && t > 0;
        if (turns && !inside)
          {
            scratch = balance_0;
            scratch.sadd(1 - t, t, balance_1);
          }
        if (turns)
          problem.contact.add_force_beyond_frames(held_reactions, step_turns, t, scratch);
        const double balance =
          inside || turns ? weighted_product(scratch, scratch) :
                            balance_a + 2 * t * balance_b + t * t * balance_c;
        return Utilities::MPI::sum(sum, du_0.get_mpi_communicator()) + balance;
      }

    private:
      /// sum_i x_i y_i / K_ii (collective).
      double
      weighted_product(const Vector &x, const Vector &y) const
      {
        weighted = x;
        weighted.scale(balance_weight);
        return weighted * y;
      }

      /// A node's reaction, augmented normal reaction r_n + c_j g, friction
      /// bound and augmented tangential reaction z at a point of the step.
      struct NodeAtStep
      {
        /// The reaction in the frame at the start of the step, and in
        /// the frame turned to the point.
        Tensor<1, dim> held_r;
        Tensor<1, dim> r;
        double         augmented_normal;
        double         bound;
        Tensor<1, dim> z;
      };

      /// Node @p j at the point @p t, its reaction corrected by @p missed.
      NodeAtStep
      node_at(const unsigned int j, const double t, const Tensor<1, dim> &missed) const
      {
        const Tensor<1, dim> u_j =
          (1 - t) * problem.relative_displacement(j, du_0) +
          t * problem.relative_displacement(j, du_1);
        NodeAtStep at;
        at.held_r = (1 - t) * r_0[j] + t * r_1[j] + missed;
        at.r      = at.held_r;
        if (!step_turns.empty())
          at.r += problem.contact.frame_turn(j, at.r, t * step_turns[j]);
        at.augmented_normal =
          at.r[0] + c[j] * problem.gap_at(j, u_j);
        const double mu_j = friction ? problem.contact.friction_coefficient(j) : 0.;
        at.bound          = mu_j * std::max(0., -at.augmented_normal);
        at.z              = at.r - c_t[j] * u_j;
        at.z[0]           = 0;
        return at;
      }

      const IncrementalProblem<dim>     &problem;
      const std::vector<NodeCondition>  &conditions;
      const std::vector<double>         &c;
      const std::vector<double>         &c_t;
      const bool                         friction;
      const double                       mean_c;
      const Vector                      &balance_weight;
      mutable Vector                     weighted;
      const Vector                      &du_0;
      const Vector                      &du_1;
      const std::vector<Tensor<1, dim>> &r_0;
      const std::vector<Tensor<1, dim>> &r_1;
      const Vector                      &balance_0;
      const Vector                      &balance_1;
      Vector                            &scratch;
      /// At each node in contact, its parts of the residuals at t = 0 and 1
      /// (nonlinear laws only).
      std::vector<std::array<Tensor<1, dim>, 2>> balance_at_nodes;
      double                             balance_a, balance_b, balance_c;
      const std::function<const Vector *(double)> nonlinear_residual;
      /// Whether the frames follow the configuration (on every rank).
      const bool frames_turn;
      /// The turn of each frame per unit step (empty for fixed frames).
      std::vector<Tensor<1, dim>>         step_turns;
    };
  } // namespace SemismoothNewton
} // namespace FrictionalContact
