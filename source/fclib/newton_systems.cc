#include <deal.II/lac/lapack_full_matrix.h>

#include <frictional_contact/fclib/newton_systems.h>

#include <algorithm>
#include <cmath>

namespace FrictionalContact
{
  namespace
  {
    /// The proximal term in the reaction block of the Jacobian: where the
    /// contacts resist fewer motions than they have components (a box
    /// resting on four corners), the reactions are not unique and the plain
    /// Jacobian is singular.
    constexpr double proximal_term = 1e-10;

    /// The condensed form is used when eliminating v costs at most as much
    /// as factorising M this many times (about a coupled Newton step each).
    constexpr double elimination_cost_in_steps = 4;
  } // namespace



  LocalLinearization
  alart_curnier(const unsigned int d,
                const double       mu,
                const double       rho,
                const double      *u,
                const double      *r)
  {
    LocalLinearization local;
    const double       z_n = r[0] - rho * u[0];
    if (z_n > 0) // in contact: u_n = 0
      {
        local.phi[0]  = rho * u[0];
        local.A[0][0] = rho;
      }
    else // open: r_n = 0
      {
        local.phi[0]  = r[0];
        local.B[0][0] = 1;
      }

    const double radius = mu * std::max(z_n, 0.);
    double       z_t[3] = {0, 0, 0}, norm_z_t = 0;
    for (unsigned int k = 1; k < d; ++k)
      {
        z_t[k] = r[k] - rho * u[k];
        norm_z_t += z_t[k] * z_t[k];
      }
    norm_z_t = std::sqrt(norm_z_t);

    if (norm_z_t <= radius) // stick: u_t = 0
      for (unsigned int k = 1; k < d; ++k)
        {
          local.phi[k]  = rho * u[k];
          local.A[k][k] = rho;
        }
    else if (radius == 0) // open: r_t = 0
      for (unsigned int k = 1; k < d; ++k)
        {
          local.phi[k]  = r[k];
          local.B[k][k] = 1;
        }
    else // slip: r_t = radius z_t / |z_t|
      {
        const double scale = radius / norm_z_t;
        for (unsigned int k = 1; k < d; ++k)
          {
            const double e_k = z_t[k] / norm_z_t;
            local.phi[k]     = r[k] - radius * e_k;
            for (unsigned int l = 1; l < d; ++l)
              {
                // scale (I - e e^T) is the derivative of the projection.
                const double P_kl =
                  scale * ((k == l ? 1. : 0.) - e_k * z_t[l] / norm_z_t);
                local.B[k][l] = (k == l ? 1. : 0.) - P_kl;
                local.A[k][l] = rho * P_kl;
              }
            // The radius follows the normal reaction.
            local.B[k][0] = -mu * e_k;
            local.A[k][0] = mu * rho * e_k;
          }
      }
    return local;
  }









  NewtonSystem::NewtonSystem(const FclibProblem &problem)
    : problem(problem)
    , d(problem.spacedim)
    , n(problem.n)
    , m(problem.spacedim * problem.n_contacts())
    , rho(problem.n_contacts(), 0.)
  {
    std::vector<double> diagonal(n, 0.);
    for (const auto &e : problem.M)
      if (e.row == e.column)
        diagonal[e.row] += e.value;
    for (const auto &e : problem.H)
      if (std::abs(diagonal[e.row]) > 0)
        rho[e.column / d] += e.value * e.value / std::abs(diagonal[e.row]);
    for (double &rho_c : rho)
      rho_c = rho_c > 0 ? d / rho_c : 1.;
  }



  void
  NewtonSystem::contact_functions(const std::vector<double>        &u,
                                  const double                     *r,
                                  double                           *phi,
                                  std::vector<LocalLinearization> &local) const
  {
    local.resize(problem.n_contacts());
    for (unsigned int c = 0; c < problem.n_contacts(); ++c)
      {
        local[c] =
          alart_curnier(d, problem.mu[c], rho[c], &u[d * c], r + d * c);
        for (unsigned int a = 0; a < d; ++a)
          phi[d * c + a] = local[c].phi[a];
      }
  }



  CoupledSystem::CoupledSystem(const FclibProblem &problem)
    : NewtonSystem(problem)
    , entries_of_contact(problem.n_contacts())
  {
    for (unsigned int i = 0; i < problem.H.size(); ++i)
      entries_of_contact[problem.H[i].column / d].push_back(i);

    DynamicSparsityPattern dsp(n + m, n + m);
    for (const auto &e : problem.M)
      dsp.add(e.row, e.column);
    for (unsigned int c = 0; c < problem.n_contacts(); ++c)
      for (unsigned int a = 0; a < d; ++a)
        {
          const unsigned int row = n + d * c + a;
          for (unsigned int b = 0; b < d; ++b)
            dsp.add(row, n + d * c + b);
          for (const unsigned int i : entries_of_contact[c])
            {
              dsp.add(problem.H[i].row, n + problem.H[i].column);
              dsp.add(row, problem.H[i].row);
            }
        }
    jacobian = std::make_unique<SparseLU>(dsp);

    for (const auto &e : problem.M)
      position_of_M.push_back(jacobian->position(e.row, e.column));
    for (const auto &e : problem.H)
      {
        position_of_H.push_back(jacobian->position(e.row, n + e.column));
        // The first of the d rows of the contact; the others follow at
        // the same offset in their rows (same pattern).
        position_of_H_transpose.push_back(
          jacobian->position(n + d * (e.column / d), e.row));
      }
    for (unsigned int c = 0; c < problem.n_contacts(); ++c)
      position_of_block.push_back(jacobian->position(n + d * c, n + d * c));
  }






  double
  CoupledSystem::residual(const Vector<double>             &x,
                         Vector<double>                   &F,
                         std::vector<LocalLinearization> &local) const
  {
    // M v - H r - f, and u = H^T v + w.
    for (unsigned int i = 0; i < n; ++i)
      F[i] = -problem.f[i];
    for (const auto &e : problem.M)
      F[e.row] += e.value * x[e.column];
    std::vector<double> u = problem.w;
    for (const auto &e : problem.H)
      {
        F[e.row] -= e.value * x[n + e.column];
        u[e.column] += e.value * x[e.row];
      }
    contact_functions(u, x.begin() + n, F.begin() + n, local);
    return F.norm_sqr();
  }



  bool
  CoupledSystem::newton_step(const std::vector<LocalLinearization> &local,
                            const Vector<double>                  &F,
                            Vector<double>                        &dx)
  {
    // The d rows of a contact have the same pattern, so entry (row + a,
    // column) sits at the position of (row, column) plus a times the
    // length of the row.
    std::vector<double> &J = jacobian->entries();
    std::fill(J.begin(), J.end(), 0.);
    for (unsigned int i = 0; i < problem.M.size(); ++i)
      J[position_of_M[i]] += problem.M[i].value;
    for (unsigned int i = 0; i < problem.H.size(); ++i)
      J[position_of_H[i]] -= problem.H[i].value;
    for (unsigned int c = 0; c < problem.n_contacts(); ++c)
      {
        const LocalLinearization &l      = local[c];
        const std::size_t         length = jacobian->row_length(n + d * c);
        for (unsigned int a = 0; a < d; ++a)
          for (unsigned int b = 0; b < d; ++b)
            J[position_of_block[c] + a * length + b] =
              l.B[a][b] + (a == b ? proximal_term : 0.);
        // dphi/dv = A H_c^T.
        for (const unsigned int i : entries_of_contact[c])
          {
            const unsigned int b = problem.H[i].column % d;
            for (unsigned int a = 0; a < d; ++a)
              J[position_of_H_transpose[i] + a * length] +=
                l.A[a][b] * problem.H[i].value;
          }
      }
    if (!jacobian->factorize())
      return false;
    Vector<double> minus_F(F);
    minus_F *= -1.;
    jacobian->solve(dx, minus_F);
    return true;
  }



  FclibSolution
  CoupledSystem::solution(const Vector<double> &x) const
  {
    FclibSolution s;
    s.v.assign(x.begin(), x.begin() + n);
    s.r.assign(x.begin() + n, x.end());
    s.u = local_velocity(problem, s.v);
    return s;
  }



  std::unique_ptr<CondensedSystem>
  CondensedSystem::create(const FclibProblem &problem)
  {
    std::unique_ptr<CondensedSystem> system(new CondensedSystem(problem));
    // The Cholesky factor where M has one; if eliminating with it does not
    // pay, neither would it with the LU factors.
    if (asymmetry(problem.M) <= largest_symmetric_asymmetry)
      {
        system->cholesky = std::make_unique<SymmetricFactor>();
        if (!system->cholesky->factorize(system->n, problem.M))
          system->cholesky.reset();
      }
    if (system->cholesky ? !system->eliminate_by_cholesky() : !system->eliminate_by_lu())
      return nullptr;
    for (const double w_ij : system->W)
      if (!std::isfinite(w_ij))
        return nullptr;

    // q = H^T M^{-1} f + w.
    system->q = problem.w;
    for (const auto &e : problem.H)
      system->q[e.column] += e.value * system->free_velocity[e.row];

    // rho_c from the exact diagonal block W_cc.
    const unsigned int d = problem.spacedim;
    for (unsigned int c = 0; c < problem.n_contacts(); ++c)
      {
        double trace = 0;
        for (unsigned int a = 0; a < d; ++a)
          trace += system->W(d * c + a, d * c + a);
        if (trace > 0)
          system->rho[c] = d / trace;
      }
    return system;
  }



  bool
  CondensedSystem::worth_eliminating(const double solve_flops,
                                     const double factorization_flops) const
  {
    // The elimination costs m solves with the factors of M; a coupled step
    // costs about one factorisation.
    return m * solve_flops <= elimination_cost_in_steps * factorization_flops;
  }



  bool
  CondensedSystem::eliminate_by_cholesky()
  {
    if (!worth_eliminating(cholesky->solve_flops, cholesky->factorization_flops))
      return false;
    free_velocity.resize(n);
    cholesky->solve(free_velocity.data(), problem.f.data());
    std::vector<double> H_columns(static_cast<std::size_t>(n) * m, 0.);
    for (const auto &e : problem.H)
      H_columns[static_cast<std::size_t>(e.column) * n + e.row] += e.value;
    W = cholesky->congruence(H_columns, m);
    return true;
  }



  bool
  CondensedSystem::eliminate_by_lu()
  {
    DynamicSparsityPattern pattern(n, n);
    for (const auto &e : problem.M)
      pattern.add(e.row, e.column);
    SparseLU M_lu(pattern);
    for (const auto &e : problem.M)
      M_lu.entries()[M_lu.position(e.row, e.column)] += e.value;
    if (!M_lu.factorize() ||
        !worth_eliminating(M_lu.solve_flops, M_lu.factorization_flops))
      return false;
    free_velocity.resize(n);
    M_lu.solve(free_velocity.data(), problem.f.data());

    // M^{-1} H, column by column.
    std::vector<std::vector<unsigned int>> entries_of_column(m);
    for (unsigned int i = 0; i < problem.H.size(); ++i)
      entries_of_column[problem.H[i].column].push_back(i);
    M_inverse_H.reinit(n, m);
    std::vector<double> column(n, 0.), solution(n);
    for (unsigned int k = 0; k < m; ++k)
      {
        for (const unsigned int i : entries_of_column[k])
          column[problem.H[i].row] += problem.H[i].value;
        M_lu.solve(solution.data(), column.data());
        for (unsigned int i = 0; i < n; ++i)
          M_inverse_H(i, k) = solution[i];
        for (const unsigned int i : entries_of_column[k])
          column[problem.H[i].row] = 0;
      }

    // W = H^T M^{-1} H.
    W.reinit(m, m);
    for (const auto &e : problem.H)
      for (unsigned int j = 0; j < m; ++j)
        W(e.column, j) += e.value * M_inverse_H(e.row, j);
    return true;
  }



  CondensedSystem::CondensedSystem(const FclibProblem &problem)
    : NewtonSystem(problem)
  {}



  double
  CondensedSystem::residual(const Vector<double>             &r,
                            Vector<double>                   &F,
                            std::vector<LocalLinearization> &local) const
  {
    std::vector<double> u = q;
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < m; ++j)
        u[i] += W(i, j) * r[j];
    contact_functions(u, r.begin(), F.begin(), local);
    return F.norm_sqr();
  }



  bool
  CondensedSystem::newton_step(const std::vector<LocalLinearization> &local,
                               const Vector<double>                  &F,
                               Vector<double>                        &dr)
  {
    // J = A W + B + proximal term, row block by row block.
    LAPACKFullMatrix<double> J(m, m);
    for (unsigned int c = 0; c < problem.n_contacts(); ++c)
      for (unsigned int a = 0; a < d; ++a)
        {
          const unsigned int row = d * c + a;
          for (unsigned int b = 0; b < d; ++b)
            {
              const double A_ab = local[c].A[a][b];
              if (A_ab != 0)
                for (unsigned int j = 0; j < m; ++j)
                  J(row, j) += A_ab * W(d * c + b, j);
              J(row, d * c + b) += local[c].B[a][b] + (a == b ? proximal_term : 0.);
            }
        }
    try
      {
        J.compute_lu_factorization();
      }
    catch (const std::exception &)
      {
        return false;
      }
    dr = F;
    dr *= -1.;
    J.solve(dr);
    return true;
  }



  FclibSolution
  CondensedSystem::solution(const Vector<double> &r) const
  {
    FclibSolution s;
    s.v = free_velocity;
    if (cholesky)
      {
        // v = M^{-1} (f + H r): one more solve.
        std::vector<double> H_r(n, 0.), M_inverse_H_r(n);
        for (const auto &e : problem.H)
          H_r[e.row] += e.value * r[e.column];
        cholesky->solve(M_inverse_H_r.data(), H_r.data());
        for (unsigned int i = 0; i < n; ++i)
          s.v[i] += M_inverse_H_r[i];
      }
    else
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int k = 0; k < m; ++k)
          s.v[i] += M_inverse_H(i, k) * r[k];
    s.r.assign(r.begin(), r.end());
    s.u = local_velocity(problem, s.v);
    return s;
  }
} // namespace FrictionalContact
