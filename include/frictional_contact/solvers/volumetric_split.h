#pragma once

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <limits>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * The stiffness of a nearly incompressible (B-bar) body with its
   * volumetric part held apart: K = A + B^T C^-1 B, where A is the
   * stiffness of the same shear modulus and a moderate bulk modulus (that
   * of nu = 0.4), B maps displacements to the cell integrals of their
   * divergence (one row per cell) and C = diag(|e| / kappa_p) with kappa_p
   * the rest of the bulk modulus. K's condition number grows with
   * kappa_p / G, A's does not: the solvers then solve the mixed system
   * [A B^T; B -C] [u; p] = [f; 0] (p the cell pressures), whose u solves
   * K u = f, preconditioned by the AMG of A and an approximate Schur
   * complement diag(|e| (1/kappa_p + 1/M)), M the P-wave modulus of A
   * (doc/algorithm.md, "Nearly incompressible bodies"). Made by the model;
   * the solvers hold references.
   */
  struct VolumetricSplit
  {
    const TrilinosWrappers::SparseMatrix *reduced_stiffness = nullptr;
    const TrilinosWrappers::SparseMatrix *divergence        = nullptr;
    const TrilinosWrappers::MPI::Vector  *compliance        = nullptr;
    const TrilinosWrappers::MPI::Vector  *inverse_schur     = nullptr;
    /// The weight of each cell's row of the mixed system, |B^T e_e| / C_e:
    /// with it, the mixed residual measures what the residual of the
    /// cell's equation does to the residual of K u = f (B^T C^-1 r_p).
    const TrilinosWrappers::MPI::Vector  *row_weight        = nullptr;
    /// Gershgorin's bound of K's largest eigenvalue, max_i sum_j |K_ij|:
    /// the product K x is exact to about eps times this times |x|.
    double stiffness_bound = 0;
  };

  namespace MixedVolumetric
  {
    using Vector      = TrilinosWrappers::MPI::Vector;
    using BlockVector = TrilinosWrappers::MPI::BlockVector;

    /// A vector of the mixed system: displacements and cell pressures.
    BlockVector
    make_block_vector(const VolumetricSplit &split);

    /**
     * [F(A u + B^T p, u); W (B u - C p)]: the mixed form of an operator
     * u -> F(K u, u) that is linear in the force K u (F adds the terms of
     * the operator that do not come from K, such as a shift or contact
     * conditions, and may project), with the rows of the cells weighted by
     * W = diag(row_weight).
     */
    template <typename Finish>
    class BlockOperator
    {
    public:
      BlockOperator(const VolumetricSplit &split, const Finish &finish)
        : split(split)
        , finish(finish)
        , pressure_part(*split.compliance)
      {}

      void
      vmult(BlockVector &dst, const BlockVector &src) const
      {
        split.reduced_stiffness->vmult(dst.block(0), src.block(0));
        split.divergence->Tvmult_add(dst.block(0), src.block(1));
        finish(dst.block(0), src.block(0));
        split.divergence->vmult(dst.block(1), src.block(0));
        pressure_part = src.block(1);
        pressure_part.scale(*split.compliance);
        dst.block(1) -= pressure_part;
        dst.block(1).scale(*split.row_weight);
      }

    private:
      const VolumetricSplit &split;
      const Finish          &finish;
      mutable Vector         pressure_part;
    };

    /**
     * The block upper-triangular preconditioner [M^-1 B^T; 0 -W S]^-1 of
     * the mixed system: p = -S^-1 W^-1 r_p, u = M (r_u - B^T p), with M a
     * preconditioner of A (plus the operator's own terms) and S the
     * approximate Schur complement.
     */
    template <typename DisplacementPreconditioner>
    class BlockPreconditioner
    {
    public:
      BlockPreconditioner(const VolumetricSplit            &split,
                          const DisplacementPreconditioner &M)
        : split(split)
        , M(M)
        , force(split.reduced_stiffness->locally_owned_range_indices(),
                split.reduced_stiffness->get_mpi_communicator())
        , inverse_weight(*split.row_weight)
      {
        for (auto &w : inverse_weight)
          w = 1. / w;
      }

      void
      vmult(BlockVector &dst, const BlockVector &src) const
      {
        dst.block(1) = src.block(1);
        dst.block(1).scale(*split.inverse_schur);
        dst.block(1).scale(inverse_weight);
        dst.block(1) *= -1.;
        split.divergence->Tvmult(force, dst.block(1));
        force.sadd(-1., 1., src.block(0));
        M.vmult(dst.block(0), force);
      }

    private:
      const VolumetricSplit            &split;
      const DisplacementPreconditioner &M;
      mutable Vector                    force;
      Vector                            inverse_weight;
    };

    /// p = C^-1 B u: the cell pressures that go with @p u in K u.
    void
    consistent_pressure(const VolumetricSplit &split,
                        const Vector          &u,
                        Vector                &p);

    /**
     * Solves F(K x, x) = b through its mixed form with GMRES, preconditioned
     * by BlockPreconditioner with @p M, starting from @p x (and the
     * pressures that go with it), until the weighted mixed residual is
     * below @p tolerance. The weights make that residual stand for the
     * residual of K x = b, but not exactly: if @p true_residual(x) =
     * |F(K x, x) - b| is still above @p tolerance, GMRES goes on with a
     * tighter goal for as long as the true residual keeps falling. It
     * stops falling at the round-off of K's product, below eps |K| |x|
     * (|K| Gershgorin's bound), which for a nearly incompressible body can
     * be above a tight tolerance: the mixed residual, free of that
     * round-off, then decides. Returns the Krylov iterations; throws
     * SolverControl::NoConvergence past @p max_iterations, or if the true
     * residual stays above both the tolerance and that round-off. A
     * @p flexible solve (FGMRES, twice the vectors) is for an @p M that is
     * not a fixed linear map, such as the geometric multigrid's V-cycle
     * (single precision, an inexact coarse solve): GMRES, which applies M
     * once more to the combination of its basis, took 79 iterations with
     * it instead of 20 on Lame's sphere at nu = 0.4.
     */
    template <typename Finish, typename Preconditioner, typename TrueResidual>
    unsigned int
    solve(const VolumetricSplit &split,
          const Finish          &finish,
          const Preconditioner  &M,
          const bool             flexible,
          const TrueResidual    &true_residual,
          const unsigned int     max_iterations,
          const double           tolerance,
          Vector                &x,
          const Vector          &b)
    {
      BlockVector X = make_block_vector(split);
      BlockVector R = make_block_vector(split);
      X.block(0)    = x;
      consistent_pressure(split, x, X.block(1));
      R.block(0) = b;
      const BlockOperator<Finish>               op(split, finish);
      const BlockPreconditioner<Preconditioner> P(split, M);
      unsigned int                              iterations = 0;
      double                                    goal       = tolerance;
      double residual = std::numeric_limits<double>::max();
      for (unsigned int round = 0; round < 4; ++round)
        {
          SolverControl control(max_iterations - iterations, goal, false, false);
          if (flexible)
            SolverFGMRES<BlockVector>(
              control, typename SolverFGMRES<BlockVector>::AdditionalData(100))
              .solve(op, X, R, P);
          else
            SolverGMRES<BlockVector>(
              control, typename SolverGMRES<BlockVector>::AdditionalData(100, true))
              .solve(op, X, R, P);
          iterations += control.last_step();
          const double previous = residual;
          residual              = true_residual(X.block(0));
          if (residual <= tolerance || residual > 0.5 * previous)
            break;
          goal = std::min(goal, control.last_value()) *
                 std::min(0.5, 0.5 * tolerance / residual);
        }
      const double roundoff = std::numeric_limits<double>::epsilon() *
                              split.stiffness_bound * X.block(0).l2_norm();
      if (residual > std::max(tolerance, roundoff))
        throw SolverControl::NoConvergence(iterations, residual);
      x = X.block(0);
      return iterations;
    }
  } // namespace MixedVolumetric
} // namespace FrictionalContact
