#pragma once

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <frictional_contact/fclib/fclib_problem.h>
#include <frictional_contact/fclib/sparse_lu.h>
#include <frictional_contact/fclib/symmetric_factor.h>

#include <memory>
#include <vector>

namespace FrictionalContact
{
  /**
   * Alart and Curnier's function phi of one contact at (u, r), in FCLIB's
   * convention, and its generalized derivatives A = dphi/du, B = dphi/dr
   * (doc/fclib.md).
   */
  struct LocalLinearization
  {
    double phi[3]  = {0, 0, 0};
    double A[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    double B[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  };

  LocalLinearization
  alart_curnier(const unsigned int d,
                const double       mu,
                const double       rho,
                const double      *u,
                const double      *r);



  /**
   * The equations F(x) = 0 of the semismooth Newton method for an FCLIB
   * problem and their generalized Jacobian, in one of two forms
   * (CoupledSystem, CondensedSystem). Owns rho_c, the parameter of each
   * contact's Alart-Curnier function: the inverse of its diagonal
   * Delassus entry, so that the method does not depend on the units.
   */
  class NewtonSystem
  {
  public:
    virtual ~NewtonSystem() = default;

    /// The number of unknowns.
    virtual unsigned int
    size() const = 0;

    /// F(x), with the linearizations of the contacts; returns |F|^2.
    virtual double
    residual(const Vector<double>             &x,
             Vector<double>                   &F,
             std::vector<LocalLinearization> &local) const = 0;

    /// Solves J dx = -F with the Jacobian of @p local; false if J is
    /// singular.
    virtual bool
    newton_step(const std::vector<LocalLinearization> &local,
                const Vector<double>                  &F,
                Vector<double>                        &dx) = 0;

    /// (v, u, r) at x.
    virtual FclibSolution
    solution(const Vector<double> &x) const = 0;

  protected:
    /// rho_c from the diagonal of M: (H_c^T diag(M)^{-1} H_c) / d.
    explicit NewtonSystem(const FclibProblem &problem);

    /// The contacts' functions at (u, r), into @p phi (size m).
    void
    contact_functions(const std::vector<double>        &u,
                      const double                     *r,
                      double                           *phi,
                      std::vector<LocalLinearization> &local) const;

    const FclibProblem &problem;
    const unsigned int  d, n, m;
    std::vector<double> rho;
  };



  /**
   * x = (v, r): the force balance M v - H r - f and the contacts' functions,
   * with the whole sparse Jacobian factorised by UMFPACK at every step
   * (pattern analysed once). For many contacts (large m). Owns the
   * Jacobian and where each entry of M and H goes in it.
   */
  class CoupledSystem : public NewtonSystem
  {
  public:
    explicit CoupledSystem(const FclibProblem &problem);

    unsigned int
    size() const override
    {
      return n + m;
    }

    double
    residual(const Vector<double>             &x,
             Vector<double>                   &F,
             std::vector<LocalLinearization> &local) const override;

    bool
    newton_step(const std::vector<LocalLinearization> &local,
                const Vector<double>                  &F,
                Vector<double>                        &dx) override;

    FclibSolution
    solution(const Vector<double> &x) const override;

  private:
    /// The entries of H by contact (indices into problem.H).
    std::vector<std::vector<unsigned int>> entries_of_contact;
    std::unique_ptr<SparseLU>              jacobian;
    /// Positions in the Jacobian's values: M_ij at (i, j), -H_ik at
    /// (i, n + k), H_ik in the first row of k's contact at (n + d c, i),
    /// and each contact's d x d block at (n + d c, n + d c).
    std::vector<std::size_t> position_of_M, position_of_H,
      position_of_H_transpose, position_of_block;
  };



  /**
   * x = r: v = M^{-1} (H r + f) eliminated with one LU of M, so that
   * u = W r + q with the Delassus matrix W = H^T M^{-1} H (dense, m x m)
   * and q = H^T M^{-1} f + w; each step factorises A W + B with LAPACK.
   * rho_c comes from the exact diagonal blocks of W. For few contacts
   * (small m): M is factorised once instead of at every step. Owns
   * M^{-1} H, W, q and the free velocity M^{-1} f.
   */
  class CondensedSystem : public NewtonSystem
  {
  public:
    /// nullptr if M is singular or the elimination would cost more than
    /// four factorisations of M (the Cholesky factorisation where M is
    /// symmetric positive definite, else the LU factorisation).
    static std::unique_ptr<CondensedSystem>
    create(const FclibProblem &problem);

    unsigned int
    size() const override
    {
      return m;
    }

    double
    residual(const Vector<double>             &r,
             Vector<double>                   &F,
             std::vector<LocalLinearization> &local) const override;

    bool
    newton_step(const std::vector<LocalLinearization> &local,
                const Vector<double>                  &F,
                Vector<double>                        &dr) override;

    FclibSolution
    solution(const Vector<double> &r) const override;

  private:
    explicit CondensedSystem(const FclibProblem &problem);

    /// With M's Cholesky factor (made by create()): W from all columns of
    /// H at once; false if that does not pay.
    bool
    eliminate_by_cholesky();

    /// With M's LU factors: M^{-1} H column by column, then W; false if M
    /// is singular or that does not pay.
    bool
    eliminate_by_lu();

    /// Whether eliminating v costs at most elimination_cost_in_steps
    /// factorisations of M.
    bool
    worth_eliminating(const double solve_flops, const double factorization_flops) const;

    /// M's Cholesky factor (for the velocities of solution()), or else
    /// M^{-1} H (n x m); W and q.
    std::unique_ptr<SymmetricFactor> cholesky;
    FullMatrix<double>               M_inverse_H, W;
    std::vector<double>              q, free_velocity;
  };
} // namespace FrictionalContact
