#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <array>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * A symmetric positive definite 3 x 3 tensor X = sum_a x_a v_a (x) v_a by
   * its eigenvalues x_a and orthonormal eigenvectors v_a (deal.II's QL
   * method with implicit shifts), for the isotropic tensor functions of
   * finite-strain plasticity: f(X) = sum_a f(x_a) v_a (x) v_a, and the
   * components of a tensor in the eigenbasis and back. Repeated eigenvalues need no care: any orthonormal
   * basis of their eigenspace serves f(X) and the derivative of f (the
   * Daleckii-Krein formula in this basis).
   */
  class SpectralDecomposition
  {
  public:
    explicit SpectralDecomposition(const SymmetricTensor<2, 3> &X);

    /// sum_a f(x_a) v_a (x) v_a.
    template <typename Function>
    SymmetricTensor<2, 3>
    map(const Function &f) const
    {
      std::array<double, 3> mapped;
      for (unsigned int a = 0; a < 3; ++a)
        mapped[a] = f(values[a]);
      return from_eigenbasis_diagonal(mapped);
    }

    /// Q^T T Q: the components of @p T in the eigenbasis (Q's columns v_a).
    SymmetricTensor<2, 3>
    to_eigenbasis(const SymmetricTensor<2, 3> &T) const;

    /// Q T Q^T: back from components @p T in the eigenbasis.
    SymmetricTensor<2, 3>
    from_eigenbasis(const SymmetricTensor<2, 3> &T) const;

    /// sum_a d_a v_a (x) v_a.
    SymmetricTensor<2, 3>
    from_eigenbasis_diagonal(const std::array<double, 3> &d) const;

    /// The eigenvalues x_a.
    std::array<double, 3> values;
    /// Q: the eigenvectors v_a as columns.
    Tensor<2, 3> vectors;
  };

  /// F T F^T for symmetric F and T (U T U for the stretch U).
  SymmetricTensor<2, 3>
  congruence(const SymmetricTensor<2, 3> &F, const SymmetricTensor<2, 3> &T);
} // namespace FrictionalContact
